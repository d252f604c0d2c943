//! Helices and spirals: the helix about a center by an angle (the third axis moving a
//! pitch per turn, U..B along in its `_Aux` form) and the spiral until the third axis
//! reaches a position (the obsolete helix; the cone builds on it too).

use super::plane_curve::{queue_about, About};
use crate::engine::command::Curve;
use crate::error::McclResult;
use crate::ffi::{direction, finite};
use crate::planner::{Axes, Path, Plane};
use crate::vendor::{BYTE, WORD};
use std::os::raw::c_int;

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
pub(in crate::ffi) struct SpiralTo {
    pub at: About,
    pub pos: f64,
    pub pitch: f64,
    pub dir: BYTE,
}

impl SpiralTo {
    /// About the center `c` of `plane` (U..B stay) until its third axis reaches `pos`,
    /// `pitch` per turn in direction `dir`.
    pub(in crate::ffi) fn new(plane: Plane, c: [f64; 2], pos: f64, pitch: f64, dir: BYTE) -> Self {
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
pub(in crate::ffi) fn queue_spiral(
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
