//! General motion: line, arc, circle and helix commands and their settings (user manual
//! §2.6.2; vendor header "General Motions"), plus the obsolete forms whose meaning is clear.

use super::{
    axis_mask, finite, finite8, queue, queue_curve, shape, shape_char, snapshot_outs, with_group,
};
use crate::error::{McclError, McclResult};
use crate::planner::{Path, Plane};
use crate::system;
use crate::vendor::consts as c;
use crate::vendor::{BYTE, DWORD, WORD};
use std::os::raw::{c_char, c_int};

use crate::config::range::time_ms;

pub(super) fn direction(byCirDir: BYTE) -> McclResult<bool> {
    match i32::from(byCirDir) {
        c::CIR_CW => Ok(false),
        c::CIR_CCW => Ok(true),
        _ => Err(McclError::Parameter),
    }
}

/// A feed speed from C: in the speed range, then at most the system maximum
/// (`MCC_SetSysMaxSpeed`).
pub(super) fn feed_speed(v: f64) -> McclResult<f64> {
    let v = crate::config::range::speed(v)?;
    Ok(system::config(|c| c.feed_speed(v)))
}

/// Acceleration shape of general motion: 'T' (trapezoid) or 'S' (S-curve).
#[no_mangle]
pub extern "C" fn MCC_SetAccType(cAccType: c_char, wGroupIndex: WORD) -> c_int {
    ffi_boundary! {
        let s = shape(cAccType)?;
        super::update_group(wGroupIndex, |g| g.settings.acc = s)
    }
}

/// The acceleration shape as its character code ('T' = 84, 'S' = 83).
#[no_mangle]
pub extern "C" fn MCC_GetAccType(wGroupIndex: WORD) -> c_int {
    ffi_boundary! {
        with_group(wGroupIndex, |g| {
            Ok(c_int::from(shape_char(g.settings.acc) as u8))
        })
    }
}

/// Deceleration shape of general motion: 'T' or 'S'.
#[no_mangle]
pub extern "C" fn MCC_SetDecType(cDecType: c_char, wGroupIndex: WORD) -> c_int {
    ffi_boundary! {
        let s = shape(cDecType)?;
        super::update_group(wGroupIndex, |g| g.settings.dec = s)
    }
}

/// The deceleration shape as its character code.
#[no_mangle]
pub extern "C" fn MCC_GetDecType(wGroupIndex: WORD) -> c_int {
    ffi_boundary! {
        with_group(wGroupIndex, |g| {
            Ok(c_int::from(shape_char(g.settings.dec) as u8))
        })
    }
}

/// Time to accelerate from 0 to the feed speed, ms (0..=2^32 − 1; default 300).
#[no_mangle]
pub extern "C" fn MCC_SetAccTime(dfAccTime: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! {
        let t = time_ms(dfAccTime)?;
        super::update_group(wGroupIndex, |g| g.settings.acc_ms = t)
    }
}

/// The acceleration time, ms.
#[no_mangle]
pub extern "C" fn MCC_GetAccTime(wGroupIndex: WORD) -> f64 {
    ffi_boundary! { with_group(wGroupIndex, |g| Ok(g.settings.acc_ms)) }
}

/// Time to decelerate from the feed speed to 0, ms (0..=2^32 − 1; default 300).
#[no_mangle]
pub extern "C" fn MCC_SetDecTime(dfDecTime: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! {
        let t = time_ms(dfDecTime)?;
        super::update_group(wGroupIndex, |g| g.settings.dec_ms = t)
    }
}

/// The deceleration time, ms.
#[no_mangle]
pub extern "C" fn MCC_GetDecTime(wGroupIndex: WORD) -> f64 {
    ffi_boundary! { with_group(wGroupIndex, |g| Ok(g.settings.dec_ms)) }
}

/// Feed speed of following general motion, UU/s (1e-6..=1e9). A speed above
/// `MCC_SetSysMaxSpeed` becomes that maximum. Returns the feed speed now in effect.
#[no_mangle]
pub extern "C" fn MCC_SetFeedSpeed(dfFeedSpeed: f64, wGroupIndex: WORD) -> f64 {
    ffi_boundary! {
        let v = feed_speed(dfFeedSpeed)?;
        with_group(wGroupIndex, |g| {
            g.settings.feed = v;
            Ok(v)
        })
    }
}

/// The feed speed of following general motion, UU/s.
#[no_mangle]
pub extern "C" fn MCC_GetFeedSpeed(wGroupIndex: WORD) -> f64 {
    ffi_boundary! { with_group(wGroupIndex, |g| Ok(g.settings.feed)) }
}

/// The current tangential speed (UU/s): X/Y/Z path speed, or the fastest aux axis.
#[no_mangle]
pub extern "C" fn MCC_GetCurFeedSpeed(wGroupIndex: WORD) -> f64 {
    ffi_boundary! { Ok(system::active()?.snapshot(wGroupIndex)?.path_speed) }
}

/// The current speed of every axis, UU/s (signed).
///
/// # Safety
/// Every pointer must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "C" fn MCC_GetSpeed(
    pdfVel0: *mut f64,
    pdfVel1: *mut f64,
    pdfVel2: *mut f64,
    pdfVel3: *mut f64,
    pdfVel4: *mut f64,
    pdfVel5: *mut f64,
    pdfVel6: *mut f64,
    pdfVel7: *mut f64,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let p = [
            pdfVel0, pdfVel1, pdfVel2, pdfVel3, pdfVel4, pdfVel5, pdfVel6, pdfVel7,
        ];
        // SAFETY: forwarded under this function's contract.
        unsafe { snapshot_outs(p, wGroupIndex, |s| s.vel) }
    }
}

/// Point-to-point speed ratio, percent of each axis's maximum safe speed
/// (0.01 <= r <= 100). Returns the ratio now in effect.
#[no_mangle]
pub extern "C" fn MCC_SetPtPSpeed(dfRatio: f64, wGroupIndex: WORD) -> f64 {
    ffi_boundary! {
        let r = crate::config::range::percent(dfRatio, 100.0)?;
        with_group(wGroupIndex, |g| {
            g.settings.ptp_ratio = r;
            Ok(r)
        })
    }
}

/// The point-to-point speed ratio, percent.
#[no_mangle]
pub extern "C" fn MCC_GetPtPSpeed(wGroupIndex: WORD) -> f64 {
    ffi_boundary! { with_group(wGroupIndex, |g| Ok(g.settings.ptp_ratio)) }
}

fn ptp(args: [f64; 8], g: WORD, m: DWORD, sync: bool) -> McclResult<c_int> {
    let args = finite8(args)?;
    let m = axis_mask(m)?;
    queue(g, |ctx| {
        ctx.ptp(ctx.resolve(&args, m), ctx.settings.ptp_ratio, sync)
    })
}

/// Point-to-point motion: every axis in the mask runs its own profile at the PtP ratio;
/// axes start together and need not arrive together. Returns the command index.
#[no_mangle]
pub extern "C" fn MCC_PtP(
    dfX0: f64,
    dfX1: f64,
    dfX2: f64,
    dfX3: f64,
    dfX4: f64,
    dfX5: f64,
    dfX6: f64,
    dfX7: f64,
    wGroupIndex: WORD,
    dwAxisMask: DWORD,
) -> c_int {
    ffi_boundary! { ptp(
        [dfX0, dfX1, dfX2, dfX3, dfX4, dfX5, dfX6, dfX7],
        wGroupIndex,
        dwAxisMask,
        false,
    ) }
}

/// Synchronised point-to-point motion: all axes start and end together, paced by the
/// slowest. Returns the command index.
#[no_mangle]
pub extern "C" fn MCC_SyncPtP(
    dfX0: f64,
    dfX1: f64,
    dfX2: f64,
    dfX3: f64,
    dfX4: f64,
    dfX5: f64,
    dfX6: f64,
    dfX7: f64,
    wGroupIndex: WORD,
    dwAxisMask: DWORD,
) -> c_int {
    ffi_boundary! { ptp(
        [dfX0, dfX1, dfX2, dfX3, dfX4, dfX5, dfX6, dfX7],
        wGroupIndex,
        dwAxisMask,
        true,
    ) }
}

fn one(axis: usize, v: f64) -> [f64; 8] {
    let mut a = [0.0; 8];
    a[axis] = v;
    a
}

/// Point-to-point motion of X alone.
#[no_mangle]
pub extern "C" fn MCC_PtPX(dfX: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { ptp(one(0, dfX), wGroupIndex, c::IMP_AXIS_X, false) }
}
/// Point-to-point motion of Y alone.
#[no_mangle]
pub extern "C" fn MCC_PtPY(dfY: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { ptp(one(1, dfY), wGroupIndex, c::IMP_AXIS_Y, false) }
}
/// Point-to-point motion of Z alone.
#[no_mangle]
pub extern "C" fn MCC_PtPZ(dfZ: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { ptp(one(2, dfZ), wGroupIndex, c::IMP_AXIS_Z, false) }
}
/// Point-to-point motion of U alone.
#[no_mangle]
pub extern "C" fn MCC_PtPU(dfU: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { ptp(one(3, dfU), wGroupIndex, c::IMP_AXIS_U, false) }
}
/// Point-to-point motion of V alone.
#[no_mangle]
pub extern "C" fn MCC_PtPV(dfV: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { ptp(one(4, dfV), wGroupIndex, c::IMP_AXIS_V, false) }
}
/// Point-to-point motion of W alone.
#[no_mangle]
pub extern "C" fn MCC_PtPW(dfW: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { ptp(one(5, dfW), wGroupIndex, c::IMP_AXIS_W, false) }
}
/// Point-to-point motion of A alone.
#[no_mangle]
pub extern "C" fn MCC_PtPA(dfA: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { ptp(one(6, dfA), wGroupIndex, c::IMP_AXIS_A, false) }
}
/// Point-to-point motion of B alone.
#[no_mangle]
pub extern "C" fn MCC_PtPB(dfB: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { ptp(one(7, dfB), wGroupIndex, c::IMP_AXIS_B, false) }
}

fn line(args: [f64; 8], g: WORD, m: DWORD) -> McclResult<c_int> {
    let args = finite8(args)?;
    let m = axis_mask(m)?;
    queue(g, |ctx| ctx.line(ctx.resolve(&args, m)))
}

/// Linear motion of the axes in the mask at the feed speed (only X/Y/Z count for the
/// path speed; U..B start and end with them). Returns the command index.
#[no_mangle]
pub extern "C" fn MCC_Line(
    dfX0: f64,
    dfX1: f64,
    dfX2: f64,
    dfX3: f64,
    dfX4: f64,
    dfX5: f64,
    dfX6: f64,
    dfX7: f64,
    wGroupIndex: WORD,
    dwAxisMask: DWORD,
) -> c_int {
    ffi_boundary! { line(
        [dfX0, dfX1, dfX2, dfX3, dfX4, dfX5, dfX6, dfX7],
        wGroupIndex,
        dwAxisMask,
    ) }
}

/// Linear motion of X alone (obsolete form).
#[no_mangle]
pub extern "C" fn MCC_LineX(dfX: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { line(one(0, dfX), wGroupIndex, c::IMP_AXIS_X) }
}
/// Linear motion of Y alone (obsolete form).
#[no_mangle]
pub extern "C" fn MCC_LineY(dfY: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { line(one(1, dfY), wGroupIndex, c::IMP_AXIS_Y) }
}
/// Linear motion of Z alone (obsolete form).
#[no_mangle]
pub extern "C" fn MCC_LineZ(dfZ: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { line(one(2, dfZ), wGroupIndex, c::IMP_AXIS_Z) }
}
/// Linear motion of U alone (obsolete form).
#[no_mangle]
pub extern "C" fn MCC_LineU(dfU: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { line(one(3, dfU), wGroupIndex, c::IMP_AXIS_U) }
}
/// Linear motion of V alone (obsolete form).
#[no_mangle]
pub extern "C" fn MCC_LineV(dfV: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { line(one(4, dfV), wGroupIndex, c::IMP_AXIS_V) }
}
/// Linear motion of W alone (obsolete form).
#[no_mangle]
pub extern "C" fn MCC_LineW(dfW: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { line(one(5, dfW), wGroupIndex, c::IMP_AXIS_W) }
}
/// Linear motion of A alone (obsolete form).
#[no_mangle]
pub extern "C" fn MCC_LineA(dfA: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { line(one(6, dfA), wGroupIndex, c::IMP_AXIS_A) }
}
/// Linear motion of B alone (obsolete form).
#[no_mangle]
pub extern "C" fn MCC_LineB(dfB: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { line(one(7, dfB), wGroupIndex, c::IMP_AXIS_B) }
}

/// Checks plane points (on `plane`'s two axes) and aux ends (U..B) against the position
/// range before any geometry is built from them.
fn check_plane(
    ctx: &crate::engine::command::Ctx<'_>,
    plane: Plane,
    pts: &[[f64; 2]],
    aux: Option<[f64; 5]>,
) -> Result<(), crate::planner::PlanError> {
    let (a, b, _) = plane.axes();
    let mut all: Vec<(usize, f64)> = pts.iter().flat_map(|p| [(a, p[0]), (b, p[1])]).collect();
    if let Some(x) = aux {
        all.extend(x.iter().enumerate().map(|(k, v)| (3 + k, *v)));
    }
    ctx.check_points(&all)
}

fn aux5(v: [f64; 5]) -> McclResult<[f64; 5]> {
    v.iter().try_for_each(|&x| finite(x).map(|_| ()))?;
    Ok(v)
}

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
        false,
    )
}

/// Arc in the XY plane from the current point through (dfRX0, dfRX1) to (dfX0, dfX1).
#[no_mangle]
pub extern "C" fn MCC_ArcXY(
    dfRX0: f64,
    dfRX1: f64,
    dfX0: f64,
    dfX1: f64,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! { arc(Plane::XY, [dfRX0, dfRX1], [dfX0, dfX1], None, wGroupIndex) }
}

/// Arc in the YZ plane through (dfRX1, dfRX2) to (dfX1, dfX2).
#[no_mangle]
pub extern "C" fn MCC_ArcYZ(
    dfRX1: f64,
    dfRX2: f64,
    dfX1: f64,
    dfX2: f64,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! { arc(Plane::YZ, [dfRX1, dfRX2], [dfX1, dfX2], None, wGroupIndex) }
}

/// Arc in the ZX plane through (dfRX2, dfRX0) to (dfX2, dfX0).
#[no_mangle]
pub extern "C" fn MCC_ArcZX(
    dfRX2: f64,
    dfRX0: f64,
    dfX2: f64,
    dfX0: f64,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! { arc(Plane::ZX, [dfRX2, dfRX0], [dfX2, dfX0], None, wGroupIndex) }
}

/// [`MCC_ArcXY`] with U..B moving linearly to the given ends.
#[no_mangle]
pub extern "C" fn MCC_ArcXY_Aux(
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
    ffi_boundary! { arc(
        Plane::XY,
        [dfRX0, dfRX1],
        [dfX0, dfX1],
        Some([dfX3, dfX4, dfX5, dfX6, dfX7]),
        wGroupIndex,
    ) }
}

/// [`MCC_ArcYZ`] with U..B moving linearly to the given ends.
#[no_mangle]
pub extern "C" fn MCC_ArcYZ_Aux(
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
    ffi_boundary! { arc(
        Plane::YZ,
        [dfRX1, dfRX2],
        [dfX1, dfX2],
        Some([dfX3, dfX4, dfX5, dfX6, dfX7]),
        wGroupIndex,
    ) }
}

/// [`MCC_ArcZX`] with U..B moving linearly to the given ends.
#[no_mangle]
pub extern "C" fn MCC_ArcZX_Aux(
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
    ffi_boundary! { arc(
        Plane::ZX,
        [dfRX2, dfRX0],
        [dfX2, dfX0],
        Some([dfX3, dfX4, dfX5, dfX6, dfX7]),
        wGroupIndex,
    ) }
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
        false,
    )
}

/// 3-D arc from the current point through (dfRX0..2) to (dfX0..2).
#[no_mangle]
pub extern "C" fn MCC_ArcXYZ(
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
pub extern "C" fn MCC_ArcXYZ_Aux(
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
    ffi_boundary! { arc_xyz(
        [dfRX0, dfRX1, dfRX2],
        [dfX0, dfX1, dfX2],
        Some([dfX3, dfX4, dfX5, dfX6, dfX7]),
        wGroupIndex,
    ) }
}

fn arc_theta(plane: Plane, cxy: [f64; 2], theta: f64, g: WORD) -> McclResult<c_int> {
    let cxy = [finite(cxy[0])?, finite(cxy[1])?];
    let theta = finite(theta)?;
    queue_curve(
        g,
        |ctx| {
            let c = ctx.resolve_plane(plane, cxy);
            check_plane(ctx, plane, &[c], None)?;
            Path::arc_theta(plane, &ctx.from, c, theta)
        },
        false,
    )
}

/// Arc around the center (dfCX, dfCY) by dfTheta degrees (> 0 counter-clockwise seen
/// from +Z).
#[no_mangle]
pub extern "C" fn MCC_ArcThetaXY(dfCX: f64, dfCY: f64, dfTheta: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { arc_theta(Plane::XY, [dfCX, dfCY], dfTheta, wGroupIndex) }
}

/// Arc around (dfCY, dfCZ) by dfTheta degrees (> 0 counter-clockwise seen from +X).
#[no_mangle]
pub extern "C" fn MCC_ArcThetaYZ(dfCY: f64, dfCZ: f64, dfTheta: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { arc_theta(Plane::YZ, [dfCY, dfCZ], dfTheta, wGroupIndex) }
}

/// Arc around (dfCZ, dfCX) by dfTheta degrees (> 0 counter-clockwise seen from +Y).
#[no_mangle]
pub extern "C" fn MCC_ArcThetaZX(dfCZ: f64, dfCX: f64, dfTheta: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { arc_theta(Plane::ZX, [dfCZ, dfCX], dfTheta, wGroupIndex) }
}

fn circle(
    plane: Plane,
    cxy: [f64; 2],
    aux: Option<[f64; 5]>,
    dir: BYTE,
    g: WORD,
) -> McclResult<c_int> {
    let cxy = [finite(cxy[0])?, finite(cxy[1])?];
    let ccw = direction(dir)?;
    let aux = aux.map(aux5).transpose()?;
    queue_curve(
        g,
        |ctx| {
            let aux = aux.map(|a| std::array::from_fn(|k| ctx.resolve_axis(3 + k, a[k])));
            let c = ctx.resolve_plane(plane, cxy);
            check_plane(ctx, plane, &[c], aux)?;
            Path::circle(plane, &ctx.from, c, ccw, aux)
        },
        false,
    )
}

/// Full circle around (dfCX, dfCY) in the XY plane, `CIR_CW` or `CIR_CCW` seen from +Z.
#[no_mangle]
pub extern "C" fn MCC_CircleXY(dfCX: f64, dfCY: f64, byCirDir: BYTE, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { circle(Plane::XY, [dfCX, dfCY], None, byCirDir, wGroupIndex) }
}

/// Full circle around (dfCY, dfCZ) in the YZ plane, seen from +X.
#[no_mangle]
pub extern "C" fn MCC_CircleYZ(dfCY: f64, dfCZ: f64, byCirDir: BYTE, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { circle(Plane::YZ, [dfCY, dfCZ], None, byCirDir, wGroupIndex) }
}

/// Full circle around (dfCZ, dfCX) in the ZX plane, seen from +Y.
#[no_mangle]
pub extern "C" fn MCC_CircleZX(dfCZ: f64, dfCX: f64, byCirDir: BYTE, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { circle(Plane::ZX, [dfCZ, dfCX], None, byCirDir, wGroupIndex) }
}

/// [`MCC_CircleXY`] with U..B moving linearly to the given ends.
#[no_mangle]
pub extern "C" fn MCC_CircleXY_Aux(
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
    ffi_boundary! { circle(
        Plane::XY,
        [dfCX, dfCY],
        Some([dfU, dfV, dfW, dfA, dfB]),
        byCirDir,
        wGroupIndex,
    ) }
}

/// [`MCC_CircleYZ`] with U..B moving linearly to the given ends.
#[no_mangle]
pub extern "C" fn MCC_CircleYZ_Aux(
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
    ffi_boundary! { circle(
        Plane::YZ,
        [dfCY, dfCZ],
        Some([dfU, dfV, dfW, dfA, dfB]),
        byCirDir,
        wGroupIndex,
    ) }
}

/// [`MCC_CircleZX`] with U..B moving linearly to the given ends.
#[no_mangle]
pub extern "C" fn MCC_CircleZX_Aux(
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
    ffi_boundary! { circle(
        Plane::ZX,
        [dfCZ, dfCX],
        Some([dfU, dfV, dfW, dfA, dfB]),
        byCirDir,
        wGroupIndex,
    ) }
}

fn helical(
    plane: Plane,
    cxy: [f64; 2],
    pitch: f64,
    theta: f64,
    aux: Option<[f64; 5]>,
    g: WORD,
) -> McclResult<c_int> {
    let cxy = [finite(cxy[0])?, finite(cxy[1])?];
    let (pitch, theta) = (finite(pitch)?, finite(theta)?);
    let aux = aux.map(aux5).transpose()?;
    queue_curve(
        g,
        |ctx| {
            let aux = aux.map(|a| std::array::from_fn(|k| ctx.resolve_axis(3 + k, a[k])));
            let c = ctx.resolve_plane(plane, cxy);
            check_plane(ctx, plane, &[c], aux)?;
            Path::helix(plane, &ctx.from, c, pitch, theta, aux)
        },
        true,
    )
}

/// Helix around (dfCX, dfCY) by dfTheta degrees (> 0 counter-clockwise); Z moves
/// dfPitch per full turn (pitch x theta / 360 in all).
#[no_mangle]
pub extern "C" fn MCC_HelicalXY_Z(
    dfCX: f64,
    dfCY: f64,
    dfPitch: f64,
    dfTheta: f64,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! { helical(Plane::XY, [dfCX, dfCY], dfPitch, dfTheta, None, wGroupIndex) }
}

/// Helix around (dfCY, dfCZ); X moves dfPitch per turn.
#[no_mangle]
pub extern "C" fn MCC_HelicalYZ_X(
    dfCY: f64,
    dfCZ: f64,
    dfPitch: f64,
    dfTheta: f64,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! { helical(Plane::YZ, [dfCY, dfCZ], dfPitch, dfTheta, None, wGroupIndex) }
}

/// Helix around (dfCZ, dfCX); Y moves dfPitch per turn.
#[no_mangle]
pub extern "C" fn MCC_HelicalZX_Y(
    dfCZ: f64,
    dfCX: f64,
    dfPitch: f64,
    dfTheta: f64,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! { helical(Plane::ZX, [dfCZ, dfCX], dfPitch, dfTheta, None, wGroupIndex) }
}

/// [`MCC_HelicalXY_Z`] with U..B moving linearly to the given ends.
#[no_mangle]
pub extern "C" fn MCC_HelicalXY_Z_Aux(
    dfCX: f64,
    dfCY: f64,
    dfPitch: f64,
    dfU: f64,
    dfV: f64,
    dfW: f64,
    dfA: f64,
    dfB: f64,
    dfTheta: f64,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! { helical(
        Plane::XY,
        [dfCX, dfCY],
        dfPitch,
        dfTheta,
        Some([dfU, dfV, dfW, dfA, dfB]),
        wGroupIndex,
    ) }
}

/// [`MCC_HelicalYZ_X`] with U..B moving linearly to the given ends.
#[no_mangle]
pub extern "C" fn MCC_HelicalYZ_X_Aux(
    dfCY: f64,
    dfCZ: f64,
    dfPitch: f64,
    dfU: f64,
    dfV: f64,
    dfW: f64,
    dfA: f64,
    dfB: f64,
    dfTheta: f64,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! { helical(
        Plane::YZ,
        [dfCY, dfCZ],
        dfPitch,
        dfTheta,
        Some([dfU, dfV, dfW, dfA, dfB]),
        wGroupIndex,
    ) }
}

/// [`MCC_HelicalZX_Y`] with U..B moving linearly to the given ends.
#[no_mangle]
pub extern "C" fn MCC_HelicalZX_Y_Aux(
    dfCZ: f64,
    dfCX: f64,
    dfPitch: f64,
    dfU: f64,
    dfV: f64,
    dfW: f64,
    dfA: f64,
    dfB: f64,
    dfTheta: f64,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! { helical(
        Plane::ZX,
        [dfCZ, dfCX],
        dfPitch,
        dfTheta,
        Some([dfU, dfV, dfW, dfA, dfB]),
        wGroupIndex,
    ) }
}

fn helica(
    plane: Plane,
    cxy: [f64; 2],
    pos: f64,
    pitch: f64,
    dir: BYTE,
    g: WORD,
) -> McclResult<c_int> {
    let cxy = [finite(cxy[0])?, finite(cxy[1])?];
    let (pos, pitch) = (finite(pos)?, finite(pitch)?);
    let ccw = direction(dir)?;
    let n = plane.axes().2;
    queue_curve(
        g,
        |ctx| {
            let (c, to) = (ctx.resolve_plane(plane, cxy), ctx.resolve_axis(n, pos));
            check_plane(ctx, plane, &[c], None)?;
            ctx.check_points(&[(n, to)])?;
            Path::helix_to(plane, &ctx.from, c, to, pitch, ccw, None)
        },
        true,
    )
}

/// Obsolete helix: around (dfCX, dfCY) in direction byCirDir until Z reaches dfPos,
/// rising dfPitch per turn.
#[no_mangle]
pub extern "C" fn MCC_HelicaXY_Z(
    dfCX: f64,
    dfCY: f64,
    dfPos: f64,
    dfPitch: f64,
    byCirDir: BYTE,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! { helica(
        Plane::XY,
        [dfCX, dfCY],
        dfPos,
        dfPitch,
        byCirDir,
        wGroupIndex,
    ) }
}

/// Obsolete helix around (dfCY, dfCZ) until X reaches dfPos.
#[no_mangle]
pub extern "C" fn MCC_HelicaYZ_X(
    dfCY: f64,
    dfCZ: f64,
    dfPos: f64,
    dfPitch: f64,
    byCirDir: BYTE,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! { helica(
        Plane::YZ,
        [dfCY, dfCZ],
        dfPos,
        dfPitch,
        byCirDir,
        wGroupIndex,
    ) }
}

/// Obsolete helix around (dfCZ, dfCX) until Y reaches dfPos.
#[no_mangle]
pub extern "C" fn MCC_HelicaZX_Y(
    dfCZ: f64,
    dfCX: f64,
    dfPos: f64,
    dfPitch: f64,
    byCirDir: BYTE,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! { helica(
        Plane::ZX,
        [dfCZ, dfCX],
        dfPos,
        dfPitch,
        byCirDir,
        wGroupIndex,
    ) }
}
