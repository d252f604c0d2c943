//! Point-to-point motion: every axis runs its own 1-D profile.

use super::{check_all_finite, Axes, PlanError, Profile, Shape, NUM_AXES};

/// Point-to-point speed of one axis (docs/decisions.md / user manual §2.6.2 II):
/// maximum safe speed `(rpm/60)·pitch/gear_ratio` times `ratio_percent/100`.
///
/// Pure formula: the caller validates its inputs (a zero gear ratio gives inf).
pub fn ptp_axis_speed(rpm: f64, pitch: f64, gear_ratio: f64, ratio_percent: f64) -> f64 {
    (rpm / 60.0) * pitch / gear_ratio * (ratio_percent / 100.0)
}

/// A point-to-point move (`MCC_PtP`, `MCC_SyncPtP`, jog to a position).
///
/// Unsynchronised: each axis has its own [`Profile`] (own speed limit, acc/dec
/// time and shape); the axes start together and need not arrive together.
///
/// Synchronised (`sync = true`): the slowest axis (longest own duration `T*`)
/// sets the pace and keeps its profile; every other moving axis is re-planned
/// to last exactly `T*` by lowering its speed, never raising a speed or an
/// acceleration:
/// * if `T* >= Ta + Td` it keeps its set acc/dec times and runs at
///   `F' = L / (T* − (Ta+Td)/2)` (≤ its own speed);
/// * otherwise (it cannot even fit both full ramps in `T*`) its acc/dec times
///   are scaled to `Ta·T*/(Ta+Td)` and `Td·T*/(Ta+Td)` with peak `F' = 2L/T*`
///   (no cruise).
///
/// In both cases the axis's acceleration (T) stays at or below `F/Ta`.
#[derive(Debug, Clone, PartialEq)]
pub struct PtpMove {
    start: Axes,
    end: Axes,
    sign: Axes,
    profiles: Vec<Profile>,
    duration: f64,
}

impl PtpMove {
    /// Plan a point-to-point move from `start` to `end`. Per axis: `max_speed`
    /// (UU/s, > 0 for every axis that moves), acc/dec times (s, >= 0) and shapes.
    ///
    /// Errors: `BadParameter` for NaN/inf positions, a non-positive speed on a
    /// moving axis, or a negative time.
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        start: &Axes,
        end: &Axes,
        max_speed: &Axes,
        acc_time: &Axes,
        dec_time: &Axes,
        acc: &[Shape; 8],
        dec: &[Shape; 8],
        sync: bool,
    ) -> Result<PtpMove, PlanError> {
        check_all_finite(start, "start position")?;
        check_all_finite(end, "end position")?;
        let mut sign = [0.0; NUM_AXES];
        let mut profiles = Vec::with_capacity(NUM_AXES);
        for i in 0..NUM_AXES {
            let d = end[i] - start[i];
            let len = d.abs();
            if !len.is_finite() {
                return Err(PlanError::BadParameter("end position"));
            }
            sign[i] = if d < 0.0 { -1.0 } else { 1.0 };
            // Validate times even on axes that do not move.
            if !acc_time[i].is_finite() || acc_time[i] < 0.0 {
                return Err(PlanError::BadParameter("acceleration time"));
            }
            if !dec_time[i].is_finite() || dec_time[i] < 0.0 {
                return Err(PlanError::BadParameter("deceleration time"));
            }
            let speed = if len == 0.0 { 1.0 } else { max_speed[i] };
            profiles.push(Profile::new(
                len,
                speed,
                acc_time[i],
                dec_time[i],
                acc[i],
                dec[i],
            )?);
        }
        let t_star = profiles.iter().map(Profile::duration).fold(0.0, f64::max);
        if sync && t_star > 0.0 {
            for i in 0..NUM_AXES {
                let p = &profiles[i];
                if p.is_empty() || p.duration() >= t_star {
                    continue;
                }
                let len = p.len();
                let (ta, td) = (acc_time[i], dec_time[i]);
                let ramps = ta + td;
                let q = if t_star >= ramps {
                    Profile::new(len, len / (t_star - 0.5 * ramps), ta, td, acc[i], dec[i])?
                } else {
                    let k = t_star / ramps;
                    Profile::new(len, 2.0 * len / t_star, ta * k, td * k, acc[i], dec[i])?
                };
                profiles[i] = q;
            }
        }
        // Synchronised: every axis counts as arrived at exactly T* (the
        // re-planned durations equal T* up to rounding).
        let duration = if sync {
            t_star
        } else {
            profiles.iter().map(Profile::duration).fold(0.0, f64::max)
        };
        Ok(PtpMove {
            start: *start,
            end: *end,
            sign,
            profiles,
            duration,
        })
    }

    /// Time until the last axis arrives.
    pub fn duration(&self) -> f64 {
        self.duration
    }

    /// Time at which axis `i` arrives (0 for an axis that does not move or is
    /// out of range; never more than [`PtpMove::duration`]).
    pub fn axis_duration(&self, i: usize) -> f64 {
        self.profiles
            .get(i)
            .map_or(0.0, |p| p.duration().min(self.duration))
    }

    /// The 1-D profile of axis `i` (its length is the axis's travel), if `i < 8`.
    pub fn axis_profile(&self, i: usize) -> Option<&Profile> {
        self.profiles.get(i)
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

    /// Positions and velocities at time `t` (clamped). An axis that has
    /// arrived is exactly at its end position with zero velocity.
    pub fn sample(&self, t: f64) -> (Axes, Axes) {
        let mut pos = self.end;
        let mut vel = [0.0; NUM_AXES];
        for (i, p) in self.profiles.iter().enumerate() {
            if p.is_empty() || t.is_nan() || t >= p.duration() || t >= self.duration {
                continue;
            }
            let (s, v, _) = p.sample(t);
            pos[i] = self.start[i] + self.sign[i] * s;
            vel[i] = self.sign[i] * v;
        }
        (pos, vel)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const T8: [Shape; 8] = [Shape::T; 8];
    const S8: [Shape; 8] = [Shape::S; 8];

    fn close(a: f64, b: f64, tol: f64) -> bool {
        (a - b).abs() <= tol
    }

    #[test]
    fn axis_speed_formula() {
        // (3000/60) * 1 / 1 * 50% = 25.
        assert_eq!(ptp_axis_speed(3000.0, 1.0, 1.0, 50.0), 25.0);
        // (1500/60) * 5 / 2 * 100% = 62.5.
        assert_eq!(ptp_axis_speed(1500.0, 5.0, 2.0, 100.0), 62.5);
    }

    /// start 0; X 100 @ 50, Y −50 @ 20, Z 30 @ 50, W 1 @ 100; Ta = 0.2, Td = 0.4 (W: 0.2/0.2).
    fn case(sync: bool) -> PtpMove {
        let start = [0.0; 8];
        let end = [100.0, -50.0, 30.0, 0.0, 0.0, 1.0, 0.0, 0.0];
        let speed = [50.0, 20.0, 50.0, 0.0, 1.0, 100.0, 1.0, 1.0];
        let ta = [0.2, 0.2, 0.2, 0.2, 0.2, 0.2, 0.2, 0.2];
        let td = [0.4, 0.4, 0.4, 0.4, 0.4, 0.2, 0.4, 0.4];
        PtpMove::new(&start, &end, &speed, &ta, &td, &T8, &T8, sync).unwrap()
    }

    #[test]
    fn independent_axes_hand_computed() {
        let m = case(false);
        // X: 100/50 + 0.3 = 2.3; Y: 50/20 + 0.3 = 2.8; Z: 30/50 + 0.3 = 0.9.
        // W: 1 < 100*0.4/2 -> short: Vp = sqrt(2*100*1/0.4) = sqrt(500); T = Vp*0.4/100.
        assert!(close(m.axis_duration(0), 2.3, 1e-12));
        assert!(close(m.axis_duration(1), 2.8, 1e-12));
        assert!(close(m.axis_duration(2), 0.9, 1e-12));
        let tw = 500f64.sqrt() * 0.4 / 100.0;
        assert!(close(m.axis_duration(5), tw, 1e-12));
        assert_eq!(m.axis_duration(3), 0.0);
        assert!(close(m.duration(), 2.8, 1e-12));
        // Mid-move at t = 1: X cruising at +50, Y at −20, Z cruising at 50 (0.2 <= 1 < 0.5? no:
        // Z cruise ends at 0.9 − 0.4 = 0.5, so at t = 1 Z has arrived).
        let (pos, vel) = m.sample(1.0);
        assert!(close(vel[0], 50.0, 1e-9) && close(vel[1], -20.0, 1e-9));
        assert_eq!((pos[2], vel[2]), (30.0, 0.0));
        // X at t = 1: 5 + 50*0.8 = 45; Y: −(2 + 20*0.8) = −18.
        assert!(close(pos[0], 45.0, 1e-12) && close(pos[1], -18.0, 1e-12));
        // Arrived axes sit exactly on their targets.
        let (pos, vel) = m.sample(2.5);
        assert_eq!(pos[0], 100.0);
        assert_eq!(vel[0], 0.0);
        let (pos, vel) = m.sample(m.duration());
        assert_eq!(pos, m.end());
        assert_eq!(vel, [0.0; 8]);
        assert_eq!(m.sample(0.0).0, m.start());
    }

    #[test]
    fn sync_ptp_all_end_together() {
        let m = case(true);
        // T* = 2.8 (Y). X: F' = 100/(2.8 − 0.3) = 40; Z: 30/2.5 = 12; W: 1/(2.8 − 0.2) = 1/2.6.
        assert!(close(m.duration(), 2.8, 1e-12));
        for i in [0, 1, 2, 5] {
            assert!(
                close(m.axis_duration(i), 2.8, 1e-12),
                "axis {i}: {}",
                m.axis_duration(i)
            );
        }
        assert!(close(m.axis_profile(0).unwrap().peak_speed(), 40.0, 1e-12));
        assert!(close(m.axis_profile(2).unwrap().peak_speed(), 12.0, 1e-12));
        assert!(close(
            m.axis_profile(5).unwrap().peak_speed(),
            1.0 / 2.6,
            1e-12
        ));
        // Acc/dec times kept: X reaches 40 at Ta = 0.2.
        assert!(close(m.axis_profile(0).unwrap().acc_time(), 0.2, 1e-12));
        // No axis has arrived before T*, all are at their targets at T*.
        let (pos, _) = m.sample(2.79);
        for i in [0, 1, 2, 5] {
            assert!(pos[i] != m.end()[i]);
        }
        let (pos, vel) = m.sample(m.duration());
        assert_eq!(pos, m.end());
        assert_eq!(vel, [0.0; 8]);
    }

    #[test]
    fn sync_ptp_short_pace_scales_ramp_times() {
        // X: 1 UU @ 10, Ta = Td = 0.1 -> reaches F? needs 10*0.1 = 1 <= 1: yes, T = 0.1 + 0.1 = 0.2.
        // Y: 0.01 UU @ 10, Ta = Td = 0.5 -> short; its own T (S/S) < 0.2 and T* = 0.2 < Ta+Td = 1
        // -> ramps scaled to 0.1/0.1, peak 2*0.01/0.2 = 0.1.
        let start = [0.0; 8];
        let end = [1.0, 0.01, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0];
        let speed = [10.0; 8];
        let ta = [0.1, 0.5, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1];
        let m = PtpMove::new(&start, &end, &speed, &ta, &ta, &S8, &S8, true).unwrap();
        assert!(close(m.duration(), 0.2, 1e-12));
        let y = m.axis_profile(1).unwrap();
        assert!(close(y.duration(), 0.2, 1e-12));
        assert!(close(y.peak_speed(), 0.1, 1e-9));
        assert!(close(y.acc_time(), 0.1, 1e-6));
        // Not faster than it would have been alone: own S peak = 10*(0.02/10)^(2/3).
        assert!(y.peak_speed() <= 10.0 * (0.02f64 / 10.0).powf(2.0 / 3.0));
        assert_eq!(m.sample(0.2).0, end);
    }

    #[test]
    fn bad_parameters() {
        let z = [0.0; 8];
        let mut e = [0.0; 8];
        e[0] = 1.0;
        let one = [1.0; 8];
        let bad = |r: Result<PtpMove, PlanError>| matches!(r, Err(PlanError::BadParameter(_)));
        // Zero speed on a moving axis.
        assert!(bad(PtpMove::new(&z, &e, &z, &one, &one, &T8, &T8, false)));
        // Zero speed on a still axis is fine.
        let mut sp = [0.0; 8];
        sp[0] = 1.0;
        assert!(PtpMove::new(&z, &e, &sp, &one, &one, &T8, &T8, false).is_ok());
        let mut neg = one;
        neg[4] = -1.0;
        assert!(bad(PtpMove::new(&z, &e, &one, &neg, &one, &T8, &T8, false)));
        let mut nan = e;
        nan[2] = f64::NAN;
        assert!(bad(PtpMove::new(
            &z, &nan, &one, &one, &one, &T8, &T8, false
        )));
        // Nothing moves: zero duration, sample is the start.
        let m = PtpMove::new(&z, &z, &one, &one, &one, &T8, &T8, true).unwrap();
        assert_eq!(m.duration(), 0.0);
        assert_eq!(m.sample(0.0), (z, z));
    }
}
