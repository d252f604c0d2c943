//! Unit tests of arcs and circles.

use super::*;
use crate::planner::path::vec3::unit3;
use crate::planner::PlanError;
use std::f64::consts::PI;

#[test]
fn arc_xy_half_circle_ccw() {
    // start (10,0), via (0,10), end (-10,0): center (0,0), R = 10, CCW, length 10π.
    let start = ax(10.0, 0.0, 5.0);
    let p = Path::arc_3pt(Plane::XY, &start, [0.0, 10.0], [-10.0, 0.0], None).unwrap();
    let Path::Arc(a) = &p else { panic!() };
    assert!(close(a.radius(), 10.0, 1e-12));
    assert_axes_close(
        &[
            a.center()[0],
            a.center()[1],
            a.center()[2],
            0.,
            0.,
            0.,
            0.,
            0.,
        ],
        &ax(0.0, 0.0, 5.0),
        1e-12,
    );
    assert!(close(a.sweep(), PI, 1e-12));
    assert_eq!(p.is_ccw(), Some(true));
    assert!(close(p.length(), 10.0 * PI, 1e-12));
    assert_eq!(p.end(), ax(-10.0, 0.0, 5.0));
    // Quarter way: (0, 10).
    assert_axes_close(&p.point(5.0 * PI), &ax(0.0, 10.0, 5.0), 1e-12);
    check_on_circle(&p, [0.0, 0.0, 5.0], [0.0, 0.0, 1.0], 10.0);
}

#[test]
fn arc_xy_cw_and_long_way() {
    // start (10,0), via (0,-10), end (-10,0): clockwise half circle.
    let p = Path::arc_3pt(
        Plane::XY,
        &ax(10.0, 0.0, 0.0),
        [0.0, -10.0],
        [-10.0, 0.0],
        None,
    )
    .unwrap();
    assert_eq!(p.is_ccw(), Some(false));
    assert_axes_close(&p.point(p.length() / 2.0), &ax(0.0, -10.0, 0.0), 1e-12);
    // start (10,0), via (-10,0), end (0,-10): 270° CCW the long way round.
    let p = Path::arc_3pt(
        Plane::XY,
        &ax(10.0, 0.0, 0.0),
        [-10.0, 0.0],
        [0.0, -10.0],
        None,
    )
    .unwrap();
    assert_eq!(p.is_ccw(), Some(true));
    assert!(close(p.length(), 15.0 * PI, 1e-12));
    assert_axes_close(&p.point(5.0 * PI), &ax(0.0, 10.0, 0.0), 1e-12);
    check_on_circle(&p, [0.0; 3], [0.0, 0.0, 1.0], 10.0);
}

#[test]
fn arc_offset_center_known_points() {
    // Circle center (3,-2), R = 5: points (8,-2), (6,2), (-2,-2) (3-4-5 triangle).
    let p = Path::arc_3pt(
        Plane::XY,
        &ax(8.0, -2.0, 0.0),
        [6.0, 2.0],
        [-2.0, -2.0],
        None,
    )
    .unwrap();
    let Path::Arc(a) = &p else { panic!() };
    assert!(close(a.center()[0], 3.0, 1e-12) && close(a.center()[1], -2.0, 1e-12));
    assert!(close(a.radius(), 5.0, 1e-12));
    assert!(close(p.length(), 5.0 * PI, 1e-12));
    check_on_circle(&p, [3.0, -2.0, 0.0], [0.0, 0.0, 1.0], 5.0);
}

#[test]
fn arc_yz_and_zx_planes() {
    // YZ: plane coords (Y, Z), X is the normal and stays.
    // start Y=10,Z=0; via (0,10); end (-10,0): CCW about +X, passes Z=+10.
    let start = [7.0, 10.0, 0.0, 1.0, 2.0, 3.0, 4.0, 5.0];
    let p = Path::arc_3pt(Plane::YZ, &start, [0.0, 10.0], [-10.0, 0.0], None).unwrap();
    assert_eq!(p.is_ccw(), Some(true));
    assert_eq!(p.end(), [7.0, -10.0, 0.0, 1.0, 2.0, 3.0, 4.0, 5.0]);
    assert_axes_close(
        &p.point(p.length() / 2.0),
        &[7.0, 0.0, 10.0, 1.0, 2.0, 3.0, 4.0, 5.0],
        1e-12,
    );
    check_on_circle(&p, [7.0, 0.0, 0.0], [1.0, 0.0, 0.0], 10.0);
    // ZX: plane coords (Z, X): the first coordinate is Z. Y stays.
    // start Z=10,X=0; via (Z=0, X=10); end (Z=-10, X=0).
    let start = ax(0.0, 3.0, 10.0);
    let p = Path::arc_3pt(Plane::ZX, &start, [0.0, 10.0], [-10.0, 0.0], None).unwrap();
    assert_eq!(p.is_ccw(), Some(true));
    assert_eq!(p.end(), ax(0.0, 3.0, -10.0));
    assert_axes_close(&p.point(p.length() / 2.0), &ax(10.0, 3.0, 0.0), 1e-12);
    check_on_circle(&p, [0.0, 3.0, 0.0], [0.0, 1.0, 0.0], 10.0);
}

#[test]
fn arc_aux_axes_follow_fraction() {
    let start = ax(10.0, 0.0, 0.0);
    let p = Path::arc_3pt(
        Plane::XY,
        &start,
        [0.0, 10.0],
        [-10.0, 0.0],
        Some([10.0, 0.0, -4.0, 0.0, 2.0]),
    )
    .unwrap();
    assert_eq!(p.end(), [-10.0, 0.0, 0.0, 10.0, 0.0, -4.0, 0.0, 2.0]);
    let q = p.point(p.length() / 4.0);
    assert!(close(q[3], 2.5, 1e-12) && close(q[5], -1.0, 1e-12) && close(q[7], 0.5, 1e-12));
    let d = p.direction(1.0);
    assert!(close(d[3], 10.0 / (10.0 * PI), 1e-12));
}

#[test]
fn arc_xyz_tilted_plane() {
    // Circle of radius 5 centered at c = (1,2,3) in the plane spanned by
    // e1 = (1,0,1)/√2 and e2 = (0,1,0): start c+5e1, via c+5e2, end c−5e1.
    let c = [1.0, 2.0, 3.0];
    let k = 5.0 / 2f64.sqrt();
    let start = ax(c[0] + k, c[1], c[2] + k);
    let via = [c[0], c[1] + 5.0, c[2]];
    let end = [c[0] - k, c[1], c[2] - k];
    let p = Path::arc_3pt_xyz(&start, via, end, None).unwrap();
    let Path::Arc(a) = &p else { panic!() };
    for (ci, ce) in a.center().iter().zip(c) {
        assert!(close(*ci, ce, 1e-12));
    }
    assert!(close(a.radius(), 5.0, 1e-12));
    assert!(close(p.length(), 5.0 * PI, 1e-12));
    assert_eq!(p.end(), ax(end[0], end[1], end[2]));
    assert_axes_close(
        &p.point(p.length() / 2.0),
        &ax(via[0], via[1], via[2]),
        1e-12,
    );
    // Normal = e1 × e2 ∝ (−1, 0, 1)/√2.
    let nrm = [-1.0 / 2f64.sqrt(), 0.0, 1.0 / 2f64.sqrt()];
    check_on_circle(&p, c, nrm, 5.0);
    // Every sample on the plane: (q − c)·n = 0.
    for k in 0..=100 {
        let q = p.point(p.length() * k as f64 / 100.0);
        assert!(dot3(sub3([q[0], q[1], q[2]], c), nrm).abs() < 1e-12);
    }
    // Short arc (via between): 90° arc from e1 through 45° to e2.
    let h = 5.0 * (PI / 4.0).cos();
    let via45 = [c[0] + h / 2f64.sqrt(), c[1] + h, c[2] + h / 2f64.sqrt()];
    let p = Path::arc_3pt_xyz(&start, via45, [c[0], c[1] + 5.0, c[2]], Some([1.0; 5])).unwrap();
    assert!(close(p.length(), 2.5 * PI, 1e-12));
    assert_eq!(p.end()[3..], [1.0; 5]);
    check_on_circle(&p, c, nrm, 5.0);
}

#[test]
fn degenerate_arcs_are_bad_arc() {
    let s = ax(0.0, 0.0, 0.0);
    // Collinear.
    assert_eq!(
        Path::arc_3pt(Plane::XY, &s, [1.0, 1.0], [2.0, 2.0], None),
        Err(PlanError::BadArc)
    );
    // Via coincides with start / end; start == end.
    assert_eq!(
        Path::arc_3pt(Plane::XY, &s, [0.0, 0.0], [2.0, 2.0], None),
        Err(PlanError::BadArc)
    );
    assert_eq!(
        Path::arc_3pt(Plane::XY, &s, [2.0, 2.0], [2.0, 2.0], None),
        Err(PlanError::BadArc)
    );
    assert_eq!(
        Path::arc_3pt(Plane::XY, &s, [1.0, 2.0], [0.0, 0.0], None),
        Err(PlanError::BadArc)
    );
    // Collinear in 3-D and coincident in 3-D.
    assert_eq!(
        Path::arc_3pt_xyz(&s, [1.0, 2.0, 3.0], [2.0, 4.0, 6.0], None),
        Err(PlanError::BadArc)
    );
    assert_eq!(
        Path::arc_3pt_xyz(&s, [0.0, 0.0, 0.0], [2.0, 4.0, 6.0], None),
        Err(PlanError::BadArc)
    );
    // Zero radius.
    assert_eq!(
        Path::arc_theta(Plane::XY, &s, [0.0, 0.0], 90.0),
        Err(PlanError::BadArc)
    );
    assert_eq!(
        Path::circle(Plane::YZ, &s, [0.0, 0.0], true, None),
        Err(PlanError::BadArc)
    );
    assert_eq!(
        Path::helix(Plane::ZX, &s, [0.0, 0.0], 1.0, 90.0, None),
        Err(PlanError::BadArc)
    );
    // In XY the normal axis does not matter for the radius.
    let s2 = ax(0.0, 0.0, 5.0);
    assert_eq!(
        Path::circle(Plane::XY, &s2, [0.0, 0.0], true, None),
        Err(PlanError::BadArc)
    );
    // NaN is a parameter error.
    assert!(matches!(
        Path::arc_theta(Plane::XY, &s, [1.0, 0.0], f64::NAN),
        Err(PlanError::BadParameter(_))
    ));
    assert!(matches!(
        Path::arc_3pt(Plane::XY, &s, [f64::NAN, 1.0], [2.0, 0.0], None),
        Err(PlanError::BadParameter(_))
    ));
}

#[test]
fn arc_theta_sign_convention_per_plane() {
    // Start on +a of a unit circle about the origin; +90° must reach +b, −90° must reach −b.
    for plane in [Plane::XY, Plane::YZ, Plane::ZX] {
        let (ia, ib, n) = plane.axes();
        let mut start = [0.0; 8];
        start[ia] = 2.0;
        start[n] = 0.5;
        for (theta, b_sign) in [(90.0, 1.0), (-90.0, -1.0)] {
            let p = Path::arc_theta(plane, &start, [0.0, 0.0], theta).unwrap();
            let mut expect = [0.0; 8];
            expect[ib] = 2.0 * b_sign;
            expect[n] = 0.5;
            assert_axes_close(&p.end(), &expect, 1e-12);
            assert_axes_close(&p.point(p.length()), &expect, 1e-12);
            assert!(close(p.length(), PI, 1e-12));
            assert_eq!(p.is_ccw(), Some(theta > 0.0));
            let mut c3 = [0.0; 3];
            c3[n] = 0.5;
            check_on_circle(&p, c3, unit3(n), 2.0);
        }
    }
    // Handedness in world coordinates: XY +90° from +X reaches +Y (about +Z);
    // YZ +90° from +Y reaches +Z (about +X); ZX +90° from +Z reaches +X (about +Y).
    let p = Path::arc_theta(Plane::ZX, &ax(0.0, 0.0, 1.0), [0.0, 0.0], 90.0).unwrap();
    assert_axes_close(&p.end(), &ax(1.0, 0.0, 0.0), 1e-15);
    let p = Path::arc_theta(Plane::YZ, &ax(0.0, 1.0, 0.0), [0.0, 0.0], 90.0).unwrap();
    assert_axes_close(&p.end(), &ax(0.0, 0.0, 1.0), 1e-15);
    // A zero angle is a valid zero-length arc.
    let p = Path::arc_theta(Plane::XY, &ax(1.0, 0.0, 0.0), [0.0, 0.0], 0.0).unwrap();
    assert_eq!(p.length(), 0.0);
    assert_eq!(p.end(), ax(1.0, 0.0, 0.0));
}

#[test]
fn circle_returns_to_start() {
    for ccw in [true, false] {
        let start = [3.0, 4.0, 1.0, 9.0, 0.0, 0.0, 0.0, 0.0];
        let p = Path::circle(Plane::XY, &start, [0.0, 0.0], ccw, None).unwrap();
        assert_eq!(p.end(), start);
        assert!(close(p.length(), 10.0 * PI, 1e-12));
        assert_eq!(p.is_ccw(), Some(ccw));
        // A quarter of the way: rotate (3,4) by ±90° -> (−4,3) or (4,−3).
        let q = p.point(p.length() / 4.0);
        let e = if ccw { (-4.0, 3.0) } else { (4.0, -3.0) };
        assert!(close(q[0], e.0, 1e-12) && close(q[1], e.1, 1e-12));
        check_on_circle(&p, [0.0, 0.0, 1.0], [0.0, 0.0, 1.0], 5.0);
    }
    // With aux: aux moves over the full circle.
    let p = Path::circle(
        Plane::ZX,
        &ax(1.0, 0.0, 0.0),
        [0.0, 0.0],
        false,
        Some([4.0, 0.0, 0.0, 0.0, 0.0]),
    )
    .unwrap();
    assert_eq!(p.end(), [1.0, 0.0, 0.0, 4.0, 0.0, 0.0, 0.0, 0.0]);
    assert!(close(p.point(p.length() / 2.0)[3], 2.0, 1e-12));
}
