//! Geometry of general-motion segments (line, arc, circle, helix), each
//! parameterised by the path length the feed speed applies to.

use super::{Axes, NUM_AXES};

mod arc;
mod aux_axes;
mod cone;
mod helix;
mod line;
mod plane;
#[cfg(test)]
mod tests;
mod v6;
mod vec3;

pub use arc::{ArcSeg, MIN_RADIUS};
pub use cone::ConeSeg;
pub use line::LineSeg;
pub use plane::Plane;

/// Number of X/Y/Z axes (the ones that define general-motion path length).
const XYZ: usize = 3;

/// Geometry of one general-motion segment, parameterised by path length `s`
/// in `[0, length()]`.
///
/// Path length: only X/Y/Z count (`sqrt((r·|sweep|)² + rise²)` for an arc or
/// helix); U..B move linearly with the path fraction `s/length` so they start
/// and end with X/Y/Z. If X/Y/Z do not move, the aux axis with the longest
/// travel is the path (it moves at the feed speed) and the others follow it.
///
/// `end()` is computed exactly from the command (never sampled), and
/// `point(length()) == end()`, `point(0) == start()` exactly.
#[derive(Debug, Clone, PartialEq)]
pub enum Path {
    /// Straight line (`MCC_Line`).
    Line(LineSeg),
    /// Arc or circle (`MCC_Arc*`, `MCC_ArcTheta*`, `MCC_Circle*`).
    Arc(ArcSeg),
    /// Helix (`MCC_Helical*`): an arc whose normal axis moves linearly with angle.
    Helix(ArcSeg),
    /// Conical helix (`MCC_Cone*`): a helix whose radius changes linearly with angle.
    Cone(ConeSeg),
}

impl Path {
    #[inline]
    fn common(&self) -> (&Axes, &Axes, f64) {
        match self {
            Path::Line(l) => (&l.start, &l.end, l.length),
            Path::Arc(a) | Path::Helix(a) => (&a.start, &a.end, a.length),
            Path::Cone(c) => (c.start(), c.end(), c.length()),
        }
    }

    /// The length the feed speed applies to (see the type's rules).
    pub fn length(&self) -> f64 {
        self.common().2
    }

    /// Start position (all axes).
    #[inline]
    pub fn start(&self) -> Axes {
        *self.common().0
    }

    /// The chord of a stretch `ds` long over `ds` (1 but on an arc).
    pub fn chord_ratio(&self, ds: f64) -> f64 {
        match self {
            Path::Arc(a) if a.radius > 0.0 && ds > 0.0 => {
                2.0 * a.radius * (ds / (2.0 * a.radius)).sin() / ds
            }
            _ => 1.0,
        }
    }

    /// Start position (all axes), borrowed.
    #[inline]
    pub fn start_ref(&self) -> &Axes {
        self.common().0
    }

    /// End position (all axes), exact as commanded (not sampled).
    pub fn end(&self) -> Axes {
        *self.common().1
    }

    /// The same path moved by `d` (a command queued behind a custom motion, which ended
    /// elsewhere than the queue assumed). Lengths and directions do not change.
    pub fn translate(&mut self, d: &Axes) {
        let add = |p: &mut Axes| {
            for (x, d) in p.iter_mut().zip(d) {
                *x += d;
            }
        };
        match self {
            Path::Line(l) => {
                add(&mut l.start);
                add(&mut l.end);
            }
            Path::Arc(a) | Path::Helix(a) => {
                add(&mut a.start);
                add(&mut a.end);
                for (c, d) in a.center.iter_mut().zip(d) {
                    *c += d;
                }
            }
            Path::Cone(c) => c.translate(d),
        }
    }

    /// Per axis, an interval `(low, high)` holding the coordinate over the whole path:
    /// from start to end for a line and for U..B; for X/Y/Z of an arc or helix the
    /// center's travel (0, or rise along the normal) widened by radius · √(u_i² + v_i²),
    /// the circle's reach along the axis (exact for a full circle). Used to refuse paths
    /// that leave the counters' range.
    pub fn extent(&self) -> [(f64, f64); NUM_AXES] {
        if let Path::Cone(c) = self {
            return c.extent();
        }
        let (start, end, _) = self.common();
        let mut e: [(f64, f64); NUM_AXES] =
            std::array::from_fn(|i| (start[i].min(end[i]), start[i].max(end[i])));
        if let Path::Arc(a) | Path::Helix(a) = self {
            for (i, ei) in e.iter_mut().enumerate().take(XYZ) {
                let reach = a.radius * (a.u[i] * a.u[i] + a.v[i] * a.v[i]).sqrt();
                let (c0, c1) = (a.center[i], a.center[i] + a.rise * a.axis[i]);
                ei.0 = ei.0.min(c0.min(c1) - reach);
                ei.1 = ei.1.max(c0.max(c1) + reach);
            }
        }
        e
    }

    /// For arcs and helices: `Some(true)` if counter-clockwise about the plane
    /// normal (for a 3-D arc: always true about its own normal). `None` for lines.
    pub fn is_ccw(&self) -> Option<bool> {
        match self {
            Path::Line(_) => None,
            Path::Arc(a) | Path::Helix(a) => Some(a.sweep >= 0.0),
            Path::Cone(c) => Some(c.sweep() >= 0.0),
        }
    }

    /// Position at path length `s` (clamped to `[0, length()]`).
    /// `point(0) == start()` and `point(length()) == end()` exactly.
    pub fn point(&self, s: f64) -> Axes {
        let (start, end, len) = self.common();
        if s.is_nan() || s <= 0.0 || len <= 0.0 {
            return *start;
        }
        if s >= len {
            return *end;
        }
        let f = s / len;
        let mut p = [0.0; NUM_AXES];
        match self {
            Path::Cone(c) => return c.point(s),
            Path::Line(l) => {
                for i in 0..NUM_AXES {
                    p[i] = start[i] + l.delta[i] * f;
                }
            }
            Path::Arc(a) | Path::Helix(a) => {
                for i in 0..NUM_AXES {
                    p[i] = start[i] + (end[i] - start[i]) * f;
                }
                let xyz = a.xyz_at(a.theta0 + a.sweep * f, f);
                p[..XYZ].copy_from_slice(&xyz);
            }
        }
        p
    }

    /// The line this path is, when it is one of some length: [`Path::point_at`] of a
    /// fraction strictly between 0 and 1 is then [`LineSeg::axis_at`] of every axis.
    pub fn as_line(&self) -> Option<&LineSeg> {
        match self {
            Path::Line(l) if l.length > 0.0 => Some(l),
            _ => None,
        }
    }

    /// The point at fraction `f` of the path (0 the start, 1 the end): [`Path::point`]
    /// of `f·length()`, computed from the fraction itself (a line: `start + delta·f`), as
    /// the vendor's library computes it.
    pub fn point_at(&self, f: f64) -> Axes {
        let (start, end, len) = self.common();
        if f.is_nan() || f <= 0.0 || len <= 0.0 {
            return *start;
        }
        if f >= 1.0 {
            return *end;
        }
        let mut p = [0.0; NUM_AXES];
        match self {
            Path::Cone(c) => return c.point(f * len),
            Path::Line(l) => {
                for (i, pi) in p.iter_mut().enumerate() {
                    *pi = l.axis_at(i, f);
                }
            }
            Path::Arc(a) | Path::Helix(a) => {
                for i in 0..NUM_AXES {
                    p[i] = start[i] + (end[i] - start[i]) * f;
                }
                let xyz = a.xyz_at(a.theta0 + a.sweep * f, f);
                p[..XYZ].copy_from_slice(&xyz);
            }
        }
        p
    }

    /// `pos = point(s)`, `vel = v x direction(s)`: position at path length `s` and the
    /// per-axis velocity at path speed `v`, written in place (the engine samples every
    /// running motion on every tick).
    #[inline(always)]
    pub fn point_velocity_into(&self, s: f64, v: f64, pos: &mut Axes, vel: &mut Axes) {
        if let Path::Line(l) = self {
            return l.point_velocity_into(s, v, pos, vel);
        }
        *vel = self.direction(s).map(|d| v * d);
        *pos = self.point(s);
    }

    /// Derivative of position with respect to path length at `s` (clamped):
    /// a unit vector in X/Y/Z (or in the leading aux axis for aux-only moves);
    /// aux axes get `Δaux/length`. Per-axis speed is `v·direction(s)`.
    /// All zeros for a zero-length path.
    pub fn direction(&self, s: f64) -> Axes {
        match self {
            Path::Line(l) => return l.dir,
            Path::Cone(c) => return c.direction(s),
            _ => {}
        }
        let (start, end, len) = self.common();
        let mut d = [0.0; NUM_AXES];
        if len <= 0.0 {
            return d;
        }
        for i in 0..NUM_AXES {
            d[i] = (end[i] - start[i]) / len;
        }
        if let Path::Arc(a) | Path::Helix(a) = self {
            let f = (s / len).clamp(0.0, 1.0);
            let th = a.theta0 + a.sweep * f;
            let k = a.radius * a.sweep / len; // dθ/ds · r
            let (c, sn) = (th.cos(), th.sin());
            for (i, di) in d.iter_mut().take(XYZ).enumerate() {
                *di = k * (-sn * a.u[i] + c * a.v[i]) + a.axis[i] * a.rise / len;
            }
        }
        d
    }
}
