//! Arcs and circles: the arc through a point to an end (in a plane, or in space), the arc
//! about a center by an angle, and the full circle, each with its form that moves U..B
//! along.

use super::plane_curve::{aux5, check_plane, queue_about, About};
use crate::engine::command::Curve;
use crate::error::McclResult;
use crate::ffi::{direction, finite, queue_curve};
use crate::planner::{Path, Plane};
use crate::vendor::{BYTE, WORD};
use std::os::raw::c_int;

fn arc(
    plane: Plane,
    r: [f64; 2],
    e: [f64; 2],
    aux: Option<[f64; 5]>,
    g: WORD,
) -> McclResult<c_int> {
    let (r, e) = (
        [finite(r[0])?, finite(r[1])?],
        [finite(e[0])?, finite(e[1])?],
    );
    let aux = aux.map(aux5).transpose()?;
    queue_curve(
        g,
        |ctx| {
            let aux = aux.map(|a| std::array::from_fn(|k| ctx.resolve_axis(3 + k, a[k])));
            let (r, e) = (ctx.resolve_plane(plane, r), ctx.resolve_plane(plane, e));
            check_plane(ctx, plane, &[r, e], aux)?;
            Path::arc_3pt(plane, &ctx.from, r, e, aux)
        },
        Curve::ThreePoint,
    )
}

/// Arc in the XY plane from the current point through (dfRX0, dfRX1) to (dfX0, dfX1).
#[no_mangle]
pub extern "system" fn MCC_ArcXY(
    dfRX0: f64,
    dfRX1: f64,
    dfX0: f64,
    dfX1: f64,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! { arc(Plane::XY, [dfRX0, dfRX1], [dfX0, dfX1], None, wGroupIndex) }
}

/// [`MCC_ArcXY`] with U..B moving linearly to the given ends.
#[no_mangle]
pub extern "system" fn MCC_ArcXY_Aux(
    dfRX0: f64,
    dfRX1: f64,
    dfX0: f64,
    dfX1: f64,
    dfX3: f64,
    dfX4: f64,
    dfX5: f64,
    dfX6: f64,
    dfX7: f64,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let aux = Some([dfX3, dfX4, dfX5, dfX6, dfX7]);
        arc(Plane::XY, [dfRX0, dfRX1], [dfX0, dfX1], aux, wGroupIndex)
    }
}

/// Arc in the YZ plane through (dfRX1, dfRX2) to (dfX1, dfX2).
#[no_mangle]
pub extern "system" fn MCC_ArcYZ(
    dfRX1: f64,
    dfRX2: f64,
    dfX1: f64,
    dfX2: f64,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! { arc(Plane::YZ, [dfRX1, dfRX2], [dfX1, dfX2], None, wGroupIndex) }
}

/// [`MCC_ArcYZ`] with U..B moving linearly to the given ends.
#[no_mangle]
pub extern "system" fn MCC_ArcYZ_Aux(
    dfRX1: f64,
    dfRX2: f64,
    dfX1: f64,
    dfX2: f64,
    dfX3: f64,
    dfX4: f64,
    dfX5: f64,
    dfX6: f64,
    dfX7: f64,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let aux = Some([dfX3, dfX4, dfX5, dfX6, dfX7]);
        arc(Plane::YZ, [dfRX1, dfRX2], [dfX1, dfX2], aux, wGroupIndex)
    }
}

/// Arc in the ZX plane through (dfRX2, dfRX0) to (dfX2, dfX0).
#[no_mangle]
pub extern "system" fn MCC_ArcZX(
    dfRX2: f64,
    dfRX0: f64,
    dfX2: f64,
    dfX0: f64,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! { arc(Plane::ZX, [dfRX2, dfRX0], [dfX2, dfX0], None, wGroupIndex) }
}

/// [`MCC_ArcZX`] with U..B moving linearly to the given ends.
#[no_mangle]
pub extern "system" fn MCC_ArcZX_Aux(
    dfRX2: f64,
    dfRX0: f64,
    dfX2: f64,
    dfX0: f64,
    dfX3: f64,
    dfX4: f64,
    dfX5: f64,
    dfX6: f64,
    dfX7: f64,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let aux = Some([dfX3, dfX4, dfX5, dfX6, dfX7]);
        arc(Plane::ZX, [dfRX2, dfRX0], [dfX2, dfX0], aux, wGroupIndex)
    }
}

fn arc_xyz(r: [f64; 3], e: [f64; 3], aux: Option<[f64; 5]>, g: WORD) -> McclResult<c_int> {
    for v in r.iter().chain(e.iter()) {
        finite(*v)?;
    }
    let aux = aux.map(aux5).transpose()?;
    queue_curve(
        g,
        |ctx| {
            let rr: [f64; 3] = std::array::from_fn(|i| ctx.resolve_axis(i, r[i]));
            let ee: [f64; 3] = std::array::from_fn(|i| ctx.resolve_axis(i, e[i]));
            let aux = aux.map(|a| std::array::from_fn(|k| ctx.resolve_axis(3 + k, a[k])));
            let pts: Vec<(usize, f64)> = (0..3).flat_map(|i| [(i, rr[i]), (i, ee[i])]).collect();
            ctx.check_points(&pts)?;
            check_plane(ctx, Plane::XY, &[], aux)?;
            Path::arc_3pt_xyz(&ctx.from, rr, ee, aux)
        },
        Curve::ThreePoint,
    )
}

/// 3-D arc from the current point through (dfRX0..2) to (dfX0..2).
#[no_mangle]
pub extern "system" fn MCC_ArcXYZ(
    dfRX0: f64,
    dfRX1: f64,
    dfRX2: f64,
    dfX0: f64,
    dfX1: f64,
    dfX2: f64,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! { arc_xyz([dfRX0, dfRX1, dfRX2], [dfX0, dfX1, dfX2], None, wGroupIndex) }
}

/// [`MCC_ArcXYZ`] with U..B moving linearly to the given ends.
#[no_mangle]
pub extern "system" fn MCC_ArcXYZ_Aux(
    dfRX0: f64,
    dfRX1: f64,
    dfRX2: f64,
    dfX0: f64,
    dfX1: f64,
    dfX2: f64,
    dfX3: f64,
    dfX4: f64,
    dfX5: f64,
    dfX6: f64,
    dfX7: f64,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let aux = Some([dfX3, dfX4, dfX5, dfX6, dfX7]);
        arc_xyz([dfRX0, dfRX1, dfRX2], [dfX0, dfX1, dfX2], aux, wGroupIndex)
    }
}

fn arc_theta(plane: Plane, cxy: [f64; 2], theta: f64, g: WORD) -> McclResult<c_int> {
    let theta = finite(theta)?;
    let at = About {
        plane,
        c: cxy,
        aux: None,
    };
    queue_about(at, Curve::Arc, g, |ctx, c, _| {
        Path::arc_theta(plane, &ctx.from, c, theta)
    })
}

/// Arc around the center (dfCX, dfCY) by dfTheta degrees (> 0 counter-clockwise seen
/// from +Z).
#[no_mangle]
pub extern "system" fn MCC_ArcThetaXY(
    dfCX: f64,
    dfCY: f64,
    dfTheta: f64,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! { arc_theta(Plane::XY, [dfCX, dfCY], dfTheta, wGroupIndex) }
}

/// Arc around (dfCY, dfCZ) by dfTheta degrees (> 0 counter-clockwise seen from +X).
#[no_mangle]
pub extern "system" fn MCC_ArcThetaYZ(
    dfCY: f64,
    dfCZ: f64,
    dfTheta: f64,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! { arc_theta(Plane::YZ, [dfCY, dfCZ], dfTheta, wGroupIndex) }
}

/// Arc around (dfCZ, dfCX) by dfTheta degrees (> 0 counter-clockwise seen from +Y).
#[no_mangle]
pub extern "system" fn MCC_ArcThetaZX(
    dfCZ: f64,
    dfCX: f64,
    dfTheta: f64,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! { arc_theta(Plane::ZX, [dfCZ, dfCX], dfTheta, wGroupIndex) }
}

fn circle(at: About, dir: BYTE, g: WORD) -> McclResult<c_int> {
    let ccw = direction(dir)?;
    queue_about(at, Curve::Arc, g, |ctx, c, aux| {
        Path::circle(at.plane, &ctx.from, c, ccw, aux)
    })
}

/// Full circle around (dfCX, dfCY) in the XY plane, `CIR_CW` or `CIR_CCW` seen from +Z.
#[no_mangle]
pub extern "system" fn MCC_CircleXY(
    dfCX: f64,
    dfCY: f64,
    byCirDir: BYTE,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let at = About::new(Plane::XY, [dfCX, dfCY], None);
        circle(at, byCirDir, wGroupIndex)
    }
}

/// [`MCC_CircleXY`] with U..B moving linearly to the given ends.
#[no_mangle]
pub extern "system" fn MCC_CircleXY_Aux(
    dfCX: f64,
    dfCY: f64,
    dfU: f64,
    dfV: f64,
    dfW: f64,
    dfA: f64,
    dfB: f64,
    byCirDir: BYTE,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let aux = Some([dfU, dfV, dfW, dfA, dfB]);
        let at = About::new(Plane::XY, [dfCX, dfCY], aux);
        circle(at, byCirDir, wGroupIndex)
    }
}

/// Full circle around (dfCY, dfCZ) in the YZ plane, seen from +X.
#[no_mangle]
pub extern "system" fn MCC_CircleYZ(
    dfCY: f64,
    dfCZ: f64,
    byCirDir: BYTE,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let at = About::new(Plane::YZ, [dfCY, dfCZ], None);
        circle(at, byCirDir, wGroupIndex)
    }
}

/// [`MCC_CircleYZ`] with U..B moving linearly to the given ends.
#[no_mangle]
pub extern "system" fn MCC_CircleYZ_Aux(
    dfCY: f64,
    dfCZ: f64,
    dfU: f64,
    dfV: f64,
    dfW: f64,
    dfA: f64,
    dfB: f64,
    byCirDir: BYTE,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let aux = Some([dfU, dfV, dfW, dfA, dfB]);
        let at = About::new(Plane::YZ, [dfCY, dfCZ], aux);
        circle(at, byCirDir, wGroupIndex)
    }
}

/// Full circle around (dfCZ, dfCX) in the ZX plane, seen from +Y.
#[no_mangle]
pub extern "system" fn MCC_CircleZX(
    dfCZ: f64,
    dfCX: f64,
    byCirDir: BYTE,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let at = About::new(Plane::ZX, [dfCZ, dfCX], None);
        circle(at, byCirDir, wGroupIndex)
    }
}

/// [`MCC_CircleZX`] with U..B moving linearly to the given ends.
#[no_mangle]
pub extern "system" fn MCC_CircleZX_Aux(
    dfCZ: f64,
    dfCX: f64,
    dfU: f64,
    dfV: f64,
    dfW: f64,
    dfA: f64,
    dfB: f64,
    byCirDir: BYTE,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let aux = Some([dfU, dfV, dfW, dfA, dfB]);
        let at = About::new(Plane::ZX, [dfCZ, dfCX], aux);
        circle(at, byCirDir, wGroupIndex)
    }
}
