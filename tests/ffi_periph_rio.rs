//! The card's remote I/O (RIO and ARIO) through the C entry points: loopback, transfer
//! status, input triggers, the tolerated failed transfers, ARIO timing. On the stepped
//! clock: 1 ms ticks, `MCC_TimeDelay(n)` runs exactly n ticks.

mod common;

use common::periph::{periph, with_periph};
use common::{fresh, init_ms};
use parking_lot::Mutex;
use MCCLPCI_IMP::ffi::isr::*;
use MCCLPCI_IMP::ffi::rio::*;
use MCCLPCI_IMP::ffi::system::*;
use MCCLPCI_IMP::ffi::trajectory::*;
use MCCLPCI_IMP::vendor::consts::*;
use MCCLPCI_IMP::vendor::*;

static RIO_BYTES: Mutex<Vec<[u8; 9]>> = Mutex::new(Vec::new());

unsafe extern "system" fn rio_log(p: *mut RIOINT) {
    // SAFETY: the library passes 9 bytes (RIOINT and the driver's FAIL byte).
    let b: [u8; 9] = unsafe { *(p as *const [u8; 9]) };
    RIO_BYTES.lock().push(b);
}

#[test]
fn remote_io_loopback_status_and_triggers() {
    let _g = fresh();
    assert_eq!(init_ms(1, 1), NO_ERR);
    RIO_BYTES.lock().clear();
    let (mut w, mut d): (WORD, DWORD) = (0, 0);
    // ARIO: examples manual §33-34.
    assert_eq!(MCC_EnableARIOSlaveControl(RIO_SET0, RIO_SLAVE0, 0), NO_ERR);
    assert_eq!(
        MCC_SetARIOOutputValue(0x1234, RIO_SET0, RIO_SLAVE0, 0),
        NO_ERR
    );
    assert_eq!(
        MCC_SetARIOOutputValue(0x5678, RIO_SET0, RIO_SLAVE1, 0),
        NO_ERR
    );
    MCC_TimeDelay(1);
    // SAFETY: valid pointers throughout.
    unsafe {
        assert_eq!(
            MCC_GetARIOInputValue(&mut w, RIO_SET0, RIO_SLAVE0, 0),
            NO_ERR
        );
        assert_eq!(w, 0x1234, "loops back");
        assert_eq!(
            MCC_GetARIOInputValue(&mut w, RIO_SET0, RIO_SLAVE1, 0),
            NO_ERR
        );
        assert_eq!(w, 0, "slave 1 not transmitting");
        assert_eq!(MCC_GetARIOTransStatus(&mut w, RIO_SET0, 0), NO_ERR);
        assert_eq!(w, 1);
        with_periph(0, |p| p.remote_io_mut().set_slave_failed(true, 0, 0, true));
        assert_eq!(MCC_GetARIOTransStatus(&mut w, RIO_SET0, 0), NO_ERR);
        assert_eq!(w, 1, "noticed at the next transfer");
        MCC_TimeDelay(1);
        assert_eq!(MCC_GetARIOTransStatus(&mut w, RIO_SET0, 0), NO_ERR);
        assert_eq!(w, 0, "the first failed transfer (tolerance 0)");
        assert_eq!(MCC_GetARIOSlaveStatus(&mut w, RIO_SET0, 0), NO_ERR);
        assert_eq!(w, 0);
        assert_eq!(MCC_GetARIOMasterStatus(&mut w, RIO_SET0, 0), NO_ERR);
        assert_eq!(w, 1);
        assert_eq!(MCC_GetARIOSlaveFail(&mut d, RIO_SET0, 0), NO_ERR);
        assert_eq!(d, 1);
        assert_eq!(
            MCC_SetARIOOutputValue(0x9999, RIO_SET0, RIO_SLAVE0, 0),
            NO_ERR
        );
        MCC_TimeDelay(1);
        assert_eq!(
            MCC_GetARIOInputValue(&mut w, RIO_SET0, RIO_SLAVE0, 0),
            NO_ERR
        );
        assert_eq!(w, 0x1234, "a failed slave does not transfer");
        assert_eq!(MCC_DisableARIOSlaveControl(RIO_SET0, RIO_SLAVE0, 0), NO_ERR);
        assert_eq!(MCC_GetARIOSlaveFail(&mut d, RIO_SET0, 0), NO_ERR);
        assert_eq!(d, 0, "only transmitting slaves count");
        assert_eq!(
            MCC_GetARIOOutputValue(&mut w, RIO_SET0, RIO_SLAVE0, 0),
            NO_ERR
        );
        assert_eq!(w, 0x9999);

        // RIO: set and slave control, DI triggers through the RIO routine.
        assert_eq!(MCC_SetRIORoutine(Some(rio_log), 0), NO_ERR);
        assert_eq!(MCC_EnableRIOSlaveControl(RIO_SET1, 0, 0), NO_ERR);
        assert_eq!(
            MCC_SetRIOTriggerType(RIO_INT_RISE, RIO_SET1, RIO_DI1, 0),
            NO_ERR
        );
        assert_eq!(
            MCC_SetRIOTriggerType(RIO_INT_LEVEL, RIO_SET1, RIO_DI2, 0),
            NO_ERR
        );
        assert_eq!(MCC_EnableRIOInputTrigger(RIO_SET1, RIO_DI1, 0), NO_ERR);
        assert_eq!(MCC_EnableRIOInputTrigger(RIO_SET1, RIO_DI2, 0), NO_ERR);
        assert_eq!(MCC_SetRIOOutputValue(0b110, RIO_SET1, RIO_PORT0, 0), NO_ERR);
        MCC_TimeDelay(2);
        assert_eq!(MCC_GetRIOInputValue(&mut w, RIO_SET1, RIO_PORT0, 0), NO_ERR);
        assert_eq!(w, 0, "set control off");
        assert_eq!(MCC_EnableRIOSetControl(RIO_SET1, 0), NO_ERR);
        MCC_TimeDelay(1);
        assert_eq!(MCC_GetRIOInputValue(&mut w, RIO_SET1, RIO_PORT0, 0), NO_ERR);
        assert_eq!(w, 0b110);
        assert!(
            RIO_BYTES.lock().is_empty(),
            "first transfer is the reference"
        );
        assert_eq!(MCC_SetRIOOutputValue(0b000, RIO_SET1, RIO_PORT0, 0), NO_ERR);
        MCC_TimeDelay(1);
        assert_eq!(MCC_SetRIOOutputValue(0b110, RIO_SET1, RIO_PORT0, 0), NO_ERR);
        MCC_TimeDelay(1);
        let log = RIO_BYTES.lock().clone();
        assert_eq!(log.len(), 2);
        assert_eq!(
            &log[0][..3],
            &[0, 0, 1],
            "DI1 fell (RISE ignores), DI2 changed"
        );
        assert_eq!(&log[1][..3], &[0, 1, 1], "DI1 rose, DI2 changed");
        // Transmission failure: FAIL byte once.
        assert_eq!(MCC_EnableRIOTransTrigger(RIO_SET1, 0), NO_ERR);
        with_periph(0, |p| p.remote_io_mut().set_master_failed(false, 1, true));
        MCC_TimeDelay(3);
        let log = RIO_BYTES.lock().clone();
        assert_eq!(log.len(), 3);
        assert_eq!(log[2], [0, 0, 0, 0, 0, 0, 0, 0, 1]);
        assert_eq!(MCC_GetRIOMasterStatus(&mut w, RIO_SET1, 0), NO_ERR);
        assert_eq!(w, 0);
        assert_eq!(MCC_GetRIOTransStatus(&mut w, RIO_SET1, 0), NO_ERR);
        assert_eq!(w, 0);
        assert_eq!(MCC_GetRIOSlaveStatus(&mut w, RIO_SET1, 0), NO_ERR);
        assert_eq!(w, 1);
        assert_eq!(MCC_GetRIOSlaveFail(&mut d, RIO_SET1, 0), NO_ERR);
        assert_eq!(d, 0);
        assert_eq!(
            MCC_GetRIOOutputValue(&mut w, RIO_SET1, RIO_PORT0, 0),
            NO_ERR
        );
        assert_eq!(w, 0b110);
    }
    assert_eq!(MCC_DisableRIOTransTrigger(RIO_SET1, 0), NO_ERR);
    assert_eq!(MCC_DisableRIOInputTrigger(RIO_SET1, RIO_DI1, 0), NO_ERR);
    assert_eq!(MCC_DisableRIOSlaveControl(RIO_SET1, 0, 0), NO_ERR);
    assert_eq!(MCC_DisableRIOSetControl(RIO_SET1, 0), NO_ERR);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn rio_trans_error_reports_after_the_tolerated_failed_transfers() {
    let _g = fresh();
    assert_eq!(init_ms(1, 1), NO_ERR);
    RIO_BYTES.lock().clear();
    let (mut w, mut d): (WORD, DWORD) = (0, 0);
    assert_eq!(MCC_SetRIORoutine(Some(rio_log), 0), NO_ERR);
    assert_eq!(MCC_EnableRIOSetControl(RIO_SET1, 0), NO_ERR);
    assert_eq!(MCC_EnableRIOSlaveControl(RIO_SET1, 2, 0), NO_ERR);
    assert_eq!(MCC_EnableRIOTransTrigger(RIO_SET1, 0), NO_ERR);
    // The vendor test's value: 5 failed transfers tolerated, the 6th reported.
    assert_eq!(MCC_SetRIOTransError(5, RIO_SET1, 0), NO_ERR);
    assert_eq!(periph(0).remote_io().rio_sets()[1].tolerance(), 5);
    assert_eq!(
        periph(0).remote_io().rio_sets()[0].tolerance(),
        0,
        "per set"
    );
    MCC_TimeDelay(1);
    with_periph(0, |p| p.remote_io_mut().set_slave_failed(false, 1, 2, true));
    // SAFETY: valid pointers throughout.
    unsafe {
        // One transfer per 1 ms tick: ticks 1..5 fail and are tolerated.
        for n in 1..=5u32 {
            MCC_TimeDelay(1);
            assert_eq!(MCC_GetRIOTransStatus(&mut w, RIO_SET1, 0), NO_ERR);
            assert_eq!(w, 1, "failed transfer {n} tolerated");
            assert_eq!(MCC_GetRIOSlaveFail(&mut d, RIO_SET1, 0), NO_ERR);
            assert_eq!(d, 0);
            assert_eq!(periph(0).remote_io().rio_sets()[1].failed_transfers(2), n);
        }
        assert!(RIO_BYTES.lock().is_empty(), "no FAIL yet");
        MCC_TimeDelay(1);
        assert_eq!(MCC_GetRIOTransStatus(&mut w, RIO_SET1, 0), NO_ERR);
        assert_eq!(w, 0, "6th failed transfer");
        assert_eq!(MCC_GetRIOSlaveStatus(&mut w, RIO_SET1, 0), NO_ERR);
        assert_eq!(w, 0);
        assert_eq!(MCC_GetRIOMasterStatus(&mut w, RIO_SET1, 0), NO_ERR);
        assert_eq!(w, 1);
        assert_eq!(MCC_GetRIOSlaveFail(&mut d, RIO_SET1, 0), NO_ERR);
        assert_eq!(d, 1 << 2);
        assert_eq!(*RIO_BYTES.lock(), [[0, 0, 0, 0, 0, 0, 0, 0, 1]]);
        // Set 0 keeps its own tolerance (0): a failure there is reported at once.
        assert_eq!(MCC_EnableRIOSetControl(RIO_SET0, 0), NO_ERR);
        assert_eq!(MCC_EnableRIOSlaveControl(RIO_SET0, 0, 0), NO_ERR);
        with_periph(0, |p| p.remote_io_mut().set_slave_failed(false, 0, 0, true));
        MCC_TimeDelay(1);
        assert_eq!(MCC_GetRIOSlaveFail(&mut d, RIO_SET0, 0), NO_ERR);
        assert_eq!(d, 1);
        // Recovery: the next transfer clears the report.
        with_periph(0, |p| {
            p.remote_io_mut().set_slave_failed(false, 1, 2, false)
        });
        MCC_TimeDelay(1);
        assert_eq!(MCC_GetRIOTransStatus(&mut w, RIO_SET1, 0), NO_ERR);
        assert_eq!(w, 1);
    }
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

/// The inputs last latched from ARIO slave `slave` of `set` (its outputs looped back).
fn ario_in(set: WORD, slave: WORD) -> WORD {
    let mut w: WORD = 0;
    assert_eq!(
        // SAFETY: valid pointer.
        unsafe { MCC_GetARIOInputValue(&mut w, set, slave, 0) },
        NO_ERR
    );
    w
}

#[test]
fn ario_transfers_follow_the_update_rate_divider_and_node_delay() {
    let _g = fresh();
    assert_eq!(init_ms(1, 1), NO_ERR); // 1 ms ticks on the stepped clock
    assert_eq!(MCC_EnableARIOSlaveControl(RIO_SET1, RIO_SLAVE4, 0), NO_ERR);
    assert_eq!(MCC_EnableARIOSlaveControl(RIO_SET0, RIO_SLAVE0, 0), NO_ERR);
    // Default timing: 32 bits x 10 clocks x 10 ns = 3.2 us per cycle: every tick.
    assert_eq!(MCC_SetARIOOutputValue(1, RIO_SET1, RIO_SLAVE4, 0), NO_ERR);
    MCC_TimeDelay(1);
    assert_eq!(ario_in(RIO_SET1, RIO_SLAVE4), 1);
    // 50 Hz: one cycle every 20 ms, counted from the call.
    assert_eq!(MCC_SetARIOUpdateRate(50.0, RIO_SET1, 0), NO_ERR);
    assert_eq!(MCC_SetARIOOutputValue(2, RIO_SET1, RIO_SLAVE4, 0), NO_ERR);
    MCC_TimeDelay(19);
    assert_eq!(ario_in(RIO_SET1, RIO_SLAVE4), 1, "19 ms: no cycle yet");
    MCC_TimeDelay(1);
    assert_eq!(ario_in(RIO_SET1, RIO_SLAVE4), 2, "20 ms");
    // Divider 65535 and a node-to-node delay of 902880 clocks: one slave's cycle is
    // (32 x 65535 + 902880) x 10 ns = 3000000 x 10 ns = 30 ms, longer than 20 ms.
    assert_eq!(MCC_SetARIOClockDivider(65535, RIO_SET1, 0), NO_ERR);
    assert_eq!(MCC_SetARIONode2NodeDelay(902_880, 0), NO_ERR);
    // The delay is the card's: set 0 (divider 10) now takes (320 + 902880) x 10 ns =
    // 9.032 ms per cycle, so it transfers at 10 ms.
    assert_eq!(MCC_SetARIOOutputValue(3, RIO_SET1, RIO_SLAVE4, 0), NO_ERR);
    assert_eq!(MCC_SetARIOOutputValue(7, RIO_SET0, RIO_SLAVE0, 0), NO_ERR);
    MCC_TimeDelay(9);
    assert_eq!(ario_in(RIO_SET0, RIO_SLAVE0), 0, "9 ms < 9.032 ms");
    MCC_TimeDelay(1);
    assert_eq!(ario_in(RIO_SET0, RIO_SLAVE0), 7, "10 ms");
    MCC_TimeDelay(19);
    assert_eq!(ario_in(RIO_SET1, RIO_SLAVE4), 2, "29 ms");
    MCC_TimeDelay(1);
    assert_eq!(ario_in(RIO_SET1, RIO_SLAVE4), 3, "30 ms");
    // A failed call changes nothing: the next cycle is still at 60 ms.
    assert_eq!(MCC_SetARIOUpdateRate(f64::NAN, RIO_SET1, 0), PARAMETER_ERR);
    assert_eq!(MCC_SetARIOClockDivider(0, RIO_SET1, 0), PARAMETER_ERR);
    assert_eq!(MCC_SetARIOOutputValue(4, RIO_SET1, RIO_SLAVE4, 0), NO_ERR);
    MCC_TimeDelay(29);
    assert_eq!(ario_in(RIO_SET1, RIO_SLAVE4), 3, "59 ms");
    MCC_TimeDelay(1);
    assert_eq!(ario_in(RIO_SET1, RIO_SLAVE4), 4, "60 ms");
    // A second transmitting slave doubles the bus time: 60 ms per cycle.
    assert_eq!(MCC_EnableARIOSlaveControl(RIO_SET1, RIO_SLAVE5, 0), NO_ERR);
    assert_eq!(
        periph(0).remote_io().ario_timing().cycle_ns(1, 0b11_0000),
        60_000_000
    );
    // RIO sets are not ARIO: they still transfer every tick.
    assert_eq!(MCC_EnableRIOSetControl(RIO_SET1, 0), NO_ERR);
    assert_eq!(MCC_EnableRIOSlaveControl(RIO_SET1, 1, 0), NO_ERR);
    assert_eq!(MCC_SetRIOOutputValue(0x55, RIO_SET1, RIO_PORT1, 0), NO_ERR);
    MCC_TimeDelay(1);
    let mut w: WORD = 0;
    assert_eq!(
        // SAFETY: valid pointer.
        unsafe { MCC_GetRIOInputValue(&mut w, RIO_SET1, RIO_PORT1, 0) },
        NO_ERR
    );
    assert_eq!(w, 0x55);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}
