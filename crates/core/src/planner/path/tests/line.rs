//! Unit tests of straight lines.

use super::*;
use crate::planner::PlanError;

#[test]
fn line_point_and_direction_are_the_formulas_bit_for_bit() {
    let lines = [
        (
            [0.1, -3.3, 7.0, 1.0, 2.0, 3.0, 4.0, 5.0],
            [1000.0; NUM_AXES],
        ),
        ([0.0; NUM_AXES], [0.0, 0.0, 0.0, 1.0, -7.7, 0.3, 0.0, 2.0]),
        ([1.0; NUM_AXES], [1.0; NUM_AXES]),
    ];
    for (a, b) in lines {
        let p = Path::line(&a, &b);
        let len = p.length();
        for k in 0..=40 {
            let s = len * f64::from(k) / 37.0;
            let d = p.direction(s);
            let q = p.point(s);
            for i in 0..NUM_AXES {
                let want = if len <= 0.0 { 0.0 } else { (b[i] - a[i]) / len };
                assert_eq!(d[i].to_bits(), want.to_bits());
                let at = if s <= 0.0 || len <= 0.0 {
                    a[i]
                } else if s >= len {
                    b[i]
                } else {
                    a[i] + (b[i] - a[i]) * (s / len)
                };
                assert_eq!(q[i].to_bits(), at.to_bits());
            }
        }
    }
}

#[test]
fn line_endpoints_and_length() {
    let a = [1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0];
    let b = [4.0, 6.0, 3.0, 14.0, 5.0, -6.0, 7.0, 9.0];
    let p = Path::line(&a, &b);
    assert_eq!(p.length(), 5.0); // 3-4-5 in XY; aux ignored
    assert_eq!(p.point(0.0), a);
    assert_eq!(p.point(5.0), b);
    assert_eq!(p.start(), a);
    assert_eq!(p.end(), b);
    let mid = p.point(2.5);
    assert_axes_close(&mid, &[2.5, 4.0, 3.0, 9.0, 5.0, 0.0, 7.0, 8.5], 1e-12);
    let d = p.direction(1.0);
    assert_axes_close(&d, &[0.6, 0.8, 0.0, 2.0, 0.0, -2.4, 0.0, 0.2], 1e-12);
    assert_eq!(p.is_ccw(), None);
}

#[test]
fn try_line_rejects_non_finite() {
    let a = [0.0; 8];
    let mut b = [1.0; 8];
    assert!(Path::try_line(&a, &b).is_ok());
    b[6] = f64::INFINITY;
    assert!(matches!(
        Path::try_line(&a, &b),
        Err(PlanError::BadParameter(_))
    ));
    assert!(matches!(
        Path::try_line(&b, &a),
        Err(PlanError::BadParameter(_))
    ));
}

#[test]
fn aux_only_line_uses_longest_aux_axis() {
    // No XYZ travel: U moves 10, V moves -20 -> the path is V, length 20.
    let a = [1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0];
    let b = [1.0, 1.0, 1.0, 10.0, -20.0, 0.0, 0.0, 0.0];
    let p = Path::line(&a, &b);
    assert_eq!(p.length(), 20.0);
    let d = p.direction(3.0);
    assert_eq!(d, [0.0, 0.0, 0.0, 0.5, -1.0, 0.0, 0.0, 0.0]);
    assert_axes_close(
        &p.point(10.0),
        &[1.0, 1.0, 1.0, 5.0, -10.0, 0.0, 0.0, 0.0],
        1e-12,
    );
    // Nothing moves at all: zero length, point is the start, direction zero.
    let z = Path::line(&a, &a);
    assert_eq!(z.length(), 0.0);
    assert_eq!(z.point(1.0), a);
    assert_eq!(z.direction(0.0), [0.0; 8]);
}

#[test]
fn consecutive_lines_do_not_drift() {
    // 10^6 small moves; each starts exactly where the previous ended and the
    // final position is the exact commanded target.
    let mut cur = [0.0; 8];
    let n = 1_000_000u32;
    for k in 1..=n {
        let x = f64::from(k) * 1e-3;
        let target = [x, -x, 0.5 * x, x, 0.0, 0.0, 0.0, 1e-7 * f64::from(k)];
        let p = Path::line(&cur, &target);
        assert_eq!(p.start(), cur);
        assert_eq!(p.end(), target);
        if k % 4096 == 0 {
            assert_eq!(p.point(p.length()), target);
        }
        cur = p.end();
    }
    assert_eq!(cur[0], f64::from(n) * 1e-3);
    assert_eq!(cur[7], f64::from(n) * 1e-7);
}
