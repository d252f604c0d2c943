//! Robot kinematics (vendor header, IMP-3 B/C variants): `MCC_SetKinematicTrans`, the
//! pre-process callback, and the V6 motion commands. How a kinematic group runs is in
//! [`crate::engine::kinematics`]; what each function does and why is in
//! docs/compatibility.md, "Robot kinematics".

use super::{direction, finite, finite2, finite8, with_group, ERR_BAD_ARC};
use crate::engine::command::Curve;
use crate::engine::command::{Command, Ctx};
use crate::engine::kinematics::{register, Registration};
use crate::error::{McclError, McclResult};
use crate::planner::{Axes, Path, PlanError, Plane};
use crate::system;
use crate::vendor::consts as c;
use crate::vendor::{
    BYTE, DWORD, FWDKINEFUN, INIT_EXTENSION, INVKINEFUN, PRE_PROCESS_MOTION_COMMAND, WORD,
};
use std::os::raw::c_int;

/// The group index of an `int nGroup` (`GROUP_PARAMETER_ERR` when negative or too big).
fn group_of(n: c_int) -> McclResult<u16> {
    u16::try_from(n).map_err(|_| McclError::Group)
}

fn set_kinematic_trans(
    fwd: FWDKINEFUN,
    inv: INVKINEFUN,
    size: DWORD,
    init: INIT_EXTENSION,
    n: c_int,
) -> McclResult<c_int> {
    // As the vendor's library: kinematics are registered before the card starts.
    if system::active().is_ok() {
        return Err(McclError::RunTime);
    }
    let g = group_of(n)?;
    register(
        usize::from(g),
        Registration {
            fwd,
            inv,
            ext_size: u64::from(size),
            init,
        },
    )?;
    Ok(c::NO_ERR)
}

/// Registers the kinematics of group `nGroup`, before the card starts (as the vendor's
/// library takes them; once it runs, `RUN_TIME_ERR`). The next `MCC_InitSystem` or
/// `MCC_InitSimulation` applies them: it allocates a zeroed extension of
/// `dwExtensionSize` bytes (at most 16 MiB) for every kinematics call, calls
/// `pfnInitExtension` (may be NULL) on it once, and the group's channels carry joints:
/// what a program reads of the group is its joints, its path commands (lines, arcs, the
/// V6 curves) move the tool in Cartesian space (X, Y, Z, RX, RY, RZ in the axes X..W,
/// two aux axes in A and B) through `pfnInvKinematics` every tick, its point-to-point
/// moves move the joints. Registering a group again replaces the registration.
#[no_mangle]
pub extern "system" fn MCC_SetKinematicTrans(
    pfnFwdKinematics: FWDKINEFUN,
    pfnInvKinematics: INVKINEFUN,
    dwExtensionSize: DWORD,
    pfnInitExtension: INIT_EXTENSION,
    nGroup: c_int,
) -> c_int {
    ffi_boundary! { set_kinematic_trans(
        pfnFwdKinematics,
        pfnInvKinematics,
        dwExtensionSize,
        pfnInitExtension,
        nGroup,
    ) }
}

/// Registers (or with NULL removes) the callback a kinematic group calls, on the engine
/// thread without any lock, before it starts each Cartesian move: with the current and
/// the target Cartesian position; the offset it writes is added to the target.
#[no_mangle]
pub extern "system" fn MCC_SetPreProcessMotionCommandCallback(
    pfnPreProcMotionCmd: PRE_PROCESS_MOTION_COMMAND,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        with_group(wGroupIndex, |g| {
            g.set_preprocess(pfnPreProcMotionCmd)?;
            Ok(c::NO_ERR)
        })
    }
}

/// Queues a V6 command: `plan` builds it from the context, the posture goes with it.
fn queue_v6(
    g: WORD,
    posture: DWORD,
    plan: impl FnOnce(&Ctx<'_>) -> McclResult<Command>,
) -> McclResult<c_int> {
    with_group(g, |grp| {
        let mut cmd = plan(&grp.ctx())?;
        cmd.posture = Some(posture);
        super::enqueue(grp, cmd)
    })
}

/// Queues a V6 arc or circle (`kind`); a degenerate one records 0xF104 when it starts,
/// as `MCC_Arc*` do.
fn queue_v6_curve(
    g: WORD,
    posture: DWORD,
    kind: Curve,
    plan: impl FnOnce(&Ctx<'_>) -> Result<Path, PlanError>,
) -> McclResult<c_int> {
    with_group(g, |grp| {
        let mut cmd = match plan(&grp.ctx()) {
            Ok(path) => grp.ctx().curve(path, kind)?,
            Err(PlanError::BadArc) => grp.ctx().fault(kind, ERR_BAD_ARC),
            Err(_) => return Err(McclError::Parameter),
        };
        cmd.posture = Some(posture);
        super::enqueue(grp, cmd)
    })
}

/// The aux-axis ends of a V6 curve: RX, RY, RZ (the axes U, V, W) go to their resolved
/// values where `m` has their bit (all when `m` is `None`), A and B stay.
fn orientation(ctx: &Ctx<'_>, r: [f64; 3], m: Option<u32>) -> [f64; 5] {
    std::array::from_fn(|k| {
        let i = 3 + k;
        if k < 3 && m.is_none_or(|m| m & (1 << i) != 0) {
            ctx.resolve_axis(i, r[k])
        } else {
            ctx.from[i]
        }
    })
}

/// Checks three numbers from C are finite.
fn finite3(v: [f64; 3]) -> McclResult<[f64; 3]> {
    Ok([finite(v[0])?, finite(v[1])?, finite(v[2])?])
}

/// A 3-D point of a V6 command, resolved (incremental: from the end of the queue).
fn point3(ctx: &Ctx<'_>, p: [f64; 3]) -> [f64; 3] {
    std::array::from_fn(|i| ctx.resolve_axis(i, p[i]))
}

/// Checks the points a curve names and its orientation ends against the ranges.
fn check_curve(ctx: &Ctx<'_>, pts: &[[f64; 3]], aux: &[f64; 5]) -> Result<(), PlanError> {
    let mut all: Vec<(usize, f64)> = pts
        .iter()
        .flat_map(|p| (0..3).map(move |i| (i, p[i])))
        .collect();
    all.extend(aux.iter().enumerate().map(|(k, v)| (3 + k, *v)));
    ctx.check_points(&all)
}

/// Moves the tool point in a straight line to (x, y, z) with the orientation (rx, ry,
/// rz) and the aux axes (a, b) interpolated linearly, component by component, at the
/// feed speed (over X/Y/Z) with the group's acc/dec; `posture` goes to the kinematics.
/// Axes outside `dwAxisMask` keep their position.
#[no_mangle]
pub extern "system" fn MCC_Line_V6(
    x: f64,
    y: f64,
    z: f64,
    rx: f64,
    ry: f64,
    rz: f64,
    a: f64,
    b: f64,
    posture: DWORD,
    wGroupIndex: WORD,
    dwAxisMask: DWORD,
) -> c_int {
    ffi_boundary! {
        let args = finite8([x, y, z, rx, ry, rz, a, b])?;
        let m = super::axis_mask(dwAxisMask)?;
        queue_v6(wGroupIndex, posture, |ctx| ctx.line(ctx.resolve(&args, m)))
    }
}

/// The V6 curves through two points.
#[derive(Clone, Copy)]
enum TwoPoint {
    /// `MCC_Arc_V6`: from the current point by way of the first point to the second.
    Arc,
    /// `MCC_Circle_V6`: a full circle from the current point through both points back to it.
    Circle,
}

/// Queues the V6 curve `curve` from the current point by way of the points `pts[0]` and
/// `pts[1]`, the orientation going linearly to `pts[2]` (RX, RY, RZ; components outside
/// `dwAxisMask` stay).
fn two_point_v6(
    curve: TwoPoint,
    pts: [[f64; 3]; 3],
    posture: DWORD,
    wGroupIndex: WORD,
    dwAxisMask: DWORD,
) -> McclResult<c_int> {
    let kind = match curve {
        TwoPoint::Arc => Curve::ThreePoint,
        TwoPoint::Circle => Curve::Arc,
    };
    let (p1, p2) = (finite3(pts[0])?, finite3(pts[1])?);
    let r = finite3(pts[2])?;
    let m = super::axis_mask(dwAxisMask)?;
    queue_v6_curve(wGroupIndex, posture, kind, |ctx| {
        let (p1, p2) = (point3(ctx, p1), point3(ctx, p2));
        let aux = orientation(ctx, r, Some(m));
        check_curve(ctx, &[p1, p2], &aux)?;
        match curve {
            TwoPoint::Arc => Path::arc_3pt_xyz(&ctx.from, p1, p2, Some(aux)),
            TwoPoint::Circle => Path::circle_3pt_xyz(&ctx.from, p1, p2, Some(aux)),
        }
    })
}

/// 3-D arc from the current point through (x0, y0, z0) to (x1, y1, z1), the orientation
/// going linearly to (rx, ry, rz) (components outside `dwAxisMask` stay).
#[no_mangle]
pub extern "system" fn MCC_Arc_V6(
    x0: f64,
    y0: f64,
    z0: f64,
    x1: f64,
    y1: f64,
    z1: f64,
    rx: f64,
    ry: f64,
    rz: f64,
    posture: DWORD,
    wGroupIndex: WORD,
    dwAxisMask: DWORD,
) -> c_int {
    ffi_boundary! {
        let pts = [[x0, y0, z0], [x1, y1, z1], [rx, ry, rz]];
        two_point_v6(TwoPoint::Arc, pts, posture, wGroupIndex, dwAxisMask)
    }
}

/// Full circle from the current point through (x0, y0, z0) and (x1, y1, z1) back to
/// it; the orientation goes linearly to (rx, ry, rz) over the turn.
#[no_mangle]
pub extern "system" fn MCC_Circle_V6(
    x0: f64,
    y0: f64,
    z0: f64,
    x1: f64,
    y1: f64,
    z1: f64,
    rx: f64,
    ry: f64,
    rz: f64,
    posture: DWORD,
    wGroupIndex: WORD,
    dwAxisMask: DWORD,
) -> c_int {
    ffi_boundary! {
        let pts = [[x0, y0, z0], [x1, y1, z1], [rx, ry, rz]];
        two_point_v6(TwoPoint::Circle, pts, posture, wGroupIndex, dwAxisMask)
    }
}

/// Arc of `theta` degrees (> 0 counter-clockwise seen from the tip of the normal) about
/// the axis through (cx, cy, cz) along (nv0, nv1, nv2); the orientation goes linearly
/// to (rx, ry, rz).
#[no_mangle]
pub extern "system" fn MCC_ArcTheta_V6(
    cx: f64,
    cy: f64,
    cz: f64,
    nv0: f64,
    nv1: f64,
    nv2: f64,
    theta: f64,
    rx: f64,
    ry: f64,
    rz: f64,
    posture: DWORD,
    wGroupIndex: WORD,
    dwAxisMask: DWORD,
) -> c_int {
    ffi_boundary! {
        let (center, normal) = (finite3([cx, cy, cz])?, finite3([nv0, nv1, nv2])?);
        let (theta, r) = (finite(theta)?, finite3([rx, ry, rz])?);
        let m = super::axis_mask(dwAxisMask)?;
        queue_v6_curve(wGroupIndex, posture, Curve::Arc, |ctx| {
            let center = point3(ctx, center);
            let aux = orientation(ctx, r, Some(m));
            check_curve(ctx, &[center], &aux)?;
            Path::arc_about_axis(&ctx.from, center, normal, theta, Some(aux))
        })
    }
}

fn circle_plane(
    plane: Plane,
    c2: [f64; 2],
    r: [f64; 3],
    dir: BYTE,
    posture: DWORD,
    g: WORD,
) -> McclResult<c_int> {
    let c2 = finite2(c2)?;
    let r = finite3(r)?;
    let ccw = direction(dir)?;
    queue_v6_curve(g, posture, Curve::Arc, |ctx| {
        let center = ctx.resolve_plane(plane, c2);
        let aux = orientation(ctx, r, None);
        let (ia, ib, n) = plane.axes();
        let mut p = [0.0; 3];
        p[ia] = center[0];
        p[ib] = center[1];
        p[n] = ctx.from[n];
        check_curve(ctx, &[p], &aux)?;
        Path::circle(plane, &ctx.from, center, ccw, Some(aux))
    })
}

/// Full circle about (cx, cy) in the XY plane (`CIR_CW`/`CIR_CCW` seen from +Z); the
/// orientation goes linearly to (rx, ry, rz) over the turn.
#[no_mangle]
pub extern "system" fn MCC_CircleXY_V6(
    cx: f64,
    cy: f64,
    rx: f64,
    ry: f64,
    rz: f64,
    byCirDir: BYTE,
    posture: DWORD,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let (center, r) = ([cx, cy], [rx, ry, rz]);
        circle_plane(Plane::XY, center, r, byCirDir, posture, wGroupIndex)
    }
}

/// [`MCC_CircleXY_V6`] in the YZ plane about (cy, cz), seen from +X.
#[no_mangle]
pub extern "system" fn MCC_CircleYZ_V6(
    cy: f64,
    cz: f64,
    rx: f64,
    ry: f64,
    rz: f64,
    byCirDir: BYTE,
    posture: DWORD,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let (center, r) = ([cy, cz], [rx, ry, rz]);
        circle_plane(Plane::YZ, center, r, byCirDir, posture, wGroupIndex)
    }
}

/// [`MCC_CircleXY_V6`] in the ZX plane about (cz, cx), seen from +Y.
#[no_mangle]
pub extern "system" fn MCC_CircleZX_V6(
    cz: f64,
    cx: f64,
    rx: f64,
    ry: f64,
    rz: f64,
    byCirDir: BYTE,
    posture: DWORD,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let (center, r) = ([cz, cx], [rx, ry, rz]);
        circle_plane(Plane::ZX, center, r, byCirDir, posture, wGroupIndex)
    }
}

/// What a joint move reads under the group's lock before the kinematics run.
struct JointPlan {
    fns: crate::engine::kinematics::KinFns,
    posture: DWORD,
    /// The queue's (Cartesian) end when it was read.
    queue_end: Axes,
    /// The joints at the queue's end, when known.
    joints: Option<Axes>,
    /// The joints of the group now (or due next).
    now: Axes,
}

/// Queues a point-to-point move of a kinematic group's joints (`MCC_PtP_V6`, and
/// `MCC_PtP`/`MCC_SyncPtP` on a kinematic group, as the vendor's library moves them):
/// `args` are joints, resolved against the joints at the queue's end (absolute, or
/// incremental, axes outside `m` keep theirs). Where those are not known yet (the queue
/// ends with a path command), they are the inverse kinematics of the queue's end. The
/// queue's Cartesian end becomes the forward kinematics of the target. `None` for a group
/// that is not kinematic. The kinematics run on this thread with no lock held.
pub(super) fn joint_ptp(args: Axes, g: WORD, m: u32, sync: bool) -> McclResult<Option<c_int>> {
    let shared = system::active()?;
    let plan = {
        let grp = shared.group(g)?;
        let Some((fns, posture)) = grp.kinematics_fns() else {
            return Ok(None);
        };
        JointPlan {
            fns,
            posture,
            queue_end: grp.ctx().from,
            joints: grp.queue_end_joints(),
            now: grp.current_joints(),
        }
    };
    let gi = usize::from(g);
    let mut posture = plan.posture;
    let from = match plan.joints {
        Some(j) => j,
        None => plan
            .fns
            .inverse(gi, &plan.queue_end, &plan.now, &mut posture)
            .ok_or(McclError::NotFinished)?,
    };
    let target = {
        let grp = shared.group(g)?;
        let ctx = Ctx { from, ..grp.ctx() };
        ctx.resolve(&args, m)
    };
    let cart = plan
        .fns
        .forward(gi, &target, &mut posture)
        .ok_or(McclError::Parameter)?;
    with_group(g, |grp| {
        if grp.ctx().from != plan.queue_end || !grp.is_kinematic() {
            // Another thread queued meanwhile: the move would start elsewhere.
            return Err(McclError::NotFinished);
        }
        let pts: Vec<(usize, f64)> = cart.iter().copied().enumerate().collect();
        grp.ctx()
            .check_points(&pts)
            .map_err(|_| McclError::Parameter)?;
        let ctx = Ctx { from, ..grp.ctx() };
        let cmd: Command = ctx.ptp(target, ctx.settings.ptp_ratio, sync)?;
        grp.enqueue_joint_move(cmd, target, cart).map(Some)
    })
}

/// Moves the joints of a kinematic group point-to-point to (j0..j7), all starting and
/// ending together, as `MCC_SyncPtP` moves the axes of any group (the vendor's library
/// moves them so, tick for tick): with the group's PtP speed ratio and acc/dec settings,
/// per joint the speeds and limits of the channels they run on. Joints outside
/// `dwAxisMask` keep their position. On a group without kinematics it is `MCC_SyncPtP`.
#[no_mangle]
pub extern "system" fn MCC_PtP_V6(
    j0: f64,
    j1: f64,
    j2: f64,
    j3: f64,
    j4: f64,
    j5: f64,
    j6: f64,
    j7: f64,
    wGroupIndex: WORD,
    dwAxisMask: DWORD,
) -> c_int {
    ffi_boundary! {
        let args = finite8([j0, j1, j2, j3, j4, j5, j6, j7])?;
        let m = super::axis_mask(dwAxisMask)?;
        match joint_ptp(args, wGroupIndex, m, true)? {
            Some(i) => Ok(i),
            None => with_group(wGroupIndex, |grp| {
                let ctx = grp.ctx();
                let cmd = ctx.ptp(ctx.resolve(&args, m), ctx.settings.ptp_ratio, true)?;
                super::enqueue(grp, cmd)
            }),
        }
    }
}
