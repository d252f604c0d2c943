//! The conical helix (vendor header, obsolete functions; the manuals do not describe
//! it): `MCC_ConeXY_Z(dfCX, dfCY, dfPos, dfPitch, CenterRate, byCirDir)` turns about the
//! center in direction `byCirDir` while the third axis goes to `dfPos` at `dfPitch` per
//! turn (as `MCC_HelicaXY_Z`), the radius changing by `CenterRate` UU per turn
//! ([`crate::planner::ConeSeg`]; docs/undocumented-functions.md). Queued like the
//! helices, reported as a helix (`COMMAND_INFO.nType` 4 clockwise, 5 counter-clockwise).

use super::finite;
use super::motion::{queue_spiral, SpiralTo};
use crate::error::McclResult;
use crate::planner::Path;
use crate::vendor::WORD;
use std::os::raw::c_int;

// Declared with the obsolete helices of the same planes (`plane_spirals!`); their Rust
// path stays here.
pub use super::motion::{MCC_ConeXY_Z, MCC_ConeYZ_X, MCC_ConeZX_Y};

/// Queues the conical helix `s` whose radius changes by `rate` per turn; the entry points
/// are declared with the obsolete helices (`plane_spirals!`, src/ffi/motion.rs).
pub(super) fn cone(s: SpiralTo, rate: f64, g: WORD) -> McclResult<c_int> {
    let rate = finite(rate)?;
    queue_spiral(s, g, |from, c, to, pitch, ccw| {
        Path::cone(s.at.plane, from, c, to, pitch, rate, ccw)
    })
}
