//! General motion: line, arc, circle and helix commands and their settings (user manual
//! §2.6.2; vendor header "General Motions"), plus the obsolete forms whose meaning is clear.

use super::{
    axis_mask, direction, finite, finite2, finite8, queue, queue_curve, read_published, shape,
    shape_code, with_group, write_outs,
};
use crate::engine::command::Curve;
use crate::error::{McclError, McclResult};
use crate::planner::{Axes, Path, Plane};
use crate::system;
use crate::vendor::consts as c;
use crate::vendor::{BYTE, DWORD, WORD};
use std::os::raw::{c_char, c_int};

use crate::config::range::time_ms;

/// A feed speed from C, as the vendor's library takes it: its size (−1 is 1), not 0, at
/// most the speed range's top, then at most the system maximum (`MCC_SetSysMaxSpeed`).
pub(super) fn feed_speed(v: f64) -> McclResult<f64> {
    let v = v.abs();
    // NaN fails both comparisons: refused too.
    if v.is_nan() || v <= 0.0 || v > crate::config::range::MAX_SPEED {
        return Err(McclError::Parameter);
    }
    Ok(system::config(|c| c.feed_speed(v)))
}

/// The ratio of point-to-point speed: a percentage in (0, 100].
fn ptp_ratio(r: f64) -> McclResult<f64> {
    if r > 0.0 && r <= 100.0 {
        Ok(r)
    } else {
        Err(McclError::Parameter)
    }
}

/// An acc or dec time from C, ms: in the time range, kept in whole ms (rounded up) as the
/// vendor's library keeps it.
fn ramp_ms(t: f64) -> McclResult<f64> {
    Ok(crate::planner::whole_ms(time_ms(t)?))
}

/// Acceleration shape of general motion: 'T' (trapezoid) or 'S' (S-curve).
#[no_mangle]
pub extern "system" fn MCC_SetAccType(cAccType: c_char, wGroupIndex: WORD) -> c_int {
    ffi_boundary! {
        let v = shape(cAccType)?;
        super::update_group(wGroupIndex, |g| g.settings.acc = v)
    }
}

/// Deceleration shape of general motion: 'T' or 'S'.
#[no_mangle]
pub extern "system" fn MCC_SetDecType(cDecType: c_char, wGroupIndex: WORD) -> c_int {
    ffi_boundary! {
        let v = shape(cDecType)?;
        super::update_group(wGroupIndex, |g| g.settings.dec = v)
    }
}

/// Time to accelerate from 0 to the feed speed, ms (0..=2^32 − 1; default 300).
/// Kept in whole ms, rounded up.
#[no_mangle]
pub extern "system" fn MCC_SetAccTime(dfAccTime: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! {
        let v = ramp_ms(dfAccTime)?;
        super::update_group(wGroupIndex, |g| g.settings.acc_ms = v)
    }
}

/// Time to decelerate from the feed speed to 0, ms (0..=2^32 − 1; default 300), kept
/// in whole ms, rounded up.
#[no_mangle]
pub extern "system" fn MCC_SetDecTime(dfDecTime: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! {
        let v = ramp_ms(dfDecTime)?;
        super::update_group(wGroupIndex, |g| g.settings.dec_ms = v)
    }
}

/// Feed speed of following general motion, UU/s (> 0; a negative one counts by its
/// size). A speed above `MCC_SetSysMaxSpeed` becomes that maximum. Returns the feed
/// speed now in effect.
#[no_mangle]
pub extern "system" fn MCC_SetFeedSpeed(dfFeedSpeed: f64, wGroupIndex: WORD) -> f64 {
    ffi_boundary! {
        let v = feed_speed(dfFeedSpeed)?;
        with_group(wGroupIndex, |g| {
            g.settings.feed = v;
            Ok(v)
        })
    }
}

/// Point-to-point speed ratio, percent of each axis's maximum safe speed
/// (0 < r <= 100). Returns the ratio now in effect.
#[no_mangle]
pub extern "system" fn MCC_SetPtPSpeed(dfRatio: f64, wGroupIndex: WORD) -> f64 {
    ffi_boundary! {
        let v = ptp_ratio(dfRatio)?;
        with_group(wGroupIndex, |g| {
            g.settings.ptp_ratio = v;
            Ok(v)
        })
    }
}

/// The acceleration shape: 0 'T', 1 'S' (as the vendor's library answers).
#[no_mangle]
pub extern "system" fn MCC_GetAccType(wGroupIndex: WORD) -> c_int {
    ffi_boundary! { with_group(wGroupIndex, |g| Ok(shape_code(g.settings.acc))) }
}

/// The deceleration shape: 0 'T', 1 'S'.
#[no_mangle]
pub extern "system" fn MCC_GetDecType(wGroupIndex: WORD) -> c_int {
    ffi_boundary! { with_group(wGroupIndex, |g| Ok(shape_code(g.settings.dec))) }
}

/// The acceleration time, ms.
#[no_mangle]
pub extern "system" fn MCC_GetAccTime(wGroupIndex: WORD) -> f64 {
    ffi_boundary! { with_group(wGroupIndex, |g| Ok(g.settings.acc_ms)) }
}

/// The deceleration time, ms.
#[no_mangle]
pub extern "system" fn MCC_GetDecTime(wGroupIndex: WORD) -> f64 {
    ffi_boundary! { with_group(wGroupIndex, |g| Ok(g.settings.dec_ms)) }
}

/// The feed speed of following general motion, UU/s.
#[no_mangle]
pub extern "system" fn MCC_GetFeedSpeed(wGroupIndex: WORD) -> f64 {
    ffi_boundary! { with_group(wGroupIndex, |g| Ok(g.settings.feed)) }
}

/// The point-to-point speed ratio, percent.
#[no_mangle]
pub extern "system" fn MCC_GetPtPSpeed(wGroupIndex: WORD) -> f64 {
    ffi_boundary! { with_group(wGroupIndex, |g| Ok(g.settings.ptp_ratio)) }
}

/// The current tangential speed (UU/s): X/Y/Z path speed, or the fastest aux axis.
#[no_mangle]
pub extern "system" fn MCC_GetCurFeedSpeed(wGroupIndex: WORD) -> f64 {
    ffi_boundary! { read_published(wGroupIndex, |p| p.load_motion().path_speed()) }
}

/// The current speed of every axis, UU/s (signed).
///
/// # Safety
/// Every pointer must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetSpeed(
    p0: *mut f64,
    p1: *mut f64,
    p2: *mut f64,
    p3: *mut f64,
    p4: *mut f64,
    p5: *mut f64,
    p6: *mut f64,
    p7: *mut f64,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let p = [p0, p1, p2, p3, p4, p5, p6, p7];
        // SAFETY: forwarded under this function's contract.
        unsafe { write_outs(p, || read_published(wGroupIndex, |p| p.load_motion().vel)) }
    }
}

fn ptp(args: [f64; 8], g: WORD, m: DWORD, sync: bool) -> McclResult<c_int> {
    let args = finite8(args)?;
    let m = axis_mask(m)?;
    // A kinematic group's PtP moves its joints.
    if let Some(i) = super::kinematics::joint_ptp(args, g, m, sync)? {
        return Ok(i);
    }
    queue(g, |ctx| {
        ctx.ptp(ctx.resolve(&args, m), ctx.settings.ptp_ratio, sync)
    })
}

fn one(axis: usize, v: f64) -> [f64; 8] {
    let mut a = [0.0; 8];
    a[axis] = v;
    a
}

fn line(args: [f64; 8], g: WORD, m: DWORD) -> McclResult<c_int> {
    let args = finite8(args)?;
    let m = axis_mask(m)?;
    queue(g, |ctx| ctx.line(ctx.resolve(&args, m)))
}

/// Point-to-point motion: every axis in the mask runs its own profile at the PtP ratio;
/// axes start together and need not arrive together. Returns the command index.
#[no_mangle]
pub extern "system" fn MCC_PtP(
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
    ffi_boundary! {
        let args = [dfX0, dfX1, dfX2, dfX3, dfX4, dfX5, dfX6, dfX7];
        ptp(args, wGroupIndex, dwAxisMask, false)
    }
}

/// Synchronised point-to-point motion: all axes start and end together, paced by the
/// slowest. Returns the command index.
#[no_mangle]
pub extern "system" fn MCC_SyncPtP(
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
    ffi_boundary! {
        let args = [dfX0, dfX1, dfX2, dfX3, dfX4, dfX5, dfX6, dfX7];
        ptp(args, wGroupIndex, dwAxisMask, true)
    }
}

/// Linear motion of the axes in the mask at the feed speed (only X/Y/Z count for the
/// path speed; U..B start and end with them). Returns the command index.
#[no_mangle]
pub extern "system" fn MCC_Line(
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
    ffi_boundary! {
        let args = [dfX0, dfX1, dfX2, dfX3, dfX4, dfX5, dfX6, dfX7];
        line(args, wGroupIndex, dwAxisMask)
    }
}

/// Point-to-point motion of X alone.
#[no_mangle]
pub extern "system" fn MCC_PtPX(dfX: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { ptp(one(0, dfX), wGroupIndex, c::IMP_AXIS_X, false) }
}

/// Point-to-point motion of Y alone.
#[no_mangle]
pub extern "system" fn MCC_PtPY(dfY: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { ptp(one(1, dfY), wGroupIndex, c::IMP_AXIS_Y, false) }
}

/// Point-to-point motion of Z alone.
#[no_mangle]
pub extern "system" fn MCC_PtPZ(dfZ: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { ptp(one(2, dfZ), wGroupIndex, c::IMP_AXIS_Z, false) }
}

/// Point-to-point motion of U alone.
#[no_mangle]
pub extern "system" fn MCC_PtPU(dfU: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { ptp(one(3, dfU), wGroupIndex, c::IMP_AXIS_U, false) }
}

/// Point-to-point motion of V alone.
#[no_mangle]
pub extern "system" fn MCC_PtPV(dfV: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { ptp(one(4, dfV), wGroupIndex, c::IMP_AXIS_V, false) }
}

/// Point-to-point motion of W alone.
#[no_mangle]
pub extern "system" fn MCC_PtPW(dfW: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { ptp(one(5, dfW), wGroupIndex, c::IMP_AXIS_W, false) }
}

/// Point-to-point motion of A alone.
#[no_mangle]
pub extern "system" fn MCC_PtPA(dfA: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { ptp(one(6, dfA), wGroupIndex, c::IMP_AXIS_A, false) }
}

/// Point-to-point motion of B alone.
#[no_mangle]
pub extern "system" fn MCC_PtPB(dfB: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { ptp(one(7, dfB), wGroupIndex, c::IMP_AXIS_B, false) }
}

/// Linear motion of X alone (obsolete form).
#[no_mangle]
pub extern "system" fn MCC_LineX(dfX: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { line(one(0, dfX), wGroupIndex, c::IMP_AXIS_X) }
}

/// Linear motion of Y alone (obsolete form).
#[no_mangle]
pub extern "system" fn MCC_LineY(dfY: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { line(one(1, dfY), wGroupIndex, c::IMP_AXIS_Y) }
}

/// Linear motion of Z alone (obsolete form).
#[no_mangle]
pub extern "system" fn MCC_LineZ(dfZ: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { line(one(2, dfZ), wGroupIndex, c::IMP_AXIS_Z) }
}

/// Linear motion of U alone (obsolete form).
#[no_mangle]
pub extern "system" fn MCC_LineU(dfU: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { line(one(3, dfU), wGroupIndex, c::IMP_AXIS_U) }
}

/// Linear motion of V alone (obsolete form).
#[no_mangle]
pub extern "system" fn MCC_LineV(dfV: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { line(one(4, dfV), wGroupIndex, c::IMP_AXIS_V) }
}

/// Linear motion of W alone (obsolete form).
#[no_mangle]
pub extern "system" fn MCC_LineW(dfW: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { line(one(5, dfW), wGroupIndex, c::IMP_AXIS_W) }
}

/// Linear motion of A alone (obsolete form).
#[no_mangle]
pub extern "system" fn MCC_LineA(dfA: f64, wGroupIndex: WORD) -> c_int {
    ffi_boundary! { line(one(6, dfA), wGroupIndex, c::IMP_AXIS_A) }
}

/// Linear motion of B alone (obsolete form).
#[no_mangle]
pub extern "system" fn MCC_LineB(dfB: f64, wGroupIndex: WORD) -> c_int {
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

/// A curve about a center `c` of a plane (arc by an angle, circle, helix, cone), with
/// the U..B ends `aux` moving linearly along, as C passed them.
#[derive(Clone, Copy)]
pub(super) struct About {
    pub plane: Plane,
    pub c: [f64; 2],
    pub aux: Option<[f64; 5]>,
}

impl About {
    /// About the center `c` of `plane`, with the U..B ends `aux` (`None`: U..B stay).
    pub(super) fn new(plane: Plane, c: [f64; 2], aux: Option<[f64; 5]>) -> Self {
        About { plane, c, aux }
    }
}

/// Queues the curve `build` makes about `at` (`helix`: reported as a helix): the center
/// and the ends are checked finite, resolved against the group (absolute or relative)
/// and checked against the position range before `build` runs with them.
pub(super) fn queue_about(
    at: About,
    kind: Curve,
    g: WORD,
    build: impl FnOnce(
        &crate::engine::command::Ctx<'_>,
        [f64; 2],
        Option<[f64; 5]>,
    ) -> Result<Path, crate::planner::PlanError>,
) -> McclResult<c_int> {
    let cxy = finite2(at.c)?;
    let aux = at.aux.map(aux5).transpose()?;
    let plan = |ctx: &crate::engine::command::Ctx<'_>| {
        let aux = aux.map(|a| std::array::from_fn(|k| ctx.resolve_axis(3 + k, a[k])));
        let c = ctx.resolve_plane(at.plane, cxy);
        check_plane(ctx, at.plane, &[c], aux)?;
        build(ctx, c, aux)
    };
    queue_curve(g, plan, kind)
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

fn helical(at: About, pitch: f64, theta: f64, g: WORD) -> McclResult<c_int> {
    let (pitch, theta) = (finite(pitch)?, finite(theta)?);
    queue_about(at, Curve::Helix, g, |ctx, c, aux| {
        Path::helix(at.plane, &ctx.from, c, pitch, theta, aux)
    })
}

/// Helix around (dfCX, dfCY) by dfTheta degrees (> 0 counter-clockwise); Z moves
/// dfPitch per full turn (pitch x theta / 360 in all).
#[no_mangle]
pub extern "system" fn MCC_HelicalXY_Z(
    dfCX: f64,
    dfCY: f64,
    dfPitch: f64,
    dfTheta: f64,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let at = About::new(Plane::XY, [dfCX, dfCY], None);
        helical(at, dfPitch, dfTheta, wGroupIndex)
    }
}

/// [`MCC_HelicalXY_Z`] with U..B moving linearly to the given ends.
#[no_mangle]
pub extern "system" fn MCC_HelicalXY_Z_Aux(
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
    ffi_boundary! {
        let aux = Some([dfU, dfV, dfW, dfA, dfB]);
        let at = About::new(Plane::XY, [dfCX, dfCY], aux);
        helical(at, dfPitch, dfTheta, wGroupIndex)
    }
}

/// Helix around (dfCY, dfCZ); X moves dfPitch per turn.
#[no_mangle]
pub extern "system" fn MCC_HelicalYZ_X(
    dfCY: f64,
    dfCZ: f64,
    dfPitch: f64,
    dfTheta: f64,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let at = About::new(Plane::YZ, [dfCY, dfCZ], None);
        helical(at, dfPitch, dfTheta, wGroupIndex)
    }
}

/// [`MCC_HelicalYZ_X`] with U..B moving linearly to the given ends.
#[no_mangle]
pub extern "system" fn MCC_HelicalYZ_X_Aux(
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
    ffi_boundary! {
        let aux = Some([dfU, dfV, dfW, dfA, dfB]);
        let at = About::new(Plane::YZ, [dfCY, dfCZ], aux);
        helical(at, dfPitch, dfTheta, wGroupIndex)
    }
}

/// Helix around (dfCZ, dfCX); Y moves dfPitch per turn.
#[no_mangle]
pub extern "system" fn MCC_HelicalZX_Y(
    dfCZ: f64,
    dfCX: f64,
    dfPitch: f64,
    dfTheta: f64,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let at = About::new(Plane::ZX, [dfCZ, dfCX], None);
        helical(at, dfPitch, dfTheta, wGroupIndex)
    }
}

/// [`MCC_HelicalZX_Y`] with U..B moving linearly to the given ends.
#[no_mangle]
pub extern "system" fn MCC_HelicalZX_Y_Aux(
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
    ffi_boundary! {
        let aux = Some([dfU, dfV, dfW, dfA, dfB]);
        let at = About::new(Plane::ZX, [dfCZ, dfCX], aux);
        helical(at, dfPitch, dfTheta, wGroupIndex)
    }
}

/// A spiral about `at` until the plane's third axis reaches `pos`, `pitch` per turn in
/// direction `dir` (the obsolete helix, the cone).
#[derive(Clone, Copy)]
pub(super) struct SpiralTo {
    pub at: About,
    pub pos: f64,
    pub pitch: f64,
    pub dir: BYTE,
}

impl SpiralTo {
    /// About the center `c` of `plane` (U..B stay) until its third axis reaches `pos`,
    /// `pitch` per turn in direction `dir`.
    pub(super) fn new(plane: Plane, c: [f64; 2], pos: f64, pitch: f64, dir: BYTE) -> Self {
        let at = About::new(plane, c, None);
        SpiralTo {
            at,
            pos,
            pitch,
            dir,
        }
    }
}

/// Queues the spiral `build(from, center, end of the third axis, pitch, counter-clockwise)`
/// makes, its arguments checked, resolved and range-checked first.
pub(super) fn queue_spiral(
    s: SpiralTo,
    g: WORD,
    build: impl FnOnce(&Axes, [f64; 2], f64, f64, bool) -> Result<Path, crate::planner::PlanError>,
) -> McclResult<c_int> {
    let (pos, pitch) = (finite(s.pos)?, finite(s.pitch)?);
    let ccw = direction(s.dir)?;
    queue_about(s.at, Curve::Helix, g, |ctx, c, _| {
        let n = s.at.plane.axes().2;
        let to = ctx.resolve_axis(n, pos);
        ctx.check_points(&[(n, to)])?;
        build(&ctx.from, c, to, pitch, ccw)
    })
}

fn helica(s: SpiralTo, g: WORD) -> McclResult<c_int> {
    queue_spiral(s, g, |from, c, to, pitch, ccw| {
        Path::helix_to(s.at.plane, from, c, to, pitch, ccw, None)
    })
}

/// Obsolete helix: around (dfCX, dfCY) in direction byCirDir until Z reaches dfPos,
/// rising dfPitch per turn.
#[no_mangle]
pub extern "system" fn MCC_HelicaXY_Z(
    dfCX: f64,
    dfCY: f64,
    dfPos: f64,
    dfPitch: f64,
    byCirDir: BYTE,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let s = SpiralTo::new(Plane::XY, [dfCX, dfCY], dfPos, dfPitch, byCirDir);
        helica(s, wGroupIndex)
    }
}

/// Obsolete helix around (dfCY, dfCZ) until X reaches dfPos.
#[no_mangle]
pub extern "system" fn MCC_HelicaYZ_X(
    dfCY: f64,
    dfCZ: f64,
    dfPos: f64,
    dfPitch: f64,
    byCirDir: BYTE,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let s = SpiralTo::new(Plane::YZ, [dfCY, dfCZ], dfPos, dfPitch, byCirDir);
        helica(s, wGroupIndex)
    }
}

/// Obsolete helix around (dfCZ, dfCX) until Y reaches dfPos.
#[no_mangle]
pub extern "system" fn MCC_HelicaZX_Y(
    dfCZ: f64,
    dfCX: f64,
    dfPos: f64,
    dfPitch: f64,
    byCirDir: BYTE,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let s = SpiralTo::new(Plane::ZX, [dfCZ, dfCX], dfPos, dfPitch, byCirDir);
        helica(s, wGroupIndex)
    }
}
