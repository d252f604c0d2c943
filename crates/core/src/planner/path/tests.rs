//! Unit tests of the path kinds, one file a kind, and the checks they share.

use super::vec3::{dot3, norm3, scale3, sub3};
use super::*;

mod arc;
mod helix;
mod line;

fn ax(x: f64, y: f64, z: f64) -> Axes {
    [x, y, z, 0.0, 0.0, 0.0, 0.0, 0.0]
}

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol
}

fn assert_axes_close(a: &Axes, b: &Axes, tol: f64) {
    for i in 0..NUM_AXES {
        assert!(close(a[i], b[i], tol), "axis {i}: {a:?} vs {b:?}");
    }
}

/// Every sample lies on the circle (radius error <= 1e-9 R) in the plane,
/// consecutive samples are close, the ends are exact, and `direction`
/// matches a finite difference of `point`.
fn check_on_circle(p: &Path, c3: [f64; 3], axis: [f64; 3], r: f64) {
    let n = 1000;
    let len = p.length();
    let mut prev = p.point(0.0);
    assert_eq!(prev, p.start());
    for k in 0..=n {
        let s = len * k as f64 / n as f64;
        let q = p.point(s);
        let d = sub3([q[0], q[1], q[2]], c3);
        // Remove the axial component (helix rise / 3-D plane offset).
        let h = dot3(d, axis);
        let radial = sub3(d, scale3(axis, h));
        assert!(
            (norm3(radial) - r).abs() <= 1e-9 * r,
            "radius at s={s}: {}",
            norm3(radial)
        );
        // Chord between samples, in the plane, never longer than the arc step (the
        // length is the arc's in the plane; a helix rises besides).
        let step = sub3([q[0], q[1], q[2]], [prev[0], prev[1], prev[2]]);
        let chord = norm3(sub3(step, scale3(axis, dot3(step, axis))));
        assert!(chord <= len / n as f64 * (1.0 + 1e-9) + 1e-12);
        prev = q;
        // Tangent check by central difference (interior).
        if k > 0 && k < n {
            let e = 1e-6 * len;
            let (a, b) = (p.point(s - e), p.point(s + e));
            let dir = p.direction(s);
            for i in 0..NUM_AXES {
                assert!(
                    close((b[i] - a[i]) / (2.0 * e), dir[i], 1e-6),
                    "tangent axis {i}"
                );
            }
            // Per unit of the length (the arc in the plane): unit in the plane.
            let d3 = [dir[0], dir[1], dir[2]];
            let unit = norm3(sub3(d3, scale3(axis, dot3(d3, axis))));
            assert!(close(unit, 1.0, 1e-12));
        }
    }
    assert_eq!(p.point(len), p.end());
    assert_eq!(p.point(len * 2.0), p.end());
}
