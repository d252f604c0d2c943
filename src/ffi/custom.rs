//! Custom motion (vendor header, "Obsolete functions" section; docs/compatibility.md,
//! "Custom motion"): commands whose geometry the program's callbacks give, run by the
//! library's speed profile. The engine's side is in `engine/custom.rs`.

use super::queue;
use crate::engine::custom::{custom_interp, infinite_interp, Blending, CustomSpec, Interp};
use crate::engine::group::custom::command;
use crate::error::{McclError, McclResult};
use crate::vendor::{
    BOOL, CUSTOM_BLENDING, CUSTOM_BLENDING_END, CUSTOM_BLENDING_START, CUSTOM_CLEANUP,
    CUSTOM_INTERPOLATION, CUSTOM_START_MOTION, DWORD, INFINITE_CLEANUP, INFINITE_INTERPOLATION,
    INFINITE_START_MOTION, WORD,
};
use std::os::raw::{c_int, c_void};
use std::sync::Arc;

/// The checks and the queuing every form shares: NULL `start` or `interp` and a mask
/// with bits above B are `PARAMETER_ERR`, then the group's refusals; nothing is queued
/// on any error.
#[allow(clippy::too_many_arguments)]
fn custom(
    start: CUSTOM_START_MOTION,
    interp: Option<Interp>,
    cleanup: CUSTOM_CLEANUP,
    blending: Option<Blending>,
    buffer: *mut c_void,
    override_motion: BOOL,
    g: WORD,
    mask: DWORD,
) -> McclResult<c_int> {
    let interp = interp.ok_or(McclError::Parameter)?;
    if start.is_none() || mask & !0xFF != 0 {
        return Err(McclError::Parameter);
    }
    queue(g, |ctx| {
        let spec = CustomSpec::new(
            crate::engine::custom::next_id(),
            crate::engine::custom::live_count(),
            start,
            interp,
            cleanup,
            blending,
            buffer,
            override_motion != 0,
            mask,
            ctx.settings.absolute,
        )
        .ok_or(McclError::Parameter)?;
        Ok(command(ctx, Arc::new(spec)))
    })
}

/// Queues a custom motion of the axes in the mask: `pfnStartMotion` gives the total
/// distance when it starts, `pfnInterpolation` the offset from the start each period,
/// `pfnCleanUp` (may be NULL) is called once when it ends. The override applies.
/// Returns the command index.
#[no_mangle]
pub extern "system" fn MCC_CustomMotion(
    pfnStartMotion: CUSTOM_START_MOTION,
    pfnInterpolation: CUSTOM_INTERPOLATION,
    pfnCleanUp: CUSTOM_CLEANUP,
    pvBuffer: *mut c_void,
    wGroupIndex: WORD,
    dwAxisMask: DWORD,
) -> c_int {
    ffi_boundary! { custom(
        pfnStartMotion,
        custom_interp(pfnInterpolation),
        pfnCleanUp,
        None,
        pvBuffer,
        1,
        wGroupIndex,
        dwAxisMask,
    ) }
}

/// [`MCC_CustomMotion`] with blending callbacks (used while blending is on, all three or
/// none; NULL ones mean none) and `bOverrideMotion` (FALSE: the override ratio does not
/// change this motion's speed).
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub extern "system" fn MCC_CustomMotionEx(
    pfnStartMotion: CUSTOM_START_MOTION,
    pfnInterpolation: CUSTOM_INTERPOLATION,
    pfnCleanUp: CUSTOM_CLEANUP,
    pfnBlendingStart: CUSTOM_BLENDING_START,
    pfnBlending: CUSTOM_BLENDING,
    pfnBlendingEnd: CUSTOM_BLENDING_END,
    pvBuffer: *mut c_void,
    bOverrideMotion: BOOL,
    wGroupIndex: WORD,
    dwAxisMask: DWORD,
) -> c_int {
    ffi_boundary! {
        let blending = match (pfnBlendingStart, pfnBlending, pfnBlendingEnd) {
            (Some(_), Some(_), Some(_)) => Some(Blending {
                start: pfnBlendingStart,
                blend: pfnBlending,
                end: pfnBlendingEnd,
            }),
            (None, None, None) => None,
            // Some but not all: the blend could not be run as described.
            _ => return Err(McclError::Parameter),
        };
        custom(
            pfnStartMotion,
            custom_interp(pfnInterpolation),
            pfnCleanUp,
            blending,
            pvBuffer,
            bOverrideMotion,
            wGroupIndex,
            dwAxisMask,
        )
    }
}

/// Queues a motion with no end: the profile accelerates to the feed and cruises until the
/// callback returns FALSE or sets `*AbortThisCommand`, or the program aborts.
#[no_mangle]
pub extern "system" fn MCC_InfiniteMotion(
    pfnStartMotion: INFINITE_START_MOTION,
    pfnInterpolation: INFINITE_INTERPOLATION,
    pfnCleanUp: INFINITE_CLEANUP,
    pvBuffer: *mut c_void,
    bOverrideMotion: BOOL,
    wGroupIndex: WORD,
    dwAxisMask: DWORD,
) -> c_int {
    ffi_boundary! { custom(
        pfnStartMotion,
        infinite_interp(pfnInterpolation),
        pfnCleanUp,
        None,
        pvBuffer,
        bOverrideMotion,
        wGroupIndex,
        dwAxisMask,
    ) }
}
