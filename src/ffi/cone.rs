//! The conical helix (vendor header, obsolete functions; the manuals do not describe
//! it): `MCC_ConeXY_Z(dfCX, dfCY, dfPos, dfPitch, CenterRate, byCirDir)` turns about the
//! center in direction `byCirDir` while the third axis goes to `dfPos` at `dfPitch` per
//! turn (as `MCC_HelicaXY_Z`), the radius changing by `CenterRate` UU per turn
//! ([`crate::planner::ConeSeg`]; docs/undocumented-functions.md). Queued like the
//! helices, reported as a helix (`COMMAND_INFO.nType` 4 clockwise, 5 counter-clockwise).

use super::finite;
use super::motion::{queue_spiral, About, SpiralTo};
use crate::error::McclResult;
use crate::planner::{Path, Plane};
use crate::vendor::{BYTE, WORD};
use std::os::raw::c_int;

fn cone(s: SpiralTo, rate: f64, g: WORD) -> McclResult<c_int> {
    let rate = finite(rate)?;
    queue_spiral(s, g, |from, c, to, pitch, ccw| {
        Path::cone(s.at.plane, from, c, to, pitch, rate, ccw)
    })
}

/// Declares the conical helices of one plane: `$name(c0, c1, dfPos, dfPitch, CenterRate,
/// byCirDir, wGroupIndex)` turns about `(c0, c1)` of `Plane::$plane` until the plane's
/// third axis reaches dfPos.
macro_rules! plane_cones {
    ($($(#[$doc:meta])* $name:ident($c0:ident, $c1:ident) => $plane:ident;)*) => {$(
        $(#[$doc])*
        #[no_mangle]
        pub extern "C" fn $name(
            $c0: f64, $c1: f64, dfPos: f64, dfPitch: f64, CenterRate: f64,
            byCirDir: BYTE, wGroupIndex: WORD,
        ) -> c_int {
            ffi_boundary! {
                let at = About { plane: Plane::$plane, c: [$c0, $c1], aux: None };
                let spiral = SpiralTo { at, pos: dfPos, pitch: dfPitch, dir: byCirDir };
                cone(spiral, CenterRate, wGroupIndex)
            }
        }
    )*};
}

plane_cones! {
    /// Conical helix about (dfCX, dfCY) in direction byCirDir until Z reaches dfPos, Z
    /// moving dfPitch per turn and the radius changing by CenterRate per turn.
    MCC_ConeXY_Z(dfCX, dfCY) => XY;
    /// Conical helix about (dfCY, dfCZ) until X reaches dfPos (see [`MCC_ConeXY_Z`]).
    MCC_ConeYZ_X(dfCY, dfCZ) => YZ;
    /// Conical helix about (dfCZ, dfCX) until Y reaches dfPos (see [`MCC_ConeXY_Z`]).
    MCC_ConeZX_Y(dfCZ, dfCX) => ZX;
}
