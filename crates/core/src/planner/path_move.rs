//! General motion: a path and the speed profile along its length.

use super::{Path, Shape, TickProfile};

/// One general motion (line, arc, circle, helix): its [`Path`] and the [`TickProfile`]
/// it was planned with from rest, with what a replan needs (the feed, the ramp periods
/// and shapes).
#[derive(Debug, Clone, PartialEq)]
pub struct PathMove {
    /// The geometry.
    pub path: Path,
    /// The profile along `path.length()` from rest.
    pub profile: TickProfile,
    /// The feed speed it was planned with (UU/s).
    pub feed: f64,
    /// Acceleration and deceleration periods.
    pub ramps: (u32, u32),
    /// Acceleration and deceleration shapes.
    pub shapes: (Shape, Shape),
}

impl PathMove {
    /// Plans `path` at `feed` with `ramps` periods of `t` seconds (see
    /// [`TickProfile::plan`]).
    pub fn new(path: Path, feed: f64, ramps: (u32, u32), shapes: (Shape, Shape), t: f64) -> Self {
        let profile = TickProfile::plan(path.length(), 0.0, feed, ramps.0, ramps.1, shapes, t);
        PathMove {
            path,
            profile,
            feed,
            ramps,
            shapes,
        }
    }

    /// Periods the move lasts from rest.
    pub fn periods(&self) -> u64 {
        self.profile.periods()
    }
}
