//! The panels of a group's picture: their pixel rectangles and data ranges (what the
//! tests and the report read back), and how each is laid out and given its mesh.

use super::style::{e, font};
use plotters::coord::Shift;
use plotters::prelude::*;

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

pub(super) fn pad((lo, hi): (f64, f64)) -> (f64, f64) {
    if hi.partial_cmp(&lo) != Some(std::cmp::Ordering::Greater) {
        let m = if lo.is_finite() { lo } else { 0.0 };
        let d = (m.abs() * 0.05).max(1.0);
        return (m - d, m + d);
    }
    let d = (hi - lo) * 0.05;
    (lo - d, hi + d)
}

#[allow(clippy::too_many_arguments)]
pub(super) fn panel_chart<DB: DrawingBackend>(
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

/// The speed panel's range: room above the peak for its label.
pub(super) fn speed_range(peak: f64) -> (f64, f64) {
    let top = if peak > 0.0 { peak } else { 1.0 };
    (-0.05 * top, 1.25 * top)
}

pub(super) fn pad_time(t0: f64, t1: f64) -> (f64, f64) {
    if t1 > t0 {
        (t0, t1)
    } else {
        (t0 - 1.0, t0 + 1.0)
    }
}
