//! Jog motion (user manual ZH §2.6.2 III; vendor header "Jog Motion"), as the vendor's
//! library runs it: `MCC_JogSpace` and `MCC_JogConti` are queued point-to-point moves of
//! one axis, `MCC_JogPulse` moves the axis its pulses at once; each requires the group to
//! be stopped (`COMMAND_NOTFINISHED_ERR` otherwise). `cAxis` is the axis's number.

use super::{axis, finite, with_group};
use crate::error::{McclError, McclResult};
use crate::vendor::consts as c;
use crate::vendor::WORD;
use std::os::raw::{c_char, c_int};

/// Largest |nPulse| of `MCC_JogPulse`.
pub const MAX_JOG_PULSES: c_int = 2048;

/// A jog's speed ratio: a percentage in (0, 100].
fn ratio(r: f64) -> McclResult<f64> {
    if r > 0.0 && r <= 100.0 {
        Ok(r)
    } else {
        Err(McclError::Parameter)
    }
}

/// Queues a one-axis PtP move of axis `a` to `target(from, mech)` at `ratio` percent.
fn jog(
    g: WORD,
    a: usize,
    ratio: Option<f64>,
    target: impl FnOnce(f64, &crate::engine::command::AxisMech) -> f64,
) -> McclResult<c_int> {
    with_group(g, |grp| {
        if grp.busy() {
            return Err(McclError::NotFinished);
        }
        let ctx = grp.ctx();
        let mut to = ctx.from;
        to[a] = target(ctx.from[a], &ctx.axes[a]);
        let r = ratio.unwrap_or(ctx.settings.ptp_ratio);
        let cmd = ctx.ptp(to, r, false)?;
        grp.enqueue(cmd)
    })
}

/// Moves one axis by `nPulse` pulses (|nPulse| <= 2048) in the next period; the group
/// reads `GMS_RUNNING` for three periods. Not a queued command: it has no index.
#[no_mangle]
pub extern "C" fn MCC_JogPulse(nPulse: c_int, cAxis: c_char, wGroupIndex: WORD) -> c_int {
    ffi_boundary! {
        let a = axis(cAxis)?;
        if nPulse.unsigned_abs() > MAX_JOG_PULSES.unsigned_abs() {
            return Err(McclError::Parameter);
        }
        with_group(wGroupIndex, |grp| {
            grp.jog_pulses(a, nPulse)?;
            Ok(c::NO_ERR)
        })
    }
}

/// Moves one axis by `dfOffset` UU at `dfRatio` percent of its maximum safe speed.
#[no_mangle]
pub extern "C" fn MCC_JogSpace(
    dfOffset: f64,
    dfRatio: f64,
    cAxis: c_char,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let off = finite(dfOffset)?;
        let r = ratio(dfRatio)?;
        let a = axis(cAxis)?;
        jog(wGroupIndex, a, Some(r), |from, _| from + off)
    }
}

/// Moves one axis in direction `nDir` (1 or -1) at `dfRatio` percent until the work-zone
/// boundary (dfHighLimit / dfLowLimit); stop it earlier with `MCC_AbortMotionEx`.
#[no_mangle]
pub extern "C" fn MCC_JogConti(
    nDir: c_int,
    dfRatio: f64,
    cAxis: c_char,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        if nDir != 1 && nDir != -1 {
            return Err(McclError::Parameter);
        }
        let r = ratio(dfRatio)?;
        let a = axis(cAxis)?;
        jog(wGroupIndex, a, Some(r), |from, m| {
            if nDir > 0 {
                m.high.max(from)
            } else {
                m.low.min(from)
            }
        })
        .map(|i| i.max(c::NO_ERR))
    }
}
