//! What the events mark on the time panels: command boundaries and the spans of holds,
//! delays, aborts and errors.

use crate::data::Event;
use crate::scan::GroupScan;

/// Spans of a group from its events: (start, end, kind, label) with kind `hold`, `delay`,
/// `abort` (from the call to the stop) or `error` (labelled with the error code).
pub fn spans(events: &[Event], gs: &GroupScan) -> Vec<(f64, f64, &'static str, String)> {
    let g = i64::from(gs.group);
    let mut out = Vec::new();
    let mut hold: Option<f64> = None;
    let mut err: Option<(f64, String)> = None;
    let mut abort: Option<f64> = None;
    for ev in events.iter().filter(|ev| ev.group == g) {
        match ev.kind.as_str() {
            "abort" => {
                abort = Some(ev.t_ms);
                if let Some(h) = hold.take() {
                    out.push((h, ev.t_ms, "hold", "hold".to_string()));
                }
            }
            "cmd_end" if ev.get("end") == Some("stopped") => {
                if let Some(a) = abort.take() {
                    out.push((a, ev.t_ms, "abort", "abort".to_string()));
                }
            }
            // An abort with nothing running stops nothing.
            "cmd_start" => abort = None,
            "hold" => hold = hold.or(Some(ev.t_ms)),
            "continue" => {
                if let Some(h) = hold.take() {
                    out.push((h, ev.t_ms, "hold", "hold".to_string()));
                }
            }
            "error_set" if err.is_none() => {
                let code = ev.get("code").unwrap_or("?");
                err = Some((ev.t_ms, format!("error {code}")));
            }
            "error_cleared" => {
                if let Some((s, l)) = err.take() {
                    out.push((s, ev.t_ms, "error", l));
                }
            }
            _ => {}
        }
    }
    if let Some(h) = hold {
        out.push((h, gs.t1, "hold", "hold".to_string()));
    }
    if let Some((s, l)) = err {
        out.push((s, gs.t1, "error", l));
    }
    for c in gs.cmds.iter().filter(|c| c.ctype == "DELAY") {
        out.push((c.start, c.end, "delay", "delay".to_string()));
    }
    out
}

/// Command boundaries of a group: every command start and the last end, ms.
pub fn boundaries(gs: &GroupScan) -> Vec<f64> {
    let mut b: Vec<f64> = gs.cmds.iter().map(|c| c.start).collect();
    if let Some(c) = gs.cmds.last() {
        b.push(c.end);
    }
    b.retain(|t| *t >= gs.t0 && *t <= gs.t1);
    b.dedup();
    b
}
