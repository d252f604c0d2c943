//! The file as written: serde checks keys and types, the spans locate later problems;
//! the validator turns the raw file into a [`SimConfig`], collecting every problem.

use super::*;

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawFile {
    #[serde(default)]
    pub(super) card: Vec<RawCard>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawCard {
    pub(super) index: Spanned<i64>,
    pub(super) emergency_stop: Option<bool>,
    pub(super) mc3b_port: Option<Spanned<String>>,
    #[serde(default)]
    pub(super) channel: Vec<RawChannel>,
    #[serde(default)]
    pub(super) rio: Vec<RawRio>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawChannel {
    pub(super) index: Spanned<i64>,
    pub(super) home: Option<Spanned<Vec<Spanned<f64>>>>,
    pub(super) home_contact: Option<Spanned<String>>,
    pub(super) limit_plus: Option<Spanned<f64>>,
    pub(super) limit_minus: Option<Spanned<f64>>,
    pub(super) index_spacing: Option<Spanned<i64>>,
    pub(super) index_phase: Option<Spanned<i64>>,
    pub(super) plant: Option<Spanned<toml::Value>>,
    pub(super) adc: Option<Spanned<toml::Value>>,
    pub(super) mc3b_limit_bits: Option<Spanned<Vec<Spanned<i64>>>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawRio {
    pub(super) set: Spanned<i64>,
    pub(super) slave: Spanned<i64>,
    pub(super) inputs: Option<Spanned<Vec<Spanned<i64>>>>,
    pub(super) loopback: Option<bool>,
}

/// Semantic checks after parsing; every problem keeps the span of the offending value.
pub(super) struct Validator<'a> {
    pub(super) text: &'a str,
    pub(super) problems: Vec<(Range<usize>, String)>,
}

impl Validator<'_> {
    pub(super) fn fail(&mut self, span: Range<usize>, msg: impl Into<String>) {
        self.problems.push((span, msg.into()));
    }

    /// An index-like integer in `0..n`.
    pub(super) fn index(&mut self, v: &Spanned<i64>, n: usize) -> Option<usize> {
        match usize::try_from(*v.get_ref()) {
            Ok(i) if i < n => Some(i),
            _ => {
                self.fail(
                    v.span(),
                    format!("must be 0..{}, not {}", n - 1, v.get_ref()),
                );
                None
            }
        }
    }

    /// A finite number (TOML allows `nan` and `inf`).
    pub(super) fn finite(&mut self, v: &Spanned<f64>) -> Option<f64> {
        let x = *v.get_ref();
        if x.is_finite() {
            Some(x)
        } else {
            self.fail(v.span(), format!("must be a finite number, not {x}"));
            None
        }
    }

    pub(super) fn file(&mut self, raw: RawFile) -> SimConfig {
        let mut cfg = SimConfig::default();
        let mut first_at: [Option<usize>; CARDS] = [None; CARDS];
        for card in &raw.card {
            let Some(ci) = self.index(&card.index, CARDS) else {
                continue;
            };
            if let Some(first) = first_at[ci] {
                let line = line_of(self.text, first);
                self.fail(
                    card.index.span(),
                    format!("card {ci} is configured twice (first at line {line})"),
                );
                continue;
            }
            first_at[ci] = Some(card.index.span().start);
            cfg.cards[ci] = self.card(card);
        }
        cfg
    }

    pub(super) fn card(&mut self, raw: &RawCard) -> CardSim {
        let mut card = CardSim {
            emergency_stop: raw.emergency_stop.unwrap_or(false),
            ..CardSim::default()
        };
        if let Some(port) = &raw.mc3b_port {
            if port.get_ref().trim().is_empty() {
                self.fail(port.span(), "must name a serial port, not be empty");
            } else {
                card.mc3b_port = Some(port.get_ref().clone());
            }
        }
        let mut first_at: [Option<usize>; AXES] = [None; AXES];
        for ch in &raw.channel {
            let Some(i) = self.index(&ch.index, AXES) else {
                continue;
            };
            if let Some(first) = first_at[i] {
                let line = line_of(self.text, first);
                self.fail(
                    ch.index.span(),
                    format!("channel {i} is configured twice on this card (first at line {line})"),
                );
                continue;
            }
            first_at[i] = Some(ch.index.span().start);
            card.channels[i] = self.channel(ch);
            if let Some(bits) = &ch.mc3b_limit_bits {
                if card.mc3b_port.is_none() || i >= 3 {
                    self.fail(
                        bits.span(),
                        "only for channels 0..2 of a card with mc3b_port (the MC3B's motors)",
                    );
                }
            }
        }
        let mut rio_first_at: Vec<((u8, u8), usize)> = Vec::new();
        for r in &raw.rio {
            let Some(slave) = self.rio(r) else {
                continue;
            };
            let key = (slave.set, slave.slave);
            if let Some((_, first)) = rio_first_at.iter().find(|(k, _)| *k == key) {
                let line = line_of(self.text, *first);
                self.fail(
                    r.slave.span(),
                    format!(
                        "set {} slave {} is configured twice on this card (first at line {line})",
                        key.0, key.1
                    ),
                );
                continue;
            }
            rio_first_at.push((key, r.slave.span().start));
            card.rio.push(slave);
        }
        card
    }

    pub(super) fn channel(&mut self, raw: &RawChannel) -> ChannelSim {
        let mut ch = ChannelSim::default();
        if let Some(home) = &raw.home {
            match home.get_ref().as_slice() {
                [from, to] => {
                    if let (Some(a), Some(b)) = (self.finite(from), self.finite(to)) {
                        if a < b {
                            ch.home = Some((a, b));
                        } else {
                            self.fail(
                                home.span(),
                                format!("from must be less than to, not [{a}, {b}]"),
                            );
                        }
                    }
                }
                other => self.fail(
                    home.span(),
                    format!(
                        "must be [from, to], two numbers, not {} value(s)",
                        other.len()
                    ),
                ),
            }
        }
        if let Some(contact) = &raw.home_contact {
            match contact.get_ref().as_str() {
                "no" => ch.home_nc = false,
                "nc" => ch.home_nc = true,
                other => self.fail(
                    contact.span(),
                    format!("must be \"no\" (normally open) or \"nc\" (normally closed), not \"{other}\""),
                ),
            }
        }
        let plus = raw.limit_plus.as_ref().and_then(|v| self.finite(v));
        let minus = raw.limit_minus.as_ref().and_then(|v| self.finite(v));
        if let (Some(p), Some(m), Some(span)) = (plus, minus, raw.limit_minus.as_ref()) {
            if m >= p {
                self.fail(
                    span.span(),
                    format!("must be less than limit_plus ({p}), not {m}"),
                );
            }
        }
        ch.limit_plus = plus;
        ch.limit_minus = minus;
        if let Some(s) = &raw.index_spacing {
            match u32::try_from(*s.get_ref()) {
                Ok(n) if n > 0 => ch.index_spacing = Some(n),
                _ => self.fail(
                    s.span(),
                    format!(
                        "must be 1..{} encoder counts, not {}",
                        u32::MAX,
                        s.get_ref()
                    ),
                ),
            }
        }
        if let Some(p) = &raw.index_phase {
            match (u32::try_from(*p.get_ref()), ch.index_spacing) {
                (Ok(n), Some(spacing)) if n >= spacing => self.fail(
                    p.span(),
                    format!("must be less than index_spacing ({spacing}), not {n}"),
                ),
                (Ok(n), _) => ch.index_phase = n,
                (Err(_), _) => self.fail(
                    p.span(),
                    format!(
                        "must be 0..{} encoder counts, not {}",
                        u32::MAX - 1,
                        p.get_ref()
                    ),
                ),
            }
        }
        if let Some(plant) = &raw.plant {
            if let Some(p) = self.plant(plant) {
                ch.plant = p;
            }
        }
        if let Some(adc) = &raw.adc {
            ch.adc = self.adc(adc);
        }
        if let Some(bits) = &raw.mc3b_limit_bits {
            match bits.get_ref().as_slice() {
                [p, m] if (-1..=5).contains(p.get_ref()) && (-1..=5).contains(m.get_ref()) => {
                    // In range -1..5, so the narrowing keeps the value.
                    ch.mc3b_limit_bits = Some([*p.get_ref() as i8, *m.get_ref() as i8]);
                }
                _ => self.fail(
                    bits.span(),
                    "must be [plus, minus]: two MC3B limit input bits 0..5, or -1 for none",
                ),
            }
        }
        ch
    }

    pub(super) fn plant(&mut self, raw: &Spanned<toml::Value>) -> Option<Plant> {
        const FORMS: &str = "must be \"ideal\" or { lag_ms = <0 < ms <= 10000> }";
        match raw.get_ref() {
            toml::Value::String(s) if s == "ideal" => Some(Plant::Ideal),
            toml::Value::Table(t) => {
                if let Some(k) = t.keys().find(|k| k.as_str() != "lag_ms") {
                    self.fail(
                        raw.span(),
                        format!("unknown key \"{k}\" in the plant table ({FORMS})"),
                    );
                    return None;
                }
                let lag = match t.get("lag_ms") {
                    Some(toml::Value::Float(f)) => *f,
                    Some(toml::Value::Integer(i)) => *i as f64,
                    Some(other) => {
                        self.fail(
                            raw.span(),
                            format!("lag_ms must be a number, not {}", other.type_str()),
                        );
                        return None;
                    }
                    None => {
                        self.fail(raw.span(), format!("lag_ms is missing ({FORMS})"));
                        return None;
                    }
                };
                if lag.is_finite() && lag > 0.0 && lag <= MAX_LAG_MS {
                    Some(Plant::Lag {
                        tau_s: lag / 1000.0,
                    })
                } else {
                    self.fail(
                        raw.span(),
                        format!("lag_ms must be 0 < lag_ms <= {MAX_LAG_MS}, not {lag}"),
                    );
                    None
                }
            }
            other => {
                self.fail(raw.span(), format!("{FORMS}, not {}", describe(other)));
                None
            }
        }
    }

    pub(super) fn adc(&mut self, raw: &Spanned<toml::Value>) -> Option<AdcSource> {
        let forms = format!(
            "must be a voltage -{MAX_ADC_VOLTS}..{MAX_ADC_VOLTS} or \"dac0\"..\"dac{}\"",
            DAC_CHANNELS - 1
        );
        let volts = match raw.get_ref() {
            toml::Value::Float(f) => *f,
            toml::Value::Integer(i) => *i as f64,
            toml::Value::String(s) => {
                let dac = s
                    .strip_prefix("dac")
                    .filter(|n| n.len() == 1)
                    .and_then(|n| n.parse::<u8>().ok())
                    .filter(|&n| usize::from(n) < DAC_CHANNELS);
                if dac.is_none() {
                    self.fail(raw.span(), format!("{forms}, not \"{s}\""));
                }
                return dac.map(AdcSource::Dac);
            }
            other => {
                self.fail(raw.span(), format!("{forms}, not {}", describe(other)));
                return None;
            }
        };
        if volts.is_finite() && volts.abs() <= MAX_ADC_VOLTS {
            Some(AdcSource::Volts(volts as f32))
        } else {
            self.fail(raw.span(), format!("{forms}, not {volts}"));
            None
        }
    }

    pub(super) fn rio(&mut self, raw: &RawRio) -> Option<RioSlaveSim> {
        let set = self.index(&raw.set, RIO_SETS);
        let slave = self.index(&raw.slave, RIO_SLAVES);
        let loopback = raw.loopback.unwrap_or(false);
        let mut inputs = [0u16; RIO_PORTS];
        let mut ok = true;
        if let Some(given) = &raw.inputs {
            if loopback {
                self.fail(
                    given.span(),
                    "a looped-back slave reads its outputs: give no inputs",
                );
                ok = false;
            } else if given.get_ref().len() > RIO_PORTS {
                self.fail(
                    given.span(),
                    format!(
                        "at most {RIO_PORTS} ports (0..{}), not {}",
                        RIO_PORTS - 1,
                        given.get_ref().len()
                    ),
                );
                ok = false;
            } else {
                for (slot, v) in inputs.iter_mut().zip(given.get_ref()) {
                    match u16::try_from(*v.get_ref()) {
                        Ok(w) => *slot = w,
                        Err(_) => {
                            self.fail(
                                v.span(),
                                format!("a port's inputs must be 0..65535, not {}", v.get_ref()),
                            );
                            ok = false;
                        }
                    }
                }
            }
        }
        let (set, slave) = (set?, slave?);
        ok.then_some(RioSlaveSim {
            set: u8::try_from(set).ok()?,
            slave: u8::try_from(slave).ok()?,
            inputs,
            loopback,
        })
    }
}

/// A value's kind for messages.
pub(super) fn describe(v: &toml::Value) -> String {
    match v {
        toml::Value::String(s) => format!("\"{s}\""),
        toml::Value::Integer(i) => i.to_string(),
        toml::Value::Float(f) => f.to_string(),
        toml::Value::Boolean(b) => b.to_string(),
        other => other.type_str().to_owned(),
    }
}
