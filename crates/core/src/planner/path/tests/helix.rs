//! Unit tests of helices (and a helix of no angle whose aux axes are the path).

use super::*;
use crate::planner::PlanError;
use std::f64::consts::PI;

#[test]
fn helix_end_point_and_length() {
    // XY helix, R = 2 about (0,0), from (2,0,0), pitch 3 per turn, θ = 450°:
    // Z travel = 3 * 450/360 = 3.75; end angle 90° -> (0, 2, 3.75).
    // Length: the arc in the plane, 2 * 2.5π, as the vendor's library measures a
    // helix (its feed runs along the arc; the rise follows the angle).
    let start = ax(2.0, 0.0, 0.0);
    let p = Path::helix(Plane::XY, &start, [0.0, 0.0], 3.0, 450.0, None).unwrap();
    assert_axes_close(&p.end(), &ax(0.0, 2.0, 3.75), 1e-12);
    let expect = 2.0 * 2.5 * PI;
    assert!(close(p.length(), expect, 1e-12));
    assert_eq!(p.point(p.length()), p.end());
    // Z is linear in the angle: after one full turn (fraction 360/450) z = 3, back at (2, 0).
    let q = p.point(p.length() * 0.8);
    assert_axes_close(&q, &ax(2.0, 0.0, 3.0), 1e-12);
    // Direction: unit in XYZ, constant axial component 3.75/length.
    let d = p.direction(1.0);
    assert!(close(d[2], 3.75 / expect, 1e-12));
    assert!(matches!(&p, Path::Helix(_)));
    assert_eq!(p.is_ccw(), Some(true));
    check_on_circle(&p, [0.0; 3], [0.0, 0.0, 1.0], 2.0);
    // CW helix in YZ (normal X) with negative pitch: X travel = -1 * |-180|/360 = -0.5
    // (the rise follows the pitch's sign, whichever way the helix turns, as the
    // vendor's library moves it).
    let start = [0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0];
    let p = Path::helix(
        Plane::YZ,
        &start,
        [0.0, 0.0],
        -1.0,
        -180.0,
        Some([0.0, 6.0, 0.0, 0.0, 0.0]),
    )
    .unwrap();
    assert_axes_close(&p.end(), &[-0.5, 0.0, -1.0, 0.0, 6.0, 0.0, 0.0, 0.0], 1e-12);
    assert!(close(p.length(), PI, 1e-12));
    // Half way: angle from +Z (90° in YZ) by −90° -> +Y, X = -0.25, V = 3.
    assert_axes_close(
        &p.point(p.length() / 2.0),
        &[-0.25, 1.0, 0.0, 0.0, 3.0, 0.0, 0.0, 0.0],
        1e-12,
    );
    check_on_circle(&p, [0.0; 3], [1.0, 0.0, 0.0], 1.0);
    // Zero pitch helix is a plain arc in geometry.
    let p = Path::helix(Plane::XY, &ax(1.0, 0.0, 0.0), [0.0, 0.0], 0.0, 180.0, None).unwrap();
    assert!(close(p.length(), PI, 1e-12));
}

#[test]
fn helix_to_end_position() {
    // Obsolete form: end at Z = 5 with pitch 2 -> 2.5 turns, CW.
    let start = ax(1.0, 0.0, 0.0);
    let p = Path::helix_to(Plane::XY, &start, [0.0, 0.0], 5.0, 2.0, false, None).unwrap();
    assert_eq!(p.end()[2], 5.0);
    assert!(close(p.end()[0], -1.0, 1e-12) && close(p.end()[1], 0.0, 1e-12));
    assert_eq!(p.is_ccw(), Some(false));
    let expect = 2.0 * 2.5 * PI;
    assert!(close(p.length(), expect, 1e-12));
    assert!(matches!(
        Path::helix_to(Plane::XY, &start, [0.0, 0.0], 5.0, 0.0, false, None),
        Err(PlanError::BadParameter(_))
    ));
}

#[test]
fn aux_only_arc_uses_aux_length() {
    // θ = 0 helix with aux travel: XYZ don't move, U is the path.
    let p = Path::helix(
        Plane::XY,
        &ax(1.0, 0.0, 0.0),
        [0.0, 0.0],
        1.0,
        0.0,
        Some([0.0, 0.0, 7.0, 0.0, 0.0]),
    )
    .unwrap();
    assert_eq!(p.length(), 7.0);
    assert_eq!(p.end(), [1.0, 0.0, 0.0, 0.0, 0.0, 7.0, 0.0, 0.0]);
    assert_eq!(p.direction(1.0)[5], 1.0);
    assert_axes_close(
        &p.point(3.5),
        &[1.0, 0.0, 0.0, 0.0, 0.0, 3.5, 0.0, 0.0],
        1e-12,
    );
}
