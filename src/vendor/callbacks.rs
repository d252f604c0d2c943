//! ISR callback types of MCCL.h (docs/vendor-interface.md, "Callback types"). `NULL` is `None`.

use super::structs::{ADCINT, ENCINT, HSKINT, LIOINT, PCLINT, RIOINT, TMRINT};

/// Position-control-loop ISR.
pub type PCLISR = Option<unsafe extern "C" fn(*mut PCLINT)>;
/// A/D converter ISR.
pub type ADCISR = Option<unsafe extern "C" fn(*mut ADCINT)>;
/// Local I/O ISR.
pub type LIOISR = Option<unsafe extern "C" fn(*mut LIOINT)>;
/// Encoder ISR.
pub type ENCISR = Option<unsafe extern "C" fn(*mut ENCINT)>;
/// Remote I/O ISR.
pub type RIOISR = Option<unsafe extern "C" fn(*mut RIOINT)>;
/// Timer ISR.
pub type TMRISR = Option<unsafe extern "C" fn(*mut TMRINT)>;
/// Handshake ISR.
pub type HSKISR = Option<unsafe extern "C" fn(*mut HSKINT)>;
/// Cycle interrupt ISR (obsolete form).
pub type CYCLE_INTERRUPT_ISR = Option<unsafe extern "C" fn()>;
/// Initialises a kinematic group's extension buffer once (`MCC_SetKinematicTrans`).
pub type INIT_EXTENSION = Option<unsafe extern "C" fn(pvExtension: *mut std::ffi::c_void)>;
/// Forward kinematics: joints (`pdfFrom`) to the Cartesian position (`pdfTo`); `FALSE`
/// when it has none. The vendor's C++ `DWORD&` posture is a `DWORD*` (the same ABI).
pub type FWDKINEFUN = Option<
    unsafe extern "C" fn(
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
    unsafe extern "C" fn(
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
    unsafe extern "C" fn(
        nGroup: std::os::raw::c_int,
        nSynAxisNum: std::os::raw::c_int,
        pdfCurCPos: *const f64,
        pdfTgtCPos: *const f64,
        pdfOffset: *mut f64,
        pvExtension: *mut std::ffi::c_void,
    ),
>;
