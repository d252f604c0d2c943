//! `report`: one self-contained HTML file (no network): the plots as inline SVG and, per
//! group, a table of its commands against the axis limits, its error records and the
//! interrupts of its card.

use crate::data::{axis_limits, AxisLimits, AXIS_NAMES};
use crate::plot::{self, Options};
use std::fmt::Write;

fn esc(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

/// The HTML report of trace `path`.
pub fn html(path: &str, opts: &Options) -> Result<String, String> {
    let (events, s, groups) = plot::prepare(path, opts)?;
    let (svg, info) = plot::svg_prepared(path, opts, &events, &s, &groups)?;
    let svg = match svg.find("<svg") {
        Some(i) => &svg[i..],
        None => &svg[..],
    };
    let name = std::path::Path::new(path)
        .file_name()
        .map_or(path.to_string(), |n| n.to_string_lossy().into_owned());
    let mut h = String::new();
    let _ = write!(
        h,
        "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>{n}</title>\n<style>\
body{{font-family:sans-serif;margin:16px}}table{{border-collapse:collapse;margin:8px 0 20px}}\
td,th{{border:1px solid #ccc;padding:2px 6px;text-align:right;font-size:13px}}\
th{{background:#eee}}td.l{{text-align:left}}.over{{background:#fcc}}svg{{max-width:100%;height:auto}}\
</style></head><body>\n<h1>{n}</h1>\n<p>{rows} rows, groups {gl}. Speeds and accelerations \
per axis are finite differences of the positions between ticks. A cell is red when it \
exceeds the axis's limit: the maximum safe speed (wRPM/60 &times; pitch / gear), or the \
pulse limits (<code>MCC_SetMaxPulseSpeed</code> pulses per period; \
<code>MCC_SetMaxPulseAcc</code> pulses per period per period).</p>\n",
        n = esc(&name),
        rows = s.rows,
        gl = groups.iter().map(|g| g.to_string()).collect::<Vec<_>>().join(", ")
    );
    h.push_str(svg);
    h.push('\n');
    for gp in &info.groups {
        let g = gp.group;
        let gs = &s.groups[&g];
        let lim = axis_limits(&events, g);
        let period = period_s(gs);
        let _ = writeln!(h, "<h2>group {g}</h2>");
        let _ = writeln!(h, "<table><tr><th>axis</th><th>dwPPR</th><th>wRPM</th><th>max speed (UU/s)</th><th>max pulse speed (pulses/period)</th><th>= UU/s</th><th>max pulse acc (pulses/period²)</th><th>= UU/s²</th></tr>");
        for &i in &gp.axes {
            if let Some(l) = lim[i] {
                let (vs, as_) = pulse_limits(&l, period);
                let _ = writeln!(
                    h,
                    "<tr><td class=l>{}</td><td>{}</td><td>{}</td><td>{:.3}</td><td>{}</td><td>{:.3}</td><td>{}</td><td>{:.3}</td></tr>",
                    AXIS_NAMES[i], l.ppr, l.rpm, l.max_speed, l.max_pulse_speed, vs, l.max_pulse_acc, as_
                );
            }
        }
        h.push_str("</table>\n<table><tr><th>command</th><th>type</th><th>start (ms)</th><th>end (ms)</th><th>duration (ms)</th><th>end</th><th>length (UU)</th><th>peak path speed (UU/s)</th>");
        for &i in &gp.axes {
            let _ = write!(
                h,
                "<th>peak |v{}| (UU/s)</th><th>peak |a{}| (UU/s²)</th>",
                AXIS_NAMES[i], AXIS_NAMES[i]
            );
        }
        h.push_str("</tr>\n");
        for c in &gs.cmds {
            let _ = write!(
                h,
                "<tr><td>{}</td><td class=l>{}</td><td>{:.3}</td><td>{:.3}</td><td>{:.3}</td><td class=l>{}</td><td>{:.6}</td><td>{:.3}</td>",
                c.index, esc(&c.ctype), c.start, c.end, c.end - c.start, esc(&c.how), c.length, c.peak_speed
            );
            for &i in &gp.axes {
                let (vmax, amax) = match lim[i] {
                    Some(l) => {
                        let (vs, as_) = pulse_limits(&l, period);
                        (l.max_speed.min(vs), as_)
                    }
                    None => (f64::INFINITY, f64::INFINITY),
                };
                let cls = |v: f64, m: f64| {
                    if v > m * (1.0 + 1e-9) {
                        " class=over"
                    } else {
                        ""
                    }
                };
                let _ = write!(
                    h,
                    "<td{}>{:.3}</td><td{}>{:.3}</td>",
                    cls(c.peak_vel[i], vmax),
                    c.peak_vel[i],
                    cls(c.peak_acc[i], amax),
                    c.peak_acc[i]
                );
            }
            h.push_str("</tr>\n");
        }
        h.push_str("</table>\n");
        let card = events
            .iter()
            .find(|e| e.group == i64::from(g))
            .map(|e| e.card);
        let rec: Vec<_> = events
            .iter()
            .filter(|e| {
                (e.group == i64::from(g)
                    && matches!(
                        e.kind.as_str(),
                        "error_set"
                            | "error_cleared"
                            | "hold"
                            | "continue"
                            | "abort"
                            | "inpos_fail"
                    ))
                    || (e.group < 0 && Some(e.card) == card && e.kind != "config")
            })
            .filter(|e| e.t_ms >= opts.from && e.t_ms <= opts.to)
            .collect();
        if rec.is_empty() {
            h.push_str("<p>No error records, holds, aborts, inputs or interrupts.</p>\n");
        } else {
            h.push_str("<table><tr><th>time (ms)</th><th>card</th><th>group</th><th>event</th><th>detail</th></tr>\n");
            for e in rec.iter().take(2000) {
                let _ = writeln!(
                    h,
                    "<tr><td>{:.3}</td><td>{}</td><td>{}</td><td class=l>{}</td><td class=l>{}</td></tr>",
                    e.t_ms, e.card, e.group, esc(&e.kind), esc(&e.detail)
                );
            }
            h.push_str("</table>\n");
            if rec.len() > 2000 {
                let _ = writeln!(
                    h,
                    "<p>… and {} more events (see the events file).</p>",
                    rec.len() - 2000
                );
            }
        }
    }
    h.push_str("</body></html>\n");
    Ok(h)
}

/// The interpolation period of a group's trace, s (its time span over its rows).
fn period_s(gs: &crate::scan::GroupScan) -> f64 {
    if gs.rows > 1 {
        (gs.t1 - gs.t0) / (gs.rows - 1) as f64 / 1000.0
    } else {
        0.001
    }
}

/// The pulse limits in UU/s and UU/s².
fn pulse_limits(l: &AxisLimits, period: f64) -> (f64, f64) {
    let ppu = l.pulses_per_uu.abs();
    (
        l.max_pulse_speed / ppu / period,
        l.max_pulse_acc / ppu / (period * period),
    )
}
