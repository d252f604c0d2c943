//! The two arc shapes only the V6 (robot) commands have: an arc about an axis given by a
//! point and a direction in space (`MCC_ArcTheta_V6`), and a full circle through the
//! start and two more points (`MCC_Circle_V6`). U..B (the tool's orientation on a
//! kinematic group, and the two aux axes) move linearly with the path fraction, as on
//! every other arc.

use super::aux_axes::with_aux;
use super::vec3::{cross3, dot3, norm3, positive_finite, scale3, sub3};
use super::{ArcSeg, Path, MIN_RADIUS, XYZ};
use crate::planner::{check_all_finite, check_finite, Axes, PlanError};
use std::f64::consts::TAU;

impl Path {
    /// Arc of `theta_deg` degrees about the axis through `center` with direction `normal`
    /// (right-handed: > 0 is counter-clockwise seen from the tip of `normal`). The start
    /// turns about that axis, so the arc's plane is the one through the start
    /// perpendicular to `normal` and its radius is the start's distance from the axis.
    ///
    /// Errors: `BadArc` for a zero `normal` or a start on the axis, `BadParameter` for
    /// NaN/inf.
    pub fn arc_about_axis(
        start: &Axes,
        center: [f64; 3],
        normal: [f64; 3],
        theta_deg: f64,
        aux_end: Option<[f64; 5]>,
    ) -> Result<Path, PlanError> {
        check_all_finite(start, "start position")?;
        check_all_finite(&center, "arc center")?;
        check_all_finite(&normal, "arc normal")?;
        check_finite(theta_deg, "arc angle")?;
        let nn = norm3(normal);
        if !positive_finite(nn) {
            return Err(PlanError::BadArc);
        }
        let axis = scale3(normal, 1.0 / nn);
        let p0 = [start[0], start[1], start[2]];
        let h = dot3(sub3(p0, center), axis);
        let foot = [
            center[0] + h * axis[0],
            center[1] + h * axis[1],
            center[2] + h * axis[2],
        ];
        let radial = sub3(p0, foot);
        let radius = norm3(radial);
        if !positive_finite(radius) || radius < MIN_RADIUS {
            return Err(PlanError::BadArc);
        }
        let u = scale3(radial, 1.0 / radius);
        let v = cross3(axis, u);
        let sweep = theta_deg.to_radians();
        let mut end = with_aux(start, aux_end)?;
        // Whole turns return exactly to the start point.
        if theta_deg % 360.0 != 0.0 {
            let (c, s) = (sweep.cos() * radius, sweep.sin() * radius);
            for i in 0..XYZ {
                end[i] = foot[i] + c * u[i] + s * v[i];
            }
        }
        Ok(Path::Arc(
            ArcSeg {
                start: *start,
                end,
                center: foot,
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

    /// Full circle from the start through `p1` and `p2` back to the start (in that
    /// order around the circle through the three points).
    ///
    /// Errors: `BadArc` for coincident or collinear points, `BadParameter` for NaN/inf.
    pub fn circle_3pt_xyz(
        start: &Axes,
        p1: [f64; 3],
        p2: [f64; 3],
        aux_end: Option<[f64; 5]>,
    ) -> Result<Path, PlanError> {
        match Path::arc_3pt_xyz(start, p1, p2, aux_end)? {
            Path::Arc(mut seg) => {
                // The arc start → p1 → p2 turns positively about `axis` by
                // construction; the whole circle is one positive turn.
                seg.sweep = TAU;
                seg.end[..XYZ].copy_from_slice(&start[..XYZ]);
                Ok(Path::Arc(seg.finish()))
            }
            _ => Err(PlanError::BadArc),
        }
    }

    /// The same path moved by `o` in every axis (an arc's center moves with it).
    pub fn translated(&self, o: &Axes) -> Path {
        let mut p = self.clone();
        p.translate(o);
        p
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arc_about_z_through_the_origin_is_the_plane_arc() {
        // Start (1, 0, 5), axis Z through (0, 0, 0), 90°: the start turns about Z at
        // height 5 to (0, 1, 5); radius 1, length π/2.
        let start = [1.0, 0.0, 5.0, 0.0, 0.0, 0.0, 0.0, 0.0];
        let p = Path::arc_about_axis(&start, [0.0; 3], [0.0, 0.0, 2.0], 90.0, None).unwrap();
        let e = p.end();
        assert!(e[0].abs() < 1e-15 && (e[1] - 1.0).abs() < 1e-15 && e[2] == 5.0);
        assert!((p.length() - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
        let mid = p.point(p.length() / 2.0);
        let r = std::f64::consts::FRAC_1_SQRT_2;
        assert!((mid[0] - r).abs() < 1e-15 && (mid[1] - r).abs() < 1e-15);
    }

    #[test]
    fn degenerate_axis_arcs_are_bad_arcs() {
        let start = [0.0, 0.0, 3.0, 0.0, 0.0, 0.0, 0.0, 0.0];
        // On the axis.
        let on = Path::arc_about_axis(&start, [0.0; 3], [0.0, 0.0, 1.0], 90.0, None);
        assert_eq!(on, Err(PlanError::BadArc));
        // Zero normal.
        let zero = Path::arc_about_axis(&start, [1.0, 0.0, 0.0], [0.0; 3], 90.0, None);
        assert_eq!(zero, Err(PlanError::BadArc));
    }

    #[test]
    fn circle_through_three_points_is_one_turn_back_to_the_start() {
        // Start (1, 0, 0), through (0, 1, 0) and (-1, 0, 0): the unit circle about Z,
        // counter-clockwise, length 2π; a quarter of the way it is at (0, 1, 0).
        let start = [1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0];
        let aux = Some([10.0, 0.0, 0.0, 0.0, 0.0]);
        let p = Path::circle_3pt_xyz(&start, [0.0, 1.0, 0.0], [-1.0, 0.0, 0.0], aux).unwrap();
        assert!((p.length() - TAU).abs() < 1e-14);
        let e = p.end();
        assert_eq!(&e[..3], &start[..3]);
        assert_eq!(e[3], 10.0);
        let q = p.point(p.length() / 4.0);
        assert!(q[0].abs() < 1e-15 && (q[1] - 1.0).abs() < 1e-15);
        assert!((q[3] - 2.5).abs() < 1e-14);
        let bad = Path::circle_3pt_xyz(&start, [2.0, 0.0, 0.0], [3.0, 0.0, 0.0], None);
        assert_eq!(bad, Err(PlanError::BadArc));
    }
}
