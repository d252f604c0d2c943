//! Reading traces and their events, as streams: a [`Reader`] yields one row at a time, so
//! memory does not grow with the length of the trace.

use crate::lines::{text, Lines};
use std::fs::File;

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
    lines: Lines,
}

impl Reader {
    /// Opens `path` and checks its header.
    pub fn open(path: &str) -> Result<Reader, String> {
        let f = File::open(path).map_err(|e| format!("{path}: cannot open: {e}"))?;
        let mut lines = Lines::new(path, f, true);
        match lines.next_record()?.map(|(_, r)| text(r)) {
            None => Err(format!("{path}: empty file (not a trace: no header)")),
            Some(h) if h == HEADER => Ok(Reader {
                name: path.to_string(),
                lines,
            }),
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
        self.lines.line_no()
    }

    /// The next row, `None` at the end of the file.
    pub fn next_row(&mut self) -> Result<Option<Row>, String> {
        let Some((ln, fields)) = self.lines.next_record()? else {
            return Ok(None);
        };
        let name = &self.name;
        let err = |what: String| format!("{name}:{ln}: {what}");
        if fields.len() != 13 {
            return Err(err(format!("expected 13 fields, found {}", fields.len())));
        }
        let field = |i: usize| fields.get(i).unwrap_or_default();
        let col = |i: usize| HEADER.split(',').nth(i).unwrap_or("?");
        let num = |i: usize| -> Result<f64, String> {
            match field(i).parse::<f64>() {
                Ok(v) if v.is_finite() => Ok(v),
                _ => Err(err(format!(
                    "field {}: not a finite number: \"{}\"",
                    col(i),
                    field(i)
                ))),
            }
        };
        let int = |i: usize| -> Result<i64, String> {
            field(i).parse::<i64>().map_err(|_| {
                err(format!(
                    "field {}: not an integer: \"{}\"",
                    col(i),
                    field(i)
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
    let mut lines = Lines::new(&ep, f, false);
    match lines.next_record()?.map(|(_, r)| text(r)) {
        None => return Ok(Vec::new()),
        Some(h) if h == EVENTS_HEADER => {}
        Some(_) => {
            return Err(format!(
                "{ep}:1: not an events header: expected \"{EVENTS_HEADER}\""
            ))
        }
    }
    let mut out = Vec::new();
    while let Some((ln, r)) = lines.next_record()? {
        let bad = |w: &str| format!("{ep}:{ln}: {w}");
        if r.len() < 5 {
            return Err(bad("expected 5 fields"));
        }
        let field = |i: usize| r.get(i).unwrap_or_default();
        // The detail has no comma; if one came, it stays in the detail.
        let detail = r.iter().skip(4).collect::<Vec<_>>().join(",");
        out.push(Event {
            t_ms: field(0)
                .parse()
                .ok()
                .filter(|v: &f64| v.is_finite())
                .ok_or_else(|| bad("time_ms: not a number"))?,
            card: field(1).parse().map_err(|_| bad("card: not an integer"))?,
            group: field(2).parse().map_err(|_| bad("group: not an integer"))?,
            kind: field(3).to_string(),
            detail,
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
