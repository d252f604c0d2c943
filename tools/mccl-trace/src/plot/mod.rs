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

mod block;
mod columns;
mod draw;
mod panel;
mod path;
mod plane;
mod spans;
mod style;

pub use panel::{GroupPlot, Panel, PlotInfo};
pub use path::PATH_TOL_PX;
pub use plane::Plane;
pub use spans::{boundaries, spans};
pub use style::{BOUNDARY, SPEED};

use crate::data::{read_events, Event};
use crate::scan::{scan, Scan};
use draw::draw;
use plotters::prelude::*;
use style::{e, BLOCK_H};

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
