//! The first pass over a trace: per group its time span, ranges, peaks, and per command
//! its statistics. Memory grows with the number of groups and commands, not rows.

use crate::data::{Event, Reader, Row};
use std::collections::BTreeMap;

/// Statistics of one command of a group.
#[derive(Debug, Clone, PartialEq)]
pub struct CmdStat {
    /// Command index.
    pub index: i32,
    /// Command type name (from the events; `?` without them).
    pub ctype: String,
    /// Start, ms.
    pub start: f64,
    /// End, ms (the last row seen while it was open when the trace ends first).
    pub end: f64,
    /// How it ended: `done`, `stopped`, or `open` (the trace ended).
    pub how: String,
    /// Path length over X/Y/Z, UU.
    pub length: f64,
    /// Peak path speed, UU/s.
    pub peak_speed: f64,
    /// Peak speed per axis, UU/s.
    pub peak_vel: [f64; 8],
    /// Peak acceleration per axis, UU/s².
    pub peak_acc: [f64; 8],
}

impl CmdStat {
    fn new(index: i32, ctype: &str, start: f64) -> CmdStat {
        CmdStat {
            index,
            ctype: ctype.to_string(),
            start,
            end: start,
            how: "open".into(),
            length: 0.0,
            peak_speed: 0.0,
            peak_vel: [0.0; 8],
            peak_acc: [0.0; 8],
        }
    }
}

/// What the first pass learnt about one group.
#[derive(Debug, Clone, PartialEq)]
pub struct GroupScan {
    /// Group index.
    pub group: u32,
    /// Rows.
    pub rows: u64,
    /// First and last time, ms.
    pub t0: f64,
    /// Last time, ms.
    pub t1: f64,
    /// Least position per axis.
    pub min: [f64; 8],
    /// Greatest position per axis.
    pub max: [f64; 8],
    /// Peak path speed, UU/s, and when.
    pub peak_speed: (f64, f64),
    /// Peak |speed| per axis, UU/s (finite differences of positions).
    pub peak_vel: [f64; 8],
    /// Peak |acceleration| per axis, UU/s².
    pub peak_acc: [f64; 8],
    /// Least and greatest signed speed per axis.
    pub vel_range: [(f64, f64); 8],
    /// Least and greatest signed acceleration per axis.
    pub acc_range: [(f64, f64); 8],
    /// Commands in start order.
    pub cmds: Vec<CmdStat>,
    prev: Option<(f64, [f64; 8], [f64; 8])>,
    next_cmd: usize,
    active: Vec<usize>,
    from_events: bool,
}

/// Per-row derived values: the finite-difference speed and acceleration per axis.
#[derive(Debug, Clone, Copy, Default)]
pub struct Derived {
    /// Speed per axis, UU/s (0 on a group's first row).
    pub vel: [f64; 8],
    /// Acceleration per axis, UU/s² (0 on a group's first two rows).
    pub acc: [f64; 8],
    /// X/Y/Z distance from the previous row, UU.
    pub step: f64,
    /// Whether there was a previous row (`vel` is known).
    pub has_prev: bool,
    /// Whether there were two previous rows (`acc` is known).
    pub has_acc: bool,
}

impl GroupScan {
    fn new(group: u32, events: &[Event]) -> GroupScan {
        // Commands from the events: cmd_start opens, cmd_end of the same index closes.
        let mut cmds: Vec<CmdStat> = Vec::new();
        let mut open: BTreeMap<i32, usize> = BTreeMap::new();
        for e in events.iter().filter(|e| e.group == i64::from(group)) {
            let idx = e.num("index").map(|v| v as i32);
            match (e.kind.as_str(), idx) {
                ("cmd_start", Some(i)) => {
                    open.insert(i, cmds.len());
                    cmds.push(CmdStat::new(i, e.get("type").unwrap_or("?"), e.t_ms));
                }
                ("cmd_end", Some(i)) => {
                    if let Some(n) = open.remove(&i) {
                        cmds[n].end = e.t_ms;
                        cmds[n].how = e.get("end").unwrap_or("done").to_string();
                    }
                }
                _ => {}
            }
        }
        for (_, n) in open {
            cmds[n].end = f64::INFINITY;
        }
        GroupScan {
            group,
            rows: 0,
            t0: f64::NAN,
            t1: f64::NAN,
            min: [f64::INFINITY; 8],
            max: [f64::NEG_INFINITY; 8],
            peak_speed: (0.0, f64::NAN),
            peak_vel: [0.0; 8],
            peak_acc: [0.0; 8],
            vel_range: [(0.0, 0.0); 8],
            acc_range: [(0.0, 0.0); 8],
            from_events: !cmds.is_empty(),
            cmds,
            prev: None,
            next_cmd: 0,
            active: Vec::new(),
        }
    }

    /// Takes one row of this group; returns its derived values.
    pub fn absorb(&mut self, r: &Row) -> Derived {
        let mut d = Derived::default();
        if let Some((pt, pp, pv)) = self.prev {
            let dt = (r.t_ms - pt) / 1000.0;
            if dt > 0.0 {
                d.has_prev = true;
                for i in 0..8 {
                    d.vel[i] = (r.pos[i] - pp[i]) / dt;
                    if self.rows >= 2 {
                        d.acc[i] = (d.vel[i] - pv[i]) / dt;
                        d.has_acc = true;
                    }
                }
                d.step = ((r.pos[0] - pp[0]).powi(2)
                    + (r.pos[1] - pp[1]).powi(2)
                    + (r.pos[2] - pp[2]).powi(2))
                .sqrt();
            }
        }
        if self.rows == 0 {
            self.t0 = r.t_ms;
        }
        self.rows += 1;
        self.t1 = r.t_ms;
        for i in 0..8 {
            self.min[i] = self.min[i].min(r.pos[i]);
            self.max[i] = self.max[i].max(r.pos[i]);
            self.peak_vel[i] = self.peak_vel[i].max(d.vel[i].abs());
            self.peak_acc[i] = self.peak_acc[i].max(d.acc[i].abs());
            let v = &mut self.vel_range[i];
            *v = (v.0.min(d.vel[i]), v.1.max(d.vel[i]));
            let a = &mut self.acc_range[i];
            *a = (a.0.min(d.acc[i]), a.1.max(d.acc[i]));
        }
        if r.speed > self.peak_speed.0 || self.peak_speed.1.is_nan() {
            self.peak_speed = (r.speed, r.t_ms);
        }
        self.prev = Some((r.t_ms, r.pos, d.vel));
        self.commands(r, &d);
        d
    }

    fn commands(&mut self, r: &Row, d: &Derived) {
        if !self.from_events {
            // Contiguous runs of the trace's command index.
            let same = self
                .cmds
                .last()
                .is_some_and(|c| c.index == r.cmd && c.how == "open");
            if !same {
                if let Some(c) = self.cmds.last_mut() {
                    if c.how == "open" {
                        c.how = "done".into();
                    }
                }
                if r.cmd >= 0 {
                    self.cmds.push(CmdStat::new(r.cmd, "?", r.t_ms));
                }
            }
            if r.cmd >= 0 {
                if let Some(c) = self.cmds.last_mut() {
                    c.end = r.t_ms;
                    update(c, r, d, true);
                }
            }
            return;
        }
        while self.next_cmd < self.cmds.len() && self.cmds[self.next_cmd].start <= r.t_ms {
            self.active.push(self.next_cmd);
            self.next_cmd += 1;
        }
        let t = r.t_ms;
        let cmds = &mut self.cmds;
        self.active.retain(|&n| cmds[n].end >= t);
        for &n in &self.active {
            let c = &mut cmds[n];
            let inside = t >= c.start;
            update(c, r, d, inside);
        }
    }

    /// After the last row: commands still open end there.
    fn finish(&mut self) {
        let t1 = self.t1;
        for c in &mut self.cmds {
            if c.end.is_infinite() {
                c.end = t1;
                c.how = "open".into();
            }
        }
    }
}

fn update(c: &mut CmdStat, r: &Row, d: &Derived, inside: bool) {
    c.peak_speed = c.peak_speed.max(r.speed);
    if inside && d.has_prev {
        c.length += d.step;
        for i in 0..8 {
            c.peak_vel[i] = c.peak_vel[i].max(d.vel[i].abs());
            c.peak_acc[i] = c.peak_acc[i].max(d.acc[i].abs());
        }
    }
}

/// The whole first pass.
#[derive(Debug, Clone, PartialEq)]
pub struct Scan {
    /// Per group, by group index.
    pub groups: BTreeMap<u32, GroupScan>,
    /// Rows read.
    pub rows: u64,
}

/// Reads the trace at `path` once, keeping rows with `from <= t <= to`.
pub fn scan(path: &str, events: &[Event], from: f64, to: f64) -> Result<Scan, String> {
    let mut r = Reader::open(path)?;
    let mut s = Scan {
        groups: BTreeMap::new(),
        rows: 0,
    };
    while let Some(row) = r.next_row()? {
        if row.t_ms < from || row.t_ms > to {
            continue;
        }
        s.rows += 1;
        s.groups
            .entry(row.group)
            .or_insert_with(|| GroupScan::new(row.group, events))
            .absorb(&row);
    }
    if s.rows == 0 {
        return Err(if from.is_finite() || to.is_finite() {
            format!("{path}: no rows in the time window")
        } else {
            format!("{path}: empty trace (a header and no rows)")
        });
    }
    for g in s.groups.values_mut() {
        g.finish();
    }
    Ok(s)
}

/// A fresh per-group derivation state for a second pass (same finite differences).
pub fn deriver(group: u32) -> GroupScan {
    GroupScan::new(group, &[])
}
