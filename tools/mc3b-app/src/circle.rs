//! The chained synchronous move of §5.4: a circle on an X-Y stage as a chain of chords,
//! each one synchronous move (§6.12), all sent before the first runs (§4.17).
//!
//! The circle starts where the stage stands, at angle 0: its centre lies `radius` steps
//! in X direction 1 (the negative side, direction 0 counting up). Chord `k` ends at the
//! point of angle `2πk/n` rounded to whole steps, so rounding never accumulates and the
//! last chord ends exactly on the start. Counter-clockwise means +Y (direction 0) first.

use serde::Serialize;

/// Chords: at least a triangle, at most a full chain (§4.17: 1..100 moves).
pub const CHORDS_RANGE: (u64, u64) = (3, 100);
/// Radius in steps: a chord of a circle of radius r is at most 2r, and a move's step
/// count is 32-bit (§6.12); 10⁶ keeps every chord far inside it.
pub const RADIUS_RANGE: (u64, u64) = (1, 1_000_000);

/// A circle ready to send.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CirclePlan {
    /// Motor of X.
    pub x_motor: u32,
    /// Motor of Y.
    pub y_motor: u32,
    /// Steps.
    pub radius: u32,
    /// Counter-clockwise.
    pub ccw: bool,
    /// Chord ends relative to the start, `[x, y]` in steps (direction 0 positive);
    /// the first is `[0, 0]`, the last is `[0, 0]` again.
    pub points: Vec<[i64; 2]>,
}

impl CirclePlan {
    /// The chords as `(steps, direction)` of X and of Y.
    pub fn moves(&self) -> Vec<[(u32, u32); 2]> {
        self.points
            .windows(2)
            .map(|w| {
                let d = |a: i64, b: i64| {
                    let s = b - a;
                    (
                        u32::try_from(s.unsigned_abs()).unwrap_or(u32::MAX),
                        u32::from(s < 0),
                    )
                };
                [d(w[0][0], w[1][0]), d(w[0][1], w[1][1])]
            })
            .collect()
    }
}

/// Plans a circle of `radius` steps in `chords` chords on motors `x` and `y`. Refused
/// (with the reason) when a chord would have no step at all: the radius is too small
/// for that many chords.
pub fn plan(x: u32, y: u32, radius: u32, chords: u32, ccw: bool) -> Result<CirclePlan, String> {
    let r = f64::from(radius);
    let n = chords.max(1);
    let sign = if ccw { 1.0 } else { -1.0 };
    let points: Vec<[i64; 2]> = (0..=n)
        .map(|k| {
            if k == n {
                return [0, 0];
            }
            let a = std::f64::consts::TAU * f64::from(k) / f64::from(n);
            [
                (r * a.cos() - r).round() as i64,
                (sign * r * a.sin()).round() as i64,
            ]
        })
        .collect();
    if let Some(k) = points.windows(2).position(|w| w[0] == w[1]) {
        return Err(format!(
            "Radius {radius} is too small for {chords} chords: chord {} would have no steps",
            k + 1
        ));
    }
    Ok(CirclePlan {
        x_motor: x,
        y_motor: y,
        radius,
        ccw,
        points,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_square_of_four_chords() {
        // r = 100, n = 4 counter-clockwise from angle 0, centre at (-100, 0): the chord
        // ends are (-100, 100), (-200, 0), (-100, -100), (0, 0).
        let p = plan(0, 1, 100, 4, true).expect("plan");
        assert_eq!(
            p.points,
            [[0, 0], [-100, 100], [-200, 0], [-100, -100], [0, 0]]
        );
        // As moves: X 100 steps in direction 1 (negative), Y 100 in direction 0, ...
        assert_eq!(
            p.moves(),
            [
                [(100, 1), (100, 0)],
                [(100, 1), (100, 1)],
                [(100, 0), (100, 1)],
                [(100, 0), (100, 0)]
            ]
        );
        let cw = plan(0, 1, 100, 4, false).expect("plan");
        assert_eq!(cw.points[1], [-100, -100]);
    }

    #[test]
    fn chords_close_exactly_and_stay_near_the_circle() {
        // 36 chords of radius 300: the chord ends are rounded points of the circle (at
        // most √2/2 step off it), and the sum of all moves is zero: back at the start.
        let p = plan(1, 2, 300, 36, true).expect("plan");
        assert_eq!(p.points.len(), 37);
        let (mut sx, mut sy) = (0i64, 0i64);
        for m in p.moves() {
            sx += if m[0].1 == 0 { 1 } else { -1 } * i64::from(m[0].0);
            sy += if m[1].1 == 0 { 1 } else { -1 } * i64::from(m[1].0);
        }
        assert_eq!((sx, sy), (0, 0));
        for q in &p.points {
            let d = ((q[0] as f64 + 300.0).powi(2) + (q[1] as f64).powi(2)).sqrt();
            assert!(
                (d - 300.0).abs() <= std::f64::consts::FRAC_1_SQRT_2 + 1e-9,
                "{q:?}"
            );
        }
    }

    #[test]
    fn too_small_for_its_chords_is_refused() {
        // r = 3 with 100 chords: a chord is 2·3·sin(π/100) ≈ 0.19 step long, so some
        // rounded ends coincide.
        let e = plan(0, 1, 3, 100, true).expect_err("refused");
        assert!(e.contains("too small for 100 chords"), "{e}");
        assert!(plan(0, 1, 100, 100, true).is_ok());
    }
}
