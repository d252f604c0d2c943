//! Helices: the helix about a plane center through an angle or to a normal-axis
//! position, and the conical helix.

use super::arc::theta_arc;
use super::{Path, Plane};
use crate::planner::{check_all_finite, check_finite, Axes, ConeSeg, PlanError};

impl Path {
    /// Helix about `center` (plane coordinates) through the signed angle
    /// `theta_deg` (`MCC_HelicalXY_Z(cx, cy, pitch, theta)` etc.): the plane part
    /// is the arc of [`Path::arc_theta`], the normal axis moves `pitch·|theta|/360`
    /// in total (the pitch's sign gives the direction, whichever way it turns, as the
    /// vendor's library moves it), linearly in the angle. Path length is the plane
    /// arc's, `r·|θ|` with `θ` in radians.
    ///
    /// Errors: `BadArc` for zero radius, `BadParameter` for NaN/inf.
    pub fn helix(
        plane: Plane,
        start: &Axes,
        center: [f64; 2],
        pitch: f64,
        theta_deg: f64,
        aux_end: Option<[f64; 5]>,
    ) -> Result<Path, PlanError> {
        check_finite(pitch, "helix pitch")?;
        check_finite(theta_deg, "helix angle")?;
        let rise = pitch * theta_deg.abs() / 360.0;
        check_finite(rise, "helix pitch")?;
        let seg = theta_arc(plane, start, center, theta_deg, rise, aux_end)?;
        Ok(Path::Helix(seg))
    }

    /// Conical helix (`MCC_ConeXY_Z(cx, cy, pos, pitch, rate, dir)` etc.): from `start`
    /// about `center` until the normal axis reaches `end_n`, `|end_n − start_n| / |pitch|`
    /// turns, counter-clockwise when `ccw`, the radius changing by `center_rate` per
    /// turn; see [`ConeSeg`].
    ///
    /// Errors: `BadArc` for a start on the center, `BadParameter` for a zero pitch, a
    /// radius that would fall below 0, NaN/inf.
    pub fn cone(
        plane: Plane,
        start: &Axes,
        center: [f64; 2],
        end_n: f64,
        pitch: f64,
        center_rate: f64,
        ccw: bool,
    ) -> Result<Path, PlanError> {
        ConeSeg::new(plane, start, center, end_n, pitch, center_rate, ccw).map(Path::Cone)
    }

    /// Helix ending at normal-axis position `end_n` (the obsolete
    /// `MCC_HelicaXY_Z(cx, cy, pos, pitch, dir)`): it turns `|end_n − start_n| / |pitch|`
    /// turns, counter-clockwise when `ccw`, and ends exactly at `end_n`.
    ///
    /// Errors: `BadArc` for zero radius, `BadParameter` for a zero pitch or NaN/inf.
    pub fn helix_to(
        plane: Plane,
        start: &Axes,
        center: [f64; 2],
        end_n: f64,
        pitch: f64,
        ccw: bool,
        aux_end: Option<[f64; 5]>,
    ) -> Result<Path, PlanError> {
        check_finite(end_n, "helix end position")?;
        check_finite(pitch, "helix pitch")?;
        if pitch == 0.0 {
            return Err(PlanError::BadParameter("helix pitch"));
        }
        check_all_finite(start, "start position")?;
        let (_, _, n) = plane.axes();
        let rise = end_n - start[n];
        let turns = (rise / pitch).abs();
        let theta = 360.0 * if ccw { turns } else { -turns };
        check_finite(theta, "helix turns")?;
        let mut seg = theta_arc(plane, start, center, theta, rise, aux_end)?;
        seg.end[n] = end_n;
        Ok(Path::Helix(seg))
    }
}
