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
/// Reverse interpolation routine: `(group, command index, time index, buffer)` ->
/// > 0 forward, < 0 backward, 0 pause (`MCC_SetReverseInterpRoutine`).
pub type INTERP = Option<
    unsafe extern "C" fn(
        nGroup: std::os::raw::c_int,
        nCommandIndex: std::os::raw::c_int,
        nTimeIndex: std::os::raw::c_int,
        pvBuffer: *mut std::os::raw::c_void,
    ) -> std::os::raw::c_int,
>;
