//! Time-scale ramps for speed override, hold, continue and abort.

/// A rate that ramps *linearly* from `r0` to `r1` over `ramp_time` seconds and
/// then stays at `r1` (before `t = 0` it is `r0`).
///
/// The engine advances a segment's own time `τ` by `∫ rate dt`, so the path
/// speed is `v(τ)·rate`: it changes continuously and the position never jumps.
/// Typical uses: override (`r0` = old ratio, `r1` = new), hold (`r1 = 0`,
/// `ramp_time` = deceleration time), continue (`0 → 1`), abort (`→ 0`).
///
/// To avoid drift, compute `τ = τ_at_ramp_start + integral(0, t)` from the
/// time since the ramp started rather than summing many small integrals
/// (summing is also accurate to rounding, see the tests).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RateRamp {
    r0: f64,
    r1: f64,
    ramp_time: f64,
}

impl RateRamp {
    /// Ramp from `r0` to `r1` over `ramp_time` seconds. A ramp time that is
    /// not positive (or not finite) is an instant step to `r1` at `t = 0`.
    pub fn new(r0: f64, r1: f64, ramp_time: f64) -> RateRamp {
        let ramp_time = if ramp_time > 0.0 && ramp_time.is_finite() {
            ramp_time
        } else {
            0.0
        };
        RateRamp { r0, r1, ramp_time }
    }

    /// Starting rate.
    pub fn from_rate(&self) -> f64 {
        self.r0
    }

    /// Final rate.
    pub fn to_rate(&self) -> f64 {
        self.r1
    }

    /// Ramp duration (0 for an instant step).
    pub fn ramp_time(&self) -> f64 {
        self.ramp_time
    }

    /// Rate at time `t` since the ramp started.
    pub fn rate(&self, t: f64) -> f64 {
        if t < 0.0 {
            self.r0
        } else if t >= self.ramp_time {
            self.r1
        } else {
            self.r0 + (self.r1 - self.r0) * (t / self.ramp_time)
        }
    }

    /// Antiderivative with `R(0) = 0`.
    fn antiderivative(&self, t: f64) -> f64 {
        if t <= 0.0 {
            self.r0 * t
        } else if t >= self.ramp_time {
            0.5 * (self.r0 + self.r1) * self.ramp_time + self.r1 * (t - self.ramp_time)
        } else {
            self.r0 * t + 0.5 * (self.r1 - self.r0) * t * (t / self.ramp_time)
        }
    }

    /// `∫ rate dt` over `[t0, t1]`, exact for the piecewise-linear rate.
    pub fn integral(&self, t0: f64, t1: f64) -> f64 {
        self.antiderivative(t1) - self.antiderivative(t0)
    }

    /// True once the ramp has reached its final rate.
    pub fn done(&self, t: f64) -> bool {
        t >= self.ramp_time
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Composite Simpson on [a, b] with n (even) intervals.
    fn simpson(f: impl Fn(f64) -> f64, a: f64, b: f64, n: usize) -> f64 {
        let h = (b - a) / n as f64;
        let mut acc = f(a) + f(b);
        for k in 1..n {
            let w = if k % 2 == 1 { 4.0 } else { 2.0 };
            acc += w * f(a + h * k as f64);
        }
        acc * h / 3.0
    }

    #[test]
    fn rate_values() {
        let r = RateRamp::new(1.0, 0.0, 0.2);
        assert_eq!(r.rate(-1.0), 1.0);
        assert_eq!(r.rate(0.0), 1.0);
        assert!((r.rate(0.05) - 0.75).abs() < 1e-15);
        assert_eq!(r.rate(0.2), 0.0);
        assert!(!r.done(0.1999) && r.done(0.2));
        // Hold from full speed covers r0*T/2 of segment time: 0.1 s.
        assert!((r.integral(0.0, 1.0) - 0.1).abs() < 1e-15);
        // Instant step.
        let s = RateRamp::new(1.0, 1.75, 0.0);
        assert_eq!(s.rate(0.0), 1.75);
        assert!(s.done(0.0));
        assert_eq!(s.integral(0.0, 2.0), 3.5);
        assert_eq!(RateRamp::new(1.0, 2.0, f64::NAN).ramp_time(), 0.0);
    }

    #[test]
    fn integral_matches_numeric_integration() {
        // Simpson is exact for piecewise quadratics when the kink is on a node;
        // use intervals that straddle the kink with a fine grid instead.
        for &(r0, r1, tr) in &[
            (1.0, 1.75, 0.3),
            (1.0, 0.0, 0.25),
            (0.0, 1.0, 1.0),
            (0.5, 0.5, 0.1),
        ] {
            let r = RateRamp::new(r0, r1, tr);
            for &(a, b) in &[
                (0.0, tr),
                (0.0, 2.0),
                (0.05, 0.123),
                (0.1, 1.3),
                (-0.2, 0.2),
            ] {
                let exact = r.integral(a, b);
                let num = simpson(|t| r.rate(t), a, b, 200_000);
                assert!(
                    (exact - num).abs() < 1e-9,
                    "{r0} {r1} {tr} [{a},{b}]: {exact} vs {num}"
                );
            }
            // Closed form: full ramp area = (r0+r1)/2 * T.
            assert!((r.integral(0.0, tr) - 0.5 * (r0 + r1) * tr).abs() < 1e-15);
        }
    }

    #[test]
    fn summed_steps_do_not_drift() {
        // 1 ms engine ticks over 3 s: the sum of per-tick integrals equals the whole.
        let r = RateRamp::new(1.0, 0.5, 0.75);
        let mut tau = 0.0;
        for k in 0..3000 {
            let t0 = k as f64 * 1e-3;
            tau += r.integral(t0, t0 + 1e-3);
        }
        // 0.75*(1+0.5)/2 + 0.5*(3 − 0.75) = 0.5625 + 1.125 = 1.6875.
        assert!((tau - 1.6875).abs() < 1e-12, "{tau}");
        assert!((r.integral(0.0, 3.0) - 1.6875).abs() < 1e-15);
        // Additivity at arbitrary split points.
        for &m in &[0.1, 0.75, 1.0] {
            let a = r.integral(0.0, m) + r.integral(m, 3.0);
            assert!((a - 1.6875).abs() < 1e-15);
        }
    }
}
