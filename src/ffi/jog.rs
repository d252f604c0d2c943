//! Jog motion (user manual ZH §2.6.2 III; vendor header "Jog Motion"), as the vendor's
//! library runs it: `MCC_JogSpace` and `MCC_JogConti` are point-to-point moves of one axis
//! queued like any command (behind what runs), `MCC_JogPulse` moves the axis its pulses
//! at once and only while the group stands still (`COMMAND_NOTFINISHED_ERR` otherwise).
//! `cAxis` is the axis's number, checked first; an axis the group lacks is
//! `GROUP_PARAMETER_ERR`.

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
        grp.own_axis(a)?;
        let ctx = grp.ctx();
        let mut to = ctx.from;
        to[a] = target(ctx.from[a], &ctx.axes[a]);
        let r = ratio.unwrap_or(ctx.settings.ptp_ratio);
        let cmd = ctx.ptp(to, r, false)?;
        super::enqueue(grp, cmd)
    })
}

/// Moves one axis by `nPulse` pulses (|nPulse| <= 2048) in the next period; the group
/// reads `GMS_RUNNING` for three periods. Not a queued command: it has no index.
#[no_mangle]
pub extern "system" fn MCC_JogPulse(nPulse: c_int, cAxis: c_char, wGroupIndex: WORD) -> c_int {
    ffi_boundary! {
        let a = axis(cAxis)?;
        if nPulse.unsigned_abs() > MAX_JOG_PULSES.unsigned_abs() {
            return Err(McclError::Parameter);
        }
        with_group(wGroupIndex, |grp| {
            grp.own_axis(a)?;
            grp.jog_pulses(a, nPulse)?;
            Ok(c::NO_ERR)
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
        let a = axis(cAxis)?;
        let off = finite(dfOffset)?;
        let r = ratio(dfRatio)?;
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
        let a = axis(cAxis)?;
        if nDir != 1 && nDir != -1 {
            return Err(McclError::Parameter);
        }
        let r = ratio(dfRatio)?;
        // As far as the work zone's bound is from 0, from where the axis is (the
        // vendor's library, measured: from 0.1 with a high limit of 50,000 it heads for
        // 50,000.1).
        jog(wGroupIndex, a, Some(r), |from, m| {
            if nDir > 0 {
                from + m.high
            } else {
                from + m.low
            }
        })
        .map(|i| i.max(c::NO_ERR))
    }
}
