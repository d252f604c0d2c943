//! ISR callback types of MCCL.h (docs/vendor-interface.md, "Callback types"). `NULL` is `None`.

use super::structs::{ADCINT, ENCINT, HSKINT, LIOINT, PCLINT, RIOINT, TMRINT};

/// Position-control-loop ISR.
pub type PCLISR = Option<unsafe extern "system" fn(*mut PCLINT)>;
/// A/D converter ISR.
pub type ADCISR = Option<unsafe extern "system" fn(*mut ADCINT)>;
/// Local I/O ISR.
pub type LIOISR = Option<unsafe extern "system" fn(*mut LIOINT)>;
/// Encoder ISR.
pub type ENCISR = Option<unsafe extern "system" fn(*mut ENCINT)>;
/// Remote I/O ISR.
pub type RIOISR = Option<unsafe extern "system" fn(*mut RIOINT)>;
/// Timer ISR.
pub type TMRISR = Option<unsafe extern "system" fn(*mut TMRINT)>;
/// Handshake ISR.
pub type HSKISR = Option<unsafe extern "system" fn(*mut HSKINT)>;
/// Cycle interrupt ISR (obsolete form).
pub type CYCLE_INTERRUPT_ISR = Option<unsafe extern "system" fn()>;

/// `CUSTOM_START_MOTION`: called when a custom motion starts; returns its total distance.
/// Arguments: group, number of axes, command index, absolute coordinates, the start
/// position (one value per axis), the program's buffer.
pub type CUSTOM_START_MOTION = Option<
    unsafe extern "system" fn(
        std::os::raw::c_int,
        std::os::raw::c_int,
        std::os::raw::c_int,
        super::BOOL,
        *const f64,
        *mut std::os::raw::c_void,
    ) -> f64,
>;
/// `INFINITE_START_MOTION`: as [`CUSTOM_START_MOTION`], for `MCC_InfiniteMotion`.
pub type INFINITE_START_MOTION = CUSTOM_START_MOTION;
/// `CUSTOM_INTERPOLATION`: called every period with the start and current positions, the
/// distance the speed profile reaches at the next period and the total; writes the next
/// position's offset from the start. FALSE ends the command.
pub type CUSTOM_INTERPOLATION = Option<
    unsafe extern "system" fn(
        std::os::raw::c_int,
        std::os::raw::c_int,
        std::os::raw::c_int,
        *const f64,
        *const f64,
        f64,
        f64,
        *mut f64,
        *mut std::os::raw::c_void,
    ) -> super::BOOL,
>;
/// `INFINITE_INTERPOLATION`: [`CUSTOM_INTERPOLATION`] plus `BOOL *AbortThisCommand`.
pub type INFINITE_INTERPOLATION = Option<
    unsafe extern "system" fn(
        std::os::raw::c_int,
        std::os::raw::c_int,
        std::os::raw::c_int,
        *const f64,
        *const f64,
        f64,
        f64,
        *mut f64,
        *mut std::os::raw::c_void,
        *mut super::BOOL,
    ) -> super::BOOL,
>;
/// `CUSTOM_CLEANUP`: called once when a started custom motion ends (group, command
/// index, buffer).
pub type CUSTOM_CLEANUP = Option<
    unsafe extern "system" fn(std::os::raw::c_int, std::os::raw::c_int, *mut std::os::raw::c_void),
>;
/// `INFINITE_CLEANUP`: as [`CUSTOM_CLEANUP`].
pub type INFINITE_CLEANUP = CUSTOM_CLEANUP;
/// `CUSTOM_BLENDING_START`: the corner before a custom motion with blending on (group,
/// axes, command index, absolute, start0, start1, start2, mid, end0, end1, end2, blend
/// interval, buffer).
pub type CUSTOM_BLENDING_START = Option<
    unsafe extern "system" fn(
        std::os::raw::c_int,
        std::os::raw::c_int,
        std::os::raw::c_int,
        super::BOOL,
        *const f64,
        *const f64,
        *const f64,
        *const f64,
        *const f64,
        *const f64,
        *const f64,
        f64,
        *mut std::os::raw::c_void,
    ) -> super::BOOL,
>;
/// `CUSTOM_BLENDING`: one period of the blend (group, axes, command index, blend start,
/// blend end, current position, distance, next offset out, buffer).
pub type CUSTOM_BLENDING = Option<
    unsafe extern "system" fn(
        std::os::raw::c_int,
        std::os::raw::c_int,
        std::os::raw::c_int,
        *const f64,
        *const f64,
        *const f64,
        f64,
        *mut f64,
        *mut std::os::raw::c_void,
    ) -> super::BOOL,
>;
/// `CUSTOM_BLENDING_END`: the blend is over (group, command index, buffer).
pub type CUSTOM_BLENDING_END = Option<
    unsafe extern "system" fn(
        std::os::raw::c_int,
        std::os::raw::c_int,
        *mut std::os::raw::c_void,
    ) -> super::BOOL,
>;
/// Reverse interpolation routine: `(group, command index, time index, buffer)` ->
/// > 0 forward, < 0 backward, 0 pause (`MCC_SetReverseInterpRoutine`).
pub type INTERP = Option<
    unsafe extern "system" fn(
        nGroup: std::os::raw::c_int,
        nCommandIndex: std::os::raw::c_int,
        nTimeIndex: std::os::raw::c_int,
        pvBuffer: *mut std::os::raw::c_void,
    ) -> std::os::raw::c_int,
>;
/// Initialises a kinematic group's extension buffer once (`MCC_SetKinematicTrans`).
pub type INIT_EXTENSION = Option<unsafe extern "system" fn(pvExtension: *mut std::ffi::c_void)>;
/// Forward kinematics: joints (`pdfFrom`) to the Cartesian position (`pdfTo`); `FALSE`
/// when it has none. The vendor's C++ `DWORD&` posture is a `DWORD*` (the same ABI).
pub type FWDKINEFUN = Option<
    unsafe extern "system" fn(
        nGroup: std::os::raw::c_int,
        nSynAxisNum: std::os::raw::c_int,
        pdfFrom: *const f64,
        pdfTo: *mut f64,
        dwPosture: *mut super::DWORD,
        pvExtension: *mut std::ffi::c_void,
    ) -> super::BOOL,
>;
/// Inverse kinematics: a Cartesian position (`pdfFrom`) to joints (`pdfTo`), given the
/// previous joints (`pdfPrevResult`); `FALSE` when unreachable.
pub type INVKINEFUN = Option<
    unsafe extern "system" fn(
        nGroup: std::os::raw::c_int,
        nSynAxisNum: std::os::raw::c_int,
        pdfFrom: *const f64,
        pdfPrevResult: *const f64,
        pdfTo: *mut f64,
        dwPosture: *mut super::DWORD,
        pvExtension: *mut std::ffi::c_void,
    ) -> super::BOOL,
>;
/// Called when a kinematic group takes a command from its queue: the current and target
/// Cartesian positions; the offset written to `pdfOffset` is added to the target.
pub type PRE_PROCESS_MOTION_COMMAND = Option<
    unsafe extern "system" fn(
        nGroup: std::os::raw::c_int,
        nSynAxisNum: std::os::raw::c_int,
        pdfCurCPos: *const f64,
        pdfTgtCPos: *const f64,
        pdfOffset: *mut f64,
        pvExtension: *mut std::ffi::c_void,
    ),
>;
