//! Straight lines: the segment, its closed form and its constructors.

use super::aux_axes::aux_travel;
use super::vec3::norm3;
use super::{Path, XYZ};
use crate::planner::{check_all_finite, Axes, PlanError, NUM_AXES};

/// A straight segment from `start` to `end` in all eight axes.
#[derive(Debug, Clone, PartialEq)]
pub struct LineSeg {
    pub(super) start: Axes,
    pub(super) end: Axes,
    pub(super) length: f64,
    /// `end - start` per axis.
    pub(super) delta: Axes,
    /// `direction(s)`, the same all along the line: `(end - start) / length`, or all
    /// zeros for a zero-length line.
    pub(super) dir: Axes,
}

impl LineSeg {
    /// Axis `i` (below [`NUM_AXES`]) at fraction `f` of the line, `f` strictly between 0
    /// and 1: `start + delta·f`, as [`Path::point_at`] computes it.
    #[inline(always)]
    pub fn axis_at(&self, i: usize, f: f64) -> f64 {
        self.start[i] + self.delta[i] * f
    }

    /// Where the line starts.
    pub fn start(&self) -> &Axes {
        &self.start
    }

    /// `end − start`, per axis.
    pub fn delta(&self) -> &Axes {
        &self.delta
    }

    /// [`Path::point_velocity_into`] for this line.
    #[inline(always)]
    pub(super) fn point_velocity_into(&self, s: f64, v: f64, pos: &mut Axes, vel: &mut Axes) {
        for (vi, d) in vel.iter_mut().zip(&self.dir) {
            *vi = v * d;
        }
        let len = self.length;
        if s.is_nan() || s <= 0.0 || len <= 0.0 {
            *pos = self.start;
        } else if s >= len {
            *pos = self.end;
        } else {
            let f = s / len;
            #[allow(clippy::needless_range_loop)] // indexes three arrays
            for i in 0..NUM_AXES {
                pos[i] = self.start[i] + self.delta[i] * f;
            }
        }
    }
}

impl Path {
    /// Straight line from `start` to `end` (all eight axes).
    pub fn line(start: &Axes, end: &Axes) -> Path {
        let d = [end[0] - start[0], end[1] - start[1], end[2] - start[2]];
        let xyz = norm3(d);
        let length = if xyz > 0.0 {
            xyz
        } else {
            aux_travel(start, end)
        };
        Path::line_with_length(start, end, length)
    }

    /// Straight line from `start` to `end` whose path length (what the feed speed is
    /// measured along) is `length` (`super::compose`: the composing axes).
    pub fn line_with_length(start: &Axes, end: &Axes, length: f64) -> Path {
        let delta: Axes = std::array::from_fn(|i| end[i] - start[i]);
        let dir = if length <= 0.0 {
            [0.0; NUM_AXES]
        } else {
            delta.map(|d| d / length)
        };
        Path::Line(LineSeg {
            start: *start,
            end: *end,
            length,
            delta,
            dir,
        })
    }

    /// Whether X, Y and Z stand still along the path (its length is then the longest
    /// auxiliary travel, see [`Path`]).
    #[inline]
    pub fn aux_only(&self) -> bool {
        match self {
            Path::Line(l) => l.delta[..XYZ].iter().all(|d| *d == 0.0),
            _ => false,
        }
    }

    /// The auxiliary axis with the longest travel (the path of an
    /// [`aux-only`](Path::aux_only) line); X for any other path.
    pub fn lead_axis(&self) -> usize {
        match self {
            Path::Line(l) if self.aux_only() => {
                let mut best = XYZ;
                for i in XYZ..NUM_AXES {
                    if l.delta[i].abs() > l.delta[best].abs() {
                        best = i;
                    }
                }
                best
            }
            _ => 0,
        }
    }

    /// [`Path::line`] with input validation: `BadParameter` if any coordinate
    /// is NaN or infinite.
    pub fn try_line(start: &Axes, end: &Axes) -> Result<Path, PlanError> {
        check_all_finite(start, "start position")?;
        check_all_finite(end, "end position")?;
        Ok(Path::line(start, end))
    }
}
