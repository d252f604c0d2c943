//! Speeds, batch settings and chords, checked against the device's own rules.

use super::*;
use crate::mc3b::backend::CHORD_TOLERANCE_STEPS;

#[test]
fn speeds_are_whole_and_within_the_mc3b_ranges() {
    assert_eq!(clamp_velocity(0.2), 1);
    assert_eq!(clamp_velocity(1234.4), 1234);
    assert_eq!(clamp_velocity(1234.5), 1235);
    assert_eq!(clamp_velocity(7000.0), 5000);
    assert_eq!(clamp_velocity(f64::NAN), 1);
    assert_eq!(clamp_accel(5.0), 100);
    assert_eq!(clamp_accel(2.0e6), 100_000);
    // 2000 steps/s reached in 0.3 s: 6667 steps/s².
    let s = speeds_for(
        2000.0,
        Ramp::Times {
            acc_s: 0.3,
            dec_s: 0.0,
        },
    );
    assert_eq!(
        s,
        Speeds {
            velocity: 2000,
            acceleration: 6667,
            deceleration: 100_000
        }
    );
    assert_eq!(speeds_for(10.0, Ramp::Fastest).acceleration, 100_000);
}

#[test]
fn a_square_runs_every_side_at_its_feed() {
    // 10 UU sides at 100 steps/UU, feed 20 UU/s: 1000 steps in 0.5 s.
    let segs = [
        Seg {
            steps: [1000, 0, 0],
            secs: 0.5,
        },
        Seg {
            steps: [0, 1000, 0],
            secs: 0.5,
        },
        Seg {
            steps: [-1000, 0, 0],
            secs: 0.5,
        },
        Seg {
            steps: [0, -1000, 0],
            secs: 0.5,
        },
    ];
    let s = sync_speeds(
        &segs,
        Ramp::Times {
            acc_s: 0.1,
            dec_s: 0.1,
        },
        1.0,
    );
    for sm in &s[..2] {
        assert_eq!(
            sm.map(|x| (x.velocity, x.acceleration)),
            Some((2000, 20_000))
        );
    }
    assert_eq!(s[2], None, "motor 2 does not move");
    // Override 50 %.
    let s = sync_speeds(&segs, Ramp::Fastest, 0.5);
    assert_eq!(s[0].map(|x| x.velocity), Some(1000));
}

/// Cruise time of a synchronous move on the MC3B: the slowest motor at its maximum
/// velocity (§4.16).
fn device_secs(seg: &Seg, sp: &[Option<Speeds>; MOTORS]) -> f64 {
    (0..MOTORS)
        .filter(|&m| seg.steps[m] != 0)
        .map(|m| {
            let v = sp[m].map_or(1.0, |s| f64::from(s.velocity));
            seg.steps[m].unsigned_abs() as f64 / v
        })
        .fold(0.0, f64::max)
}

#[test]
fn chained_moves_never_run_faster_than_their_feed() {
    // A circle of 64 chords: every chord at most at the feed, none below 1/√2 of it.
    let n = 64;
    let r = 2000.0;
    let segs: Vec<Seg> = (0..n)
        .map(|j| {
            let a0 = std::f64::consts::TAU * j as f64 / n as f64;
            let a1 = std::f64::consts::TAU * (j + 1) as f64 / n as f64;
            let d = [r * (a1.cos() - a0.cos()), r * (a1.sin() - a0.sin())];
            let len = (d[0] * d[0] + d[1] * d[1]).sqrt();
            Seg {
                steps: [d[0].round() as i64, d[1].round() as i64, 0],
                secs: len / 2000.0,
            }
        })
        .collect();
    let sp = sync_speeds(&segs, Ramp::Fastest, 1.0);
    let mut ratios: Vec<f64> = segs.iter().map(|s| s.secs / device_secs(s, &sp)).collect();
    ratios.sort_by(f64::total_cmp);
    let (lo, hi) = (ratios[0], ratios[ratios.len() - 1]);
    assert!(hi <= 1.0 + 2e-3, "fastest chord at {hi} of its feed");
    assert!(
        lo >= std::f64::consts::FRAC_1_SQRT_2 - 2e-3,
        "slowest at {lo}"
    );
    let mean = ratios.iter().sum::<f64>() / ratios.len() as f64;
    println!("circle chords run at {lo:.3}..{hi:.3} of the feed, mean {mean:.3}");
}

/// Largest distance from the circle of `r` around the origin to the polyline through
/// `pts` (sampled finely along every chord).
fn max_deviation(pts: &[(f64, f64)], r: f64) -> f64 {
    let mut worst = 0.0f64;
    for w in pts.windows(2) {
        let ((x0, y0), (x1, y1)) = (w[0], w[1]);
        for k in 0..=200 {
            let t = f64::from(k) / 200.0;
            let (x, y) = (x0 + (x1 - x0) * t, y0 + (y1 - y0) * t);
            worst = worst.max(((x * x + y * y).sqrt() - r).abs());
        }
    }
    worst
}

#[test]
fn arcs_become_chords_within_the_tolerance() {
    for &(r, tol) in &[(5.0, 0.01), (100.0, 0.001), (0.3, 0.01), (1.0, 2.0)] {
        let start = [r, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0];
        let path = match Path::circle(crate::planner::Plane::XY, &start, [0.0, 0.0], true, None) {
            Ok(p) => p,
            Err(e) => panic!("circle: {e}"),
        };
        let pts = chord_points(&path, tol);
        let n = chord_count(r, std::f64::consts::TAU, tol);
        assert_eq!(pts.len(), n);
        assert!(sagitta(r, std::f64::consts::TAU, n) <= tol + 1e-12);
        assert!(n >= 4, "no chord spans more than 90 degrees");
        assert_eq!(
            pts.last().copied(),
            Some(path.end()),
            "ends exactly at the end"
        );
        let mut poly = vec![(start[0], start[1])];
        poly.extend(pts.iter().map(|p| (p[0], p[1])));
        let dev = max_deviation(&poly, r);
        assert!(dev <= tol * 1.0001, "r {r}: deviation {dev} > {tol}");
        // One chord fewer would break the tolerance (the count is the smallest).
        if n > 4 {
            assert!(sagitta(r, std::f64::consts::TAU, n - 1) > tol);
        }
    }
}

#[test]
fn chord_endpoints_rounded_to_steps_stay_within_tolerance_plus_half_a_step() {
    // Radius 5 UU at 100 steps/UU, tolerance 1 step (0.01 UU): the chord ends rounded
    // to whole steps leave the polyline within 1 + √2/2 steps of the true circle.
    let (r, k) = (5.0, 100.0);
    let tol = CHORD_TOLERANCE_STEPS / k;
    let start = [r, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0];
    let path = match Path::circle(crate::planner::Plane::XY, &start, [0.0, 0.0], true, None) {
        Ok(p) => p,
        Err(e) => panic!("circle: {e}"),
    };
    let pts = chord_points(&path, tol);
    let mut poly = vec![(r * k, 0.0)];
    poly.extend(pts.iter().map(|p| ((p[0] * k).round(), (p[1] * k).round())));
    let dev = max_deviation(&poly, r * k);
    println!(
        "circle r=5 UU, 100 steps/UU: {} chords, sagitta {:.3} steps, with rounding {dev:.3} steps",
        pts.len(),
        sagitta(r, std::f64::consts::TAU, pts.len()) * k
    );
    assert!(dev <= 1.0 + std::f64::consts::FRAC_1_SQRT_2, "{dev}");
}
