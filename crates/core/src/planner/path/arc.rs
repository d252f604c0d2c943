//! Arcs and circles: the segment (shared with the helix), its constructors from three
//! points, a center and an angle, or a full turn, and the plane arc they build on.

use super::aux_axes::{aux_travel, with_aux};
use super::vec3::{cross3, dot3, norm3, positive_finite, scale3, sub3, unit3, COLLINEAR_EPS};
use super::{Path, Plane, XYZ};
use crate::planner::{check_all_finite, check_finite, Axes, PlanError};
use std::f64::consts::TAU;

/// A circular arc or helix segment in X/Y/Z, with U..B interpolated linearly.
///
/// The X/Y/Z position at angle `θ` is `center + r·(cos θ·u + sin θ·v) + axis·rise·f`
/// where `f = s/length` is the path fraction and `θ = θ0 + sweep·f`. For plane
/// arcs `u`, `v`, `axis` are the plane's unit axes `a`, `b`, `n`; for a 3-D arc
/// `u` points from the center to the start and `v = axis × u`.
#[derive(Debug, Clone, PartialEq)]
pub struct ArcSeg {
    pub(super) start: Axes,
    pub(super) end: Axes,
    pub(super) center: [f64; 3],
    pub(super) u: [f64; 3],
    pub(super) v: [f64; 3],
    pub(super) axis: [f64; 3],
    pub(super) radius: f64,
    pub(super) theta0: f64,
    pub(super) sweep: f64,
    pub(super) rise: f64,
    pub(super) length: f64,
}

impl ArcSeg {
    /// Finish an arc: set length and validate. `end` must already hold the exact end.
    ///
    /// The length the feed applies to is the arc in its plane (`r·|θ|`): a helix's rise
    /// comes on top, as the vendor's library times it.
    pub(super) fn finish(mut self) -> ArcSeg {
        let arc = (self.radius * self.sweep).abs();
        self.length = if arc > 0.0 {
            arc
        } else if self.rise != 0.0 {
            self.rise.abs()
        } else {
            aux_travel(&self.start, &self.end)
        };
        self
    }

    /// X/Y/Z position at angle `theta` and path fraction `f` (not clamped).
    pub(super) fn xyz_at(&self, theta: f64, f: f64) -> [f64; 3] {
        let (c, s) = (theta.cos() * self.radius, theta.sin() * self.radius);
        let h = self.rise * f;
        let mut p = [0.0; 3];
        for (i, pi) in p.iter_mut().enumerate() {
            *pi = self.center[i] + c * self.u[i] + s * self.v[i] + h * self.axis[i];
        }
        p
    }

    /// Signed sweep in radians (> 0 counter-clockwise about the normal).
    pub fn sweep(&self) -> f64 {
        self.sweep
    }

    /// Radius of the arc.
    pub fn radius(&self) -> f64 {
        self.radius
    }

    /// Center in X/Y/Z (for a helix: the center's start position on the axis).
    pub fn center(&self) -> [f64; 3] {
        self.center
    }

    /// Travel along the normal axis (helix; 0 for an arc).
    pub fn rise(&self) -> f64 {
        self.rise
    }
}

impl Path {
    /// Arc in `plane` from `start` through the plane point `via` to `end_plane`
    /// (`MCC_ArcXY` etc.). The normal axis does not move; aux axes go to `aux_end`
    /// (U..B, absolute) when given, else stay.
    ///
    /// The center is the circumcenter of the three points; the direction is the
    /// one that passes `via` (counter-clockwise iff the triangle start, via, end
    /// is counter-clockwise in plane coordinates).
    ///
    /// Errors: `BadArc` for coincident or collinear points, `BadParameter` for NaN/inf.
    pub fn arc_3pt(
        plane: Plane,
        start: &Axes,
        via: [f64; 2],
        end_plane: [f64; 2],
        aux_end: Option<[f64; 5]>,
    ) -> Result<Path, PlanError> {
        check_all_finite(start, "start position")?;
        check_all_finite(&via, "arc reference point")?;
        check_all_finite(&end_plane, "arc end point")?;
        let (ia, ib, _) = plane.axes();
        let p0 = [start[ia], start[ib]];
        let d1 = [via[0] - p0[0], via[1] - p0[1]];
        let d2 = [end_plane[0] - p0[0], end_plane[1] - p0[1]];
        let d12 = [end_plane[0] - via[0], end_plane[1] - via[1]];
        let n1 = d1[0].hypot(d1[1]);
        let n2 = d2[0].hypot(d2[1]);
        if n1 == 0.0 || n2 == 0.0 || d12[0].hypot(d12[1]) == 0.0 {
            return Err(PlanError::BadArc);
        }
        let cross = d1[0] * d2[1] - d1[1] * d2[0];
        if cross.is_nan() || cross.abs() <= COLLINEAR_EPS * n1 * n2 {
            return Err(PlanError::BadArc);
        }
        // Circumcenter relative to p0.
        let (b2, c2) = (n1 * n1, n2 * n2);
        let den = 2.0 * cross;
        let ux = (d2[1] * b2 - d1[1] * c2) / den;
        let uy = (d1[0] * c2 - d2[0] * b2) / den;
        let center = [p0[0] + ux, p0[1] + uy];
        let radius = ux.hypot(uy);
        if !positive_finite(radius) {
            return Err(PlanError::BadArc);
        }
        // Sweep from start to end, in the direction that passes via.
        let r0 = [p0[0] - center[0], p0[1] - center[1]];
        let r2 = [end_plane[0] - center[0], end_plane[1] - center[1]];
        let mut sweep = (r0[0] * r2[1] - r0[1] * r2[0]).atan2(r0[0] * r2[0] + r0[1] * r2[1]);
        if cross > 0.0 {
            if sweep <= 0.0 {
                sweep += TAU;
            }
        } else if sweep >= 0.0 {
            sweep -= TAU;
        }
        let mut end = with_aux(start, aux_end)?;
        end[ia] = end_plane[0];
        end[ib] = end_plane[1];
        Ok(Path::Arc(plane_arc(
            plane, start, end, center, radius, sweep, 0.0,
        )))
    }

    /// 3-D arc from `start` through `via` to `end` in X/Y/Z (`MCC_ArcXYZ`), on the
    /// plane of the three points. Aux axes go to `aux_end` when given.
    ///
    /// Errors: `BadArc` for coincident or collinear points, `BadParameter` for NaN/inf.
    pub fn arc_3pt_xyz(
        start: &Axes,
        via: [f64; 3],
        end: [f64; 3],
        aux_end: Option<[f64; 5]>,
    ) -> Result<Path, PlanError> {
        check_all_finite(start, "start position")?;
        check_all_finite(&via, "arc reference point")?;
        check_all_finite(&end, "arc end point")?;
        let p0 = [start[0], start[1], start[2]];
        let a = sub3(via, p0);
        let b = sub3(end, p0);
        let (na, nb) = (norm3(a), norm3(b));
        if na == 0.0 || nb == 0.0 || norm3(sub3(end, via)) == 0.0 {
            return Err(PlanError::BadArc);
        }
        let n = cross3(a, b);
        let nn = norm3(n);
        if nn.is_nan() || nn <= COLLINEAR_EPS * na * nb {
            return Err(PlanError::BadArc);
        }
        // Circumcenter: p0 + ((|a|² b − |b|² a) × (a × b)) / (2 |a × b|²).
        let w = sub3(scale3(b, na * na), scale3(a, nb * nb));
        let off = scale3(cross3(w, n), 1.0 / (2.0 * nn * nn));
        let center = [p0[0] + off[0], p0[1] + off[1], p0[2] + off[2]];
        let radius = norm3(off);
        if !positive_finite(radius) {
            return Err(PlanError::BadArc);
        }
        let axis = scale3(n, 1.0 / nn);
        let u = scale3(sub3(p0, center), 1.0 / radius);
        let v = cross3(axis, u);
        // The triangle p0, via, end is counter-clockwise about `axis` by
        // construction, so the arc through via sweeps positively.
        let r2 = sub3(end, center);
        let mut sweep = dot3(r2, v).atan2(dot3(r2, u));
        if sweep <= 0.0 {
            sweep += TAU;
        }
        let mut e = with_aux(start, aux_end)?;
        e[..XYZ].copy_from_slice(&end);
        Ok(Path::Arc(
            ArcSeg {
                start: *start,
                end: e,
                center,
                u,
                v,
                axis,
                radius,
                theta0: 0.0,
                sweep,
                rise: 0.0,
                length: 0.0,
            }
            .finish(),
        ))
    }

    /// Arc about `center` (plane coordinates) through the signed angle `theta_deg`
    /// from `start` (`MCC_ArcThetaXY` etc.); `theta_deg > 0` is counter-clockwise.
    /// Aux axes stay. A zero angle is a zero-length arc.
    ///
    /// Errors: `BadArc` for zero radius, `BadParameter` for NaN/inf.
    pub fn arc_theta(
        plane: Plane,
        start: &Axes,
        center: [f64; 2],
        theta_deg: f64,
    ) -> Result<Path, PlanError> {
        check_finite(theta_deg, "arc angle")?;
        let seg = theta_arc(plane, start, center, theta_deg, 0.0, None)?;
        Ok(Path::Arc(seg))
    }

    /// Full circle about `center` from `start`, back to `start`
    /// (`MCC_CircleXY` etc.): counter-clockwise when `ccw`. Aux axes go to
    /// `aux_end` when given.
    ///
    /// Errors: `BadArc` for zero radius, `BadParameter` for NaN/inf.
    pub fn circle(
        plane: Plane,
        start: &Axes,
        center: [f64; 2],
        ccw: bool,
        aux_end: Option<[f64; 5]>,
    ) -> Result<Path, PlanError> {
        let theta = if ccw { 360.0 } else { -360.0 };
        let seg = theta_arc(plane, start, center, theta, 0.0, aux_end)?;
        Ok(Path::Arc(seg))
    }
}

/// A plane arc/helix from the circle `center`/`radius` in plane coordinates.
fn plane_arc(
    plane: Plane,
    start: &Axes,
    end: Axes,
    center: [f64; 2],
    radius: f64,
    sweep: f64,
    rise: f64,
) -> ArcSeg {
    let (ia, ib, n) = plane.axes();
    let mut c3 = [0.0; 3];
    c3[ia] = center[0];
    c3[ib] = center[1];
    c3[n] = start[n];
    let theta0 = (start[ib] - center[1]).atan2(start[ia] - center[0]);
    ArcSeg {
        start: *start,
        end,
        center: c3,
        u: unit3(ia),
        v: unit3(ib),
        axis: unit3(n),
        radius,
        theta0,
        sweep,
        rise,
        length: 0.0,
    }
    .finish()
}

/// Arc/circle/helix about a plane center through `theta_deg` with normal travel `rise`.
/// A radius below this (UU) is a center on the start point: the end point of a previous
/// arc carries rounding of about 1e-15, which must not pass as a circle.
pub const MIN_RADIUS: f64 = 1e-9;

pub(super) fn theta_arc(
    plane: Plane,
    start: &Axes,
    center: [f64; 2],
    theta_deg: f64,
    rise: f64,
    aux_end: Option<[f64; 5]>,
) -> Result<ArcSeg, PlanError> {
    check_all_finite(start, "start position")?;
    check_all_finite(&center, "arc center")?;
    let (ia, ib, n) = plane.axes();
    let radius = (start[ia] - center[0]).hypot(start[ib] - center[1]);
    if !positive_finite(radius) || radius < MIN_RADIUS {
        return Err(PlanError::BadArc);
    }
    let sweep = theta_deg.to_radians();
    let mut end = with_aux(start, aux_end)?;
    // Whole turns return exactly to the start point in the plane.
    if theta_deg % 360.0 != 0.0 {
        let th = (start[ib] - center[1]).atan2(start[ia] - center[0]) + sweep;
        end[ia] = center[0] + radius * th.cos();
        end[ib] = center[1] + radius * th.sin();
    }
    end[n] = start[n] + rise;
    Ok(plane_arc(plane, start, end, center, radius, sweep, rise))
}
