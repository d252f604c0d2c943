//! Cross-module tests: blending of paths and profiles.

use super::*;

fn ax(x: f64, y: f64, z: f64) -> Axes {
    [x, y, z, 0.0, 0.0, 0.0, 0.0, 0.0]
}

fn speed_xyz(v: &Axes) -> f64 {
    (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt()
}

fn dist_xyz(a: &Axes, b: &Axes) -> f64 {
    ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt()
}

/// Two collinear lines, equal feed, Td(prev) = Ta(next): the path speed stays
/// exactly F through the join, for both shapes.
#[test]
fn collinear_blend_keeps_feed() {
    for shape in [Shape::T, Shape::S] {
        let f = 20.0;
        let a = Path::line(&ax(0.0, 0.0, 0.0), &ax(6.0, 8.0, 0.0)); // length 10
        let b = Path::line(&ax(6.0, 8.0, 0.0), &ax(12.0, 16.0, 0.0)); // length 10
        let pa = Profile::new(10.0, f, 0.2, 0.3, shape, shape).unwrap();
        // b cruises from 0.3 to 0.3 + (10 − 5)/20 = 0.55 after it starts.
        let pb = Profile::new(10.0, f, 0.3, 0.2, shape, shape).unwrap();
        let t0 = pa.decel_start(); // next starts here: 0.2 + (10 − 5)/20 = 0.45
        assert!((t0 - 0.45).abs() < 1e-12);
        let n = 3000;
        let (lo, hi) = (t0 - 0.05, pa.duration() + 0.05);
        let mut prev_pos = blended_position(&a, &pa, lo, &b, &pb, lo - t0);
        for k in 1..=n {
            let t = lo + (hi - lo) * k as f64 / n as f64;
            let v = blended_velocity(&a, &pa, t, &b, &pb, t - t0);
            assert!(
                (speed_xyz(&v) - f).abs() <= 1e-9 * f,
                "{shape:?} t={t}: {}",
                speed_xyz(&v)
            );
            // Position agrees: distance travelled between samples = F dt.
            let pos = blended_position(&a, &pa, t, &b, &pb, t - t0);
            let dt = (hi - lo) / n as f64;
            assert!((dist_xyz(&pos, &prev_pos) - f * dt).abs() <= 1e-9 * f * dt + 1e-12);
            prev_pos = pos;
        }
        // After the overlap: exactly on b's path, at the end exactly b.end().
        let end = blended_position(&a, &pa, t0 + pb.duration(), &b, &pb, pb.duration());
        assert_eq!(end, b.end());
    }
}

/// 90° corner with a trapezoid, Td(prev) = Ta(next) = 0.4, F = 10: the blended
/// point at mid-blend is (10 − F·Td/8, F·Ta/8) = (9.5, 0.5), i.e. √2·0.5 from
/// the corner; the path never leaves the box [10 − F·Td/2, 10] × [0, F·Ta/2]
/// during the overlap and never overshoots either segment's end.
#[test]
fn corner_blend_is_bounded() {
    let f = 10.0;
    let a = Path::line(&ax(0.0, 0.0, 0.0), &ax(10.0, 0.0, 0.0));
    let b = Path::line(&ax(10.0, 0.0, 0.0), &ax(10.0, 10.0, 0.0));
    let pa = Profile::new(10.0, f, 0.4, 0.4, Shape::T, Shape::T).unwrap();
    let pb = Profile::new(10.0, f, 0.4, 0.4, Shape::T, Shape::T).unwrap();
    let t0 = pa.decel_start();
    let mid = blended_position(&a, &pa, t0 + 0.2, &b, &pb, 0.2);
    assert!(
        (mid[0] - 9.5).abs() < 1e-12 && (mid[1] - 0.5).abs() < 1e-12,
        "{mid:?}"
    );
    let corner = ax(10.0, 0.0, 0.0);
    assert!((dist_xyz(&mid, &corner) - 0.5 * 2f64.sqrt()).abs() < 1e-12);
    // Blend region: prev's last F·Td/2 = 2 and next's first F·Ta/2 = 2.
    let mut min_d = f64::INFINITY;
    for k in 0..=4000 {
        let t = t0 + 0.4 * k as f64 / 4000.0;
        let p = blended_position(&a, &pa, t, &b, &pb, t - t0);
        assert!(p[0] <= 10.0 && p[0] >= 8.0, "{p:?}");
        assert!(p[1] >= 0.0 && p[1] <= 2.0, "{p:?}");
        min_d = min_d.min(dist_xyz(&p, &corner));
    }
    // Closest approach is at mid-blend (symmetric case).
    assert!((min_d - 0.5 * 2f64.sqrt()).abs() < 1e-6, "{min_d}");
    // Speed through the corner: |v| = sqrt(v1² + v2²) with v1 + v2 = F -> F/√2 at mid.
    let v = blended_velocity(&a, &pa, t0 + 0.2, &b, &pb, 0.2);
    assert!((speed_xyz(&v) - f / 2f64.sqrt()).abs() < 1e-9);
    // Overall: nothing beyond either segment's end.
    for k in 0..=2000 {
        let t = (pa.duration() + pb.duration()) * k as f64 / 2000.0;
        let p = blended_position(&a, &pa, t, &b, &pb, t - t0);
        assert!(p[0] <= 10.0 && p[1] <= 10.0 && p[1] >= 0.0);
    }
}

/// Line into an arc, S curves: the blend stays inside the union of the two
/// blend regions' bounding radius F·(Ta+Td)/2 around the join point.
#[test]
fn line_arc_blend_bounded() {
    let f = 5.0;
    let a = Path::line(&ax(0.0, 0.0, 0.0), &ax(10.0, 0.0, 0.0));
    let b = Path::arc_theta(Plane::XY, &ax(10.0, 0.0, 0.0), [10.0, 5.0], 90.0).unwrap();
    let pa = Profile::new(a.length(), f, 0.3, 0.3, Shape::S, Shape::S).unwrap();
    let pb = Profile::new(b.length(), f, 0.3, 0.3, Shape::S, Shape::S).unwrap();
    let t0 = pa.decel_start();
    let join = a.end();
    for k in 0..=1000 {
        let t = t0 + 0.3 * k as f64 / 1000.0;
        let p = blended_position(&a, &pa, t, &b, &pb, t - t0);
        assert!(dist_xyz(&p, &join) <= f * 0.3 / 2.0 * 2.0 + 1e-12);
        // Speed never above F (the two speeds add to F and the directions differ).
        let v = blended_velocity(&a, &pa, t, &b, &pb, t - t0);
        assert!(speed_xyz(&v) <= f * (1.0 + 1e-12));
    }
}

/// Blending off: the first segment ends with v = 0 exactly at its end point.
#[test]
fn unblended_segment_stops_on_its_end() {
    for shape in [Shape::T, Shape::S] {
        let a =
            Path::arc_3pt(Plane::XY, &ax(1.0, 0.0, 0.0), [0.0, 1.0], [-1.0, 0.0], None).unwrap();
        let pa = Profile::new(a.length(), 2.0, 0.25, 0.5, shape, shape).unwrap();
        let (s, v, acc) = pa.sample(pa.duration());
        assert_eq!((s, v, acc), (a.length(), 0.0, 0.0));
        assert_eq!(a.point(s), a.end());
        assert_eq!(a.end(), ax(-1.0, 0.0, 0.0));
        // Just before the end the speed is small and positive.
        let (_, v, _) = pa.sample(pa.duration() - 1e-3);
        assert!(v > 0.0 && v < 0.1);
    }
}

/// End-to-end: a profiled helix sampled every 1 ms ends exactly on its end
/// and per-axis speeds never exceed the feed.
#[test]
fn profiled_helix_per_axis_speed() {
    let h = Path::helix(Plane::XY, &ax(3.0, 0.0, 0.0), [0.0, 0.0], 2.0, 720.0, None).unwrap();
    let p = Profile::new(h.length(), 15.0, 0.2, 0.2, Shape::S, Shape::T).unwrap();
    let n = (p.duration() / 1e-3).ceil() as usize;
    for k in 0..=n {
        let t = (k as f64 * 1e-3).min(p.duration());
        let (s, v, _) = p.sample(t);
        let d = h.direction(s);
        let vel: Vec<f64> = d.iter().map(|x| x * v).collect();
        let sp = (vel[0] * vel[0] + vel[1] * vel[1] + vel[2] * vel[2]).sqrt();
        assert!((sp - v).abs() <= 1e-12 * 15.0);
        // Z moves pitch·θ/360 · s/L.
        assert!((h.point(s)[2] - 4.0 * s / h.length()).abs() < 1e-12);
    }
    assert_eq!(h.point(p.sample(p.duration()).0), ax(3.0, 0.0, 4.0));
}

/// PathMove ties path and profile together: a 3-4-5 line at F = 10 with
/// Ta = Td = 0.2 lasts 5/10 + 0.2 = 0.7 s; mid-cruise velocity is (6, 8, 0).
#[test]
fn path_move_samples() {
    let m = PathMove::new(
        Path::line(&ax(0.0, 0.0, 0.0), &ax(3.0, 4.0, 0.0)),
        10.0,
        0.2,
        0.2,
        Shape::T,
        Shape::S,
    )
    .unwrap();
    assert!((m.duration() - 0.7).abs() < 1e-12);
    assert!((m.decel_start() - 0.5).abs() < 1e-12);
    let (pos, vel) = m.sample(0.35);
    // s = 1 + 10*0.25 = 2.5 -> (1.5, 2, 0).
    assert!((pos[0] - 1.5).abs() < 1e-12 && (pos[1] - 2.0).abs() < 1e-12);
    assert!((vel[0] - 6.0).abs() < 1e-12 && (vel[1] - 8.0).abs() < 1e-12);
    assert_eq!(m.sample(0.7), (ax(3.0, 4.0, 0.0), [0.0; 8]));
    assert!(PathMove::new(m.path.clone(), 0.0, 0.1, 0.1, Shape::T, Shape::T).is_err());
}
