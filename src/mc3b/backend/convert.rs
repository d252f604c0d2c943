//! Conversions from the virtual card's units to the MC3B's: steps/s and steps/s² as the
//! device takes them, the per-motor settings of a batch of synchronous moves, and the
//! chords an arc becomes.

use super::MOTORS;
use crate::planner::{Axes, Path};
use ::mc3b::codec::{ACCEL_RANGE, VELOCITY_RANGE};

/// Most chords one arc is cut into (the tolerance is met below this).
pub const MAX_CHORDS: usize = 1_000_000;

/// Maximum velocity, acceleration and deceleration of one motor, as the MC3B takes them.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Speeds {
    /// Steps/s, 1..5000.
    pub velocity: u32,
    /// Steps/s², 100..100000.
    pub acceleration: u32,
    /// Steps/s², 100..100000.
    pub deceleration: u32,
}

impl Speeds {
    /// The §6.1 defaults (what the device has after `I`).
    pub const DEFAULT: Speeds = Speeds {
        velocity: 1000,
        acceleration: 5000,
        deceleration: 5000,
    };
}

/// A speed in steps/s as the MC3B takes it: rounded to a whole number, within 1..5000.
pub fn clamp_velocity(v: f64) -> u32 {
    clamp_round(v, VELOCITY_RANGE)
}

/// An acceleration in steps/s² as the MC3B takes it: rounded, within 100..100000.
pub fn clamp_accel(a: f64) -> u32 {
    clamp_round(a, ACCEL_RANGE)
}

fn clamp_round(x: f64, (lo, hi): (u32, u32)) -> u32 {
    if x.is_nan() {
        return lo;
    }
    let r = x.round().clamp(f64::from(lo), f64::from(hi));
    // In range by the clamp.
    r as u32
}

/// How the motors of a batch ramp.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Ramp {
    /// Each motor reaches its speed in `acc_s` and stops from it in `dec_s` seconds (the
    /// command's acc/dec time; 0 = as fast as the MC3B can).
    Times {
        /// Acceleration time, s.
        acc_s: f64,
        /// Deceleration time, s.
        dec_s: f64,
    },
    /// The MC3B's largest acceleration and deceleration (chords of arcs).
    Fastest,
}

/// One synchronous move: signed steps per motor (direction 0 counts up) and the time it
/// should take at its command's feed speed (its length / feed).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Seg {
    /// Steps of motors 0..2.
    pub steps: [i64; MOTORS],
    /// Time at the feed speed, s (without acceleration).
    pub secs: f64,
}

/// The per-motor settings of a batch of synchronous moves, and the speed factor the
/// feed speed was scaled by.
///
/// The MC3B runs every move of a chain with the same settings and gives each move the
/// largest speed at which no motor exceeds its maximum velocity (§4.16). The speed each
/// motor needs in segment `s` is `w = |n| / secs`; the maximum velocity of a motor is
/// the largest `w` it needs, divided by the largest overshoot over the batch (how much
/// faster than its feed a segment would run), so no segment runs faster than its feed
/// speed; segments whose direction makes another motor the limiting one run slower (a
/// chain around a circle: between 1/√2 and 1 of the feed). `scale` multiplies every
/// speed (the override ratio). Accelerations follow `ramp`. Motors that do not move get
/// `None`.
pub fn sync_speeds(segs: &[Seg], ramp: Ramp, scale: f64) -> [Option<Speeds>; MOTORS] {
    let need = |s: &Seg, m: usize| {
        if s.secs > 0.0 {
            s.steps[m].unsigned_abs() as f64 / s.secs
        } else {
            f64::INFINITY
        }
    };
    let mut want = [0.0f64; MOTORS];
    let mut moves = [false; MOTORS];
    for s in segs {
        for m in 0..MOTORS {
            if s.steps[m] != 0 {
                moves[m] = true;
                want[m] = want[m].max(need(s, m));
            }
        }
    }
    let mut worst = 1.0f64;
    for s in segs {
        let mut rho = f64::INFINITY;
        for (m, w) in want.iter().enumerate() {
            if s.steps[m] != 0 && w.is_finite() {
                rho = rho.min(w / need(s, m));
            }
        }
        if rho.is_finite() {
            worst = worst.max(rho);
        }
    }
    let scale = if scale.is_finite() && scale > 0.0 {
        scale
    } else {
        1.0
    };
    std::array::from_fn(|m| {
        moves[m].then(|| {
            let v = want[m] / worst * scale;
            speeds_for(v, ramp)
        })
    })
}

/// The settings of a motor that should run at `v` steps/s with `ramp`.
pub fn speeds_for(v: f64, ramp: Ramp) -> Speeds {
    let velocity = clamp_velocity(v);
    let vf = f64::from(velocity);
    let (acceleration, deceleration) = match ramp {
        Ramp::Fastest => (ACCEL_RANGE.1, ACCEL_RANGE.1),
        Ramp::Times { acc_s, dec_s } => (
            if acc_s > 0.0 {
                clamp_accel(vf / acc_s)
            } else {
                ACCEL_RANGE.1
            },
            if dec_s > 0.0 {
                clamp_accel(vf / dec_s)
            } else {
                ACCEL_RANGE.1
            },
        ),
    };
    Speeds {
        velocity,
        acceleration,
        deceleration,
    }
}

/// Number of equal-angle chords of an arc of `radius` sweeping `sweep` radians whose
/// sagitta `r (1 − cos(α/2))` is at most `tol` (chords never span more than 90°).
pub fn chord_count(radius: f64, sweep: f64, tol: f64) -> usize {
    let sweep = sweep.abs();
    if !(radius > 0.0 && sweep > 0.0 && tol > 0.0 && radius.is_finite() && sweep.is_finite()) {
        return 1;
    }
    let alpha = if tol >= radius {
        std::f64::consts::FRAC_PI_2
    } else {
        (2.0 * (1.0 - tol / radius).acos()).min(std::f64::consts::FRAC_PI_2)
    };
    let n = (sweep / alpha).ceil();
    if n.is_finite() && n >= 1.0 {
        (n as usize).min(MAX_CHORDS)
    } else {
        1
    }
}

/// Largest distance between an arc and its `n` equal chords: `r (1 − cos(sweep / 2n))`.
pub fn sagitta(radius: f64, sweep: f64, n: usize) -> f64 {
    radius * (1.0 - (sweep.abs() / (2.0 * n.max(1) as f64)).cos())
}

/// The end points of the straight moves a path becomes: a line is one move to its end;
/// an arc, circle or helix is cut into [`chord_count`] chords of equal angle (sagitta at
/// most `tol` UU), a cone into chords of equal path length counted on its smallest
/// radius, the last one ending exactly at the path's end.
pub fn chord_points(path: &Path, tol: f64) -> Vec<Axes> {
    match path {
        Path::Line(_) => vec![path.end()],
        Path::Arc(_) | Path::Helix(_) | Path::Cone(_) => {
            let n = match path {
                Path::Cone(c) => {
                    // Chords of equal path length: their sagitta is largest where the
                    // radius is smallest, so count them on a circle of that radius (at
                    // least `tol`) covering the path's length, and keep the 90° rule.
                    let r_min = c.min_radius().max(tol);
                    chord_count(c.max_radius(), c.sweep(), tol).max(chord_count(
                        r_min,
                        path.length() / r_min,
                        tol,
                    ))
                }
                Path::Arc(a) | Path::Helix(a) => chord_count(a.radius(), a.sweep(), tol),
                Path::Line(_) => 1,
            };
            let len = path.length();
            (1..=n)
                .map(|j| {
                    if j == n {
                        path.end()
                    } else {
                        path.point(len * j as f64 / n as f64)
                    }
                })
                .collect()
        }
    }
}

/// Length a feed speed applies to between two points: X/Y/Z distance, or the longest
/// U..B travel when X/Y/Z stand still (as the planner measures paths).
pub fn move_length(from: &Axes, to: &Axes) -> f64 {
    let xyz = (0..3)
        .map(|i| (to[i] - from[i]).powi(2))
        .sum::<f64>()
        .sqrt();
    if xyz > 0.0 {
        xyz
    } else {
        (3..from.len())
            .map(|i| (to[i] - from[i]).abs())
            .fold(0.0, f64::max)
    }
}

#[cfg(test)]
mod tests;
