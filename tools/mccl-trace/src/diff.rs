//! `diff A B`: compares two traces row by row, streaming both.

use crate::data::{Reader, AXIS_NAMES};
use std::collections::BTreeMap;
use std::fmt::Write;

/// The outcome of a comparison.
#[derive(Debug, Clone, PartialEq)]
pub struct DiffResult {
    /// Whether the traces agree within the tolerance (same rows, times and groups).
    pub agree: bool,
    /// The report to print.
    pub text: String,
    /// The first difference beyond the tolerance: (time ms, group, axis name).
    pub first: Option<(f64, u32, String)>,
}

/// Compares trace `a` with trace `b`: positions per axis beyond `tol` UU; times, groups,
/// command indices and statuses must match exactly.
pub fn diff(a: &str, b: &str, tol: f64) -> Result<DiffResult, String> {
    let mut ra = Reader::open(a)?;
    let mut rb = Reader::open(b)?;
    let mut text = String::new();
    let mut first: Option<(f64, u32, String)> = None;
    let mut structural: Option<String> = None;
    // Per group: max |deviation| per axis and of the path speed.
    let mut maxdev: BTreeMap<u32, ([f64; 8], f64)> = BTreeMap::new();
    let mut rows = 0u64;
    loop {
        let (x, y) = (ra.next_row()?, rb.next_row()?);
        if rows == 0 {
            for (r, name) in [(&x, a), (&y, b)] {
                if r.is_none() {
                    return Err(format!("{name}: empty trace (a header and no rows)"));
                }
            }
        }
        let (x, y) = match (x, y) {
            (None, None) => break,
            (Some(x), None) => {
                structural = Some(format!(
                    "{b} ends after {rows} rows; {a} goes on (line {}: {:.6} ms, group {})",
                    ra.line_no(),
                    x.t_ms,
                    x.group
                ));
                break;
            }
            (None, Some(y)) => {
                structural = Some(format!(
                    "{a} ends after {rows} rows; {b} goes on (line {}: {:.6} ms, group {})",
                    rb.line_no(),
                    y.t_ms,
                    y.group
                ));
                break;
            }
            (Some(x), Some(y)) => (x, y),
        };
        rows += 1;
        if x.t_ms != y.t_ms || x.group != y.group {
            structural = Some(format!(
                "row {rows} (line {}): {a} has {:.6} ms group {}, {b} has {:.6} ms group {} \
                 (different ticks or groups)",
                ra.line_no(),
                x.t_ms,
                x.group,
                y.t_ms,
                y.group
            ));
            break;
        }
        let m = maxdev.entry(x.group).or_insert(([0.0; 8], 0.0));
        for i in 0..8 {
            let d = (x.pos[i] - y.pos[i]).abs();
            m.0[i] = m.0[i].max(d);
            if d > tol && first.is_none() {
                first = Some((x.t_ms, x.group, AXIS_NAMES[i].to_string()));
                let _ = writeln!(
                    text,
                    "first difference: {:.6} ms, group {}, axis {}: {:.9} vs {:.9} \
                     (|d| = {:.3e} UU > {:.3e}), line {}",
                    x.t_ms,
                    x.group,
                    AXIS_NAMES[i],
                    x.pos[i],
                    y.pos[i],
                    d,
                    tol,
                    ra.line_no()
                );
            }
        }
        m.1 = m.1.max((x.speed - y.speed).abs());
        if (x.cmd != y.cmd || x.status != y.status) && structural.is_none() && first.is_none() {
            first = Some((x.t_ms, x.group, "command/status".into()));
            let _ = writeln!(
                text,
                "first difference: {:.6} ms, group {}: command {} status {} vs command {} status {}",
                x.t_ms, x.group, x.cmd, x.status, y.cmd, y.status
            );
        }
    }
    if let Some(s) = &structural {
        let _ = writeln!(text, "traces differ in shape: {s}");
    }
    let _ = writeln!(text, "{rows} rows compared; max deviation per axis (UU):");
    for (g, (d, sp)) in &maxdev {
        let _ = write!(text, "  group {g}:");
        for (i, v) in d.iter().enumerate() {
            let _ = write!(text, " {}={:.3e}", AXIS_NAMES[i], v);
        }
        let _ = writeln!(text, " speed={sp:.3e} UU/s");
    }
    let agree = structural.is_none() && first.is_none();
    let _ = writeln!(
        text,
        "{}",
        if agree {
            format!("traces agree within {tol:.3e} UU")
        } else {
            "traces differ".to_string()
        }
    );
    Ok(DiffResult { agree, text, first })
}
