//! General motion: line, arc, circle and helix commands and their settings (user manual
//! §2.6.2; vendor header "General Motions"), plus the obsolete forms whose meaning is clear.
//!
//! One kind of motion a file, every entry point re-exported here, so that the chapter is
//! one module to its users (`MCCLPCI_IMP::ffi::motion::MCC_Line`): `settings` (the
//! group's acc/dec shapes and times, feed and point-to-point speeds, the current speeds),
//! `line_and_ptp` (lines and point-to-point moves, of the axes in a mask or of one),
//! `arc` (arcs and circles), `helix` (helices and spirals), and `plane_curve`, what
//! the curves of a plane share.

mod arc;
mod helix;
mod line_and_ptp;
mod plane_curve;
mod settings;

pub use arc::*;
pub use helix::*;
pub use line_and_ptp::*;
pub use settings::*;

pub(super) use helix::{queue_spiral, SpiralTo};
pub(super) use settings::feed_speed;
