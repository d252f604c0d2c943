//! The conical helix (vendor header, obsolete functions; the manuals do not describe
//! it): `MCC_ConeXY_Z(dfCX, dfCY, dfPos, dfPitch, CenterRate, byCirDir)` turns about the
//! center in direction `byCirDir` while the third axis goes to `dfPos` at `dfPitch` per
//! turn (as `MCC_HelicaXY_Z`), the radius changing by `CenterRate` UU per turn
//! ([`crate::planner::ConeSeg`]; docs/undocumented-functions.md). Queued like the
//! helices, reported as a helix (`COMMAND_INFO.nType` 4 clockwise, 5 counter-clockwise).

use super::finite;
use super::motion::{queue_spiral, SpiralTo};
use crate::error::McclResult;
use crate::planner::{Path, Plane};
use crate::vendor::{BYTE, WORD};
use std::os::raw::c_int;

/// Queues the conical helix `s` whose radius changes by `rate` per turn.
fn cone(s: SpiralTo, rate: f64, g: WORD) -> McclResult<c_int> {
    let rate = finite(rate)?;
    queue_spiral(s, g, |from, c, to, pitch, ccw| {
        Path::cone(s.at.plane, from, c, to, pitch, rate, ccw)
    })
}

/// Conical helix about (dfCX, dfCY) in direction byCirDir until Z reaches dfPos, Z
/// moving dfPitch per turn and the radius changing by CenterRate per turn.
#[no_mangle]
pub extern "system" fn MCC_ConeXY_Z(
    dfCX: f64,
    dfCY: f64,
    dfPos: f64,
    dfPitch: f64,
    CenterRate: f64,
    byCirDir: BYTE,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let s = SpiralTo::new(Plane::XY, [dfCX, dfCY], dfPos, dfPitch, byCirDir);
        cone(s, CenterRate, wGroupIndex)
    }
}

/// Conical helix about (dfCY, dfCZ) until X reaches dfPos (see [`MCC_ConeXY_Z`]).
#[no_mangle]
pub extern "system" fn MCC_ConeYZ_X(
    dfCY: f64,
    dfCZ: f64,
    dfPos: f64,
    dfPitch: f64,
    CenterRate: f64,
    byCirDir: BYTE,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let s = SpiralTo::new(Plane::YZ, [dfCY, dfCZ], dfPos, dfPitch, byCirDir);
        cone(s, CenterRate, wGroupIndex)
    }
}

/// Conical helix about (dfCZ, dfCX) until Y reaches dfPos (see [`MCC_ConeXY_Z`]).
#[no_mangle]
pub extern "system" fn MCC_ConeZX_Y(
    dfCZ: f64,
    dfCX: f64,
    dfPos: f64,
    dfPitch: f64,
    CenterRate: f64,
    byCirDir: BYTE,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let s = SpiralTo::new(Plane::ZX, [dfCZ, dfCX], dfPos, dfPitch, byCirDir);
        cone(s, CenterRate, wGroupIndex)
    }
}
