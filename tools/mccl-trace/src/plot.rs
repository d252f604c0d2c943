//! `plot`: per group, the path in a plane (equal axis scales, coloured by command, start
//! and end marked) and position, path speed, per-axis speed and acceleration against
//! time, with command boundaries and hold/delay/error spans from the events.
//!
//! Two passes over the trace: the first ([`crate::scan`]) finds the ranges, the second
//! decimates for display: each time panel keeps per pixel column the first, least,
//! greatest and last value of each series (so no extreme is lost), the path keeps a point
//! whenever its pixel changes. Memory depends on the picture, not on the trace's length
//! (the path: on how many pixels it crosses).
//!
//! Pixels are computed here, rounded to the nearest ([`Panel::map`]), and drawn with
//! plotters in pixel coordinates; text uses the embedded DejaVu Sans, so the output is
//! the same byte for byte on every machine.

use crate::data::{read_events, Event, Reader, AXIS_NAMES};
use crate::scan::{deriver, scan, GroupScan, Scan};
use plotters::coord::Shift;
use plotters::prelude::*;
use std::collections::BTreeMap;
use std::sync::Once;

/// The plane of the path panel.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Plane {
    /// X horizontal, Y vertical.
    Xy,
    /// X horizontal, Z vertical.
    Xz,
    /// Y horizontal, Z vertical.
    Yz,
    /// Isometric view of X, Y, Z.
    Iso,
}

impl Plane {
    /// Parses `xy`, `xz`, `yz`, `3d`.
    pub fn parse(s: &str) -> Option<Plane> {
        match s.to_ascii_lowercase().as_str() {
            "xy" => Some(Plane::Xy),
            "xz" => Some(Plane::Xz),
            "yz" => Some(Plane::Yz),
            "3d" | "iso" => Some(Plane::Iso),
            _ => None,
        }
    }

    /// The point of the panel for axis positions `p`.
    pub fn project(self, p: &[f64; 8]) -> (f64, f64) {
        let c = 0.866_025_403_784_438_6; // cos 30°
        match self {
            Plane::Xy => (p[0], p[1]),
            Plane::Xz => (p[0], p[2]),
            Plane::Yz => (p[1], p[2]),
            Plane::Iso => ((p[0] - p[1]) * c, p[2] + (p[0] + p[1]) * 0.5),
        }
    }

    fn labels(self) -> (&'static str, &'static str) {
        match self {
            Plane::Xy => ("x (UU)", "y (UU)"),
            Plane::Xz => ("x (UU)", "z (UU)"),
            Plane::Yz => ("y (UU)", "z (UU)"),
            Plane::Iso => ("isometric x-y (UU)", "isometric z (UU)"),
        }
    }
}

/// What to plot.
#[derive(Debug, Clone, PartialEq)]
pub struct Options {
    /// Groups to plot (all in the trace when `None`).
    pub groups: Option<Vec<u32>>,
    /// The path panel's plane.
    pub plane: Plane,
    /// Time window, ms.
    pub from: f64,
    /// Time window, ms.
    pub to: f64,
    /// Axes in the time panels (those that move when `None`).
    pub axes: Option<Vec<usize>>,
    /// Picture width, px.
    pub width: u32,
}

impl Default for Options {
    fn default() -> Options {
        Options {
            groups: None,
            plane: Plane::Xy,
            from: f64::NEG_INFINITY,
            to: f64::INFINITY,
            axes: None,
            width: 1400,
        }
    }
}

/// A panel: its pixel rectangle (inclusive) and the data ranges mapped onto it.
#[derive(Debug, Clone, PartialEq)]
pub struct Panel {
    /// `path`, `position`, `speed`, `axis_speed`, `acceleration`.
    pub name: String,
    /// Left and right pixel.
    pub px: (i32, i32),
    /// Top and bottom pixel.
    pub py: (i32, i32),
    /// Data range shown horizontally.
    pub x: (f64, f64),
    /// Data range shown vertically.
    pub y: (f64, f64),
}

impl Panel {
    /// The pixel of data point (x, y): rounded to the nearest.
    pub fn map(&self, x: f64, y: f64) -> (i32, i32) {
        (self.map_x(x), self.map_y(y))
    }

    /// The exact (unrounded) pixel position of data point (x, y).
    pub fn map_f(&self, x: f64, y: f64) -> (f64, f64) {
        let fx = (x - self.x.0) / (self.x.1 - self.x.0);
        let fy = (y - self.y.0) / (self.y.1 - self.y.0);
        (
            f64::from(self.px.0) + fx * f64::from(self.px.1 - self.px.0),
            f64::from(self.py.1) - fy * f64::from(self.py.1 - self.py.0),
        )
    }

    /// The pixel column of x.
    pub fn map_x(&self, x: f64) -> i32 {
        let f = (x - self.x.0) / (self.x.1 - self.x.0);
        self.px.0 + (f * f64::from(self.px.1 - self.px.0)).round() as i32
    }

    /// The pixel row of y.
    pub fn map_y(&self, y: f64) -> i32 {
        let f = (y - self.y.0) / (self.y.1 - self.y.0);
        self.py.1 - (f * f64::from(self.py.1 - self.py.0)).round() as i32
    }
}

/// The panels of one group's picture.
#[derive(Debug, Clone, PartialEq)]
pub struct GroupPlot {
    /// Group index.
    pub group: u32,
    /// `path`, `position`, `speed`, `axis_speed`, `acceleration`.
    pub panels: Vec<Panel>,
    /// The axes shown in the time panels.
    pub axes: Vec<usize>,
}

/// Where everything went, for tests and the report.
#[derive(Debug, Clone, PartialEq)]
pub struct PlotInfo {
    /// Per group plotted.
    pub groups: Vec<GroupPlot>,
    /// Picture size.
    pub size: (u32, u32),
}

/// Colour of command boundary lines.
pub const BOUNDARY: RGBColor = RGBColor(120, 120, 120);
/// Colour of the path speed.
pub const SPEED: RGBColor = RGBColor(0, 0, 0);
const AXIS_COLORS: [RGBColor; 8] = [
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(23, 190, 207),
];
const CMD_COLORS: [RGBColor; 10] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
    RGBColor(255, 127, 14),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(127, 127, 0),
    RGBColor(23, 190, 207),
    RGBColor(60, 60, 60),
];
const BLOCK_H: u32 = 720;
const TITLE_H: i32 = 28;

fn fonts() {
    static ONCE: Once = Once::new();
    ONCE.call_once(|| {
        // The embedded font; a failure leaves plotters without text (never happens with
        // the bytes of a valid TTF, which these are).
        let _ = plotters::style::register_font(
            "sans-serif",
            FontStyle::Normal,
            dejavu::sans::regular(),
        );
    });
}

fn font(size: f64) -> TextStyle<'static> {
    ("sans-serif", size).into_font().color(&BLACK)
}

fn e<T: std::fmt::Debug>(x: T) -> String {
    format!("drawing failed: {x:?}")
}

/// The picture size for `n` groups.
pub fn size(opts: &Options, n: usize) -> (u32, u32) {
    (opts.width.max(600), BLOCK_H * n.max(1) as u32)
}

/// Reads the trace (and its events) once and chooses the groups and axes to plot.
pub fn prepare(path: &str, opts: &Options) -> Result<(Vec<Event>, Scan, Vec<u32>), String> {
    let events = read_events(path)?;
    let s = scan(path, &events, opts.from, opts.to)?;
    let groups: Vec<u32> = match &opts.groups {
        Some(gs) => {
            for g in gs {
                if !s.groups.contains_key(g) {
                    let have: Vec<String> = s.groups.keys().map(|g| g.to_string()).collect();
                    return Err(format!(
                        "{path}: no group {g} in the trace (groups: {})",
                        have.join(", ")
                    ));
                }
            }
            gs.clone()
        }
        None => s.groups.keys().copied().collect(),
    };
    Ok((events, s, groups))
}

/// Renders `path` as SVG; returns the document and where things went.
pub fn svg(path: &str, opts: &Options) -> Result<(String, PlotInfo), String> {
    let (events, s, groups) = prepare(path, opts)?;
    svg_prepared(path, opts, &events, &s, &groups)
}

/// [`svg`] with the first pass already made ([`prepare`]).
pub fn svg_prepared(
    path: &str,
    opts: &Options,
    events: &[Event],
    s: &Scan,
    groups: &[u32],
) -> Result<(String, PlotInfo), String> {
    let sz = size(opts, groups.len());
    let mut out = String::new();
    let info = {
        let root = SVGBackend::with_string(&mut out, sz).into_drawing_area();
        let info = draw(&root, path, opts, events, s, groups)?;
        root.present().map_err(e)?;
        info
    };
    Ok((out, info))
}

/// Renders `path` as PNG into `out`.
pub fn png(path: &str, opts: &Options, out: &str) -> Result<PlotInfo, String> {
    let (events, s, groups) = prepare(path, opts)?;
    let sz = size(opts, groups.len());
    let root = BitMapBackend::new(out, sz).into_drawing_area();
    let info = draw(&root, path, opts, &events, &s, &groups)?;
    root.present().map_err(|x| format!("{out}: {x:?}"))?;
    Ok(info)
}

/// Decimated time series of one panel: per pixel column, per series,
/// (first, min, max, last).
struct Columns {
    n: usize,
    t0: f64,
    t1: f64,
    series: Vec<Vec<Option<[f64; 4]>>>,
}

impl Columns {
    fn new(n: usize, series: usize, t0: f64, t1: f64) -> Columns {
        Columns {
            n,
            t0,
            t1,
            series: vec![vec![None; n]; series],
        }
    }

    fn push(&mut self, t: f64, s: usize, v: f64) {
        let f = if self.t1 > self.t0 {
            (t - self.t0) / (self.t1 - self.t0)
        } else {
            0.0
        };
        let c = ((f * self.n as f64) as usize).min(self.n - 1);
        let cell = &mut self.series[s][c];
        match cell {
            None => *cell = Some([v, v, v, v]),
            Some(a) => {
                a[1] = a[1].min(v);
                a[2] = a[2].max(v);
                a[3] = v;
            }
        }
    }
}

fn pad((lo, hi): (f64, f64)) -> (f64, f64) {
    if hi.partial_cmp(&lo) != Some(std::cmp::Ordering::Greater) {
        let m = if lo.is_finite() { lo } else { 0.0 };
        let d = (m.abs() * 0.05).max(1.0);
        return (m - d, m + d);
    }
    let d = (hi - lo) * 0.05;
    (lo - d, hi + d)
}

struct Block {
    group: u32,
    panels: Vec<Panel>,
    axes: Vec<usize>,
    path: PathSimplifier,
    cols: Vec<Columns>,
}

/// Largest distance, px, of a trace point from the drawn path (plus `MERGE_PX`, below
/// which points merge).
pub const PATH_TOL_PX: f64 = 0.75;
/// Points closer than this to the last one kept for the check are not kept for it.
const MERGE_PX: f64 = 0.2;
/// Most points between two vertices that are kept for the check.
const BUF_MAX: usize = 512;

/// Streaming simplification of the path: a vertex is kept only when the segment from the
/// last vertex would pass further than [`PATH_TOL_PX`] from a point since it. Vertices
/// are rounded to whole pixels and the check is made against the rounded segment, so
/// every trace point lies within `PATH_TOL_PX + MERGE_PX` = 0.95 px of what is drawn.
#[derive(Default)]
struct PathSimplifier {
    kept: Vec<(i32, i32, i32)>,
    anchor: Option<(i32, i32)>,
    buf: Vec<(f64, f64)>,
    last: Option<(f64, f64, i32)>,
    last_kept: bool,
}

fn seg_dist(p: (f64, f64), a: (f64, f64), b: (f64, f64)) -> f64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let l2 = dx * dx + dy * dy;
    let t = if l2 > 0.0 {
        (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / l2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    ((p.0 - a.0 - t * dx).powi(2) + (p.1 - a.1 - t * dy).powi(2)).sqrt()
}

impl PathSimplifier {
    fn keep(&mut self, p: (f64, f64), cmd: i32) {
        let r = (p.0.round() as i32, p.1.round() as i32);
        self.kept.push((r.0, r.1, cmd));
        self.anchor = Some(r);
        self.buf.clear();
        self.buf.push(p);
    }

    fn push(&mut self, p: (f64, f64), cmd: i32) {
        let Some((lx, ly, lc)) = self.last else {
            self.keep(p, cmd);
            self.last = Some((p.0, p.1, cmd));
            self.last_kept = true;
            return;
        };
        if cmd != lc {
            if !self.last_kept {
                self.keep((lx, ly), lc);
            }
            self.keep(p, cmd);
            self.last = Some((p.0, p.1, cmd));
            self.last_kept = true;
            return;
        }
        let a = self
            .anchor
            .map_or((lx, ly), |a| (f64::from(a.0), f64::from(a.1)));
        let b = (p.0.round(), p.1.round());
        let fits =
            self.buf.len() < BUF_MAX && self.buf.iter().all(|&q| seg_dist(q, a, b) <= PATH_TOL_PX);
        if fits {
            self.last_kept = false;
        } else {
            if !self.last_kept {
                self.keep((lx, ly), lc);
            }
            self.last_kept = false;
        }
        let close = self
            .buf
            .last()
            .is_some_and(|q| (q.0 - p.0).hypot(q.1 - p.1) < MERGE_PX);
        if !close {
            self.buf.push(p);
        }
        self.last = Some((p.0, p.1, cmd));
    }

    fn finish(&mut self) {
        if let (Some((x, y, c)), false) = (self.last, self.last_kept) {
            self.keep((x, y), c);
            self.last_kept = true;
        }
    }
}

#[allow(clippy::too_many_arguments)]
fn panel_chart<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    name: &str,
    x: (f64, f64),
    y: (f64, f64),
    xdesc: &str,
    ydesc: &str,
    equal: bool,
) -> Result<Panel, String> {
    let build = |x: (f64, f64), y: (f64, f64)| {
        ChartBuilder::on(area)
            .margin(8)
            .x_label_area_size(34)
            .y_label_area_size(72)
            .build_cartesian_2d(x.0..x.1, y.0..y.1)
            .map_err(e)
    };
    let (mut x, mut y) = (x, y);
    let probe = build(x, y)?;
    let (rx, ry) = probe.plotting_area().get_pixel_range();
    let (w, h) = (
        f64::from(rx.end - 1 - rx.start),
        f64::from(ry.end - 1 - ry.start),
    );
    if equal {
        // Equal scales: the larger of the two UU-per-pixel wins, the other range grows.
        let s = ((x.1 - x.0) / w).max((y.1 - y.0) / h);
        let (cx, cy) = ((x.0 + x.1) / 2.0, (y.0 + y.1) / 2.0);
        x = (cx - s * w / 2.0, cx + s * w / 2.0);
        y = (cy - s * h / 2.0, cy + s * h / 2.0);
    }
    let mut chart = build(x, y)?;
    chart
        .configure_mesh()
        .x_desc(xdesc)
        .y_desc(ydesc)
        .label_style(font(12.0))
        .axis_desc_style(font(13.0))
        .light_line_style(RGBColor(235, 235, 235))
        .bold_line_style(RGBColor(205, 205, 205))
        .x_labels(8)
        .y_labels(6)
        .draw()
        .map_err(e)?;
    Ok(Panel {
        name: name.to_string(),
        px: (rx.start, rx.end - 1),
        py: (ry.start, ry.end - 1),
        x,
        y,
    })
}

fn draw<DB: DrawingBackend>(
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

/// The speed panel's range: room above the peak for its label.
fn speed_range(peak: f64) -> (f64, f64) {
    let top = if peak > 0.0 { peak } else { 1.0 };
    (-0.05 * top, 1.25 * top)
}

fn pad_time(t0: f64, t1: f64) -> (f64, f64) {
    if t1 > t0 {
        (t0, t1)
    } else {
        (t0 - 1.0, t0 + 1.0)
    }
}

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

fn draw_block<DB: DrawingBackend>(
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
