//! Drawing a picture: the panels of each group laid out from the first pass, the second
//! pass over the trace decimating into them, then each group's block drawn.

use super::block::{draw_block, Block};
use super::columns::Columns;
use super::panel::{pad, pad_time, panel_chart, speed_range, GroupPlot, PlotInfo};
use super::path::PathSimplifier;
use super::style::{e, font, fonts, TITLE_H};
use super::Options;
use crate::data::{Event, Reader};
use crate::scan::{deriver, GroupScan, Scan};
use plotters::coord::Shift;
use plotters::prelude::*;
use std::collections::BTreeMap;

pub(super) fn draw<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    path: &str,
    opts: &Options,
    events: &[Event],
    s: &Scan,
    groups: &[u32],
) -> Result<PlotInfo, String> {
    fonts();
    root.fill(&WHITE).map_err(e)?;
    let (w, _) = root.dim_in_pixel();
    let mut blocks: Vec<Block> = Vec::new();
    let areas = root.split_evenly((groups.len(), 1));
    for (area, &g) in areas.iter().zip(groups) {
        let gs = &s.groups[&g];
        let axes: Vec<usize> = match &opts.axes {
            Some(a) => a.clone(),
            None => {
                let moving: Vec<usize> = (0..8).filter(|&i| gs.max[i] > gs.min[i]).collect();
                if moving.is_empty() {
                    vec![0, 1, 2]
                } else {
                    moving
                }
            }
        };
        let title = format!(
            "group {g}: {} rows, {:.3} to {:.3} ms, {} commands, peak path speed {:.3} UU/s at {:.3} ms",
            gs.rows,
            gs.t0,
            gs.t1,
            gs.cmds.len(),
            gs.peak_speed.0,
            gs.peak_speed.1
        );
        area.draw(&Text::new(title, (10, 6), font(15.0)))
            .map_err(e)?;
        let (_, bh) = area.dim_in_pixel();
        let body = area.margin(TITLE_H as u32, 0, 0, 0);
        let left_w = (bh as i32 - TITLE_H).min(w as i32 * 45 / 100);
        let (left, right) = body.split_horizontally(left_w);
        // Path panel, equal scales.
        let (mut ux, mut uy) = (
            (f64::INFINITY, f64::NEG_INFINITY),
            (f64::INFINITY, f64::NEG_INFINITY),
        );
        for corner in 0..8u32 {
            let mut p = [0.0; 8];
            for i in 0..3 {
                p[i] = if corner & (1 << i) != 0 {
                    gs.max[i]
                } else {
                    gs.min[i]
                };
            }
            let (a, b) = opts.plane.project(&p);
            ux = (ux.0.min(a), ux.1.max(a));
            uy = (uy.0.min(b), uy.1.max(b));
        }
        let (lx, ly) = opts.plane.labels();
        let mut panels = vec![panel_chart(&left, "path", pad(ux), pad(uy), lx, ly, true)?];
        let rows = right.split_evenly((4, 1));
        let t = pad_time(gs.t0, gs.t1);
        let fold = |f: &dyn Fn(usize) -> (f64, f64)| {
            axes.iter().fold((0.0f64, 0.0f64), |r, &i| {
                let (a, b) = f(i);
                (r.0.min(a), r.1.max(b))
            })
        };
        let pos = axes
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |r, &i| {
                (r.0.min(gs.min[i]), r.1.max(gs.max[i]))
            });
        panels.push(panel_chart(
            &rows[0],
            "position",
            t,
            pad(pos),
            "time (ms)",
            "position (UU)",
            false,
        )?);
        panels.push(panel_chart(
            &rows[1],
            "speed",
            t,
            speed_range(gs.peak_speed.0),
            "time (ms)",
            "path speed (UU/s)",
            false,
        )?);
        let vr = fold(&|i| gs.vel_range[i]);
        panels.push(panel_chart(
            &rows[2],
            "axis_speed",
            t,
            pad(vr),
            "time (ms)",
            "axis speed (UU/s)",
            false,
        )?);
        let ar = fold(&|i| gs.acc_range[i]);
        panels.push(panel_chart(
            &rows[3],
            "acceleration",
            t,
            pad(ar),
            "time (ms)",
            "acc (UU/s²)",
            false,
        )?);
        let cols = panels[1..]
            .iter()
            .enumerate()
            .map(|(k, p)| {
                let n = (p.px.1 - p.px.0 + 1).max(1) as usize;
                let series = if k == 1 { 1 } else { axes.len() };
                Columns::new(n, series, p.x.0, p.x.1)
            })
            .collect();
        blocks.push(Block {
            group: g,
            panels,
            axes,
            path: PathSimplifier::default(),
            cols,
        });
    }
    // Second pass: decimate.
    let index: BTreeMap<u32, usize> = blocks
        .iter()
        .enumerate()
        .map(|(n, b)| (b.group, n))
        .collect();
    let mut derive: BTreeMap<u32, GroupScan> = BTreeMap::new();
    let mut r = Reader::open(path)?;
    while let Some(row) = r.next_row()? {
        if row.t_ms < opts.from || row.t_ms > opts.to {
            continue;
        }
        let Some(&n) = index.get(&row.group) else {
            continue;
        };
        let d = derive
            .entry(row.group)
            .or_insert_with(|| deriver(row.group))
            .absorb(&row);
        let b = &mut blocks[n];
        let (u, v) = opts.plane.project(&row.pos);
        let p = b.panels[0].map_f(u, v);
        b.path.push(p, row.cmd);
        let t = row.t_ms;
        for (k, &i) in b.axes.iter().enumerate() {
            b.cols[0].push(t, k, row.pos[i]);
            // A group's first row has no speed, its first two no acceleration.
            if d.has_prev {
                b.cols[2].push(t, k, d.vel[i]);
            }
            if d.has_acc {
                b.cols[3].push(t, k, d.acc[i]);
            }
        }
        b.cols[1].push(t, 0, row.speed);
    }
    for b in &mut blocks {
        b.path.finish();
    }
    for b in &blocks {
        draw_block(root, b, events, &s.groups[&b.group])?;
    }
    Ok(PlotInfo {
        groups: blocks
            .into_iter()
            .map(|b| GroupPlot {
                group: b.group,
                panels: b.panels,
                axes: b.axes,
            })
            .collect(),
        size: root.dim_in_pixel(),
    })
}
