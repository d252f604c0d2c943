//! `MCCL_TRACE=path.csv`: a CSV row per group per tick — virtual time, group, command
//! index, motion status, the 8 axis positions (UU, user coordinates) and the path speed.
//! Numbers are printed with fixed precision, so under the fast and stepped clocks the same
//! program writes the same file byte for byte.
//!
//! Next to it, `path.events.csv` (`x.csv` gives `x.events.csv`) records what happened:
//! `time_ms,card,group,kind,detail` (group -1 for card events; `detail` is
//! space-separated `key=value` pairs, never a comma). Groups note their events where they
//! happen ([`Note`], only while tracing); the card's inputs, go home and interrupts are
//! compared with the last tick here. When the system closes, the notes no row took yet
//! and the ends of the commands the close cuts short are written at the end of the last
//! tick ([`Trace::close_groups`]): every command started in the file ends there. Kinds: `config` (per mapped axis, at time 0: the
//! mechanism parameters the limits come from), `cmd_start`, `cmd_end`, `hold`,
//! `continue`, `abort`, `error_set`, `error_cleared`, `inpos_begin`, `inpos_done`,
//! `inpos_fail`, `limit_plus`, `limit_minus`, `home_input`, `emergency_stop`,
//! `max_pulse_speed`, `max_pulse_acc`, `home_phase`, `home_end`, `interrupt`.

use super::group::GroupState;
use super::isr;
pub use super::note::Note;
use crate::config::MacTable;
use crate::config::AXES;
use crate::machine::{Machine, SensorLevels};
use std::fs::File;

/// A CSV file being written, which stops (once, saying why) at its first error.
#[derive(Debug)]
struct CsvFile {
    out: csv::Writer<File>,
    path: String,
    failed: bool,
}

impl CsvFile {
    /// Creates `path`.
    fn create(path: String) -> std::io::Result<CsvFile> {
        Ok(CsvFile {
            out: csv::Writer::from_writer(File::create(&path)?),
            path,
            failed: false,
        })
    }

    /// Writes one record (fields are quoted only where CSV needs it; none of the
    /// library's does).
    fn record<T: AsRef<[u8]>>(&mut self, what: &str, fields: impl IntoIterator<Item = T>) {
        if self.failed {
            return;
        }
        if let Err(e) = self.out.write_record(fields) {
            eprintln!("MCCL: {what} {} stopped: {e}", self.path);
            self.failed = true;
        }
    }

    /// Writes buffered records out.
    fn flush(&mut self) {
        if !self.failed {
            let _ = self.out.flush();
        }
    }
}

/// An open trace file.
#[derive(Debug)]
pub struct Trace {
    out: CsvFile,
    events: Events,
}

impl Trace {
    /// Opens the file named by `MCCL_TRACE` (none when unset or empty).
    pub fn from_env() -> Result<Option<Trace>, String> {
        match std::env::var("MCCL_TRACE") {
            Ok(p) if !p.is_empty() => Trace::create(&p).map(Some),
            _ => Ok(None),
        }
    }

    /// Creates `path` and writes the header line.
    pub fn create(path: &str) -> Result<Trace, String> {
        let out =
            CsvFile::create(path.to_string()).map_err(|e| format!("MCCL_TRACE={path}: {e}"))?;
        let ep = events_path(path);
        let events =
            CsvFile::create(ep.clone()).map_err(|e| format!("MCCL_TRACE={path}: {ep}: {e}"))?;
        let mut t = Trace {
            out,
            events: Events {
                out: events,
                cards: Vec::new(),
                home: None,
            },
        };
        t.out.record("trace", ROW_HEADER);
        t.events.out.record("trace events", EVENTS_HEADER);
        Ok(t)
    }

    /// One row for group `g` at virtual time `t_ns`.
    pub fn row(&mut self, t_ns: u128, g: &GroupState) {
        let s = g.snapshot();
        let head = [
            fmt_time(t_ns),
            g.index().to_string(),
            s.cmd.nCommandIndex.to_string(),
            s.status.to_string(),
        ];
        let numbers = s
            .pos
            .iter()
            .chain([&s.path_speed])
            .map(|v| format!("{v:.9}"));
        self.out.record("trace", head.into_iter().chain(numbers));
    }

    /// Writes buffered rows out.
    pub fn flush(&mut self) {
        self.out.flush();
        self.events.out.flush();
    }

    /// At start: turns on group `g`'s notes and writes a `config` event per mapped axis
    /// (`ppr`, `rpm`, `pitch`, `gear` of `mac`; `max_speed` = the maximum safe speed in
    /// UU/s; `pulses_per_uu`; the work zone; `max_pulse_speed`/`max_pulse_acc` of the
    /// channel in pulses per period).
    pub fn start_group(&mut self, g: &mut GroupState, mac: &MacTable, machine: &Machine) {
        g.start_notes();
        for (i, a) in g.axes().iter().enumerate() {
            let Some((card, ch)) = a.channel else {
                continue;
            };
            let m = &mac[card][ch];
            let (ms, ma) = machine
                .channel(card, ch)
                .map_or((0, 0), |c| (c.max_speed(), c.max_acc()));
            let d = format!(
                "axis={} channel={ch} ppr={} rpm={} pitch={:.9} gear={:.9} max_speed={:.9} \
                 pulses_per_uu={:.9} high={:.9} low={:.9} max_pulse_speed={ms} max_pulse_acc={ma}",
                AXIS_NAMES[i],
                m.dwPPR,
                m.wRPM,
                m.dfPitch,
                m.dfGearRatio,
                a.safe_speed,
                a.factor,
                a.high,
                a.low
            );
            self.events
                .write(0, card as i64, g.index() as i64, "config", &d);
        }
    }

    /// The events group `g` noted since its last row (call after [`Trace::row`]).
    pub fn group_events(&mut self, t_ns: u128, g: &mut GroupState) {
        let card = g.def().card.0 as i64;
        let index = g.index() as i64;
        let Some(notes) = g.notes_mut() else {
            return;
        };
        for n in notes.drain(..) {
            let (kind, detail) = note_text(&n);
            self.events.write(t_ns, card, index, kind, &detail);
        }
    }

    /// The system closes at `t_ns` (no tick follows): each group's events noted since
    /// its last row, then the end (`stopped`) of every command still running, which the
    /// close cuts short. Without this an abort called just before the close, and the
    /// command it stopped, would have no line, and the command no end.
    pub fn close_groups(&mut self, t_ns: u128, groups: &mut [GroupState]) {
        for g in groups {
            g.note_stopped();
            self.group_events(t_ns, g);
        }
    }

    /// The card's inputs and limits after the machine stepped: changes of the limit
    /// switches, home sensors (as the program reads them), the emergency-stop input and
    /// the pulse speed/acceleration limits.
    pub fn machine_events(&mut self, t_ns: u128, m: &Machine) {
        let ev = &mut self.events;
        if ev.cards.len() < m.cards().len() {
            ev.cards.resize(m.cards().len(), CardSeen::default());
            for (card, chans) in m.cards().iter().enumerate() {
                let seen = &mut ev.cards[card];
                for (ch, c) in chans.iter().enumerate() {
                    seen.max_speed[ch] = c.max_speed();
                    seen.max_acc[ch] = c.max_acc();
                }
            }
        }
        for (card, chans) in m.cards().iter().enumerate() {
            let emg = m.emergency(card);
            if emg != ev.cards[card].emergency {
                ev.cards[card].emergency = emg;
                let d = format!("active={}", u8::from(emg));
                ev.write(t_ns, card as i64, -1, "emergency_stop", &d);
            }
            for (ch, c) in chans.iter().enumerate() {
                let now = c.levels();
                let was = ev.cards[card].levels[ch];
                for (kind, a, b) in [
                    ("limit_plus", was.plus, now.plus),
                    ("limit_minus", was.minus, now.minus),
                    ("home_input", was.home, now.home),
                ] {
                    if a != b {
                        let d = format!("channel={ch} active={}", u8::from(b));
                        ev.write(t_ns, card as i64, -1, kind, &d);
                    }
                }
                ev.cards[card].levels[ch] = now;
                if c.max_speed() != ev.cards[card].max_speed[ch] {
                    ev.cards[card].max_speed[ch] = c.max_speed();
                    let d = format!("channel={ch} pulses={}", c.max_speed());
                    ev.write(t_ns, card as i64, -1, "max_pulse_speed", &d);
                }
                if c.max_acc() != ev.cards[card].max_acc[ch] {
                    ev.cards[card].max_acc[ch] = c.max_acc();
                    let d = format!("channel={ch} pulses={}", c.max_acc());
                    ev.write(t_ns, card as i64, -1, "max_pulse_acc", &d);
                }
            }
        }
    }

    /// A go-home tick: the order and phase running (`home_phase` when they change) and
    /// its end (`home_end` with the go-home status).
    pub fn home_events(
        &mut self,
        t_ns: u128,
        card: usize,
        order: i32,
        phase: u8,
        end: Option<i32>,
    ) {
        let ev = &mut self.events;
        if ev.home != Some((order, phase)) && end.is_none() {
            ev.home = Some((order, phase));
            let d = format!("order={order} phase={phase}");
            ev.write(t_ns, card as i64, -1, "home_phase", &d);
        }
        if let Some(status) = end {
            ev.home = None;
            ev.write(
                t_ns,
                card as i64,
                -1,
                "home_end",
                &format!("status={status}"),
            );
        }
    }

    /// The interrupt causes a tick collected, per card and routine kind: `delivered=1`
    /// when a routine is registered for it (the causes of a kind without one are dropped).
    pub fn interrupt_events(
        &mut self,
        t_ns: u128,
        collected: &isr::Collected,
        table: &isr::IsrTable,
    ) {
        for (card, pending) in collected.as_slice() {
            for kind in isr::ORDER {
                let bytes = pending.bytes(kind);
                if bytes.iter().all(|&b| b == 0) {
                    continue;
                }
                let mut d = format!(
                    "routine={} delivered={} causes=",
                    kind_name(kind),
                    u8::from(table.get(*card, kind) != 0)
                );
                let mut first = true;
                for (i, &b) in bytes.iter().enumerate() {
                    if b != 0 {
                        if !first {
                            d.push(';');
                        }
                        first = false;
                        d.push_str(&format!("{}:{b}", cause_name(kind, i)));
                    }
                }
                self.events.write(t_ns, *card as i64, -1, "interrupt", &d);
            }
        }
    }
}

/// Name of a `COMMAND_INFO.nType` code in the events file.
pub fn ctype_name(t: i32) -> &'static str {
    use super::command::ctype;
    match t {
        ctype::PTP => "PTP",
        ctype::LINE => "LINE",
        ctype::ARC_CW => "ARC_CW",
        ctype::ARC_CCW => "ARC_CCW",
        ctype::HELIX_CW => "HELIX_CW",
        ctype::HELIX_CCW => "HELIX_CCW",
        ctype::DELAY => "DELAY",
        ctype::BLEND_ON => "BLEND_ON",
        ctype::BLEND_OFF => "BLEND_OFF",
        ctype::INPOS_ON => "INPOS_ON",
        ctype::INPOS_OFF => "INPOS_OFF",
        super::custom::CTYPE_CUSTOM => "CUSTOM",
        _ => "OTHER",
    }
}

fn note_text(n: &Note) -> (&'static str, String) {
    match *n {
        Note::Start { index, ctype } => (
            "cmd_start",
            format!("index={index} type={}", ctype_name(ctype)),
        ),
        Note::End {
            index,
            ctype,
            stopped,
        } => (
            "cmd_end",
            format!(
                "index={index} type={} end={}",
                ctype_name(ctype),
                if stopped { "stopped" } else { "done" }
            ),
        ),
        Note::Hold { block_end } => ("hold", format!("block_end={}", u8::from(block_end))),
        Note::Continue => ("continue", String::new()),
        Note::Abort { dec_s, block_end } => (
            "abort",
            format!(
                "dec_ms={:.3} block_end={}",
                dec_s * 1000.0,
                u8::from(block_end)
            ),
        ),
        Note::ErrorSet(c) => ("error_set", format!("code=0x{:04X}", c)),
        Note::ErrorCleared(c) => ("error_cleared", format!("code=0x{:04X}", c)),
        Note::InPosBegin(m) => ("inpos_begin", format!("axes=0x{m:02X}")),
        Note::InPosDone(m) => ("inpos_done", format!("axes=0x{m:02X}")),
        Note::InPosFail { mask, error } => (
            "inpos_fail",
            format!("axes=0x{mask:02X} error={}", u8::from(error)),
        ),
    }
}

/// Names of the interrupt cause bytes per routine kind (the vendor struct fields).
fn cause_name(kind: isr::Kind, i: usize) -> String {
    match kind {
        isr::Kind::Lio => match i {
            0..=7 => format!("OTP{i}"),
            8..=15 => format!("OTN{}", i - 8),
            _ => format!("HOME{}", i - 16),
        },
        isr::Kind::Enc => match i {
            0..=7 => format!("INDEX{i}"),
            _ => format!("COMP{}", i - 8),
        },
        isr::Kind::Pcl => match i {
            0..=7 => format!("OVP{i}"),
            _ => format!("OVN{}", i - 8),
        },
        isr::Kind::Adc => match i {
            0..=7 => format!("COMP{i}"),
            8 => "CONV".into(),
            _ => "TAG".into(),
        },
        isr::Kind::Tmr => "TIMER".into(),
        isr::Kind::Rio => match i {
            0..=7 => format!("RDI{i}"),
            _ => "FAIL".into(),
        },
        isr::Kind::Hsk => "HANDSHAKE".into(),
    }
}

fn kind_name(kind: isr::Kind) -> &'static str {
    match kind {
        isr::Kind::Lio => "LIO",
        isr::Kind::Enc => "ENC",
        isr::Kind::Pcl => "PCL",
        isr::Kind::Adc => "ADC",
        isr::Kind::Tmr => "TMR",
        isr::Kind::Rio => "RIO",
        isr::Kind::Hsk => "HSK",
    }
}

fn fmt_time(t_ns: u128) -> String {
    format!("{}.{:06}", t_ns / 1_000_000, t_ns % 1_000_000)
}

/// What the events file last saw of a card's inputs, to write their changes.
#[derive(Debug, Clone, Default)]
struct CardSeen {
    levels: [SensorLevels; AXES],
    emergency: bool,
    max_speed: [i32; AXES],
    max_acc: [i32; AXES],
}

/// The events file next to the trace: `time_ms,card,group,kind,detail`.
#[derive(Debug)]
struct Events {
    out: CsvFile,
    cards: Vec<CardSeen>,
    home: Option<(i32, u8)>,
}

/// Axis names in `config` events.
const AXIS_NAMES: [&str; AXES] = ["x", "y", "z", "u", "v", "w", "a", "b"];

/// The trace's columns.
const ROW_HEADER: [&str; 13] = [
    "time_ms", "group", "command", "status", "x", "y", "z", "u", "v", "w", "a", "b", "speed",
];

/// The events file's columns.
const EVENTS_HEADER: [&str; 5] = ["time_ms", "card", "group", "kind", "detail"];

impl Events {
    fn write(&mut self, t_ns: u128, card: i64, group: i64, kind: &str, detail: &str) {
        let fields = [
            fmt_time(t_ns),
            card.to_string(),
            group.to_string(),
            kind.to_string(),
            detail.to_string(),
        ];
        self.out.record("trace events", fields);
    }
}

/// The events file's name for trace file `path`: `x.csv` gives `x.events.csv`.
pub fn events_path(path: &str) -> String {
    match path.strip_suffix(".csv") {
        Some(stem) => format!("{stem}.events.csv"),
        None => format!("{path}.events.csv"),
    }
}
