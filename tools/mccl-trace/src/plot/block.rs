//! Drawing one group's block: the path coloured by command, the time panels' series,
//! command boundaries and the hold, delay, abort and error spans.

use super::columns::Columns;
use super::panel::Panel;
use super::path::PathSimplifier;
use super::spans::{boundaries, spans};
use super::style::{e, font, AXIS_COLORS, BOUNDARY, CMD_COLORS, SPEED};
use crate::data::{Event, AXIS_NAMES};
use crate::scan::GroupScan;
use plotters::coord::Shift;
use plotters::prelude::*;

/// One group's block of panels in the plot: its panels, the axes drawn, the path
/// drawn in the plane and the columns read for each panel.
pub(super) struct Block {
    pub(super) group: u32,
    pub(super) panels: Vec<Panel>,
    pub(super) axes: Vec<usize>,
    pub(super) path: PathSimplifier,
    pub(super) cols: Vec<Columns>,
}

pub(super) fn draw_block<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    b: &Block,
    events: &[Event],
    gs: &GroupScan,
) -> Result<(), String> {
    // Path, one polyline per command run, each starting where the last ended.
    let path = &b.path.kept;
    let mut start = 0;
    let mut labelled = 0;
    let mut labels: Vec<(i32, i32, i32)> = Vec::new();
    while start < path.len() {
        let cmd = path[start].2;
        let mut end = start;
        while end + 1 < path.len() && path[end + 1].2 == cmd {
            end += 1;
        }
        let from = start.saturating_sub(1);
        let pts: Vec<(i32, i32)> = path[from..=end].iter().map(|p| (p.0, p.1)).collect();
        let color = if cmd < 0 {
            RGBColor(150, 150, 150)
        } else {
            CMD_COLORS[cmd as usize % CMD_COLORS.len()]
        };
        root.draw(&PathElement::new(pts, color.stroke_width(2)))
            .map_err(e)?;
        let mid = path[(start + end) / 2];
        let near =
            |l: &(i32, i32, i32)| l.0 == cmd && (l.1 - mid.0).abs() + (l.2 - mid.1).abs() < 30;
        if cmd >= 0 && labelled < 40 && !labels.iter().any(near) {
            labels.push((cmd, mid.0, mid.1));
            root.draw(&Text::new(
                format!("#{cmd}"),
                (mid.0 + 4, mid.1 - 14),
                font(12.0).color(&color),
            ))
            .map_err(e)?;
            labelled += 1;
        }
        start = end + 1;
    }
    if let (Some(f), Some(l)) = (path.first(), path.last()) {
        root.draw(&Circle::new((f.0, f.1), 6, RGBColor(0, 150, 0).filled()))
            .map_err(e)?;
        root.draw(&Text::new("start", (f.0 + 8, f.1 + 4), font(12.0)))
            .map_err(e)?;
        root.draw(&Rectangle::new(
            [(l.0 - 5, l.1 - 5), (l.0 + 5, l.1 + 5)],
            RED.filled(),
        ))
        .map_err(e)?;
        root.draw(&Text::new("end", (l.0 + 8, l.1 + 4), font(12.0)))
            .map_err(e)?;
    }
    let sp = spans(events, gs);
    let bounds = boundaries(gs);
    for (k, p) in b.panels[1..].iter().enumerate() {
        for (s, t, kind, label) in &sp {
            let (s, t, kind) = (*s, *t, *kind);
            let c = match kind {
                "hold" => RGBColor(255, 165, 0).mix(0.25),
                "delay" => RGBColor(100, 149, 237).mix(0.2),
                "abort" => RGBColor(128, 0, 128).mix(0.25),
                _ => RGBColor(220, 0, 0).mix(0.2),
            };
            let (x0, x1) = (p.map_x(s.max(p.x.0)), p.map_x(t.min(p.x.1)));
            root.draw(&Rectangle::new(
                [(x0, p.py.0), (x1.max(x0 + 1), p.py.1)],
                c.filled(),
            ))
            .map_err(e)?;
            if k == 1 && s >= p.x.0 && s <= p.x.1 && kind != "delay" {
                // Where it stopped and why: the label at the span's start.
                root.draw(&Text::new(label.clone(), (x0 + 2, p.py.1 - 16), font(11.0)))
                    .map_err(e)?;
            }
        }
        for &t in &bounds {
            let x = p.map_x(t);
            root.draw(&PathElement::new(
                vec![(x, p.py.0), (x, p.py.1)],
                BOUNDARY.stroke_width(1),
            ))
            .map_err(e)?;
        }
        let cols = &b.cols[k];
        for (si, series) in cols.series.iter().enumerate() {
            let color = if k == 1 {
                SPEED
            } else {
                AXIS_COLORS[b.axes[si]]
            };
            let mut pts = Vec::new();
            for (c, cell) in series.iter().enumerate() {
                if let Some([f, lo, hi, l]) = cell {
                    let x = p.px.0 + c as i32;
                    for v in [*f, *lo, *hi, *l] {
                        let y = p.map_y(v);
                        if pts.last() != Some(&(x, y)) {
                            pts.push((x, y));
                        }
                    }
                }
            }
            root.draw(&PathElement::new(pts, color.stroke_width(1)))
                .map_err(e)?;
        }
        // Legend.
        if k == 1 {
            let txt = format!(
                "peak {:.3} UU/s at {:.3} ms",
                gs.peak_speed.0, gs.peak_speed.1
            );
            root.draw(&Text::new(txt, (p.px.0 + 8, p.py.0 + 4), font(12.0)))
                .map_err(e)?;
        } else {
            for (si, &i) in b.axes.iter().enumerate() {
                let color = AXIS_COLORS[i];
                root.draw(&Text::new(
                    AXIS_NAMES[i],
                    (p.px.1 - 16 * (b.axes.len() - si) as i32, p.py.0 + 4),
                    font(13.0).color(&color),
                ))
                .map_err(e)?;
            }
        }
    }
    Ok(())
}
