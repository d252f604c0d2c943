//! One axis driven on its own by speed commands, as go-home searches move (user manual
//! §2.8): run toward a speed until told otherwise, stop with a deceleration or at once,
//! or travel to a position with a trapezoidal profile.
//!
//! Every drive is evaluated in closed form from the state where it began, so a long run
//! of ticks does not accumulate rounding. Speeds change linearly (constant acceleration):
//! the go-home parameters have times, not curve shapes (§2.4.3).

use super::{Profile, Shape};

/// What the axis is doing.
#[derive(Debug, Clone, PartialEq)]
enum Drive {
    /// Standing still.
    Rest,
    /// Changing speed from `v0` toward `target` at `rate` (UU/s², > 0; infinite: at once),
    /// then keeping `target`.
    Run { v0: f64, target: f64, rate: f64 },
    /// Travelling from `from` to `to` (`sign` is the direction).
    MoveTo {
        from: f64,
        to: f64,
        sign: f64,
        profile: Profile,
    },
}

/// A single axis's position (UU) and speed (UU/s) under a `Drive`.
#[derive(Debug, Clone, PartialEq)]
pub struct Axis1D {
    /// Where the current drive began.
    x0: f64,
    /// Time since the current drive began (s).
    t: f64,
    drive: Drive,
}

impl Axis1D {
    /// An axis standing at `x`.
    pub fn at(x: f64) -> Axis1D {
        Axis1D {
            x0: x,
            t: 0.0,
            drive: Drive::Rest,
        }
    }

    /// Position and speed now.
    pub fn state(&self) -> (f64, f64) {
        self.sample(self.t)
    }

    /// Position now (UU).
    pub fn x(&self) -> f64 {
        self.state().0
    }

    /// Speed now (UU/s, signed).
    pub fn v(&self) -> f64 {
        self.state().1
    }

    /// Whether the axis stands still and will stay so.
    pub fn at_rest(&self) -> bool {
        match &self.drive {
            Drive::Rest => true,
            Drive::Run { target, .. } => *target == 0.0 && self.v() == 0.0,
            Drive::MoveTo { profile, .. } => self.t >= profile.duration(),
        }
    }

    fn sample(&self, t: f64) -> (f64, f64) {
        match &self.drive {
            Drive::Rest => (self.x0, 0.0),
            Drive::Run { v0, target, rate } => {
                let dv = target - v0;
                let t_ramp = if rate.is_infinite() {
                    0.0
                } else {
                    dv.abs() / rate
                };
                if t < t_ramp {
                    let v = v0 + dv.signum() * rate * t;
                    (self.x0 + 0.5 * (v0 + v) * t, v)
                } else {
                    let ramp = 0.5 * (v0 + target) * t_ramp;
                    (self.x0 + ramp + target * (t - t_ramp), *target)
                }
            }
            Drive::MoveTo {
                from,
                to,
                sign,
                profile,
            } => {
                if t >= profile.duration() {
                    return (*to, 0.0);
                }
                let (s, v, _) = profile.sample(t);
                (from + sign * s, sign * v)
            }
        }
    }

    /// Starts a new drive from where the axis is now.
    fn begin(&mut self, drive: Drive) {
        self.x0 = self.x();
        self.t = 0.0;
        self.drive = drive;
    }

    /// Runs toward speed `target` (signed UU/s), changing speed at `rate` (UU/s²;
    /// infinite or non-positive: at once), then keeps it.
    pub fn run(&mut self, target: f64, rate: f64) {
        let v0 = self.v();
        let rate = if rate > 0.0 { rate } else { f64::INFINITY };
        self.begin(Drive::Run { v0, target, rate });
    }

    /// Stops at once where it is (the manual's "emergency stop").
    pub fn halt(&mut self) {
        self.begin(Drive::Rest);
    }

    /// Decelerates to a stop at `rate` (UU/s²; infinite or non-positive: at once).
    pub fn stop(&mut self, rate: f64) {
        if rate > 0.0 && rate.is_finite() {
            self.run(0.0, rate);
        } else {
            self.halt();
        }
    }

    /// Travels from rest to `target` at `speed` (> 0) with acceleration and deceleration
    /// times `acc_s`, `dec_s` (trapezoid: 0 to `speed` in `acc_s`); a travel too short to
    /// reach `speed` keeps the accelerations. Returns false (and stays) when the numbers
    /// cannot be planned.
    pub fn move_to(&mut self, target: f64, speed: f64, acc_s: f64, dec_s: f64) -> bool {
        let from = self.x();
        let d = target - from;
        match Profile::new(d.abs(), speed, acc_s, dec_s, Shape::T, Shape::T) {
            Ok(profile) => {
                self.begin(Drive::MoveTo {
                    from,
                    to: target,
                    sign: if d < 0.0 { -1.0 } else { 1.0 },
                    profile,
                });
                true
            }
            Err(_) => false,
        }
    }

    /// Advances time by `dt` seconds.
    pub fn advance(&mut self, dt: f64) {
        self.t += dt;
        // A drive that has come to rest becomes `Rest` (keeps the numbers small).
        if self.at_rest() && !matches!(self.drive, Drive::Rest) {
            let x = self.x();
            *self = Axis1D::at(x);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ticks(a: &mut Axis1D, n: usize, dt: f64) {
        for _ in 0..n {
            a.advance(dt);
        }
    }

    #[test]
    fn accelerates_cruises_and_decelerates_in_closed_form() {
        // 10 UU/s reached in 0.3 s at 10/0.3 UU/s²: 1.5 UU covered while accelerating.
        let mut a = Axis1D::at(0.0);
        a.run(-10.0, 10.0 / 0.3);
        ticks(&mut a, 300, 0.001);
        assert!((a.x() + 1.5).abs() < 1e-12, "{}", a.x());
        assert!((a.v() + 10.0).abs() < 1e-9);
        ticks(&mut a, 50, 0.001);
        assert!((a.x() + 2.0).abs() < 1e-12, "0.5 UU more at 10 UU/s");
        // Stopping from 10 UU/s at 10/0.3 UU/s² covers 1.5 UU and takes 0.3 s.
        a.stop(10.0 / 0.3);
        ticks(&mut a, 299, 0.001);
        assert!(!a.at_rest());
        ticks(&mut a, 1, 0.001);
        assert!(a.at_rest());
        assert!((a.x() + 3.5).abs() < 1e-12, "{}", a.x());
        assert_eq!(a.v(), 0.0);
    }

    #[test]
    fn speed_change_between_two_speeds_and_halt() {
        let mut a = Axis1D::at(1.0);
        a.run(10.0, f64::INFINITY);
        assert_eq!(a.v(), 10.0, "infinite rate: at once");
        ticks(&mut a, 10, 0.01);
        assert!((a.x() - 2.0).abs() < 1e-12);
        // From 10 to 2 UU/s at 40 UU/s²: 0.2 s covering (10+2)/2 x 0.2 = 1.2 UU.
        a.run(2.0, 40.0);
        ticks(&mut a, 20, 0.01);
        assert!((a.x() - 3.2).abs() < 1e-12, "{}", a.x());
        assert!((a.v() - 2.0).abs() < 1e-12);
        a.halt();
        assert!(a.at_rest());
        ticks(&mut a, 5, 0.01);
        assert!((a.x() - 3.2).abs() < 1e-12);
    }

    #[test]
    fn move_to_lands_exactly() {
        let mut a = Axis1D::at(-3.5);
        assert!(a.move_to(-2.0, 2.0, 0.3, 0.3));
        // 1.5 UU at 2 UU/s with 0.3 s ramps: 1.5/2 + 0.3 = 1.05 s.
        ticks(&mut a, 1049, 0.001);
        assert!(!a.at_rest());
        assert!(a.v() > 0.0);
        ticks(&mut a, 2, 0.001);
        assert!(a.at_rest());
        assert_eq!(a.x(), -2.0);
        assert!(a.move_to(-2.0, 2.0, 0.3, 0.3), "zero travel");
        assert!(a.at_rest());
        assert!(!a.move_to(0.0, 0.0, 0.3, 0.3), "no speed");
    }
}
