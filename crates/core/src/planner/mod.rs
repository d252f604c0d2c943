//! Pure trajectory planner: velocity profiles, path geometry, point-to-point
//! moves, time-scale ramps and motion blending.
//!
//! Everything here is a pure function of its inputs: no threads, no clocks, no
//! globals, no FFI. Units are user units (UU) for positions, seconds for times
//! and UU/s for speeds (the FFI layer converts the vendor's milliseconds).
//!
//! Conventions (see `docs/decisions.md`, "Motion conventions the manuals leave open"):
//! * Acc/dec by time: the set time `Ta` is the time from 0 to the feed `F`.
//!   [`Shape::T`] has constant acceleration `F/Ta`; [`Shape::S`] is jerk-limited
//!   with no constant-acceleration phase (peak `2F/Ta` at `Ta/2`). Both cover
//!   `F·Ta/2` while accelerating, so a move of length `L` that reaches `F` lasts
//!   `L/F + (Ta+Td)/2`. See [`Profile`] for moves too short to reach `F`.
//! * General motion: only X/Y/Z count for the path length; U..B follow the path
//!   fraction. With no X/Y/Z travel the aux axis with the longest travel is the
//!   path. See [`Path`].
//! * Blending: the next general motion starts in the previous one's first
//!   decelerating period and the displacements add (the engine's execution runs it).

#![warn(missing_docs)]

mod axis1d;
pub mod compose;
mod path;
mod path_move;
mod profile;
mod ptp;
mod ramp;
mod ticks;

pub use axis1d::Axis1D;
pub use path::ConeSeg;
pub use path::{ArcSeg, LineSeg, Path, Plane};
pub use path_move::PathMove;
pub use profile::Profile;
pub use ptp::{ptp_axis_speed, PtpMove};
pub use ramp::RateRamp;
pub use ticks::{periods_f64, ramp_periods, smoothstep, whole_ms, SteadyFraction, TickProfile};

/// Positions (or velocities) of the eight axes X, Y, Z, U, V, W, A, B (index 0..8).
pub type Axes = [f64; 8];

/// Number of axes in a group.
pub const NUM_AXES: usize = 8;

/// Acceleration / deceleration curve shape.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Shape {
    /// Trapezoidal velocity: constant acceleration `F/Ta`.
    T,
    /// S-curve velocity: acceleration rises linearly to `2F/Ta` over `Ta/2` and
    /// falls linearly back to 0 over the next `Ta/2` (no constant-acceleration phase).
    S,
}

impl Shape {
    /// Map the vendor's curve byte (`b'T'` / `b'S'`) to a shape; anything else is `None`.
    pub fn from_char(c: u8) -> Option<Shape> {
        match c {
            b'T' => Some(Shape::T),
            b'S' => Some(Shape::S),
            _ => None,
        }
    }
}

/// Why a plan was rejected.
#[derive(Debug, Clone, PartialEq)]
pub enum PlanError {
    /// Arc/circle/helix geometry is degenerate: collinear or coincident points,
    /// or zero radius. The FFI maps it to `PARAMETER_ERR` (error record 0xF104).
    BadArc,
    /// A numeric argument is out of range (negative time, non-positive speed,
    /// NaN/inf ...). The string names the offending argument.
    BadParameter(&'static str),
}

impl std::fmt::Display for PlanError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            PlanError::BadArc => write!(f, "degenerate arc/circle/helix geometry"),
            PlanError::BadParameter(what) => write!(f, "bad parameter: {what}"),
        }
    }
}

impl std::error::Error for PlanError {}

/// Return `Err(BadParameter(what))` unless `x` is finite.
pub(crate) fn check_finite(x: f64, what: &'static str) -> Result<(), PlanError> {
    if x.is_finite() {
        Ok(())
    } else {
        Err(PlanError::BadParameter(what))
    }
}

/// Return `Err(BadParameter(what))` unless every element of `xs` is finite.
pub(crate) fn check_all_finite(xs: &[f64], what: &'static str) -> Result<(), PlanError> {
    xs.iter().try_for_each(|&x| check_finite(x, what))
}
