//! Remote I/O (user manual §2.14; examples manual §33–34; vendor header "Remote
//! Input/Output Control", the B/C signatures with `wSet`). Behaviour in
//! `crate::card::rio`: 2 sets; RIO has 4 ports (one slave each), ARIO 32 slaves (the
//! `wPort` argument names the slave); RIO data moves once per tick, ARIO data once per
//! cycle (update rate, clock divider, node-to-node delay); simulated slaves loop their
//! outputs back to their inputs unless set otherwise from Rust. Statuses read 1 for
//! normal transfer, 0 for an error; a slave's failure is reported once it has failed more
//! consecutive transfers than `MCC_SetRIOTransError` tolerates. Bad card, set, port,
//! slave, input, value or NULL: `PARAMETER_ERR`, nothing changed.

use super::{card_do, with_card, write_out, Done};
use crate::card::rio::{Master, Set, ARIO_SLAVES, RIO_PORTS};
use crate::error::McclResult;
use crate::vendor::consts as c;
use crate::vendor::{DWORD, WORD};
use std::os::raw::c_int;

/// How a card's remote I/O gives one of its RIO or ARIO sets: [`rio_sets`] or
/// [`ario_sets`] (a bad set is `PARAMETER_ERR`).
type Pick<const N: usize> = fn(&mut Master, usize) -> McclResult<&mut Set<N>>;

/// Runs `f` on set `wSet` of the card's RIO or ARIO sets (`pick`): `INITIAL_MOTION_ERR`
/// before init whatever the arguments, then `PARAMETER_ERR` for a bad set or card.
fn on_set<const N: usize, R>(
    pick: Pick<N>,
    wSet: WORD,
    wCardIndex: WORD,
    f: impl FnOnce(&mut Set<N>) -> McclResult<R>,
) -> McclResult<R> {
    super::initialised()?;
    with_card(wCardIndex, |p| {
        f(pick(p.remote_io_mut(), usize::from(wSet))?)
    })
}

/// RIO set `set` of a card's remote I/O.
fn rio_sets(m: &mut Master, set: usize) -> McclResult<&mut Set<RIO_PORTS>> {
    m.rio_set_mut(set)
}

/// ARIO set `set` of a card's remote I/O.
fn ario_sets(m: &mut Master, set: usize) -> McclResult<&mut Set<ARIO_SLAVES>> {
    m.ario_set_mut(set)
}

/// Runs setter `f` on set `wSet` of the sets `pick` chooses (see [`on_set`]); `NO_ERR`.
fn set_do<const N: usize, D: Done>(
    pick: Pick<N>,
    wSet: WORD,
    wCardIndex: WORD,
    f: impl FnOnce(&mut Set<N>) -> D,
) -> McclResult<c_int> {
    on_set(pick, wSet, wCardIndex, |s| f(s).done())?;
    Ok(c::NO_ERR)
}

/// Writes a value read by `get` to `p` (checked first).
///
/// # Safety
/// `p` must be NULL or point to a writable T.
unsafe fn read<T>(p: *mut T, get: impl FnOnce() -> McclResult<T>) -> McclResult<c_int> {
    super::initialised()?;
    // SAFETY: forwarded under this function's contract.
    unsafe { write_out(p, get) }
}

/// Writes what `get` reads from set `wSet` of the sets `pick` chooses (see [`on_set`]) to
/// `p` (checked first).
///
/// # Safety
/// `p` must be NULL or point to a writable T.
unsafe fn read_set<const N: usize, T>(
    p: *mut T,
    pick: Pick<N>,
    wSet: WORD,
    wCardIndex: WORD,
    get: impl FnOnce(&mut Set<N>) -> McclResult<T>,
) -> McclResult<c_int> {
    // SAFETY: forwarded under this function's contract.
    unsafe { read(p, || on_set(pick, wSet, wCardIndex, get)) }
}

/// Writes a status of set `wSet` (see [`read_set`]).
///
/// # Safety
/// `p` must be NULL or point to a writable T.
unsafe fn read_status<const N: usize, T>(
    p: *mut T,
    pick: Pick<N>,
    wSet: WORD,
    wCardIndex: WORD,
    status: fn(&Set<N>) -> T,
) -> McclResult<c_int> {
    // SAFETY: forwarded under this function's contract.
    unsafe { read_set(p, pick, wSet, wCardIndex, |s| Ok(status(s))) }
}

/// Turns data transfer with slave `wSlave` of set `wSet` on or off (see [`set_do`]).
fn slave_control<const N: usize>(
    pick: Pick<N>,
    wSet: WORD,
    wSlave: WORD,
    wCardIndex: WORD,
    on: bool,
) -> McclResult<c_int> {
    set_do(pick, wSet, wCardIndex, |s| s.set_slave_control(wSlave, on))
}

// ---- RIO ----

/// Starts data transfer of a RIO set.
#[no_mangle]
pub extern "system" fn MCC_EnableRIOSetControl(wSet: WORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! {
        card_do(wCardIndex, |p| {
            p.remote_io_mut().set_rio_control(usize::from(wSet), true)
        })
    }
}

/// Stops data transfer of a RIO set.
#[no_mangle]
pub extern "system" fn MCC_DisableRIOSetControl(wSet: WORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! {
        card_do(wCardIndex, |p| {
            p.remote_io_mut().set_rio_control(usize::from(wSet), false)
        })
    }
}

/// Starts data transfer with one slave (0..3, the slave on port n) of a RIO set.
#[no_mangle]
pub extern "system" fn MCC_EnableRIOSlaveControl(
    wSet: WORD,
    wSlave: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! { slave_control(rio_sets, wSet, wSlave, wCardIndex, true) }
}

/// Stops data transfer with one slave of a RIO set.
#[no_mangle]
pub extern "system" fn MCC_DisableRIOSlaveControl(
    wSet: WORD,
    wSlave: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! { slave_control(rio_sets, wSet, wSlave, wCardIndex, false) }
}

/// Transfer status of a RIO set: 1 normal, 0 error (master or a transmitting slave).
///
/// # Safety
/// `pwStatus` must be NULL (refused with `PARAMETER_ERR`) or point to a valid `WORD`.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetRIOTransStatus(
    pwStatus: *mut WORD,
    wSet: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        // SAFETY: forwarded under this function's contract.
        unsafe { read_status(pwStatus, rio_sets, wSet, wCardIndex, Set::trans_status) }
    }
}

/// Master status of a RIO set: 1 normal, 0 error.
///
/// # Safety
/// `pwStatus` must be NULL (refused with `PARAMETER_ERR`) or point to a valid `WORD`.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetRIOMasterStatus(
    pwStatus: *mut WORD,
    wSet: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        // SAFETY: forwarded under this function's contract.
        unsafe { read_status(pwStatus, rio_sets, wSet, wCardIndex, Set::master_status) }
    }
}

/// Slave status of a RIO set: 1 when every transmitting slave works, 0 otherwise.
///
/// # Safety
/// `pwStatus` must be NULL (refused with `PARAMETER_ERR`) or point to a valid `WORD`.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetRIOSlaveStatus(
    pwStatus: *mut WORD,
    wSet: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        // SAFETY: forwarded under this function's contract.
        unsafe { read_status(pwStatus, rio_sets, wSet, wCardIndex, Set::slave_status) }
    }
}

/// Failed transmitting slaves of a RIO set, bit n = slave n.
///
/// # Safety
/// `pdwStatus` must be NULL (refused with `PARAMETER_ERR`) or point to a valid `DWORD`.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetRIOSlaveFail(
    pdwStatus: *mut DWORD,
    wSet: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        // SAFETY: forwarded under this function's contract.
        unsafe { read_status(pdwStatus, rio_sets, wSet, wCardIndex, Set::slave_fail) }
    }
}

/// The 16 inputs of a RIO port (bit n = input n), as last transferred.
///
/// # Safety
/// `pwValue` must be NULL (refused with `PARAMETER_ERR`) or point to a valid `WORD`.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetRIOInputValue(
    pwValue: *mut WORD,
    wSet: WORD,
    wPort: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        // SAFETY: forwarded under this function's contract.
        unsafe { read_set(pwValue, rio_sets, wSet, wCardIndex, |s| s.input(wPort)) }
    }
}

/// Sets the 16 outputs of a RIO port (sent at the next transfer).
#[no_mangle]
pub extern "system" fn MCC_SetRIOOutputValue(
    wValue: WORD,
    wSet: WORD,
    wPort: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! { set_do(rio_sets, wSet, wCardIndex, |s| s.set_output(wPort, wValue)) }
}

/// The 16 outputs set for a RIO port.
///
/// # Safety
/// `pwValue` must be NULL (refused with `PARAMETER_ERR`) or point to a valid `WORD`.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetRIOOutputValue(
    pwValue: *mut WORD,
    wSet: WORD,
    wPort: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        // SAFETY: forwarded under this function's contract.
        unsafe { read_set(pwValue, rio_sets, wSet, wCardIndex, |s| s.output(wPort)) }
    }
}

/// Consecutive failed transfers a slave of the RIO set may have before the set reports
/// it (`…SlaveFail` bit, statuses 0, the transfer trigger): 0 (the default) reports the
/// first failed transfer, 5 the sixth. Undocumented by the vendor; see docs/compatibility.md.
#[no_mangle]
pub extern "system" fn MCC_SetRIOTransError(wTime: WORD, wSet: WORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! { set_do(rio_sets, wSet, wCardIndex, |s| s.set_tolerance(wTime)) }
}

/// Sets the trigger type of digital input `wDigitalInput` (`RIO_DI0..7` = bits 0..7 of
/// port 0): `RIO_INT_NO`, `RIO_INT_RISE` (default), `RIO_INT_FALL`, `RIO_INT_LEVEL`.
#[no_mangle]
pub extern "system" fn MCC_SetRIOTriggerType(
    wType: WORD,
    wSet: WORD,
    wDigitalInput: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        set_do(rio_sets, wSet, wCardIndex, |s| {
            s.set_trigger_type(wDigitalInput, wType)
        })
    }
}

/// An edge of the digital input calls the RIO routine with `RDIn` set.
#[no_mangle]
pub extern "system" fn MCC_EnableRIOInputTrigger(
    wSet: WORD,
    wDigitalInput: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        set_do(rio_sets, wSet, wCardIndex, |s| {
            s.set_input_trigger(wDigitalInput, true)
        })
    }
}

/// The digital input no longer calls the RIO routine.
#[no_mangle]
pub extern "system" fn MCC_DisableRIOInputTrigger(
    wSet: WORD,
    wDigitalInput: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        set_do(rio_sets, wSet, wCardIndex, |s| {
            s.set_input_trigger(wDigitalInput, false)
        })
    }
}

/// A transfer error of the set (its status going from 1 to 0) calls the RIO routine with
/// every `RDIn` 0 and the driver's `FAIL` byte (after the 8 RDI bytes) set.
#[no_mangle]
pub extern "system" fn MCC_EnableRIOTransTrigger(wSet: WORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! { set_do(rio_sets, wSet, wCardIndex, |s| s.set_trans_trigger(true)) }
}

/// Transfer errors no longer call the RIO routine.
#[no_mangle]
pub extern "system" fn MCC_DisableRIOTransTrigger(wSet: WORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! { set_do(rio_sets, wSet, wCardIndex, |s| s.set_trans_trigger(false)) }
}

// ---- ARIO ----

/// At most `dfUpdateRate` transfer cycles per second (Hz; > 0, a cycle of 1 / rate at most
/// 2^32 − 1 ms long) for the ARIO
/// set: a cycle lasts `1 / rate` or the bus time, whichever is longer. The cycle count
/// restarts at the call.
#[no_mangle]
pub extern "system" fn MCC_SetARIOUpdateRate(
    dfUpdateRate: f64,
    wSet: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        card_do(wCardIndex, |p| {
            p.remote_io_mut().set_ario_update_rate(usize::from(wSet), dfUpdateRate)
        })
    }
}

/// Serial clock of the ARIO set: one bit every `wDivider` system clocks of 10 ns
/// (1..65535, default 10); a slave's 32 bits take `32 × wDivider × 10 ns`. The cycle count
/// restarts at the call.
#[no_mangle]
pub extern "system" fn MCC_SetARIOClockDivider(
    wDivider: WORD,
    wSet: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        card_do(wCardIndex, |p| {
            p.remote_io_mut().set_ario_clock_divider(usize::from(wSet), wDivider)
        })
    }
}

/// Gap after each ARIO slave's frame, in system clocks of 10 ns (default 0), for both sets
/// of the card. The cycle count restarts at the call.
#[no_mangle]
pub extern "system" fn MCC_SetARIONode2NodeDelay(dwDelay: DWORD, wCardIndex: WORD) -> c_int {
    ffi_boundary! {
        card_do(wCardIndex, |p| p.remote_io_mut().set_ario_node_delay(dwDelay))
    }
}

/// Starts data transfer with an ARIO slave (`RIO_SLAVE0..31`).
#[no_mangle]
pub extern "system" fn MCC_EnableARIOSlaveControl(
    wSet: WORD,
    wSlave: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! { slave_control(ario_sets, wSet, wSlave, wCardIndex, true) }
}

/// Stops data transfer with an ARIO slave.
#[no_mangle]
pub extern "system" fn MCC_DisableARIOSlaveControl(
    wSet: WORD,
    wSlave: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! { slave_control(ario_sets, wSet, wSlave, wCardIndex, false) }
}

/// ARIO transfer status: 1 normal, 0 error (master or a transmitting slave).
///
/// # Safety
/// `pwStatus` must be NULL (refused with `PARAMETER_ERR`) or point to a valid `WORD`.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetARIOTransStatus(
    pwStatus: *mut WORD,
    wSet: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        // SAFETY: forwarded under this function's contract.
        unsafe { read_status(pwStatus, ario_sets, wSet, wCardIndex, Set::trans_status) }
    }
}

/// ARIO master status: 1 normal, 0 error.
///
/// # Safety
/// `pwStatus` must be NULL (refused with `PARAMETER_ERR`) or point to a valid `WORD`.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetARIOMasterStatus(
    pwStatus: *mut WORD,
    wSet: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        // SAFETY: forwarded under this function's contract.
        unsafe { read_status(pwStatus, ario_sets, wSet, wCardIndex, Set::master_status) }
    }
}

/// ARIO slave status: 1 when every transmitting slave works, 0 otherwise.
///
/// # Safety
/// `pwStatus` must be NULL (refused with `PARAMETER_ERR`) or point to a valid `WORD`.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetARIOSlaveStatus(
    pwStatus: *mut WORD,
    wSet: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        // SAFETY: forwarded under this function's contract.
        unsafe { read_status(pwStatus, ario_sets, wSet, wCardIndex, Set::slave_status) }
    }
}

/// Failed transmitting ARIO slaves, bit n = slave n.
///
/// # Safety
/// `pdwStatus` must be NULL (refused with `PARAMETER_ERR`) or point to a valid `DWORD`.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetARIOSlaveFail(
    pdwStatus: *mut DWORD,
    wSet: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        // SAFETY: forwarded under this function's contract.
        unsafe { read_status(pdwStatus, ario_sets, wSet, wCardIndex, Set::slave_fail) }
    }
}

/// The 16 inputs of ARIO slave `wPort` (0..31), as last transferred.
///
/// # Safety
/// `pwValue` must be NULL (refused with `PARAMETER_ERR`) or point to a valid `WORD`.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetARIOInputValue(
    pwValue: *mut WORD,
    wSet: WORD,
    wPort: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        // SAFETY: forwarded under this function's contract.
        unsafe { read_set(pwValue, ario_sets, wSet, wCardIndex, |s| s.input(wPort)) }
    }
}

/// Sets the 16 outputs of ARIO slave `wPort` (0..31; sent at the next transfer).
#[no_mangle]
pub extern "system" fn MCC_SetARIOOutputValue(
    wValue: WORD,
    wSet: WORD,
    wPort: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! { set_do(ario_sets, wSet, wCardIndex, |s| s.set_output(wPort, wValue)) }
}

/// The 16 outputs set for ARIO slave `wPort`.
///
/// # Safety
/// `pwValue` must be NULL (refused with `PARAMETER_ERR`) or point to a valid `WORD`.
#[no_mangle]
pub unsafe extern "system" fn MCC_GetARIOOutputValue(
    pwValue: *mut WORD,
    wSet: WORD,
    wPort: WORD,
    wCardIndex: WORD,
) -> c_int {
    ffi_boundary! {
        // SAFETY: forwarded under this function's contract.
        unsafe { read_set(pwValue, ario_sets, wSet, wCardIndex, |s| s.output(wPort)) }
    }
}
