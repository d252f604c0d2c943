//! Reading traces and their events, as streams: a [`Reader`] yields one row at a time, so
//! memory does not grow with the length of the trace.

use std::fs::File;
use std::io::{BufRead, BufReader};

/// The header line of a trace (`MCCL_TRACE`).
pub const HEADER: &str = "time_ms,group,command,status,x,y,z,u,v,w,a,b,speed";
/// The header line of an events file.
pub const EVENTS_HEADER: &str = "time_ms,card,group,kind,detail";
/// Axis names, in trace column order.
pub const AXIS_NAMES: [&str; 8] = ["x", "y", "z", "u", "v", "w", "a", "b"];

/// One row of a trace: a group at a tick.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Row {
    /// Virtual time, ms.
    pub t_ms: f64,
    /// Group index.
    pub group: u32,
    /// Index of the running command (-1 when none).
    pub cmd: i32,
    /// Motion status (`GMS_*`).
    pub status: i32,
    /// Axis positions X..B, UU.
    pub pos: [f64; 8],
    /// Path speed, UU/s.
    pub speed: f64,
}

/// A trace file read row by row.
pub struct Reader {
    name: String,
    input: Box<dyn BufRead>,
    line_no: usize,
    buf: String,
}

impl Reader {
    /// Opens `path` and checks its header.
    pub fn open(path: &str) -> Result<Reader, String> {
        let f = File::open(path).map_err(|e| format!("{path}: cannot open: {e}"))?;
        let mut r = Reader {
            name: path.to_string(),
            input: Box::new(BufReader::with_capacity(1 << 16, f)),
            line_no: 0,
            buf: String::new(),
        };
        match r.line()? {
            None => Err(format!("{path}: empty file (not a trace: no header)")),
            Some(h) if h == HEADER => Ok(r),
            Some(h) => Err(format!(
                "{path}:1: not a trace header: expected \"{HEADER}\", found \"{}\"",
                h.chars().take(80).collect::<String>()
            )),
        }
    }

    /// The file name, for messages.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The line number of the last row read.
    pub fn line_no(&self) -> usize {
        self.line_no
    }

    fn line(&mut self) -> Result<Option<&str>, String> {
        self.buf.clear();
        let n = self
            .input
            .read_line(&mut self.buf)
            .map_err(|e| format!("{}:{}: cannot read: {e}", self.name, self.line_no + 1))?;
        if n == 0 {
            return Ok(None);
        }
        self.line_no += 1;
        if !self.buf.ends_with('\n') {
            return Err(format!(
                "{}:{}: truncated line (the file ends without an end of line)",
                self.name, self.line_no
            ));
        }
        Ok(Some(self.buf.trim_end_matches(['\n', '\r'])))
    }

    /// The next row, `None` at the end of the file.
    pub fn next_row(&mut self) -> Result<Option<Row>, String> {
        if self.line()?.is_none() {
            return Ok(None);
        }
        let (name, ln, line) = (
            &self.name,
            self.line_no,
            self.buf.trim_end_matches(['\n', '\r']),
        );
        let err = |what: String| format!("{name}:{ln}: {what}");
        let mut fields = [""; 13];
        let mut n = 0;
        for s in line.split(',') {
            if n < 13 {
                fields[n] = s;
            }
            n += 1;
        }
        if n != 13 {
            return Err(err(format!("expected 13 fields, found {n}")));
        }
        let col = |i: usize| HEADER.split(',').nth(i).unwrap_or("?");
        let num = |i: usize| -> Result<f64, String> {
            match fields[i].parse::<f64>() {
                Ok(v) if v.is_finite() => Ok(v),
                _ => Err(err(format!(
                    "field {}: not a finite number: \"{}\"",
                    col(i),
                    fields[i]
                ))),
            }
        };
        let int = |i: usize| -> Result<i64, String> {
            fields[i].parse::<i64>().map_err(|_| {
                err(format!(
                    "field {}: not an integer: \"{}\"",
                    col(i),
                    fields[i]
                ))
            })
        };
        let group = u32::try_from(int(1)?).map_err(|_| err("field group: negative".into()))?;
        let cmd = i32::try_from(int(2)?).map_err(|_| err("field command: out of range".into()))?;
        let status =
            i32::try_from(int(3)?).map_err(|_| err("field status: out of range".into()))?;
        let mut pos = [0.0; 8];
        for (i, p) in pos.iter_mut().enumerate() {
            *p = num(4 + i)?;
        }
        Ok(Some(Row {
            t_ms: num(0)?,
            group,
            cmd,
            status,
            pos,
            speed: num(12)?,
        }))
    }
}

/// One line of an events file.
#[derive(Debug, Clone, PartialEq)]
pub struct Event {
    /// Virtual time, ms.
    pub t_ms: f64,
    /// Card.
    pub card: i64,
    /// Group (-1 for card events).
    pub group: i64,
    /// Kind (`cmd_start`, `error_set`, ...).
    pub kind: String,
    /// `key=value` pairs separated by spaces.
    pub detail: String,
}

impl Event {
    /// The value of `key` in the detail.
    pub fn get(&self, key: &str) -> Option<&str> {
        self.detail
            .split(' ')
            .find_map(|kv| kv.strip_prefix(key).and_then(|r| r.strip_prefix('=')))
    }

    /// The value of `key` as a number.
    pub fn num(&self, key: &str) -> Option<f64> {
        let v = self.get(key)?;
        match v.strip_prefix("0x") {
            Some(h) => i64::from_str_radix(h, 16).ok().map(|x| x as f64),
            None => v.parse().ok(),
        }
    }
}

/// The events file beside trace `path` (`x.csv` gives `x.events.csv`).
pub fn events_path(path: &str) -> String {
    match path.strip_suffix(".csv") {
        Some(stem) => format!("{stem}.events.csv"),
        None => format!("{path}.events.csv"),
    }
}

/// Reads the events beside trace `path`; none when there is no such file.
pub fn read_events(path: &str) -> Result<Vec<Event>, String> {
    let ep = events_path(path);
    let f = match File::open(&ep) {
        Ok(f) => f,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(Vec::new()),
        Err(e) => return Err(format!("{ep}: cannot open: {e}")),
    };
    let mut out = Vec::new();
    for (i, line) in BufReader::new(f).lines().enumerate() {
        let line = line.map_err(|e| format!("{ep}:{}: cannot read: {e}", i + 1))?;
        if i == 0 {
            if line != EVENTS_HEADER {
                return Err(format!(
                    "{ep}:1: not an events header: expected \"{EVENTS_HEADER}\""
                ));
            }
            continue;
        }
        let bad = |w: &str| format!("{ep}:{}: {w}", i + 1);
        let mut f = line.splitn(5, ',');
        let (Some(t), Some(c), Some(g), Some(k), Some(d)) =
            (f.next(), f.next(), f.next(), f.next(), f.next())
        else {
            return Err(bad("expected 5 fields"));
        };
        out.push(Event {
            t_ms: t
                .parse()
                .ok()
                .filter(|v: &f64| v.is_finite())
                .ok_or_else(|| bad("time_ms: not a number"))?,
            card: c.parse().map_err(|_| bad("card: not an integer"))?,
            group: g.parse().map_err(|_| bad("group: not an integer"))?,
            kind: k.to_string(),
            detail: d.to_string(),
        });
    }
    Ok(out)
}

/// Axis limits of one axis from the `config` events.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct AxisLimits {
    /// Maximum safe speed, UU/s ((wRPM/60) x pitch / gear).
    pub max_speed: f64,
    /// Pulses per UU.
    pub pulses_per_uu: f64,
    /// `MCC_SetMaxPulseSpeed`: pulses per interpolation period.
    pub max_pulse_speed: f64,
    /// `MCC_SetMaxPulseAcc`: change of pulses per period between periods.
    pub max_pulse_acc: f64,
    /// dwPPR.
    pub ppr: f64,
    /// wRPM.
    pub rpm: f64,
}

/// The `config` limits of group `g`'s axes (None for unmapped axes).
pub fn axis_limits(events: &[Event], g: u32) -> [Option<AxisLimits>; 8] {
    let mut out = [None; 8];
    for e in events
        .iter()
        .filter(|e| e.kind == "config" && e.group == i64::from(g))
    {
        let Some(i) = e
            .get("axis")
            .and_then(|a| AXIS_NAMES.iter().position(|n| *n == a))
        else {
            continue;
        };
        out[i] = Some(AxisLimits {
            max_speed: e.num("max_speed").unwrap_or(f64::NAN),
            pulses_per_uu: e.num("pulses_per_uu").unwrap_or(f64::NAN),
            max_pulse_speed: e.num("max_pulse_speed").unwrap_or(f64::NAN),
            max_pulse_acc: e.num("max_pulse_acc").unwrap_or(f64::NAN),
            ppr: e.num("ppr").unwrap_or(f64::NAN),
            rpm: e.num("rpm").unwrap_or(f64::NAN),
        });
    }
    out
}
