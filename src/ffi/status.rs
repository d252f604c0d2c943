//! Motion status (user manual §2.6.5; vendor header "Motion Status").

use super::{read_published, write_out};
use crate::system;
use crate::vendor::consts as c;
use crate::vendor::WORD;
use std::os::raw::c_int;

/// The group's motion status (`GMS_*`). Reads the engine's published snapshot. Under the
/// fast and stepped clocks a poll repeated at the same virtual time is a program waiting:
/// virtual time runs (see `clock`), so `while (MCC_GetMotionStatus(g) != GMS_STOP);` ends.
#[no_mangle]
pub extern "system" fn MCC_GetMotionStatus(wGroupIndex: WORD) -> c_int {
    ffi_boundary! {
        let shared = system::active()?;
        let published = shared.published(wGroupIndex)?;
        let status = published.load_status();
        if status != c::GMS_STOP {
            shared.poll(wGroupIndex, status);
            return Ok(published.load_status());
        }
        Ok(status)
    }
}

/// The command being executed (`nType` -1 when none): type (user manual §2.6.5 codes
/// 0..10), index, feed speed (PtP: ratio; delay: ms left), target, acc/dec times,
/// phase (0 accelerating, 1 constant speed, 2 decelerating) and the count of commands
/// started since `MCC_ResetCommandIndexLD`.
/// With nothing running it writes the index of the last command started and returns
/// `RUN_TIME_ERR`, as the vendor's library does.
///
/// # Safety
/// `pstCurCommand` must be NULL (refused with `PARAMETER_ERR`) or point to a valid
/// `crate::vendor::COMMAND_INFO`.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetCurCommand(
    pstCurCommand: *mut crate::vendor::COMMAND_INFO,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        // SAFETY: forwarded under this function's contract.
        unsafe {
            let info = read_published(wGroupIndex, |p| p.load_info())?;
            write_out(pstCurCommand, || Ok(info.cmd))?;
            if info.running {
                Ok(crate::vendor::consts::NO_ERR)
            } else {
                Err(crate::error::McclError::RunTime)
            }
        }
    }
}

/// Commands queued and not yet started (the running one is not counted).
///
/// # Safety
/// `pnCmdCount` must be NULL (refused with `PARAMETER_ERR`) or point to a valid `c_int`.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetCommandCount(
    pnCmdCount: *mut c_int,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        // SAFETY: forwarded under this function's contract.
        unsafe {
            write_out(pnCmdCount, || {
                let n = super::with_group(wGroupIndex, |g| Ok(g.queued()))?;
                Ok(c_int::try_from(n).unwrap_or(c_int::MAX))
            })
        }
    }
}

/// The next queued command gets index 0 again (automatic numbering).
#[no_mangle]
pub extern "system" fn MCC_ResetCommandIndex(wGroupIndex: WORD) -> c_int {
    ffi_boundary! { super::update_group(wGroupIndex, |g| g.set_command_index(0, false)) }
}

/// The count of started commands (`COMMAND_INFO.nCommandIndex_LD`) restarts from 0.
#[no_mangle]
pub extern "system" fn MCC_ResetCommandIndexLD(wGroupIndex: WORD) -> c_int {
    ffi_boundary! { super::update_group(wGroupIndex, |g| g.reset_ld_index()) }
}

/// The next queued command gets index `wIndex`; with `bManualIndex` TRUE every following
/// command keeps that index (the program numbers its commands itself), with FALSE the
/// numbering counts on from it.
#[no_mangle]
pub extern "system" fn MCC_SetCommandIndex(
    wIndex: WORD,
    bManualIndex: crate::vendor::BOOL,
    wGroupIndex: WORD,
) -> c_int {
    ffi_boundary! {
        super::update_group(wGroupIndex, |g| {
            g.set_command_index(i32::from(wIndex), bManualIndex != 0)
        })
    }
}

/// The index of the last command started (0 before any; one queued and not started
/// yet does not count), as the vendor's library answers.
///
/// # Safety
/// `wIndex` must be NULL (refused with `PARAMETER_ERR`) or point to a valid `WORD`.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetCommandIndex(wIndex: *mut WORD, wGroupIndex: WORD) -> c_int {
    ffi_boundary! {
        // SAFETY: forwarded under this function's contract.
        unsafe {
            write_out(wIndex, || {
                let n = super::with_group(wGroupIndex, |g| Ok(g.last_command_index()))?;
                Ok(n as WORD)
            })
        }
    }
}

/// Depth of the card's pulse FIFO (> 0; at most [`MAX_PULSE_STOCK`], a larger one is
/// taken as that); returns the depth set, as the vendor's library does (default 1).
#[no_mangle]
pub extern "system" fn MCC_SetMaxPulseStockNum(nMaxStockNum: c_int) -> c_int {
    ffi_boundary! {
        let n = u32::try_from(nMaxStockNum)
            .ok()
            .filter(|n| *n >= 1)
            .ok_or(crate::error::McclError::Parameter)?
            .min(MAX_PULSE_STOCK);
        system::active()?.set_max_pulse_stock(n);
        Ok(n as c_int)
    }
}

/// The deepest pulse FIFO `MCC_SetMaxPulseStockNum` sets (the vendor's library: 63).
pub const MAX_PULSE_STOCK: u32 = 63;

/// The depth of the card's pulse FIFO.
#[no_mangle]
pub extern "system" fn MCC_GetMaxPulseStockNum() -> c_int {
    ffi_boundary! {
        let n = system::active()?.max_pulse_stock();
        Ok(c_int::try_from(n).unwrap_or(c_int::MAX))
    }
}

/// Fine movement commands waiting in a channel's FIFO. The virtual card never lets the
/// FIFO run dry: it holds the full depth while the channel's group moves, 0 when stopped.
///
/// # Safety
/// `pwStockCount` must be NULL (refused with `PARAMETER_ERR`) or writable.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetCurPulseStockCount(
    pwStockCount: *mut WORD,
    wChannel: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        let (cd, ch) = (super::card(wCardIndex)?, super::channel(wChannel)?);
        // SAFETY: forwarded under this function's contract.
        unsafe {
            write_out(pwStockCount, || {
                let shared = system::active()?;
                shared.card(cd)?;
                let moving = shared.channel_moving(cd.0, ch.0);
                let depth = shared.max_pulse_stock();
                let n = if moving {
                    depth.min(u32::from(WORD::MAX)) as WORD
                } else {
                    0
                };
                Ok(n)
            })
        }
    }
}

/// The group's error record (0 when none; codes in docs/vendor-interface.md).
#[no_mangle]
pub extern "system" fn MCC_GetErrorCode(wGroupIndex: WORD) -> c_int {
    ffi_boundary! { read_published(wGroupIndex, |p| p.load_info().error) }
}

/// Clears the group's error record; queued commands run again.
#[no_mangle]
pub extern "system" fn MCC_ClearError(wGroupIndex: WORD) -> c_int {
    ffi_boundary! { super::update_group(wGroupIndex, |g| g.clear_error()) }
}
