//! Colours, sizes and the embedded font of the pictures.

use plotters::prelude::*;
use std::sync::Once;

/// Colour of command boundary lines.
pub const BOUNDARY: RGBColor = RGBColor(120, 120, 120);
/// Colour of the path speed.
pub const SPEED: RGBColor = RGBColor(0, 0, 0);
pub(super) const AXIS_COLORS: [RGBColor; 8] = [
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(23, 190, 207),
];
pub(super) const CMD_COLORS: [RGBColor; 10] = [
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
pub(super) const BLOCK_H: u32 = 720;
pub(super) const TITLE_H: i32 = 28;

pub(super) fn fonts() {
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

pub(super) fn font(size: f64) -> TextStyle<'static> {
    ("sans-serif", size).into_font().color(&BLACK)
}

pub(super) fn e<T: std::fmt::Debug>(x: T) -> String {
    format!("drawing failed: {x:?}")
}
