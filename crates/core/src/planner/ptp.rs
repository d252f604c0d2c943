//! Point-to-point motion: every axis runs its own profile on the period grid.

use super::{check_all_finite, Axes, PlanError, Shape, TickProfile, NUM_AXES};

/// Point-to-point speed of one axis (user manual §2.6.2 II): the maximum safe speed
/// `(rpm/60)·pitch/gear_ratio` times `ratio_percent/100`.
///
/// Pure formula: the caller validates its inputs (a zero gear ratio gives inf).
pub fn ptp_axis_speed(rpm: f64, pitch: f64, gear_ratio: f64, ratio_percent: f64) -> f64 {
    (rpm / 60.0) * pitch / gear_ratio * (ratio_percent / 100.0)
}

/// A point-to-point move (`MCC_PtP`, `MCC_SyncPtP`, a jog to a position).
///
/// Each moving axis has its own [`TickProfile`] over its travel at its own speed, with
/// the ramps given; the axes start together. Unsynchronised, each arrives when its
/// profile ends. Synchronised, the axis whose profile lasts longest (the master) sets
/// the pace and every other axis covers the same fraction of its travel as the master
/// at every period, so that all arrive together.
///
/// The master is also the axis whose speed a program reads as the move's feed speed.
#[derive(Debug, Clone, PartialEq)]
pub struct PtpMove {
    start: Axes,
    end: Axes,
    sign: Axes,
    /// The speed each axis was planned at (before its profile rounded it to whole
    /// periods).
    speeds: Axes,
    profiles: [TickProfile; NUM_AXES],
    master: usize,
    sync: bool,
    shapes: (Shape, Shape),
}

impl PtpMove {
    /// Plans a point-to-point move from `start` to `end`. Per axis: `speed` (UU/s, > 0
    /// for every axis that moves), ramp periods and shapes; `t` is the period (s).
    ///
    /// Errors: `BadParameter` for NaN/inf positions or a non-positive speed on a moving
    /// axis.
    pub fn new(
        start: &Axes,
        end: &Axes,
        speed: &Axes,
        ramps: &[(u32, u32); NUM_AXES],
        shapes: &[(Shape, Shape); NUM_AXES],
        t: f64,
        sync: bool,
    ) -> Result<PtpMove, PlanError> {
        check_all_finite(start, "start position")?;
        check_all_finite(end, "end position")?;
        let mut sign = [1.0; NUM_AXES];
        let mut profiles =
            [TickProfile::plan(0.0, 0.0, 1.0, 0, 0, (Shape::T, Shape::T), t); NUM_AXES];
        for i in 0..NUM_AXES {
            let d = end[i] - start[i];
            let len = d.abs();
            if !len.is_finite() {
                return Err(PlanError::BadParameter("end position"));
            }
            if d < 0.0 {
                sign[i] = -1.0;
            }
            if len == 0.0 {
                continue;
            }
            if !speed[i].is_finite() || speed[i] <= 0.0 {
                return Err(PlanError::BadParameter("speed"));
            }
            profiles[i] =
                TickProfile::plan(len, 0.0, speed[i], ramps[i].0, ramps[i].1, shapes[i], t);
        }
        // The master: the axis with the longest travel for its speed (the vendor's
        // library reads its speed as the move's feed); the first of equals.
        let mut master = 0;
        let mut longest = 0.0;
        for i in 0..NUM_AXES {
            if profiles[i].is_empty() {
                continue;
            }
            let time = profiles[i].len() / speed[i];
            if time > longest {
                longest = time;
                master = i;
            }
        }
        Ok(PtpMove {
            start: *start,
            end: *end,
            sign,
            speeds: *speed,
            profiles,
            master,
            sync,
            shapes: shapes[master],
        })
    }

    /// Periods until the last axis arrives.
    pub fn periods(&self) -> u64 {
        self.profiles
            .iter()
            .map(TickProfile::periods)
            .max()
            .unwrap_or(0)
    }

    /// The speed axis `i` was planned at (`i < 8`): its maximum safe speed times the
    /// ratio, which an override scales (its profile cruises at this speed rounded to
    /// whole periods).
    pub fn speed(&self, i: usize) -> f64 {
        self.speeds[i]
    }

    /// The axis that sets the pace (and whose speed is the move's feed speed).
    pub fn master(&self) -> usize {
        self.master
    }

    /// The master axis's ramp shapes (a re-plan of any axis uses them).
    pub fn shapes(&self) -> (Shape, Shape) {
        self.shapes
    }

    /// Whether the axes arrive together (`MCC_SyncPtP`).
    pub fn is_sync(&self) -> bool {
        self.sync
    }

    /// The profile of axis `i` over its travel (`i < 8`).
    pub fn profile(&self, i: usize) -> &TickProfile {
        &self.profiles[i]
    }

    /// +1 or −1: the direction axis `i` moves in.
    pub fn sign(&self, i: usize) -> f64 {
        self.sign[i]
    }

    /// Start position.
    pub fn start(&self) -> Axes {
        self.start
    }

    /// End position, exactly as commanded.
    pub fn end(&self) -> Axes {
        self.end
    }

    /// The same move shifted by `d` (see [`crate::planner::Path::translate`]).
    pub fn translate(&mut self, d: &Axes) {
        for ((s, e), d) in self.start.iter_mut().zip(self.end.iter_mut()).zip(d) {
            *s += d;
            *e += d;
        }
    }

    /// The positions after `k` periods of the plan.
    pub fn position(&self, k: u64) -> Axes {
        if self.sync {
            let m = &self.profiles[self.master];
            let frac = if m.len() > 0.0 {
                m.distance(k) / m.len()
            } else {
                1.0
            };
            return std::array::from_fn(|i| {
                if k >= m.periods() {
                    self.end[i]
                } else {
                    self.start[i] + (self.end[i] - self.start[i]) * frac
                }
            });
        }
        std::array::from_fn(|i| {
            let p = &self.profiles[i];
            if k >= p.periods() {
                self.end[i]
            } else {
                self.start[i] + self.sign[i] * p.distance(k)
            }
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const S2: (Shape, Shape) = (Shape::S, Shape::S);

    #[test]
    fn axis_speed_formula() {
        // (3000/60) * 1 / 1 * 50% = 25.
        assert_eq!(ptp_axis_speed(3000.0, 1.0, 1.0, 50.0), 25.0);
        // (1500/60) * 5 / 2 * 100% = 62.5.
        assert_eq!(ptp_axis_speed(1500.0, 5.0, 2.0, 100.0), 62.5);
    }

    #[test]
    fn each_axis_runs_its_own_profile_and_the_longest_is_the_master() {
        // The vendor's PtP to (10, 5, 2) at 25 UU/s each, 50 ms S ramps, 1 ms: X arrives
        // after 450 periods, Y after 250, Z after 130 (2 UU at 25: 80 ms + 50).
        let end = [10.0, 5.0, 2.0, 0.0, 0.0, 0.0, 0.0, 0.0];
        let m = PtpMove::new(
            &[0.0; 8],
            &end,
            &[25.0; 8],
            &[(50, 50); 8],
            &[S2; 8],
            0.001,
            false,
        )
        .expect("planned");
        assert_eq!(m.master(), 0);
        assert_eq!(m.periods(), 450);
        assert_eq!(m.profile(1).periods(), 250);
        assert_eq!(m.profile(2).periods(), 130);
        assert_eq!(m.position(250)[1], 5.0);
        assert_eq!(m.position(450), end);
        assert!(m.position(200)[0] < 10.0);
    }

    #[test]
    fn synchronised_axes_cover_the_masters_fraction() {
        let end = [10.0, -5.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0];
        let m = PtpMove::new(
            &[0.0; 8],
            &end,
            &[25.0; 8],
            &[(50, 50); 8],
            &[S2; 8],
            0.001,
            true,
        )
        .expect("planned");
        for k in [0, 1, 100, 300, 449] {
            let p = m.position(k);
            assert!((p[1] + p[0] / 2.0).abs() < 1e-12, "period {k}");
        }
        assert_eq!(m.position(450), end);
    }

    #[test]
    fn bad_parameters() {
        let z = [0.0; 8];
        let mut e = [0.0; 8];
        e[0] = 1.0;
        let r = [(10, 10); 8];
        let bad = |x: Result<PtpMove, PlanError>| matches!(x, Err(PlanError::BadParameter(_)));
        assert!(bad(PtpMove::new(&z, &e, &z, &r, &[S2; 8], 0.001, false)));
        let mut sp = [0.0; 8];
        sp[0] = 1.0;
        assert!(PtpMove::new(&z, &e, &sp, &r, &[S2; 8], 0.001, false).is_ok());
        let mut nan = e;
        nan[2] = f64::NAN;
        assert!(bad(PtpMove::new(&z, &nan, &sp, &r, &[S2; 8], 0.001, false)));
        let m = PtpMove::new(&z, &z, &sp, &r, &[S2; 8], 0.001, true).expect("still");
        assert_eq!(m.periods(), 0);
        assert_eq!(m.position(0), z);
    }
}
