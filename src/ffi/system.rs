//! System management (user manual §2.4–2.5; vendor header "System Management").

use super::{card, channel, get_channel_config, set_channel_config};
use crate::config::{self, Config, GroupDef};
use crate::error::McclError;
use crate::error::McclResult;
use crate::system::{self, InitKind};
use crate::vendor::consts as c;
use crate::vendor::{SYS_CARD_CONFIG, SYS_ENCODER_CONFIG, SYS_HOME_CONFIG, SYS_MAC_PARAM, WORD};
use std::os::raw::{c_char, c_int};

/// The version string written by `MCC_GetVersion`: the vendor interface level this
/// library reproduces (short, because callers pass small buffers).
pub const VERSION_STRING: &[u8] = b"6.00\0";

/// Writes the library version ("6.00", NUL-terminated, 5 bytes) to `strVersion`.
/// A NULL pointer is ignored.
///
/// # Safety
/// Every pointer argument must be NULL (refused with `PARAMETER_ERR`) or point to
/// valid memory of the declared C type, as in the vendor library.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetVersion(strVersion: *mut c_char) {
    ffi_boundary! {
        if strVersion.is_null() {
            return Err(McclError::Parameter);
        }
        // SAFETY: non-null; the caller provides a buffer for the version string (the
        // vendor's is 5 bytes, the same as ours).
        unsafe {
            std::ptr::copy_nonoverlapping(
                VERSION_STRING.as_ptr().cast::<c_char>(),
                strVersion,
                VERSION_STRING.len(),
            )
        };
        Ok(())
    }
}

/// Sets the upper limit of the general-motion feed speed (UU/s, in the speed range
/// 1e-6..=1e9 of `config::range`).
#[no_mangle]
pub extern "system" fn MCC_SetSysMaxSpeed(dfMaxSpeed: f64) -> c_int {
    ffi_boundary! {
        let v = config::range::speed(dfMaxSpeed)?;
        system::config(|c| c.sys_max_speed = v);
        Ok(c::NO_ERR)
    }
}

/// The upper limit of the general-motion feed speed (UU/s).
#[no_mangle]
pub extern "system" fn MCC_GetSysMaxSpeed() -> f64 {
    ffi_boundary! { Ok(system::config(|c| c.sys_max_speed)) }
}

/// Sets the mechanism parameters of one channel (§2.4.1). After `MCC_InitSystem` they
/// take effect at `MCC_UpdateParam`.
///
/// # Safety
/// `pstMacParam` must be NULL (refused with `PARAMETER_ERR`) or point to a valid `SYS_MAC_PARAM`.
#[no_mangle]
pub unsafe extern "system" fn MCC_SetMacParam(
    pstMacParam: *mut SYS_MAC_PARAM,
    wChannel: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        // SAFETY: forwarded under this function's contract.
        unsafe { set_channel_config(pstMacParam, wChannel, wCardIndex, Config::set_mac_param) }
    }
}

/// Reads the mechanism parameters last set for one channel.
///
/// # Safety
/// `pstMacParam` must be NULL (refused with `PARAMETER_ERR`) or point to a valid `SYS_MAC_PARAM`.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetMacParam(
    pstMacParam: *mut SYS_MAC_PARAM,
    wChannel: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        // SAFETY: forwarded under this function's contract.
        unsafe { get_channel_config(pstMacParam, wChannel, wCardIndex, |c| &c.mac) }
    }
}

/// Sets the encoder configuration of one channel (§2.4.2).
///
/// # Safety
/// `pstEncoderConfig` must be NULL (refused with `PARAMETER_ERR`) or point to a valid
/// `SYS_ENCODER_CONFIG`.
#[no_mangle]
pub unsafe extern "system" fn MCC_SetEncoderConfig(
    pstEncoderConfig: *mut SYS_ENCODER_CONFIG,
    wChannel: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        // SAFETY: forwarded under this function's contract.
        unsafe {
            set_channel_config(
                pstEncoderConfig,
                wChannel,
                wCardIndex,
                Config::set_encoder_config,
            )
        }
    }
}

/// Reads the encoder configuration last set for one channel.
///
/// # Safety
/// `pstEncoderConfig` must be NULL (refused with `PARAMETER_ERR`) or point to a valid
/// `SYS_ENCODER_CONFIG`.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetEncoderConfig(
    pstEncoderConfig: *mut SYS_ENCODER_CONFIG,
    wChannel: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        // SAFETY: forwarded under this function's contract.
        unsafe { get_channel_config(pstEncoderConfig, wChannel, wCardIndex, |c| &c.encoder) }
    }
}

/// Sets the go-home parameters of one channel (§2.4.3); mode 0..19 (`MCC_Home` runs
/// 3..16).
///
/// # Safety
/// `pstHomeConfig` must be NULL (refused with `PARAMETER_ERR`) or point to a valid
/// `SYS_HOME_CONFIG`.
#[no_mangle]
pub unsafe extern "system" fn MCC_SetHomeConfig(
    pstHomeConfig: *mut SYS_HOME_CONFIG,
    wChannel: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        // SAFETY: forwarded under this function's contract.
        unsafe { set_channel_config(pstHomeConfig, wChannel, wCardIndex, Config::set_home_config) }
    }
}

/// Reads the go-home parameters last set for one channel.
///
/// # Safety
/// `pstHomeConfig` must be NULL (refused with `PARAMETER_ERR`) or point to a valid
/// `SYS_HOME_CONFIG`.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetHomeConfig(
    pstHomeConfig: *mut SYS_HOME_CONFIG,
    wChannel: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        // SAFETY: forwarded under this function's contract.
        unsafe { get_channel_config(pstHomeConfig, wChannel, wCardIndex, |c| &c.home) }
    }
}

/// Removes every group (only while the system is closed).
#[no_mangle]
pub extern "system" fn MCC_CloseAllGroups() -> c_int {
    ffi_boundary! { system::with(|s| s.close_all_groups()).map(|()| c::NO_ERR) }
}

/// Creates a group of `nMotionQueueSize` commands mapping axes X..B to the channels of
/// `map` on card `nCardIndex`; its index.
fn create_group(map: [c_int; 8], nCardIndex: c_int, nMotionQueueSize: c_int) -> McclResult<c_int> {
    let def = GroupDef::new(map, nCardIndex, nMotionQueueSize)?;
    let g = system::with(|s| s.create_group(def))?;
    Ok(g as c_int)
}

/// Creates a group with a queue of `MOTION_QUEUE_SIZE` commands; returns its index.
#[no_mangle]
pub extern "system" fn MCC_CreateGroup(
    xMapToCh: c_int,
    yMapToCh: c_int,
    zMapToCh: c_int,
    uMapToCh: c_int,
    vMapToCh: c_int,
    wMapToCh: c_int,
    aMapToCh: c_int,
    bMapToCh: c_int,
    nCardIndex: c_int,
) -> c_int {
    ffi_boundary! {
        let map = [
            xMapToCh, yMapToCh, zMapToCh, uMapToCh, vMapToCh, wMapToCh, aMapToCh, bMapToCh,
        ];
        create_group(map, nCardIndex, c::MOTION_QUEUE_SIZE)
    }
}

/// Creates a group mapping axes X..B to channels of one card (-1: unused) with a queue
/// of `nMotionQueueSize` commands; returns the group index (lowest free slot).
#[no_mangle]
pub extern "system" fn MCC_CreateGroupEx(
    xMapToCh: c_int,
    yMapToCh: c_int,
    zMapToCh: c_int,
    uMapToCh: c_int,
    vMapToCh: c_int,
    wMapToCh: c_int,
    aMapToCh: c_int,
    bMapToCh: c_int,
    nCardIndex: c_int,
    nMotionQueueSize: c_int,
) -> c_int {
    ffi_boundary! {
        let map = [
            xMapToCh, yMapToCh, zMapToCh, uMapToCh, vMapToCh, wMapToCh, aMapToCh, bMapToCh,
        ];
        create_group(map, nCardIndex, nMotionQueueSize)
    }
}

/// Removes one group (only while the system is closed).
#[no_mangle]
pub extern "system" fn MCC_CloseGroup(nGroupIndex: c_int) -> c_int {
    ffi_boundary! { system::with(|s| s.close_group(nGroupIndex)).map(|()| c::NO_ERR) }
}

/// The capacity of a group's motion command queue (0 for no such group, as the vendor's
/// library answers).
#[no_mangle]
pub extern "system" fn MCC_GetCmdQueueSize(wGroupIndex: WORD) -> c_int {
    ffi_boundary! {
        match system::with(|s| s.group_def(wGroupIndex)) {
            Ok(def) => Ok(c_int::try_from(def.queue_size).unwrap_or(c_int::MAX)),
            Err(_) => Ok(0),
        }
    }
}

/// Changes no queue, as the vendor's library answers (measured, before init and after,
/// for existing groups and others): `GROUP_PARAMETER_ERR` for a size below 1, else
/// `RUN_TIME_ERR`. A queue's size is set when its group is created
/// (`MCC_CreateGroupEx`), as the English user manual says (§2.3).
#[no_mangle]
pub extern "system" fn MCC_SetCmdQueueSize(nSize: c_int, wGroupIndex: WORD) -> c_int {
    ffi_boundary! {
        let _ = wGroupIndex;
        if nSize < 1 {
            Err(McclError::Group)
        } else {
            Err(McclError::RunTime)
        }
    }
}

/// Reads `wCardNo` card descriptions (1..=MAX_CARD_NUM) from C.
///
/// # Safety
/// `p` must be NULL or point to `n` readable `SYS_CARD_CONFIG`.
unsafe fn card_configs(
    p: *mut SYS_CARD_CONFIG,
    n: WORD,
) -> Result<Vec<SYS_CARD_CONFIG>, McclError> {
    let n = usize::from(n);
    if n == 0 || n > config::CARDS {
        return Err(McclError::Parameter);
    }
    // No table: every card an IMP-III (the vendor's library takes NULL so).
    if p.is_null() {
        let imp3 = SYS_CARD_CONFIG {
            wCardType: c::IMP_III_8_AXIS_PCI_CARD,
            ..SYS_CARD_CONFIG::default()
        };
        return Ok(vec![imp3; n]);
    }
    // SAFETY: non-null; the caller passes an array of wCardNo SYS_CARD_CONFIG (the
    // vendor's contract); each element is read unaligned.
    Ok((0..n)
        .map(|i| unsafe { p.add(i).read_unaligned() })
        .collect())
}

/// # Safety
/// `p` must be NULL or point to `n` readable `SYS_CARD_CONFIG`.
unsafe fn init(ms: f64, p: *mut SYS_CARD_CONFIG, n: WORD, kind: InitKind) -> McclResult<c_int> {
    let period = system::check_period_ms(ms)?;
    // SAFETY: card_configs checks NULL and the count; see its contract.
    let cards = unsafe { card_configs(p, n) }?;
    system::init(period, &cards, kind)?;
    Ok(c::NO_ERR)
}

/// Starts the library and the virtual card with an interpolation period of
/// `nInterpolateTime` ms (1..50) for `wCardNo` cards described in `pstCardConfig`.
///
/// # Safety
/// Every pointer argument must be NULL (refused with `PARAMETER_ERR`) or point to
/// valid memory of the declared C type, as in the vendor library.
#[no_mangle]
pub unsafe extern "system" fn MCC_InitSystem(
    nInterpolateTime: c_int,
    pstCardConfig: *mut SYS_CARD_CONFIG,
    wCardNo: WORD,
) -> c_int {
    ffi_boundary! {
        // SAFETY: forwarded under this function's contract.
        unsafe {
            init(
                f64::from(nInterpolateTime),
                pstCardConfig,
                wCardNo,
                InitKind::System,
            )
        }
    }
}

/// `MCC_InitSystem` with a fractional interpolation period in ms (1.0..=50.0).
///
/// # Safety
/// Every pointer argument must be NULL (refused with `PARAMETER_ERR`) or point to
/// valid memory of the declared C type, as in the vendor library.
#[no_mangle]
pub unsafe extern "system" fn MCC_InitSystemEx(
    dfInterpolateTime: f64,
    pstCardConfig: *mut SYS_CARD_CONFIG,
    wCardNo: WORD,
) -> c_int {
    ffi_boundary! {
    // SAFETY: forwarded under this function's contract.
        unsafe { init(dfInterpolateTime, pstCardConfig, wCardNo, InitKind::System) }
        }
}

/// Starts the library in simulation mode: the same virtual card, never a hardware backend.
///
/// # Safety
/// Every pointer argument must be NULL (refused with `PARAMETER_ERR`) or point to
/// valid memory of the declared C type, as in the vendor library.
#[no_mangle]
pub unsafe extern "system" fn MCC_InitSimulation(
    nInterpolateTime: c_int,
    pstCardConfig: *mut SYS_CARD_CONFIG,
    wCardNo: WORD,
) -> c_int {
    ffi_boundary! {
        // SAFETY: forwarded under this function's contract.
        unsafe {
            init(
                f64::from(nInterpolateTime),
                pstCardConfig,
                wCardNo,
                InitKind::Simulation,
            )
        }
    }
}

/// Stops the card at once and releases the engine thread; with no system running it
/// does nothing and returns `NO_ERR`, as the vendor's library does.
#[no_mangle]
pub extern "system" fn MCC_CloseSystem() -> c_int {
    ffi_boundary! { system::close().map(|()| c::NO_ERR) }
}

/// Returns every group to its state right after `MCC_InitSystem`, settings kept: motion
/// stops at once and positions restart from 0 (`COMMAND_NOTACCEPTED_ERR`, reset all the
/// same, when a group was busy, as the vendor's library answers).
#[no_mangle]
pub extern "system" fn MCC_ResetMotion() -> c_int {
    ffi_boundary! { system::reset_motion().map(|()| c::NO_ERR) }
}

/// Applies mechanism and encoder parameters set since init; resets motion (§2.4.2).
#[no_mangle]
pub extern "system" fn MCC_UpdateParam() -> c_int {
    ffi_boundary! { system::update_param().map(|()| c::NO_ERR) }
}

/// Pulses per user unit of a channel: dwPPR x dfGearRatio / dfPitch of the mechanism
/// parameters in effect, negative for a reversed output (`wPosToEncoderDir` nonzero). A
/// bad channel or card reads 0, as the vendor's library answers.
#[no_mangle]
pub extern "system" fn MCC_GetConvFactor(wChannel: WORD, wCardIndex: WORD) -> f64 {
    ffi_boundary! {
        let (Ok(cd), Ok(ch)) = (card(wCardIndex), channel(wChannel)) else {
            return Ok(0.0);
        };
        Ok(system::with(|s| s.conv_factor(cd, ch)))
    }
}

/// Turns dry run on: trajectories are planned and reported, nothing moves
/// (`COMMAND_NOTACCEPTED_ERR` when a card is an MC3B: its motion is the device's).
#[no_mangle]
pub extern "system" fn MCC_EnableDryRun() -> c_int {
    ffi_boundary! {
        let shared = system::active()?;
        if system::has_mc3b() {
            return Err(crate::error::McclError::NotAccepted);
        }
        shared.set_dry_run(true);
        Ok(c::NO_ERR)
    }
}

/// Turns dry run off.
#[no_mangle]
pub extern "system" fn MCC_DisableDryRun() -> c_int {
    ffi_boundary! {
        system::active()?.set_dry_run(false);
        Ok(c::NO_ERR)
    }
}

/// 0 when dry run is on, 1 when off (the same sense as `MCC_CheckBlend`).
#[no_mangle]
pub extern "system" fn MCC_CheckDryRun() -> c_int {
    ffi_boundary! {
        Ok(c_int::from(
            !system::active()?.dry_run(),
        ))
    }
}
