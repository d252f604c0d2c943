//! The conical helix (vendor header, obsolete functions; the manuals do not describe
//! it): `MCC_ConeXY_Z(dfCX, dfCY, dfPos, dfPitch, CenterRate, byCirDir)` turns about the
//! center in direction `byCirDir` while the third axis goes to `dfPos` at `dfPitch` per
//! turn (as `MCC_HelicaXY_Z`), the radius changing by `CenterRate` UU per turn
//! ([`crate::planner::ConeSeg`]; docs/undocumented-functions.md). Queued like the
//! helices, reported as a helix (`COMMAND_INFO.nType` 4 clockwise, 5 counter-clockwise).

use super::{finite, queue_curve};
use crate::error::{McclError, McclResult};
use crate::planner::{Path, Plane};
use crate::vendor::consts as c;
use crate::vendor::{BYTE, WORD};
use std::os::raw::c_int;

fn cone(
    plane: Plane,
    cxy: [f64; 2],
    pos: f64,
    pitch: f64,
    rate: f64,
    dir: BYTE,
    g: WORD,
) -> McclResult<c_int> {
    let cxy = [finite(cxy[0])?, finite(cxy[1])?];
    let (pos, pitch, rate) = (finite(pos)?, finite(pitch)?, finite(rate)?);
    let ccw = match i32::from(dir) {
        c::CIR_CW => false,
        c::CIR_CCW => true,
        _ => return Err(McclError::Parameter),
    };
    let (a, b, n) = plane.axes();
    queue_curve(
        g,
        |ctx| {
            let (c, to) = (ctx.resolve_plane(plane, cxy), ctx.resolve_axis(n, pos));
            ctx.check_points(&[(a, c[0]), (b, c[1]), (n, to)])?;
            Path::cone(plane, &ctx.from, c, to, pitch, rate, ccw)
        },
        true,
    )
}

/// Conical helix about (dfCX, dfCY) in direction byCirDir until Z reaches dfPos, Z
/// moving dfPitch per turn and the radius changing by CenterRate per turn.
#[no_mangle]
pub extern "C" fn MCC_ConeXY_Z(
    dfCX: f64,
    dfCY: f64,
    dfPos: f64,
    dfPitch: f64,
    CenterRate: f64,
    byCirDir: BYTE,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! { cone(Plane::XY, [dfCX, dfCY], dfPos, dfPitch, CenterRate, byCirDir, wGroupIndex) }
}

/// Conical helix about (dfCY, dfCZ) until X reaches dfPos (see [`MCC_ConeXY_Z`]).
#[no_mangle]
pub extern "C" fn MCC_ConeYZ_X(
    dfCY: f64,
    dfCZ: f64,
    dfPos: f64,
    dfPitch: f64,
    CenterRate: f64,
    byCirDir: BYTE,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! { cone(Plane::YZ, [dfCY, dfCZ], dfPos, dfPitch, CenterRate, byCirDir, wGroupIndex) }
}

/// Conical helix about (dfCZ, dfCX) until Y reaches dfPos (see [`MCC_ConeXY_Z`]).
#[no_mangle]
pub extern "C" fn MCC_ConeZX_Y(
    dfCZ: f64,
    dfCX: f64,
    dfPos: f64,
    dfPitch: f64,
    CenterRate: f64,
    byCirDir: BYTE,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! { cone(Plane::ZX, [dfCZ, dfCX], dfPos, dfPitch, CenterRate, byCirDir, wGroupIndex) }
}
