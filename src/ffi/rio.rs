//! Remote I/O (user manual §2.14; examples manual §33–34; vendor header "Remote
//! Input/Output Control", the B/C signatures with `wSet`). Behaviour in
//! `crate::card::rio`: 2 sets; RIO has 4 ports (one slave each), ARIO 32 slaves (the
//! `wPort` argument names the slave); RIO data moves once per tick, ARIO data once per
//! cycle (update rate, clock divider, node-to-node delay); simulated slaves loop their
//! outputs back to their inputs unless set otherwise from Rust. Statuses read 1 for
//! normal transfer, 0 for an error; a slave's failure is reported once it has failed more
//! consecutive transfers than `MCC_SetRIOTransError` tolerates. Bad card, set, port,
//! slave, input, value or NULL: `PARAMETER_ERR`, nothing changed.

use super::{card_do_at, with_card, write_out, Done};
use crate::card::rio::{set_ix, Master, Set, ARIO_SLAVES, RIO_PORTS, SETS};
use crate::error::McclResult;
use crate::vendor::consts as c;
use crate::vendor::{DWORD, WORD};
use std::os::raw::c_int;

/// Runs `f` on set `wSet` of the card's RIO (`pick` = `Master::rio`) or ARIO
/// (`Master::ario`) sets: `INITIAL_MOTION_ERR` before init whatever the arguments, then
/// `PARAMETER_ERR` for a bad set or card.
fn on_set<const N: usize, R>(
    pick: fn(&mut Master) -> &mut [Set<N>; SETS],
    wSet: WORD,
    wCardIndex: WORD,
    f: impl FnOnce(&mut Set<N>) -> McclResult<R>,
) -> McclResult<R> {
    super::initialised()?;
    let s = set_ix(wSet)?;
    with_card(wCardIndex, |p| f(&mut pick(&mut p.rio)[s]))
}

/// The RIO sets of a card's master.
fn rio_sets(m: &mut Master) -> &mut [Set<RIO_PORTS>; SETS] {
    &mut m.rio
}

/// The ARIO sets of a card's master.
fn ario_sets(m: &mut Master) -> &mut [Set<ARIO_SLAVES>; SETS] {
    &mut m.ario
}

/// Runs setter `f` on set `wSet` of the sets `pick` chooses (see [`on_set`]); `NO_ERR`.
fn set_do<const N: usize, D: Done>(
    pick: fn(&mut Master) -> &mut [Set<N>; SETS],
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

// ---- RIO ----

on_off! {
    /// Starts data transfer of a RIO set.
    MCC_EnableRIOSetControl,
    /// Stops data transfer of a RIO set.
    MCC_DisableRIOSetControl(wSet: WORD, wCardIndex: WORD)
        = |on| set_do(rio_sets, wSet, wCardIndex, |s| s.control = on);
}

/// Declares the entry points RIO and ARIO share, for one kind of master: `$sets` picks
/// its sets ([`rio_sets`], [`ario_sets`]). The members are, in this order: slave control
/// on and off, transfer, master and slave status, failed slaves, a port's (RIO) or
/// slave's (ARIO) inputs, and setting and reading its outputs.
macro_rules! remote_io {
    (
        $sets:ident;
        $(#[$on_doc:meta])* $slave_on:ident,
        $(#[$off_doc:meta])* $slave_off:ident,
        $(#[$trans_doc:meta])* $trans:ident,
        $(#[$master_doc:meta])* $master:ident,
        $(#[$slaves_doc:meta])* $slaves:ident,
        $(#[$fail_doc:meta])* $fail:ident,
        $(#[$input_doc:meta])* $input:ident,
        $(#[$set_output_doc:meta])* $set_output:ident,
        $(#[$output_doc:meta])* $output:ident;
    ) => {
        on_off! {
            $(#[$on_doc])* $slave_on,
            $(#[$off_doc])* $slave_off(wSet: WORD, wSlave: WORD, wCardIndex: WORD)
                = |on| set_do($sets, wSet, wCardIndex, |s| s.set_slave_control(wSlave, on));
        }

        pointer_fns! {
            $(#[$trans_doc])* $trans(pwStatus: WORD; wSet, wCardIndex)
                = read(pwStatus, || on_set($sets, wSet, wCardIndex, |s| Ok(s.trans_status())));
            $(#[$master_doc])* $master(pwStatus: WORD; wSet, wCardIndex)
                = read(pwStatus, || on_set($sets, wSet, wCardIndex, |s| Ok(s.master_status())));
            $(#[$slaves_doc])* $slaves(pwStatus: WORD; wSet, wCardIndex)
                = read(pwStatus, || on_set($sets, wSet, wCardIndex, |s| Ok(s.slave_status())));
            $(#[$fail_doc])* $fail(pdwStatus: DWORD; wSet, wCardIndex)
                = read(pdwStatus, || on_set($sets, wSet, wCardIndex, |s| Ok(s.slave_fail())));
            $(#[$input_doc])* $input(pwValue: WORD; wSet, wPort, wCardIndex)
                = read(pwValue, || on_set($sets, wSet, wCardIndex, |s| s.input(wPort)));
            $(#[$output_doc])* $output(pwValue: WORD; wSet, wPort, wCardIndex)
                = read(pwValue, || on_set($sets, wSet, wCardIndex, |s| s.output(wPort)));
        }

        $(#[$set_output_doc])*
        #[no_mangle]
        pub extern "system" fn $set_output(
            wValue: WORD, wSet: WORD, wPort: WORD, wCardIndex: WORD,
        ) -> c_int {
            ffi_boundary! { set_do($sets, wSet, wCardIndex, |s| s.set_output(wPort, wValue)) }
        }
    };
}

remote_io! {
    rio_sets;
    /// Starts data transfer with one slave (0..3, the slave on port n) of a RIO set.
    MCC_EnableRIOSlaveControl,
    /// Stops data transfer with one slave of a RIO set.
    MCC_DisableRIOSlaveControl,
    /// Transfer status of a RIO set: 1 normal, 0 error (master or a transmitting slave).
    MCC_GetRIOTransStatus,
    /// Master status of a RIO set: 1 normal, 0 error.
    MCC_GetRIOMasterStatus,
    /// Slave status of a RIO set: 1 when every transmitting slave works, 0 otherwise.
    MCC_GetRIOSlaveStatus,
    /// Failed transmitting slaves of a RIO set, bit n = slave n.
    MCC_GetRIOSlaveFail,
    /// The 16 inputs of a RIO port (bit n = input n), as last transferred.
    MCC_GetRIOInputValue,
    /// Sets the 16 outputs of a RIO port (sent at the next transfer).
    MCC_SetRIOOutputValue,
    /// The 16 outputs set for a RIO port.
    MCC_GetRIOOutputValue;
}

value_fns! {
    /// Consecutive failed transfers a slave of the RIO set may have before the set reports
    /// it (`…SlaveFail` bit, statuses 0, the transfer trigger): 0 (the default) reports the
    /// first failed transfer, 5 the sixth. Undocumented by the vendor; see docs/compatibility.md.
    MCC_SetRIOTransError(wTime: WORD; wSet, wCardIndex)
        = set_do(rio_sets, wSet, wCardIndex, |s| s.set_tolerance(wTime));
    /// Sets the trigger type of digital input `wDigitalInput` (`RIO_DI0..7` = bits 0..7 of
    /// port 0): `RIO_INT_NO`, `RIO_INT_RISE` (default), `RIO_INT_FALL`, `RIO_INT_LEVEL`.
    MCC_SetRIOTriggerType(wType: WORD; wSet, wDigitalInput, wCardIndex)
        = set_do(rio_sets, wSet, wCardIndex, |s| s.set_trigger_type(wDigitalInput, wType));
}

on_off! {
    /// An edge of the digital input calls the RIO routine with `RDIn` set.
    MCC_EnableRIOInputTrigger,
    /// The digital input no longer calls the RIO routine.
    MCC_DisableRIOInputTrigger(wSet: WORD, wDigitalInput: WORD, wCardIndex: WORD)
        = |on| set_do(rio_sets, wSet, wCardIndex, |s| s.set_input_trigger(wDigitalInput, on));
}

on_off! {
    /// A transfer error of the set (its status going from 1 to 0) calls the RIO routine with
    /// every `RDIn` 0 and the driver's `FAIL` byte (after the 8 RDI bytes) set.
    MCC_EnableRIOTransTrigger,
    /// Transfer errors no longer call the RIO routine.
    MCC_DisableRIOTransTrigger(wSet: WORD, wCardIndex: WORD)
        = |on| set_do(rio_sets, wSet, wCardIndex, |s| s.set_trans_trigger(on));
}

// ---- ARIO ----

value_fns! {
    /// At most `dfUpdateRate` transfer cycles per second (Hz; > 0, a cycle of 1 / rate at most
    /// 2^32 − 1 ms long) for the ARIO
    /// set: a cycle lasts `1 / rate` or the bus time, whichever is longer. The cycle count
    /// restarts at the call.
    MCC_SetARIOUpdateRate(dfUpdateRate: f64; wSet, wCardIndex)
        = card_do_at(wCardIndex, || set_ix(wSet), |p, s| {
            p.rio.ario_timing.set_update_rate(s, dfUpdateRate)
        });
    /// Serial clock of the ARIO set: one bit every `wDivider` system clocks of 10 ns
    /// (1..65535, default 10); a slave's 32 bits take `32 × wDivider × 10 ns`. The cycle count
    /// restarts at the call.
    MCC_SetARIOClockDivider(wDivider: WORD; wSet, wCardIndex)
        = card_do_at(wCardIndex, || set_ix(wSet), |p, s| {
            p.rio.ario_timing.set_divider(s, wDivider)
        });
    /// Gap after each ARIO slave's frame, in system clocks of 10 ns (default 0), for both sets
    /// of the card. The cycle count restarts at the call.
    MCC_SetARIONode2NodeDelay(dwDelay: DWORD; wCardIndex)
        = card_do_at(wCardIndex, || Ok(()), |p, ()| {
            p.rio.ario_timing.set_node_delay(dwDelay)
        });
}

remote_io! {
    ario_sets;
    /// Starts data transfer with an ARIO slave (`RIO_SLAVE0..31`).
    MCC_EnableARIOSlaveControl,
    /// Stops data transfer with an ARIO slave.
    MCC_DisableARIOSlaveControl,
    /// ARIO transfer status: 1 normal, 0 error (master or a transmitting slave).
    MCC_GetARIOTransStatus,
    /// ARIO master status: 1 normal, 0 error.
    MCC_GetARIOMasterStatus,
    /// ARIO slave status: 1 when every transmitting slave works, 0 otherwise.
    MCC_GetARIOSlaveStatus,
    /// Failed transmitting ARIO slaves, bit n = slave n.
    MCC_GetARIOSlaveFail,
    /// The 16 inputs of ARIO slave `wPort` (0..31), as last transferred.
    MCC_GetARIOInputValue,
    /// Sets the 16 outputs of ARIO slave `wPort` (0..31; sent at the next transfer).
    MCC_SetARIOOutputValue,
    /// The 16 outputs set for ARIO slave `wPort`.
    MCC_GetARIOOutputValue;
}
