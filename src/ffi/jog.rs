//! Jog motion (user manual ZH §2.6.2 III; vendor header "Jog Motion"). Every jog is a
//! queued point-to-point move of one axis and requires the group to be stopped
//! (`COMMAND_NOTACCEPTED_ERR` otherwise).

use super::{axis, finite, with_group};
use crate::error::{McclError, McclResult};
use crate::vendor::consts as c;
use crate::vendor::WORD;
use std::os::raw::{c_char, c_int};

/// Largest |nPulse| of `MCC_JogPulse`.
pub const MAX_JOG_PULSES: c_int = 2048;

fn ratio(r: f64) -> McclResult<f64> {
    crate::config::range::percent(r, 100.0)
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
            return Err(McclError::NotAccepted);
        }
        let ctx = grp.ctx();
        let mut to = ctx.from;
        to[a] = target(ctx.from[a], &ctx.axes[a]);
        let r = ratio.unwrap_or(ctx.settings.ptp_ratio);
        let cmd = ctx.ptp(to, r, false)?;
        grp.enqueue(cmd)
    })
}

/// Moves one axis by `nPulse` pulses (|nPulse| <= 2048) at the PtP speed ratio.
#[no_mangle]
pub extern "system" fn MCC_JogPulse(nPulse: c_int, cAxis: c_char, wGroupIndex: WORD) -> c_int {
    ffi_boundary! {
        if nPulse.unsigned_abs() > MAX_JOG_PULSES.unsigned_abs() {
            return Err(McclError::Parameter);
        }
        let a = axis(cAxis)?;
        jog(wGroupIndex, a, None, |from, m| {
            from + f64::from(nPulse) / m.factor.abs()
        })
    }
}

/// Moves one axis by `dfOffset` UU at `dfRatio` percent of its maximum safe speed.
#[no_mangle]
pub extern "system" fn MCC_JogSpace(
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
pub extern "system" fn MCC_JogConti(
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
