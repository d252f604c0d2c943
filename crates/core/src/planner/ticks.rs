//! Speed profiles on the grid of interpolation periods, the way the vendor's library
//! plans them (measured with its own DLL, docs/decisions.md "Motion as the vendor's
//! library runs it").
//!
//! A move is planned in whole periods: its ramps last whole periods, and its feed is
//! lowered so that the part at constant speed does too. A profile runs from a start
//! speed `v0` to a constant speed `v` over `na` periods, holds `v` for `nc` periods and
//! ramps to 0 over `nd` periods. [`TickProfile::distance`] gives where it is after `k`
//! periods; the speed a program reads for period `k` is the distance covered in it over
//! the period.

use super::Shape;

/// The velocity fraction of an S ramp at `x` in `[0, 1]` of its time: the cubic
/// smoothstep `3x² − 2x³` (what the vendor's S-curve is, per period to six digits).
#[inline]
pub fn smoothstep(x: f64) -> f64 {
    x * x * (3.0 - 2.0 * x)
}

/// The distance a ramp from 0 to `v` lasting `time` seconds covers in its first `t`
/// seconds (`0 <= t <= time`).
#[inline]
fn ramp_distance(shape: Shape, v: f64, time: f64, t: f64) -> f64 {
    if time <= 0.0 {
        return v * t;
    }
    let x = t / time;
    match shape {
        Shape::T => v * t * x * 0.5,
        // ∫ v (3u² − 2u³) dt with u = t/time: v·time·(u³ − u⁴/2).
        Shape::S => v * time * (x * x * x - 0.5 * x * x * x * x),
    }
}

/// How many periods an acceleration of `acc_ms` and a deceleration of `dec_ms` take at a
/// period of `period_ms`: each rounded up to whole periods, and when the two together
/// are odd the shorter one is a period longer, so that their half sum is whole and the
/// time at speed stays a whole number of periods (the times are whole milliseconds, see
/// [`whole_ms`]).
pub fn ramp_periods(acc_ms: f64, dec_ms: f64, period_ms: f64) -> (u32, u32) {
    let periods = |ms: f64| -> u32 {
        // NaN or not positive: no ramp.
        if ms.is_nan() || ms <= 0.0 || period_ms.is_nan() || period_ms <= 0.0 {
            return 0;
        }
        let n = (ms / period_ms).ceil();
        // A whole number of milliseconds over a whole period: an exact quotient when it
        // divides, so `ceil` cannot round a whole quotient up.
        if n >= f64::from(u32::MAX) {
            u32::MAX
        } else {
            n as u32
        }
    };
    let (mut na, mut nd) = (periods(acc_ms), periods(dec_ms));
    if (u64::from(na) + u64::from(nd)) % 2 == 1 {
        if na < nd {
            na += 1;
        } else {
            nd += 1;
        }
    }
    (na, nd)
}

/// A time in milliseconds as the vendor keeps it: rounded up to a whole millisecond.
pub fn whole_ms(ms: f64) -> f64 {
    ms.ceil()
}

/// A speed profile on the period grid (see the module).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TickProfile {
    len: f64,
    v0: f64,
    v: f64,
    na: u32,
    nc: u64,
    nd: u32,
    acc: Shape,
    dec: Shape,
    /// The period, seconds.
    t: f64,
    /// Distance covered by the ramp from `v0` to `v`.
    acc_len: f64,
    /// `v0 / v` (0 when `v` is 0), the acceleration's units and the whole profile's (see
    /// [`TickProfile::fraction`]): kept so that a period's fraction costs a few
    /// operations.
    u0: f64,
    acc_units: f64,
    total_units: f64,
}

impl TickProfile {
    /// A move of `len` (>= 0) from speed `v0` (>= 0) at a feed of at most `feed` (> 0),
    /// ramping over `na` and `nd` periods of `t` seconds.
    ///
    /// When the ramps and some time at `feed` fit in `len`, the time at speed is rounded
    /// up to whole periods and the speed lowered to fit exactly:
    /// `(v0 + v)/2·na·t + v·nc·t + v/2·nd·t = len`. When they do not (a short move), the
    /// ramps keep their periods and the peak speed is lowered: `nc = 0`.
    pub fn plan(
        len: f64,
        v0: f64,
        feed: f64,
        na: u32,
        nd: u32,
        shapes: (Shape, Shape),
        t: f64,
    ) -> TickProfile {
        let ta = f64::from(na) * t;
        let td = f64::from(nd) * t;
        let ramps = 0.5 * (v0 + feed) * ta + 0.5 * feed * td;
        let nc = if len > ramps && feed > 0.0 && t > 0.0 {
            // The periods at speed: the move's periods at the feed less the ramps', in
            // that order (as the vendor's library gets whole numbers: 0.2 UU at 0.5 UU/s
            // over 1 ms is 400 periods, 300 with two ramps of 100, not 300.00000000000006),
            // its time counted in milliseconds, `len / feed × 1000`, over the period in
            // milliseconds: 1.394 UU at 0.5 UU/s takes 2788.0000000000005 ms, so 2724
            // periods at speed besides ramps of 90 and 40 where `len / feed / t` gives
            // 2788 and 2723 [`mix_67`].
            let total = len / feed * 1000.0 / (t * 1000.0);
            let at_speed = total - 0.5 * f64::from(na) * (1.0 + v0 / feed) - 0.5 * f64::from(nd);
            let periods = at_speed.ceil();
            if periods >= 1.0 {
                periods.min(9.0e15) as u64
            } else {
                0
            }
        } else {
            0
        };
        let denom = 0.5 * ta + nc as f64 * t + 0.5 * td;
        let v = if denom > 0.0 {
            ((len - 0.5 * v0 * ta) / denom).max(0.0)
        } else {
            0.0
        };
        TickProfile::from_parts(len, v0, v, na, nc, nd, shapes, t)
    }

    /// A stop from speed `v0`: the distance a ramp from `v0` to 0 lasting `dec_s` at the
    /// full feed `feed` would take at the same deceleration, `v0²·dec_s/(2·feed)`, run as
    /// a ramp to 0 over `floor(dec_s·v0/feed / t) + 1` periods (the vendor's hold and
    /// timed abort).
    pub fn stop(v0: f64, feed: f64, dec_s: f64, shape: Shape, t: f64) -> TickProfile {
        let (d, n) = if v0 > 0.0 && feed > 0.0 && t > 0.0 {
            let time = dec_s * v0 / feed;
            let periods = (time / t).floor();
            if periods > 1.0e9 {
                // Longer than the periods a profile counts: the ramp over the most it
                // counts, starting a hair under `v0` (a stop never speeds up, and the
                // vendor's ramp this long starts under `v0` too).
                let n = 1_000_000_001u32;
                (0.5 * v0 * f64::from(n - 1) * t, n)
            } else {
                (v0 * v0 * dec_s / (2.0 * feed), periods as u32 + 1)
            }
        } else {
            (0.0, 0)
        };
        let vs = if n > 0 {
            2.0 * d / (f64::from(n) * t)
        } else {
            0.0
        };
        TickProfile::from_parts(d, vs, vs, 0, 0, n, (shape, shape), t)
    }

    #[allow(clippy::too_many_arguments)]
    fn from_parts(
        len: f64,
        v0: f64,
        v: f64,
        na: u32,
        nc: u64,
        nd: u32,
        (acc, dec): (Shape, Shape),
        t: f64,
    ) -> TickProfile {
        let ta = f64::from(na) * t;
        let u0 = if v > 0.0 { v0 / v } else { 0.0 };
        let mut p = TickProfile {
            len,
            v0,
            v,
            na,
            nc,
            nd,
            acc,
            dec,
            t,
            acc_len: v0 * ta + ramp_distance(acc, v - v0, ta, ta),
            u0,
            acc_units: 0.5 * f64::from(na) * (1.0 + u0),
            total_units: 0.0,
        };
        p.total_units = p.units(p.periods());
        p
    }

    /// The same profile with other ramp shapes (blending runs both ramps of the overlap
    /// as S ramps).
    pub fn with_shapes(self, acc: Shape, dec: Shape) -> TickProfile {
        TickProfile::from_parts(
            self.len,
            self.v0,
            self.v,
            self.na,
            self.nc,
            self.nd,
            (acc, dec),
            self.t,
        )
    }

    /// Periods the profile lasts.
    #[inline]
    pub fn periods(&self) -> u64 {
        u64::from(self.na) + self.nc + u64::from(self.nd)
    }

    /// The period at which the deceleration starts (the periods before it).
    #[inline]
    pub fn decel_start(&self) -> u64 {
        u64::from(self.na) + self.nc
    }

    /// Periods of the acceleration (from `v0` to the constant speed).
    #[inline]
    pub fn acc_periods(&self) -> u32 {
        self.na
    }

    /// Periods of the deceleration.
    #[inline]
    pub fn dec_periods(&self) -> u32 {
        self.nd
    }

    /// The constant speed.
    #[inline]
    pub fn speed(&self) -> f64 {
        self.v
    }

    /// The start speed.
    #[inline]
    pub fn start_speed(&self) -> f64 {
        self.v0
    }

    /// The length of the move.
    #[inline]
    pub fn len(&self) -> f64 {
        self.len
    }

    /// Whether the move has no length.
    #[inline]
    pub fn is_empty(&self) -> bool {
        self.len == 0.0
    }

    /// The period in seconds.
    #[inline]
    pub fn period(&self) -> f64 {
        self.t
    }

    /// The distance covered after `k` periods (`len` from the last period on).
    ///
    /// Computed as the vendor's library computes it, as far as its speeds show: the
    /// length times the fraction of the profile's distance in units of "one period at
    /// the constant speed" (`D(k) / D(N)`), so that a move of whole periods lands on the
    /// same doubles (a cruise of 2 UU over 200 periods: `2·(99/200)` after 149).
    #[inline]
    pub fn distance(&self, k: u64) -> f64 {
        if k >= self.periods() {
            return self.len;
        }
        self.len * self.fraction(k)
    }

    /// The fraction of the length covered after `k` periods (`D(k) / D(N)`, see
    /// [`TickProfile::distance`]; 1 from the last period on).
    #[inline]
    pub fn fraction(&self, k: u64) -> f64 {
        let n = self.periods();
        if k >= n {
            return 1.0;
        }
        let total = self.total_units;
        if total.is_nan() || total <= 0.0 {
            return k as f64 / n as f64;
        }
        self.units(k) / total
    }

    /// The periods at the constant speed, before the last period (which reaches 1), as a
    /// [`SteadyFraction`]; `None` when there are none or the profile has no distance in
    /// units (its fractions are then periods over periods).
    pub fn steady(&self) -> Option<SteadyFraction> {
        let total = self.total_units;
        if total.is_nan() || total <= 0.0 {
            return None;
        }
        let na = u64::from(self.na);
        let last = self.decel_start().min(self.periods().saturating_sub(1));
        (last > na).then_some(SteadyFraction {
            acc_units: self.acc_units,
            na,
            last,
            total_units: total,
        })
    }

    /// The distance after `k` periods in units of one period at the constant speed.
    #[inline]
    fn units(&self, k: u64) -> f64 {
        let na = u64::from(self.na);
        let (u0, acc_units) = (self.u0, self.acc_units);
        if k <= na {
            let kf = k as f64;
            if self.na == 0 {
                return 0.0;
            }
            return u0 * kf + (1.0 - u0) * ramp_units(self.acc, f64::from(self.na), kf);
        }
        if k <= na + self.nc {
            return steady_units(acc_units, k - na);
        }
        let n = self.periods();
        let end = acc_units + self.nc as f64 + 0.5 * f64::from(self.nd);
        end - ramp_units(self.dec, f64::from(self.nd), (n - k) as f64)
    }
}

/// The units of distance after `at_speed` periods at the constant speed that follow
/// `acc_units` of acceleration: [`TickProfile::fraction`] and [`SteadyFraction::at`] both
/// compute it here, so they give the same doubles.
#[inline(always)]
fn steady_units(acc_units: f64, at_speed: u64) -> f64 {
    acc_units + periods_f64(at_speed)
}

/// A count of periods as a double: `n as f64` exactly, in one signed conversion for
/// counts below 2^63 (all of them in practice), where x86-64 converts an unsigned one in
/// several instructions. Every cruise period converts counts.
#[inline(always)]
pub fn periods_f64(n: u64) -> f64 {
    match i64::try_from(n) {
        Ok(i) => i as f64,
        Err(_) => n as f64,
    }
}

/// The periods of a profile at its constant speed ([`TickProfile::steady`]), whose
/// fractions ([`TickProfile::fraction`]) are a sum and a division each: what a period
/// along them computes without asking where on the profile it is.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SteadyFraction {
    acc_units: f64,
    na: u64,
    last: u64,
    total_units: f64,
}

impl SteadyFraction {
    /// The fraction after `k` periods, `k` in `first()..=last()`: exactly
    /// [`TickProfile::fraction`] of `k`.
    #[inline(always)]
    pub fn at(&self, k: u64) -> f64 {
        steady_units(self.acc_units, k.wrapping_sub(self.na)) / self.total_units
    }

    /// The first period it covers.
    pub fn first(&self) -> u64 {
        self.na + 1
    }

    /// The last period it covers.
    pub fn last(&self) -> u64 {
        self.last
    }
}

/// The units of distance (periods at speed 1) a ramp from 0 to 1 over `n` periods covers
/// in its first `k`.
#[inline]
fn ramp_units(shape: Shape, n: f64, k: f64) -> f64 {
    if n <= 0.0 {
        return k;
    }
    let x = k / n;
    match shape {
        Shape::T => k * k / (2.0 * n),
        Shape::S => n * (x * x * x - 0.5 * x * x * x * x),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn avg_speeds(p: &TickProfile) -> Vec<f64> {
        (1..=p.periods())
            .map(|k| (p.distance(k) - p.distance(k - 1)) / p.period())
            .collect()
    }

    #[test]
    fn ramp_periods_round_up_and_make_the_half_sum_whole() {
        // Measured on the vendor's library: (acc, dec) ms at 1 ms -> the periods its
        // current-command record shows; and at 10 ms.
        for ((a, d, p), want) in [
            ((1.0, 2.0, 1.0), (2, 2)),
            ((2.0, 3.0, 1.0), (3, 3)),
            ((3.0, 8.0, 1.0), (4, 8)),
            ((7.0, 2.0, 1.0), (7, 3)),
            ((0.0, 3.0, 1.0), (1, 3)),
            ((30.0, 120.0, 1.0), (30, 120)),
            ((25.0, 35.0, 10.0), (4, 4)),
            ((14.0, 6.0, 10.0), (2, 2)),
            ((30.0, 50.0, 10.0), (3, 5)),
            ((0.0, 20.0, 10.0), (0, 2)),
            ((10.0, 30.0, 10.0), (1, 3)),
        ] {
            assert_eq!(ramp_periods(a, d, p), want, "({a}, {d}) at {p} ms");
        }
    }

    #[test]
    fn a_moves_time_is_counted_in_milliseconds() {
        // mix_67: a PtP axis from −0.89 to 0.504 (1.3940000000000001 UU) at 0.5 UU/s,
        // ramps of 90 and 40 ms at 1 ms. Its time is 2.7880000000000003 s, which is
        // 2788.0000000000005 ms (× 1000) but 2788 periods (÷ 0.001): the vendor's library
        // takes the milliseconds, so ceil(2788.0000000000005 − 45 − 20) = 2724 periods at
        // speed, and the speed that covers the length in 45 + 2724 + 20 periods:
        // 1.394 / 2.789 = 0.49982072427... UU/s (the trace's Y speed).
        let len = 0.504 - -0.89;
        let p = TickProfile::plan(len, 0.0, 0.5, 90, 40, (Shape::T, Shape::T), 0.001);
        assert_eq!(p.periods(), 90 + 2724 + 40);
        assert_eq!(p.speed(), len / 2.789);
    }

    #[test]
    fn a_long_line_rounds_its_time_at_speed_up_to_whole_periods() {
        // Line (10, 10) at F 10 UU/s, 100 ms T ramps, 1 ms: L/F = 1414.2 ms -> the vendor
        // cruises 1315 periods at 14.1421/1.415 = 9.99444 UU/s and ends after 1515.
        let len = 200f64.sqrt();
        let p = TickProfile::plan(len, 0.0, 10.0, 100, 100, (Shape::T, Shape::T), 0.001);
        assert_eq!(p.periods(), 1515);
        assert_eq!(p.decel_start(), 1415);
        assert!((p.speed() - len / 1.415).abs() < 1e-12);
        let v = avg_speeds(&p);
        // The vendor's first period: 0.049972210684561653 (path speed).
        assert!((v[0] - 0.049_972_210_684_561_65).abs() < 1e-12, "{}", v[0]);
        assert_eq!(p.distance(1515), len);
    }

    #[test]
    fn a_short_line_keeps_its_ramp_periods_and_lowers_its_peak() {
        // 0.05 UU at F 10 with 100 ms ramps: peak 2L/(Ta+Td) = 0.5, 200 periods.
        let p = TickProfile::plan(0.05, 0.0, 10.0, 100, 100, (Shape::S, Shape::S), 0.001);
        assert_eq!(p.periods(), 200);
        assert!((p.speed() - 0.5).abs() < 1e-15);
        let v = avg_speeds(&p);
        assert!(
            (v[99] - 0.49995).abs() < 1e-6,
            "the highest period {}",
            v[99]
        );
    }

    #[test]
    fn an_s_ramp_is_the_smoothstep() {
        // The vendor's S ramp of 50 periods to 25 UU/s: first period 0.0099, second 0.0685.
        let p = TickProfile::plan(10.0, 0.0, 25.0, 50, 50, (Shape::S, Shape::S), 0.001);
        let v = avg_speeds(&p);
        assert!((v[0] - 0.0099).abs() < 1e-12);
        assert!((v[1] - 0.0685).abs() < 1e-12);
    }

    #[test]
    fn a_replan_from_speed_ramps_from_the_last_periods_speed() {
        // Override to 40 % at period 30 of a T ramp to 10 UU/s over 100 periods: from
        // 2.95 UU/s (the last period's average) the vendor ramps over 100 periods to
        // 3.998893805309711 with 352 periods at speed for the 1.955 UU left.
        let p = TickProfile::plan(1.955, 2.95, 4.0, 100, 100, (Shape::T, Shape::T), 0.001);
        assert_eq!(p.periods(), 552);
        assert!(
            (p.speed() - 3.998893805309711).abs() < 1e-9,
            "{}",
            p.speed()
        );
    }

    #[test]
    fn a_stop_keeps_the_deceleration_and_adds_a_period() {
        // Hold at 10 UU/s with a 100 ms deceleration at F 10: 0.5 UU over 101 periods,
        // first period 9.851975296539583. From 4.95 UU/s: 0.1225125 UU over 50 periods.
        let p = TickProfile::stop(10.0, 10.0, 0.1, Shape::T, 0.001);
        assert_eq!(p.periods(), 101);
        assert!((p.len() - 0.5).abs() < 1e-15);
        let v = avg_speeds(&p);
        assert!((v[0] - 9.851975296539583).abs() < 1e-9, "{}", v[0]);
        let p = TickProfile::stop(4.95, 10.0, 0.1, Shape::T, 0.001);
        assert_eq!(p.periods(), 50);
        assert!((p.len() - 0.1225125).abs() < 1e-15);
    }

    #[test]
    fn distances_rise_and_end_at_the_length() {
        for (len, v0, feed, na, nd) in [
            (1.0, 0.0, 10.0, 30, 120),
            (0.001, 0.0, 10.0, 40, 40),
            (3.0, 5.0, 2.0, 7, 3),
            (2.0, 0.0, 10.0, 0, 0),
        ] {
            for shapes in [(Shape::T, Shape::S), (Shape::S, Shape::T)] {
                let p = TickProfile::plan(len, v0, feed, na, nd, shapes, 0.001);
                let mut last = 0.0;
                for k in 0..=p.periods() {
                    let s = p.distance(k);
                    assert!(s >= last - 1e-12, "rises");
                    last = s;
                }
                assert_eq!(p.distance(p.periods()), len);
            }
        }
    }
}
