//! General motion: line, arc, circle and helix commands and their settings (user manual
//! §2.6.2; vendor header "General Motions"), plus the obsolete forms whose meaning is clear.

use super::{
    axis_mask, finite, finite8, queue, queue_curve, read_published, shape, shape_code, with_group,
};
use crate::engine::command::Curve;
use crate::error::{McclError, McclResult};
use crate::planner::{Axes, Path, Plane};
use crate::system;
use crate::vendor::consts as c;
use crate::vendor::{BYTE, DWORD, WORD};
use std::os::raw::{c_char, c_int};

use crate::config::range::time_ms;

/// `byCirDir`: counter-clockwise (true) or clockwise.
pub(super) fn direction(byCirDir: BYTE) -> McclResult<bool> {
    // `CIR_CW` (0) or anything else: counter-clockwise, as the vendor's library takes it.
    Ok(i32::from(byCirDir) != c::CIR_CW)
}

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

/// Declares setters of a group's motion settings: `$name(value, wGroupIndex) -> int`
/// checks the value with `$check` (an error leaves the group unchanged) and stores the
/// result in `settings.$field`.
macro_rules! settings_setters {
    ($($(#[$doc:meta])* $name:ident($arg:ident: $ty:ty) = $check:expr => $field:ident;)*) => {$(
        $(#[$doc])*
        #[no_mangle]
        pub extern "system" fn $name($arg: $ty, wGroupIndex: WORD) -> c_int {
            ffi_boundary! {
                let v = $check($arg)?;
                super::update_group(wGroupIndex, |g| g.settings.$field = v)
            }
        }
    )*};
}

/// Declares setters of a group's speeds that return the value now in effect:
/// `$name(value, wGroupIndex) -> double` checks the value with `$check` and stores it in
/// `settings.$field`.
macro_rules! speed_setters {
    ($($(#[$doc:meta])* $name:ident($arg:ident) = $check:expr => $field:ident;)*) => {$(
        $(#[$doc])*
        #[no_mangle]
        pub extern "system" fn $name($arg: f64, wGroupIndex: WORD) -> f64 {
            ffi_boundary! {
                let v = $check($arg)?;
                with_group(wGroupIndex, |g| {
                    g.settings.$field = v;
                    Ok(v)
                })
            }
        }
    )*};
}

/// Declares getters of a group's motion settings: `$name(wGroupIndex) -> $ret` returns
/// `$get` evaluated with `$s` bound to the group's settings.
macro_rules! settings_getters {
    ($($(#[$doc:meta])* $name:ident -> $ret:ty = |$s:ident| $get:expr;)*) => {$(
        $(#[$doc])*
        #[no_mangle]
        pub extern "system" fn $name(wGroupIndex: WORD) -> $ret {
            ffi_boundary! {
                with_group(wGroupIndex, |g| {
                    let $s = &g.settings;
                    Ok($get)
                })
            }
        }
    )*};
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

settings_setters! {
    /// Acceleration shape of general motion: 'T' (trapezoid) or 'S' (S-curve).
    MCC_SetAccType(cAccType: c_char) = shape => acc;
    /// Deceleration shape of general motion: 'T' or 'S'.
    MCC_SetDecType(cDecType: c_char) = shape => dec;
    /// Time to accelerate from 0 to the feed speed, ms (0..=2^32 − 1; default 300).
    /// Kept in whole ms, rounded up.
    MCC_SetAccTime(dfAccTime: f64) = ramp_ms => acc_ms;
    /// Time to decelerate from the feed speed to 0, ms (0..=2^32 − 1; default 300), kept
    /// in whole ms, rounded up.
    MCC_SetDecTime(dfDecTime: f64) = ramp_ms => dec_ms;
}

speed_setters! {
    /// Feed speed of following general motion, UU/s (> 0; a negative one counts by its
    /// size). A speed above `MCC_SetSysMaxSpeed` becomes that maximum. Returns the feed
    /// speed now in effect.
    MCC_SetFeedSpeed(dfFeedSpeed) = feed_speed => feed;
    /// Point-to-point speed ratio, percent of each axis's maximum safe speed
    /// (0 < r <= 100). Returns the ratio now in effect.
    MCC_SetPtPSpeed(dfRatio) = ptp_ratio => ptp_ratio;
}

settings_getters! {
    /// The acceleration shape: 0 'T', 1 'S' (as the vendor's library answers).
    MCC_GetAccType -> c_int = |s| shape_code(s.acc);
    /// The deceleration shape: 0 'T', 1 'S'.
    MCC_GetDecType -> c_int = |s| shape_code(s.dec);
    /// The acceleration time, ms.
    MCC_GetAccTime -> f64 = |s| s.acc_ms;
    /// The deceleration time, ms.
    MCC_GetDecTime -> f64 = |s| s.dec_ms;
    /// The feed speed of following general motion, UU/s.
    MCC_GetFeedSpeed -> f64 = |s| s.feed;
    /// The point-to-point speed ratio, percent.
    MCC_GetPtPSpeed -> f64 = |s| s.ptp_ratio;
}

/// The current tangential speed (UU/s): X/Y/Z path speed, or the fastest aux axis.
#[no_mangle]
pub extern "system" fn MCC_GetCurFeedSpeed(wGroupIndex: WORD) -> f64 {
    ffi_boundary! { read_published(wGroupIndex, |p| p.load_motion().path_speed()) }
}

per_axis_getters! {
    /// The current speed of every axis, UU/s (signed).
    MCC_GetSpeed(f64; wGroupIndex)
        = read_published(wGroupIndex, |p| p.load_motion().vel);
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

/// Declares the motions of up to eight axes: `$name(dfX0..dfX7, wGroupIndex, dwAxisMask)`
/// calls `$f(positions, group, mask, $extra...)`, which checks and queues the command and
/// returns its index.
macro_rules! axes_motions {
    ($($(#[$doc:meta])* $name:ident => $f:ident($($extra:expr),*);)*) => {$(
        $(#[$doc])*
        #[no_mangle]
        pub extern "system" fn $name(
            dfX0: f64, dfX1: f64, dfX2: f64, dfX3: f64,
            dfX4: f64, dfX5: f64, dfX6: f64, dfX7: f64,
            wGroupIndex: WORD, dwAxisMask: DWORD,
        ) -> c_int {
            ffi_boundary! {
                $f(
                    [dfX0, dfX1, dfX2, dfX3, dfX4, dfX5, dfX6, dfX7],
                    wGroupIndex,
                    dwAxisMask,
                    $($extra),*
                )
            }
        }
    )*};
}

/// Declares the motions of one axis (the obsolete one-axis forms):
/// `$name($arg, wGroupIndex)` calls `$f` with `$arg` at index `$axis`, the axis's mask bit
/// `$mask` and `$extra...`.
macro_rules! axis_motions {
    ($(
        $(#[$doc:meta])*
        $name:ident($arg:ident) => $f:ident($axis:expr, $mask:ident $(, $extra:expr)*);
    )*) => {$(
        $(#[$doc])*
        #[no_mangle]
        pub extern "system" fn $name($arg: f64, wGroupIndex: WORD) -> c_int {
            ffi_boundary! { $f(one($axis, $arg), wGroupIndex, c::$mask $(, $extra)*) }
        }
    )*};
}

axes_motions! {
    /// Point-to-point motion: every axis in the mask runs its own profile at the PtP ratio;
    /// axes start together and need not arrive together. Returns the command index.
    MCC_PtP => ptp(false);
    /// Synchronised point-to-point motion: all axes start and end together, paced by the
    /// slowest. Returns the command index.
    MCC_SyncPtP => ptp(true);
    /// Linear motion of the axes in the mask at the feed speed (only X/Y/Z count for the
    /// path speed; U..B start and end with them). Returns the command index.
    MCC_Line => line();
}

axis_motions! {
    /// Point-to-point motion of X alone.
    MCC_PtPX(dfX) => ptp(0, IMP_AXIS_X, false);
    /// Point-to-point motion of Y alone.
    MCC_PtPY(dfY) => ptp(1, IMP_AXIS_Y, false);
    /// Point-to-point motion of Z alone.
    MCC_PtPZ(dfZ) => ptp(2, IMP_AXIS_Z, false);
    /// Point-to-point motion of U alone.
    MCC_PtPU(dfU) => ptp(3, IMP_AXIS_U, false);
    /// Point-to-point motion of V alone.
    MCC_PtPV(dfV) => ptp(4, IMP_AXIS_V, false);
    /// Point-to-point motion of W alone.
    MCC_PtPW(dfW) => ptp(5, IMP_AXIS_W, false);
    /// Point-to-point motion of A alone.
    MCC_PtPA(dfA) => ptp(6, IMP_AXIS_A, false);
    /// Point-to-point motion of B alone.
    MCC_PtPB(dfB) => ptp(7, IMP_AXIS_B, false);
    /// Linear motion of X alone (obsolete form).
    MCC_LineX(dfX) => line(0, IMP_AXIS_X);
    /// Linear motion of Y alone (obsolete form).
    MCC_LineY(dfY) => line(1, IMP_AXIS_Y);
    /// Linear motion of Z alone (obsolete form).
    MCC_LineZ(dfZ) => line(2, IMP_AXIS_Z);
    /// Linear motion of U alone (obsolete form).
    MCC_LineU(dfU) => line(3, IMP_AXIS_U);
    /// Linear motion of V alone (obsolete form).
    MCC_LineV(dfV) => line(4, IMP_AXIS_V);
    /// Linear motion of W alone (obsolete form).
    MCC_LineW(dfW) => line(5, IMP_AXIS_W);
    /// Linear motion of A alone (obsolete form).
    MCC_LineA(dfA) => line(6, IMP_AXIS_A);
    /// Linear motion of B alone (obsolete form).
    MCC_LineB(dfB) => line(7, IMP_AXIS_B);
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

/// A point of a plane from C: both coordinates finite.
pub(super) fn finite2(v: [f64; 2]) -> McclResult<[f64; 2]> {
    Ok([finite(v[0])?, finite(v[1])?])
}

/// A curve about a center `c` of a plane (arc by an angle, circle, helix, cone), with
/// the U..B ends `aux` moving linearly along, as C passed them.
#[derive(Clone, Copy)]
pub(super) struct About {
    pub plane: Plane,
    pub c: [f64; 2],
    pub aux: Option<[f64; 5]>,
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

/// Declares the three-point arcs of one plane, each with its `_Aux` form:
/// `$name(r0, r1, e0, e1, wGroupIndex)` runs from the current point through `(r0, r1)` to
/// `(e0, e1)` on `Plane::$plane`; `$aux` takes U..B ends (`dfX3..dfX7`) too, which move
/// linearly along.
macro_rules! plane_arcs {
    ($(
        $(#[$doc:meta])*
        $name:ident, $aux:ident($r0:ident, $r1:ident, $e0:ident, $e1:ident) => $plane:ident;
    )*) => {$(
        $(#[$doc])*
        #[no_mangle]
        pub extern "system" fn $name(
            $r0: f64, $r1: f64, $e0: f64, $e1: f64, wGroupIndex: WORD,
        ) -> c_int {
            ffi_boundary! { arc(Plane::$plane, [$r0, $r1], [$e0, $e1], None, wGroupIndex) }
        }

        #[doc = concat!("[`", stringify!($name), "`] with U..B moving linearly to the given ends.")]
        #[no_mangle]
        pub extern "system" fn $aux(
            $r0: f64, $r1: f64, $e0: f64, $e1: f64,
            dfX3: f64, dfX4: f64, dfX5: f64, dfX6: f64, dfX7: f64,
            wGroupIndex: WORD,
        ) -> c_int {
            ffi_boundary! {
                let aux = Some([dfX3, dfX4, dfX5, dfX6, dfX7]);
                arc(Plane::$plane, [$r0, $r1], [$e0, $e1], aux, wGroupIndex)
            }
        }
    )*};
}

plane_arcs! {
    /// Arc in the XY plane from the current point through (dfRX0, dfRX1) to (dfX0, dfX1).
    MCC_ArcXY, MCC_ArcXY_Aux(dfRX0, dfRX1, dfX0, dfX1) => XY;
    /// Arc in the YZ plane through (dfRX1, dfRX2) to (dfX1, dfX2).
    MCC_ArcYZ, MCC_ArcYZ_Aux(dfRX1, dfRX2, dfX1, dfX2) => YZ;
    /// Arc in the ZX plane through (dfRX2, dfRX0) to (dfX2, dfX0).
    MCC_ArcZX, MCC_ArcZX_Aux(dfRX2, dfRX0, dfX2, dfX0) => ZX;
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

/// Declares the 3-D arc `$name(dfRX0..2, dfX0..2, wGroupIndex)` from the current point
/// through (dfRX0..2) to (dfX0..2), and its `_Aux` form `$aux`, which takes U..B ends
/// (`dfX3..dfX7`) too.
macro_rules! arcs_xyz {
    ($(#[$doc:meta])* $name:ident, $aux:ident) => {
        $(#[$doc])*
        #[no_mangle]
        pub extern "system" fn $name(
            dfRX0: f64, dfRX1: f64, dfRX2: f64, dfX0: f64, dfX1: f64, dfX2: f64, wGroupIndex: WORD,
        ) -> c_int {
            ffi_boundary! { arc_xyz([dfRX0, dfRX1, dfRX2], [dfX0, dfX1, dfX2], None, wGroupIndex) }
        }

        #[doc = concat!("[`", stringify!($name), "`] with U..B moving linearly to the given ends.")]
        #[no_mangle]
        pub extern "system" fn $aux(
            dfRX0: f64, dfRX1: f64, dfRX2: f64, dfX0: f64, dfX1: f64, dfX2: f64,
            dfX3: f64, dfX4: f64, dfX5: f64, dfX6: f64, dfX7: f64,
            wGroupIndex: WORD,
        ) -> c_int {
            ffi_boundary! {
                let aux = Some([dfX3, dfX4, dfX5, dfX6, dfX7]);
                arc_xyz([dfRX0, dfRX1, dfRX2], [dfX0, dfX1, dfX2], aux, wGroupIndex)
            }
        }
    };
}

arcs_xyz! {
    /// 3-D arc from the current point through (dfRX0..2) to (dfX0..2).
    MCC_ArcXYZ, MCC_ArcXYZ_Aux
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

/// Declares the arcs by an angle of one plane: `$name(c0, c1, dfTheta, wGroupIndex)` turns
/// around the center `(c0, c1)` of `Plane::$plane` by dfTheta degrees.
macro_rules! plane_arcs_theta {
    ($($(#[$doc:meta])* $name:ident($c0:ident, $c1:ident) => $plane:ident;)*) => {$(
        $(#[$doc])*
        #[no_mangle]
        pub extern "system" fn $name($c0: f64, $c1: f64, dfTheta: f64, wGroupIndex: WORD) -> c_int {
            ffi_boundary! { arc_theta(Plane::$plane, [$c0, $c1], dfTheta, wGroupIndex) }
        }
    )*};
}

plane_arcs_theta! {
    /// Arc around the center (dfCX, dfCY) by dfTheta degrees (> 0 counter-clockwise seen
    /// from +Z).
    MCC_ArcThetaXY(dfCX, dfCY) => XY;
    /// Arc around (dfCY, dfCZ) by dfTheta degrees (> 0 counter-clockwise seen from +X).
    MCC_ArcThetaYZ(dfCY, dfCZ) => YZ;
    /// Arc around (dfCZ, dfCX) by dfTheta degrees (> 0 counter-clockwise seen from +Y).
    MCC_ArcThetaZX(dfCZ, dfCX) => ZX;
}

fn circle(at: About, dir: BYTE, g: WORD) -> McclResult<c_int> {
    let ccw = direction(dir)?;
    queue_about(at, Curve::Arc, g, |ctx, c, aux| {
        Path::circle(at.plane, &ctx.from, c, ccw, aux)
    })
}

/// Declares the full circles of one plane, each with its `_Aux` form:
/// `$name(c0, c1, byCirDir, wGroupIndex)` circles around `(c0, c1)` of `Plane::$plane`,
/// `CIR_CW` or `CIR_CCW`; `$aux` takes U..B ends (`dfU..dfB`) too, which move linearly
/// along.
macro_rules! plane_circles {
    ($($(#[$doc:meta])* $name:ident, $aux:ident($c0:ident, $c1:ident) => $plane:ident;)*) => {$(
        $(#[$doc])*
        #[no_mangle]
        pub extern "system" fn $name($c0: f64, $c1: f64, byCirDir: BYTE, wGroupIndex: WORD) -> c_int {
            ffi_boundary! {
                let at = About { plane: Plane::$plane, c: [$c0, $c1], aux: None };
                circle(at, byCirDir, wGroupIndex)
            }
        }

        #[doc = concat!("[`", stringify!($name), "`] with U..B moving linearly to the given ends.")]
        #[no_mangle]
        pub extern "system" fn $aux(
            $c0: f64, $c1: f64,
            dfU: f64, dfV: f64, dfW: f64, dfA: f64, dfB: f64,
            byCirDir: BYTE, wGroupIndex: WORD,
        ) -> c_int {
            ffi_boundary! {
                let aux = Some([dfU, dfV, dfW, dfA, dfB]);
                circle(About { plane: Plane::$plane, c: [$c0, $c1], aux }, byCirDir, wGroupIndex)
            }
        }
    )*};
}

plane_circles! {
    /// Full circle around (dfCX, dfCY) in the XY plane, `CIR_CW` or `CIR_CCW` seen from +Z.
    MCC_CircleXY, MCC_CircleXY_Aux(dfCX, dfCY) => XY;
    /// Full circle around (dfCY, dfCZ) in the YZ plane, seen from +X.
    MCC_CircleYZ, MCC_CircleYZ_Aux(dfCY, dfCZ) => YZ;
    /// Full circle around (dfCZ, dfCX) in the ZX plane, seen from +Y.
    MCC_CircleZX, MCC_CircleZX_Aux(dfCZ, dfCX) => ZX;
}

fn helical(at: About, pitch: f64, theta: f64, g: WORD) -> McclResult<c_int> {
    let (pitch, theta) = (finite(pitch)?, finite(theta)?);
    queue_about(at, Curve::Helix, g, |ctx, c, aux| {
        Path::helix(at.plane, &ctx.from, c, pitch, theta, aux)
    })
}

/// Declares the helices of one plane, each with its `_Aux` form:
/// `$name(c0, c1, dfPitch, dfTheta, wGroupIndex)` turns around `(c0, c1)` of
/// `Plane::$plane` by dfTheta degrees while the third axis moves dfPitch per full turn;
/// `$aux` takes U..B ends (`dfU..dfB`) too, which move linearly along.
macro_rules! plane_helicals {
    ($($(#[$doc:meta])* $name:ident, $aux:ident($c0:ident, $c1:ident) => $plane:ident;)*) => {$(
        $(#[$doc])*
        #[no_mangle]
        pub extern "system" fn $name(
            $c0: f64, $c1: f64, dfPitch: f64, dfTheta: f64, wGroupIndex: WORD,
        ) -> c_int {
            ffi_boundary! {
                let at = About { plane: Plane::$plane, c: [$c0, $c1], aux: None };
                helical(at, dfPitch, dfTheta, wGroupIndex)
            }
        }

        #[doc = concat!("[`", stringify!($name), "`] with U..B moving linearly to the given ends.")]
        #[no_mangle]
        pub extern "system" fn $aux(
            $c0: f64, $c1: f64, dfPitch: f64,
            dfU: f64, dfV: f64, dfW: f64, dfA: f64, dfB: f64,
            dfTheta: f64, wGroupIndex: WORD,
        ) -> c_int {
            ffi_boundary! {
                let aux = Some([dfU, dfV, dfW, dfA, dfB]);
                let at = About { plane: Plane::$plane, c: [$c0, $c1], aux };
                helical(at, dfPitch, dfTheta, wGroupIndex)
            }
        }
    )*};
}

plane_helicals! {
    /// Helix around (dfCX, dfCY) by dfTheta degrees (> 0 counter-clockwise); Z moves
    /// dfPitch per full turn (pitch x theta / 360 in all).
    MCC_HelicalXY_Z, MCC_HelicalXY_Z_Aux(dfCX, dfCY) => XY;
    /// Helix around (dfCY, dfCZ); X moves dfPitch per turn.
    MCC_HelicalYZ_X, MCC_HelicalYZ_X_Aux(dfCY, dfCZ) => YZ;
    /// Helix around (dfCZ, dfCX); Y moves dfPitch per turn.
    MCC_HelicalZX_Y, MCC_HelicalZX_Y_Aux(dfCZ, dfCX) => ZX;
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

/// Declares the spirals of one plane that run until its third axis reaches dfPos: the
/// obsolete helix `$helica(c0, c1, dfPos, dfPitch, byCirDir, wGroupIndex)`, turning around
/// `(c0, c1)` of `Plane::$plane` and moving dfPitch per turn, and the conical helix
/// `$cone(c0, c1, dfPos, dfPitch, CenterRate, byCirDir, wGroupIndex)`, whose radius also
/// changes by CenterRate per turn (src/ffi/cone.rs).
macro_rules! plane_spirals {
    ($(
        $(#[$doc:meta])* $helica:ident,
        $(#[$cone_doc:meta])* $cone:ident($c0:ident, $c1:ident) => $plane:ident;
    )*) => {$(
        $(#[$doc])*
        #[no_mangle]
        pub extern "system" fn $helica(
            $c0: f64, $c1: f64, dfPos: f64, dfPitch: f64, byCirDir: BYTE, wGroupIndex: WORD,
        ) -> c_int {
            ffi_boundary! {
                let at = About { plane: Plane::$plane, c: [$c0, $c1], aux: None };
                helica(SpiralTo { at, pos: dfPos, pitch: dfPitch, dir: byCirDir }, wGroupIndex)
            }
        }

        $(#[$cone_doc])*
        #[no_mangle]
        pub extern "system" fn $cone(
            $c0: f64, $c1: f64, dfPos: f64, dfPitch: f64, CenterRate: f64,
            byCirDir: BYTE, wGroupIndex: WORD,
        ) -> c_int {
            ffi_boundary! {
                let at = About { plane: Plane::$plane, c: [$c0, $c1], aux: None };
                let spiral = SpiralTo { at, pos: dfPos, pitch: dfPitch, dir: byCirDir };
                super::cone::cone(spiral, CenterRate, wGroupIndex)
            }
        }
    )*};
}

plane_spirals! {
    /// Obsolete helix: around (dfCX, dfCY) in direction byCirDir until Z reaches dfPos,
    /// rising dfPitch per turn.
    MCC_HelicaXY_Z,
    /// Conical helix about (dfCX, dfCY) in direction byCirDir until Z reaches dfPos, Z
    /// moving dfPitch per turn and the radius changing by CenterRate per turn.
    MCC_ConeXY_Z(dfCX, dfCY) => XY;
    /// Obsolete helix around (dfCY, dfCZ) until X reaches dfPos.
    MCC_HelicaYZ_X,
    /// Conical helix about (dfCY, dfCZ) until X reaches dfPos (see [`MCC_ConeXY_Z`]).
    MCC_ConeYZ_X(dfCY, dfCZ) => YZ;
    /// Obsolete helix around (dfCZ, dfCX) until Y reaches dfPos.
    MCC_HelicaZX_Y,
    /// Conical helix about (dfCZ, dfCX) until Y reaches dfPos (see [`MCC_ConeXY_Z`]).
    MCC_ConeZX_Y(dfCZ, dfCX) => ZX;
}
