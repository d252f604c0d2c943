//! Motion blending: overlapping two general motions.

use super::{Axes, Path, PlanError, Profile, Shape, NUM_AXES};

/// One general motion: a [`Path`] traversed with a [`Profile`] over its length.
#[derive(Debug, Clone, PartialEq)]
pub struct PathMove {
    /// The geometry.
    pub path: Path,
    /// Motion along `path.length()`.
    pub profile: Profile,
}

impl PathMove {
    /// Plan `path` at `feed` (UU/s) with the given acc/dec times (s) and shapes.
    ///
    /// Errors: as [`Profile::new`].
    pub fn new(
        path: Path,
        feed: f64,
        acc_time: f64,
        dec_time: f64,
        acc: Shape,
        dec: Shape,
    ) -> Result<PathMove, PlanError> {
        let profile = Profile::new(path.length(), feed, acc_time, dec_time, acc, dec)?;
        Ok(PathMove { path, profile })
    }

    /// Total time of the move.
    pub fn duration(&self) -> f64 {
        self.profile.duration()
    }

    /// Time at which deceleration begins (a blended next move starts here).
    pub fn decel_start(&self) -> f64 {
        self.profile.decel_start()
    }

    /// Positions and per-axis velocities at time `t` (clamped to `[0, duration]`);
    /// exactly `path.end()` with zero velocity at `t >= duration`.
    pub fn sample(&self, t: f64) -> (Axes, Axes) {
        let mut pos = [0.0; NUM_AXES];
        let mut vel = [0.0; NUM_AXES];
        self.sample_into(t, &mut pos, &mut vel);
        (pos, vel)
    }

    /// [`PathMove::sample`] written in place.
    #[inline(always)]
    pub fn sample_into(&self, t: f64, pos: &mut Axes, vel: &mut Axes) {
        let (s, v, _) = self.profile.sample(t);
        self.path.point_velocity_into(s, v, pos, vel);
    }
}

/// Position while two general motions overlap (blending on).
///
/// The next motion starts when the previous one starts to decelerate
/// (`t_next = t_prev − prev_prof.decel_start()`), and the displacements add:
/// `prev.point(s1(t_prev)) + (next.point(s2(t_next)) − next.start())`.
/// Outside the overlap the same formula still holds (`s1 = L1` once `prev`
/// has finished, `s2 = 0` before `next` starts), so the engine may use it
/// for the whole time both segments are alive. `next.start()` is expected to
/// be `prev.end()`.
pub fn blended_position(
    prev: &Path,
    prev_prof: &Profile,
    t_prev: f64,
    next: &Path,
    next_prof: &Profile,
    t_next: f64,
) -> Axes {
    let p1 = prev.point(prev_prof.sample(t_prev).0);
    let p2 = next.point(next_prof.sample(t_next).0);
    let n0 = next.start();
    let mut out = [0.0; NUM_AXES];
    for i in 0..NUM_AXES {
        out[i] = p1[i] + (p2[i] - n0[i]);
    }
    out
}

/// Per-axis velocity while two general motions overlap: the sum of
/// `v1·prev.direction(s1)` and `v2·next.direction(s2)`.
pub fn blended_velocity(
    prev: &Path,
    prev_prof: &Profile,
    t_prev: f64,
    next: &Path,
    next_prof: &Profile,
    t_next: f64,
) -> Axes {
    let (s1, v1, _) = prev_prof.sample(t_prev);
    let (s2, v2, _) = next_prof.sample(t_next);
    let d1 = prev.direction(s1);
    let d2 = next.direction(s2);
    let mut out = [0.0; NUM_AXES];
    for i in 0..NUM_AXES {
        out[i] = v1 * d1[i] + v2 * d2[i];
    }
    out
}
