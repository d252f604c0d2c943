//! One-dimensional rest-to-rest velocity profiles (acceleration, cruise,
//! deceleration) with trapezoidal or S-shaped ramps.

use super::{check_finite, PlanError, Shape};

/// A velocity ramp from 0 to `vp` lasting `time`, of the given shape.
///
/// Both shapes are point-symmetric about the ramp's midpoint, so they cover
/// `vp·time/2` and `v(τ) + v(time-τ) = vp` (which is what makes blended
/// profiles with equal times add up to a constant speed).
#[derive(Debug, Clone, Copy, PartialEq)]
struct Ramp {
    shape: Shape,
    time: f64,
    vp: f64,
}

impl Ramp {
    /// Distance covered by the whole ramp.
    fn distance(&self) -> f64 {
        0.5 * self.vp * self.time
    }

    /// `(s, v, a)` at `tau` in `[0, time]` after the ramp start.
    /// For a zero-time ramp the speed is already `vp` (instant acceleration).
    fn eval(&self, tau: f64) -> (f64, f64, f64) {
        let t = self.time;
        if t <= 0.0 {
            return (0.0, self.vp, 0.0);
        }
        let tau = tau.clamp(0.0, t);
        match self.shape {
            Shape::T => {
                let a = self.vp / t;
                let x = tau / t; // in [0, 1]
                (0.5 * self.vp * tau * x, self.vp * x, a)
            }
            Shape::S => {
                // Jerk J = 4 vp / t^2, peak acceleration J t / 2 = 2 vp / t.
                let j = 4.0 * self.vp / (t * t);
                let h = 0.5 * t;
                if tau <= h {
                    (j * tau * tau * tau / 6.0, 0.5 * j * tau * tau, j * tau)
                } else {
                    let r = t - tau; // time left in the ramp, in [0, t/2)
                    (
                        self.distance() - (self.vp * r - j * r * r * r / 6.0),
                        self.vp - 0.5 * j * r * r,
                        j * r,
                    )
                }
            }
        }
    }
}

/// How long a ramp of `shape` to peak `vp` lasts when the full ramp to `feed`
/// lasts `full_time`, keeping the ramp's acceleration limits (see [`Profile`]).
fn scaled_ramp_time(shape: Shape, full_time: f64, vp: f64, feed: f64) -> f64 {
    let x = (vp / feed).clamp(0.0, 1.0);
    match shape {
        Shape::T => full_time * x,
        Shape::S => full_time * x.sqrt(),
    }
}

/// A 1-D rest-to-rest motion over length `len`: acceleration ramp, cruise at
/// the peak speed, deceleration ramp.
///
/// # Ramps
/// The set acceleration time `Ta` is the time to go from 0 to the feed `F`.
/// * [`Shape::T`]: constant acceleration `F/Ta`.
/// * [`Shape::S`]: acceleration rises linearly from 0 to `2F/Ta` over `Ta/2`
///   and falls back to 0 over the next `Ta/2`; the jerk is `J = 4F/Ta²`.
///
/// Both cover `F·Ta/2`, so a move that reaches `F` lasts exactly
/// `L/F + (Ta+Td)/2`. `Ta` or `Td` may be 0 (instant speed change).
///
/// # Short moves
/// If `L < F·(Ta+Td)/2` the move cannot reach `F`. It then keeps the ramps'
/// *acceleration limits* and lowers the peak to `Vp < F`, with no cruise:
/// * `T` keeps the acceleration `F/Ta`: the ramp lasts `Ta·Vp/F`.
/// * `S` keeps the jerk `J = 4F/Ta²` and stays a pure S (no constant-acceleration
///   phase): a pure S ramp to `Vp` with jerk `J` lasts `2·sqrt(Vp/J) = Ta·sqrt(Vp/F)`
///   and peaks at acceleration `2F/Ta·sqrt(Vp/F)`, below the full-speed peak.
///
/// `Vp` solves `Vp/2·(ta(Vp) + td(Vp)) = L`: in closed form when both ramps have
/// the same shape (`T`: `Vp = sqrt(2FL/(Ta+Td))`; `S`: `Vp = F·(2L/(F(Ta+Td)))^(2/3)`),
/// by bisection for mixed shapes.
///
/// The deceleration phase is evaluated backwards from the end, so
/// `sample(duration()).0 == len` exactly.
#[derive(Debug, Clone, PartialEq)]
pub struct Profile {
    len: f64,
    feed: f64,
    acc: Ramp,
    dec: Ramp,
    cruise_time: f64,
    /// Position at the end of the acceleration ramp.
    s_acc_end: f64,
    /// Position where the deceleration ramp starts (>= `s_acc_end`).
    s_dec_start: f64,
    duration: f64,
}

impl Profile {
    /// Plan a rest-to-rest motion over `len` (>= 0) at feed `feed` (> 0) with
    /// acceleration/deceleration times `acc_time`/`dec_time` (>= 0, seconds)
    /// and the given ramp shapes.
    ///
    /// Errors: `BadParameter` for a negative or non-finite length or time or a
    /// non-positive or non-finite feed.
    pub fn new(
        len: f64,
        feed: f64,
        acc_time: f64,
        dec_time: f64,
        acc: Shape,
        dec: Shape,
    ) -> Result<Profile, PlanError> {
        check_finite(len, "length")?;
        check_finite(feed, "feed speed")?;
        check_finite(acc_time, "acceleration time")?;
        check_finite(dec_time, "deceleration time")?;
        if len < 0.0 {
            return Err(PlanError::BadParameter("length"));
        }
        if feed <= 0.0 {
            return Err(PlanError::BadParameter("feed speed"));
        }
        if acc_time < 0.0 {
            return Err(PlanError::BadParameter("acceleration time"));
        }
        if dec_time < 0.0 {
            return Err(PlanError::BadParameter("deceleration time"));
        }

        if len == 0.0 {
            let zero = |shape| Ramp {
                shape,
                time: 0.0,
                vp: 0.0,
            };
            return Ok(Profile {
                len,
                feed,
                acc: zero(acc),
                dec: zero(dec),
                cruise_time: 0.0,
                s_acc_end: 0.0,
                s_dec_start: 0.0,
                duration: 0.0,
            });
        }

        let ramps_len = 0.5 * feed * (acc_time + dec_time);
        let (vp, ta, td, tc) = if len >= ramps_len {
            (feed, acc_time, dec_time, (len - ramps_len) / feed)
        } else {
            let vp = short_peak(len, feed, acc_time, dec_time, acc, dec).min(feed);
            (
                vp,
                scaled_ramp_time(acc, acc_time, vp, feed),
                scaled_ramp_time(dec, dec_time, vp, feed),
                0.0,
            )
        };
        let acc_r = Ramp {
            shape: acc,
            time: ta,
            vp,
        };
        let dec_r = Ramp {
            shape: dec,
            time: td,
            vp,
        };
        let s_acc_end = acc_r.distance().min(len);
        let s_dec_start = (len - dec_r.distance()).clamp(s_acc_end, len);
        Ok(Profile {
            len,
            feed,
            acc: acc_r,
            dec: dec_r,
            cruise_time: tc,
            s_acc_end,
            s_dec_start,
            duration: ta + tc + td,
        })
    }

    /// The acceleration and deceleration shapes it was planned with.
    pub fn shapes(&self) -> (Shape, Shape) {
        (self.acc.shape, self.dec.shape)
    }

    /// Total time of the move (seconds).
    pub fn duration(&self) -> f64 {
        self.duration
    }

    /// Time at which deceleration begins; with blending on, the next general
    /// motion starts at this time.
    pub fn decel_start(&self) -> f64 {
        self.acc.time + self.cruise_time
    }

    /// Highest speed reached (the feed, or less for a short move).
    pub fn peak_speed(&self) -> f64 {
        self.acc.vp
    }

    /// Length of the move.
    pub fn len(&self) -> f64 {
        self.len
    }

    /// True for a zero-length move.
    pub fn is_empty(&self) -> bool {
        self.len == 0.0
    }

    /// The feed speed the profile was planned with.
    pub fn feed(&self) -> f64 {
        self.feed
    }

    /// Actual acceleration time (the set time, shortened for a short move).
    pub fn acc_time(&self) -> f64 {
        self.acc.time
    }

    /// Actual deceleration time (the set time, shortened for a short move).
    pub fn dec_time(&self) -> f64 {
        self.dec.time
    }

    /// Time spent at constant peak speed.
    pub fn cruise_time(&self) -> f64 {
        self.cruise_time
    }

    /// `(s, v, a)`: position along the move, speed and acceleration at time `t`
    /// (clamped to `[0, duration]`).
    ///
    /// Values are right-continuous: with `Ta = 0`, `v(0)` is already the peak.
    /// At `t >= duration` the move is over: `(len, 0, 0)` exactly. `s` is
    /// monotone non-decreasing in `t`.
    #[inline(always)]
    pub fn sample(&self, t: f64) -> (f64, f64, f64) {
        // NaN compares false everywhere and lands in the `t >= duration` branch.
        if t.is_nan() || t >= self.duration {
            return (self.len, 0.0, 0.0);
        }
        let t = t.max(0.0);
        let ta = self.acc.time;
        if t < ta {
            let (s, v, a) = self.acc.eval(t);
            return (s.clamp(0.0, self.s_acc_end), v, a);
        }
        if t < ta + self.cruise_time {
            let s = self.s_acc_end + self.acc.vp * (t - ta);
            return (s.clamp(self.s_acc_end, self.s_dec_start), self.acc.vp, 0.0);
        }
        let r = (self.duration - t).max(0.0); // time left
        let (d, v, a) = self.dec.eval(r);
        ((self.len - d).clamp(self.s_dec_start, self.len), v, -a)
    }
}

/// Peak speed of a short move (no cruise): solve `Vp/2·(ta(Vp)+td(Vp)) = len`.
/// Precondition: `0 < len < feed·(acc_time+dec_time)/2` (so `acc_time+dec_time > 0`).
fn short_peak(len: f64, feed: f64, acc_time: f64, dec_time: f64, acc: Shape, dec: Shape) -> f64 {
    let sum = acc_time + dec_time;
    match (acc, dec) {
        // Vp^2 (Ta+Td) / (2F) = L
        (Shape::T, Shape::T) => (2.0 * feed * len / sum).sqrt(),
        // Vp^(3/2) (Ta+Td) / (2 sqrt F) = L  =>  Vp = F (2L / (F (Ta+Td)))^(2/3)
        (Shape::S, Shape::S) => feed * (2.0 * len / (feed * sum)).powf(2.0 / 3.0),
        _ => {
            // With u = sqrt(Vp/F): L(u) = F u^2 / 2 * (Ta g_a(u) + Td g_d(u)),
            // g_T(u) = u^2, g_S(u) = u; increasing in u on [0, 1].
            let g = |shape: Shape, u: f64| match shape {
                Shape::T => u * u,
                Shape::S => u,
            };
            let dist = |u: f64| 0.5 * feed * u * u * (acc_time * g(acc, u) + dec_time * g(dec, u));
            let (mut lo, mut hi) = (0.0_f64, 1.0_f64);
            for _ in 0..200 {
                let mid = 0.5 * (lo + hi);
                if mid <= lo || mid >= hi {
                    break;
                }
                if dist(mid) < len {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            let u = 0.5 * (lo + hi);
            feed * u * u
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const DT: f64 = 1e-4;

    /// Dense samples `(t, s, v, a)` every `DT` plus the exact end.
    fn samples(p: &Profile) -> Vec<(f64, f64, f64, f64)> {
        let n = (p.duration() / DT).ceil() as usize;
        let mut out = Vec::with_capacity(n + 2);
        for k in 0..=n {
            let t = (k as f64 * DT).min(p.duration());
            let (s, v, a) = p.sample(t);
            out.push((t, s, v, a));
        }
        out
    }

    /// Invariants every profile must satisfy.
    fn check_invariants(p: &Profile, feed: f64, peak_acc: f64, jerk: Option<f64>) {
        let sm = samples(p);
        let mut prev = sm[0];
        assert_eq!(prev.1, 0.0, "starts at 0");
        for &cur in &sm[1..] {
            assert!(cur.1 >= prev.1, "s monotone: {prev:?} -> {cur:?}");
            assert!(cur.2 <= feed * (1.0 + 1e-12), "v <= F: {cur:?}");
            assert!(cur.2 >= 0.0);
            assert!(
                cur.3.abs() <= peak_acc * (1.0 + 1e-9),
                "|a| <= peak: {cur:?}"
            );
            let dt = cur.0 - prev.0;
            // Position consistent with speed: |ds - v dt| <= a_max dt^2 (Taylor bound).
            let ds = cur.1 - prev.1;
            let vavg = 0.5 * (cur.2 + prev.2);
            assert!(
                (ds - vavg * dt).abs() <= peak_acc * dt * dt + 1e-12 * p.len().max(1.0),
                "position continuous: {prev:?} -> {cur:?}"
            );
            if let Some(j) = jerk {
                assert!(
                    (cur.3 - prev.3).abs() <= j * dt * (1.0 + 1e-9) + 1e-9,
                    "acceleration continuous: {prev:?} -> {cur:?}"
                );
            }
            prev = cur;
        }
        let (s, v, a) = p.sample(p.duration());
        assert_eq!(s, p.len(), "ends exactly at L");
        assert_eq!((v, a), (0.0, 0.0));
        assert_eq!(p.sample(p.duration() + 1.0).0, p.len());
        assert_eq!(p.sample(-1.0).0, 0.0);
    }

    #[test]
    fn trapezoid_long_move_closed_form() {
        // L = 100, F = 50, Ta = 0.2, Td = 0.4: ramps cover 50*(0.6)/2 = 15 <= 100.
        // Duration = 100/50 + 0.3 = 2.3; cruise = (100-15)/50 = 1.7.
        let p = Profile::new(100.0, 50.0, 0.2, 0.4, Shape::T, Shape::T).unwrap();
        assert!((p.duration() - 2.3).abs() < 1e-12);
        assert!((p.decel_start() - 1.9).abs() < 1e-12);
        assert_eq!(p.peak_speed(), 50.0);
        // At t = 0.1 (half of Ta): a = 250, v = 25, s = 0.5*250*0.01 = 1.25.
        let (s, v, a) = p.sample(0.1);
        assert!((s - 1.25).abs() < 1e-12 && (v - 25.0).abs() < 1e-12 && (a - 250.0).abs() < 1e-9);
        // Cruise at t = 1.0: s = 5 + 50*0.8 = 45.
        let (s, v, a) = p.sample(1.0);
        assert!((s - 45.0).abs() < 1e-12);
        assert!((v - 50.0).abs() <= 1e-6 * 50.0 && a == 0.0);
        // Dec: 0.1 s before the end: a = -125, v = 12.5, s = 100 - 0.5*125*0.01 = 99.375.
        let (s, v, a) = p.sample(2.2);
        assert!((s - 99.375).abs() < 1e-9 && (v - 12.5).abs() < 1e-9 && (a + 125.0).abs() < 1e-9);
        check_invariants(&p, 50.0, 250.0, None);
        // Acceleration phase ends within one sample of Ta.
        let first_cruise = samples(&p)
            .into_iter()
            .find(|x| (x.2 - 50.0).abs() <= 1e-9)
            .unwrap();
        assert!((first_cruise.0 - 0.2).abs() <= DT + 1e-12);
    }

    #[test]
    fn s_curve_long_move_closed_form() {
        // L = 10, F = 20, Ta = 0.5, Td = 0.25: ramps cover 20*0.75/2 = 7.5 <= 10.
        // Duration = 0.5 + 0.375 = 0.875. Acc: J = 4F/Ta^2 = 320, peak a = 2F/Ta = 80.
        let p = Profile::new(10.0, 20.0, 0.5, 0.25, Shape::S, Shape::S).unwrap();
        assert!((p.duration() - 0.875).abs() < 1e-12);
        assert!((p.decel_start() - 0.625).abs() < 1e-12);
        // t = 0.25 (mid acc): a = 80, v = J t^2/2 = 10, s = J t^3/6 = 320/6/64 = 0.8333...
        let (s, v, a) = p.sample(0.25);
        assert!((a - 80.0).abs() < 1e-9 && (v - 10.0).abs() < 1e-12);
        assert!((s - 320.0 * 0.25f64.powi(3) / 6.0).abs() < 1e-12);
        // End of acceleration: s = F Ta / 2 = 5.
        assert!((p.sample(0.5).0 - 5.0).abs() < 1e-12);
        // Dec jerk = 4*20/0.0625 = 1280, peak dec = 160.
        check_invariants(&p, 20.0, 160.0, Some(1280.0));
        // The acceleration phase ends within one sample of Ta.
        let sm = samples(&p);
        let first_cruise = sm.iter().find(|x| x.3 == 0.0 && x.0 > 0.0).unwrap();
        assert!(
            (first_cruise.0 - 0.5).abs() <= DT + 1e-12,
            "{first_cruise:?}"
        );
        // Cruise speed within 1e-6 of F.
        for x in sm.iter().filter(|x| x.0 > 0.5 && x.0 < 0.625) {
            assert!((x.2 - 20.0).abs() <= 20.0 * 1e-6);
        }
    }

    #[test]
    fn duration_formula_all_shape_pairs() {
        for &(sa, sd) in &[
            (Shape::T, Shape::T),
            (Shape::T, Shape::S),
            (Shape::S, Shape::T),
            (Shape::S, Shape::S),
        ] {
            for &(ta, td) in &[(0.3, 0.3), (0.1, 0.7), (0.0, 0.4), (0.4, 0.0), (0.0, 0.0)] {
                let (l, f) = (37.0, 60.0); // ramps need <= 60*0.8/2 = 24 <= 37
                let p = Profile::new(l, f, ta, td, sa, sd).unwrap();
                let expect = l / f + (ta + td) / 2.0;
                assert!(
                    (p.duration() - expect).abs() < 1e-12,
                    "{sa:?}{sd:?} {ta} {td}"
                );
                assert_eq!(p.peak_speed(), f);
                let pk = |s: Shape, t: f64| match s {
                    Shape::T => f / t,
                    Shape::S => 2.0 * f / t,
                };
                let peak = pk(sa, ta).max(pk(sd, td));
                let peak = if peak.is_finite() { peak } else { 0.0 };
                if ta > 0.0 && td > 0.0 {
                    check_invariants(&p, f, peak, None);
                } else {
                    // Instant ramps: just the end and monotonicity.
                    assert_eq!(p.sample(p.duration()).0, l);
                    let sm = samples(&p);
                    assert!(sm.windows(2).all(|w| w[1].1 >= w[0].1));
                    assert!(sm.iter().all(|x| x.2 <= f));
                }
            }
        }
    }

    #[test]
    fn instant_acceleration() {
        // Ta = 0: full speed at t = 0; Td = 0: stops dead at the end.
        let p = Profile::new(10.0, 5.0, 0.0, 0.0, Shape::T, Shape::T).unwrap();
        assert_eq!(p.duration(), 2.0);
        assert_eq!(p.sample(0.0), (0.0, 5.0, 0.0));
        assert_eq!(p.sample(1.0), (5.0, 5.0, 0.0));
        assert_eq!(p.sample(2.0), (10.0, 0.0, 0.0));
        // Ta = 0, Td = 1, short move: L = 1 < 5*1/2. T dec: Vp^2*Td/(2F) = L -> Vp = sqrt(10).
        let p = Profile::new(1.0, 5.0, 0.0, 1.0, Shape::T, Shape::T).unwrap();
        assert!((p.peak_speed() - 10f64.sqrt()).abs() < 1e-12);
        assert_eq!(p.sample(0.0).1, p.peak_speed());
        assert_eq!(p.sample(p.duration()).0, 1.0);
    }

    #[test]
    fn trapezoid_short_move() {
        // L = 1, F = 10, Ta = 0.4, Td = 0.2: full ramps need 10*0.6/2 = 3 > 1.
        // Vp = sqrt(2 F L / (Ta+Td)) = sqrt(20/0.6) = 5.7735; acc keeps a = F/Ta = 25.
        let p = Profile::new(1.0, 10.0, 0.4, 0.2, Shape::T, Shape::T).unwrap();
        let vp = (20.0f64 / 0.6).sqrt();
        assert!((p.peak_speed() - vp).abs() < 1e-12);
        assert!((p.acc_time() - 0.4 * vp / 10.0).abs() < 1e-12);
        assert!((p.dec_time() - 0.2 * vp / 10.0).abs() < 1e-12);
        assert_eq!(p.cruise_time(), 0.0);
        assert_eq!(p.decel_start(), p.acc_time());
        assert!((p.sample(0.01).2 - 25.0).abs() < 1e-9, "acceleration kept");
        assert!(
            (p.sample(p.duration() - 0.01).2 + 50.0).abs() < 1e-9,
            "deceleration kept"
        );
        check_invariants(&p, vp, 50.0, None);
    }

    #[test]
    fn s_curve_short_move_keeps_jerk() {
        // L = 1, F = 10, Ta = Td = 0.5: full ramps need 5 > 1.
        // Vp = F (2L/(F(Ta+Td)))^(2/3) = 10 * 0.2^(2/3) = 3.41995.
        // Ramp time = Ta sqrt(Vp/F); jerk J = 4F/Ta^2 = 160 unchanged;
        // peak acceleration = J t/2 = 2F/Ta sqrt(Vp/F) = 40*0.5848 = 23.39 < 40.
        let p = Profile::new(1.0, 10.0, 0.5, 0.5, Shape::S, Shape::S).unwrap();
        let vp = 10.0 * 0.2f64.powf(2.0 / 3.0);
        assert!((p.peak_speed() - vp).abs() < 1e-12);
        let t = 0.5 * (vp / 10.0).sqrt();
        assert!((p.acc_time() - t).abs() < 1e-12);
        assert!((p.duration() - 2.0 * t).abs() < 1e-12);
        // Ramp distance check: vp * t = L.
        assert!((vp * t - 1.0).abs() < 1e-12);
        let peak = 160.0 * t / 2.0;
        assert!(peak < 40.0);
        assert!((p.sample(t / 2.0).2 - peak).abs() < 1e-9);
        check_invariants(&p, vp, peak, Some(160.0));
    }

    #[test]
    fn s_curve_short_move_unequal_times() {
        // L = 1, F = 10, Ta = 0.2, Td = 0.6: Vp = 10 (2/(10*0.8))^(2/3) = 10 * 0.25^(2/3).
        // Acc jerk 4F/Ta^2 = 1000 over Ta sqrt(Vp/F); dec jerk 4F/Td^2 = 111.1.
        let p = Profile::new(1.0, 10.0, 0.2, 0.6, Shape::S, Shape::S).unwrap();
        let vp = 10.0 * 0.25f64.powf(2.0 / 3.0);
        assert!((p.peak_speed() - vp).abs() < 1e-12);
        let x = (vp / 10.0).sqrt();
        assert!((p.acc_time() - 0.2 * x).abs() < 1e-12);
        assert!((p.dec_time() - 0.6 * x).abs() < 1e-12);
        assert!((0.5 * vp * (p.acc_time() + p.dec_time()) - 1.0).abs() < 1e-12);
        // Peak accelerations: 2F/Ta x = 100 x (acc), 2F/Td x = 33.3 x (dec).
        assert!((p.sample(0.1 * x).2 - 100.0 * x).abs() < 1e-9);
        check_invariants(&p, vp, 100.0 * x, Some(1000.0));
    }

    #[test]
    fn mixed_short_moves_end_exactly() {
        for &(sa, sd) in &[(Shape::T, Shape::S), (Shape::S, Shape::T)] {
            // L = 0.5, F = 8, Ta = 0.3, Td = 0.6: full ramps need 3.6 > 0.5.
            let p = Profile::new(0.5, 8.0, 0.3, 0.6, sa, sd).unwrap();
            let vp = p.peak_speed();
            assert!(vp < 8.0 && vp > 0.0);
            // No cruise and the two ramps cover L.
            assert_eq!(p.cruise_time(), 0.0);
            let covered = 0.5 * vp * (p.acc_time() + p.dec_time());
            assert!((covered - 0.5).abs() < 1e-12, "{covered}");
            // Ramp times follow the documented scaling.
            let x = vp / 8.0;
            let st = |s: Shape, t: f64| match s {
                Shape::T => t * x,
                Shape::S => t * x.sqrt(),
            };
            assert!((p.acc_time() - st(sa, 0.3)).abs() < 1e-12);
            assert!((p.dec_time() - st(sd, 0.6)).abs() < 1e-12);
            // Accelerations never above the full-speed peaks (T: F/T, S: 2F/T).
            let pk = |s: Shape, t: f64| match s {
                Shape::T => 8.0 / t,
                Shape::S => 16.0 / t,
            };
            check_invariants(&p, vp, pk(sa, 0.3).max(pk(sd, 0.6)), None);
        }
    }

    #[test]
    fn boundary_between_short_and_long() {
        // Exactly L = F (Ta+Td)/2: reaches F with zero cruise.
        let p = Profile::new(3.0, 10.0, 0.3, 0.3, Shape::S, Shape::S).unwrap();
        assert_eq!(p.peak_speed(), 10.0);
        assert_eq!(p.cruise_time(), 0.0);
        assert!((p.duration() - 0.6).abs() < 1e-12);
        // Just below: continuous peak speed.
        let q = Profile::new(3.0 - 1e-9, 10.0, 0.3, 0.3, Shape::S, Shape::S).unwrap();
        assert!((q.peak_speed() - 10.0).abs() < 1e-6);
    }

    #[test]
    fn zero_length_and_bad_parameters() {
        let p = Profile::new(0.0, 10.0, 0.3, 0.3, Shape::S, Shape::T).unwrap();
        assert_eq!(p.duration(), 0.0);
        assert_eq!(p.sample(0.0), (0.0, 0.0, 0.0));
        assert_eq!(p.sample(1.0), (0.0, 0.0, 0.0));
        let bad = |r: Result<Profile, PlanError>| matches!(r, Err(PlanError::BadParameter(_)));
        assert!(bad(Profile::new(-1.0, 1.0, 0.1, 0.1, Shape::T, Shape::T)));
        assert!(bad(Profile::new(1.0, 0.0, 0.1, 0.1, Shape::T, Shape::T)));
        assert!(bad(Profile::new(1.0, -1.0, 0.1, 0.1, Shape::T, Shape::T)));
        assert!(bad(Profile::new(1.0, 1.0, -0.1, 0.1, Shape::T, Shape::T)));
        assert!(bad(Profile::new(1.0, 1.0, 0.1, -0.1, Shape::T, Shape::T)));
        assert!(bad(Profile::new(
            f64::NAN,
            1.0,
            0.1,
            0.1,
            Shape::T,
            Shape::T
        )));
        assert!(bad(Profile::new(
            1.0,
            f64::INFINITY,
            0.1,
            0.1,
            Shape::T,
            Shape::T
        )));
        assert!(bad(Profile::new(
            1.0,
            1.0,
            f64::NAN,
            0.1,
            Shape::T,
            Shape::T
        )));
        // NaN time samples to the end rather than panicking.
        let p = Profile::new(2.0, 1.0, 0.1, 0.1, Shape::T, Shape::T).unwrap();
        assert_eq!(p.sample(f64::NAN).0, 2.0);
    }

    #[test]
    fn shape_from_char() {
        assert_eq!(Shape::from_char(b'T'), Some(Shape::T));
        assert_eq!(Shape::from_char(b'S'), Some(Shape::S));
        assert_eq!(Shape::from_char(b'x'), None);
        assert_eq!(Shape::from_char(0), None);
    }
}
