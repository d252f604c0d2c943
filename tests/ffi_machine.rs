//! The simulated machine through the C entry points (stepped clock): encoders, software
//! over-travel, limit switches in every mode, emergency stop, tracking error, pulse
//! limits, compensation and dry run, with expected values worked out by hand.

mod common;

use common::{enc, fresh, init_ms};
use std::os::raw::c_long;
use MCCLPCI_IMP::ffi::coordinate::*;
use MCCLPCI_IMP::ffi::encoder::*;
use MCCLPCI_IMP::ffi::limits::*;
use MCCLPCI_IMP::ffi::local_io::*;
use MCCLPCI_IMP::ffi::motion::*;
use MCCLPCI_IMP::ffi::position::*;
use MCCLPCI_IMP::ffi::sim::*;
use MCCLPCI_IMP::ffi::status::*;
use MCCLPCI_IMP::ffi::system::*;
use MCCLPCI_IMP::ffi::trajectory::*;
use MCCLPCI_IMP::vendor::consts::*;
use MCCLPCI_IMP::vendor::*;

fn line_x(x: f64) -> i32 {
    MCC_Line(x, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0, IMP_AXIS_ALL)
}

fn x() -> f64 {
    let mut p = [0.0; 8];
    let [a, b, c, d, e, f, g, h] = &mut p;
    // SAFETY: eight valid pointers.
    unsafe { MCC_GetCurPos(a, b, c, d, e, f, g, h, 0) };
    p[0]
}

fn status() -> i32 {
    MCCLPCI_IMP::system::active()
        .unwrap()
        .snapshot(0)
        .unwrap()
        .status
}

fn run(ms: u32) {
    MCC_TimeDelay(ms);
}

/// Channel 0 with both limit switches read normally open, then init at 1 ms.
fn setup() -> parking_lot::MutexGuard<'static, ()> {
    let g = fresh();
    let mut m = MCCLPCI_IMP::config::default_mac_param();
    m.wOverTravelUpSensorMode = SL_NORMAL_OPEN;
    m.wOverTravelDownSensorMode = SL_NORMAL_OPEN;
    // SAFETY: valid pointer.
    assert_eq!(unsafe { MCC_SetMacParam(&mut m, 0, 0) }, NO_ERR);
    assert_eq!(init_ms(1, 1), NO_ERR);
    assert_eq!(MCC_SetFeedSpeed(10.0, 0), 10.0);
    assert_eq!(MCC_SetAccTime(0.0, 0), NO_ERR);
    assert_eq!(MCC_SetDecTime(0.0, 0), NO_ERR);
    g
}

#[test]
fn encoder_follows_the_motor() {
    let _g = setup();
    assert_eq!(line_x(10.0), 0);
    run(1000);
    // 10 UU x 500 pulses/UU = 5000 pulses = 5000 counts at x4.
    assert_eq!(enc(0), 5000);
    assert_eq!(MCC_SetENCInputRate(1, 0, 0), NO_ERR);
    assert_eq!(enc(0), 5000, "the count keeps its value at the change");
    // The first line's 1000 periods have run; its end period (phase 21) comes next,
    // then the second line's 400 periods (4 UU at 10 UU/s).
    assert_eq!(line_x(14.0), 1);
    run(401);
    assert_eq!(enc(0), 5000 + 2000 / 4, "2000 pulses at x1");
    assert_eq!(MCC_ClearENCCounter(0, 0), NO_ERR);
    assert_eq!(enc(0), 0);
    assert_eq!(MCC_SetENCValue(-77, 0, 0), NO_ERR);
    assert_eq!(enc(0), -77);
    assert_eq!(MCC_SetENCInputRate(3, 0, 0), NO_ERR, "3 = ENC_RATE_X4");
    assert_eq!(MCC_SetENCInputRate(5, 0, 0), PARAMETER_ERR);
    assert_eq!(MCC_SetENCGearRate(f64::NAN, 0, 0), PARAMETER_ERR);
    assert_eq!(MCC_SetENCGearRate(0.0, 0, 0), PARAMETER_ERR);
    let mut v: c_long = 0;
    // SAFETY: NULL is refused; valid pointer otherwise.
    unsafe {
        assert_eq!(MCC_GetENCValue(std::ptr::null_mut(), 0, 0), PARAMETER_ERR);
        assert_eq!(MCC_GetENCValue(&mut v, 8, 0), PARAMETER_ERR);
        assert_eq!(
            MCC_GetENCValue(&mut v, 0, 1),
            PARAMETER_ERR,
            "only one card"
        );
    }
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn over_travel_never_passes_the_high_limit() {
    let _g = fresh();
    let mut m = MCCLPCI_IMP::config::default_mac_param();
    m.dfHighLimit = 5.0;
    m.dfLowLimit = -5.0;
    // SAFETY: valid pointer.
    assert_eq!(unsafe { MCC_SetMacParam(&mut m, 0, 0) }, NO_ERR);
    assert_eq!(init_ms(1, 1), NO_ERR);
    assert_eq!(MCC_SetFeedSpeed(10.0, 0), 10.0);
    // Any nonzero switches the check on, read back as 1 (scenario setters_inpos_group).
    assert_eq!(MCC_SetOverTravelCheck(2, 0, 0, 0, 0, 0, 0, 0, 0), NO_ERR);
    let mut ot = [0; 8];
    let [a, b, c, d, e, f, g, h] = &mut ot;
    assert_eq!(
        // SAFETY: eight valid pointers.
        unsafe { MCC_GetOverTravelCheck(a, b, c, d, e, f, g, h, 0) },
        NO_ERR
    );
    assert_eq!(ot, [1, 0, 0, 0, 0, 0, 0, 0]);
    assert_eq!(line_x(8.0), 0);
    let mut max: f64 = 0.0;
    for _ in 0..2000 {
        run(1);
        max = max.max(x());
    }
    assert!(max <= 5.0, "went to {max}");
    assert!(max > 4.9, "stopped within a tick of the limit: {max}");
    assert_eq!(MCC_GetErrorCode(0), 0xF301);
    assert_eq!(status(), GMS_STOP);
    // Refused (RUN_TIME_ERR) until the error is cleared, as the vendor's library
    // answers; then back into the zone.
    assert_eq!(line_x(0.0), RUN_TIME_ERR);
    run(100);
    assert_eq!(x(), max, "stands");
    assert_eq!(MCC_ClearError(0), NO_ERR);
    assert_eq!(line_x(0.0), 1);
    run(1000);
    assert_eq!(x(), 0.0);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn limit_switch_modes() {
    let _g = setup();
    // + limit switch at 3 UU on channel 0.
    assert_eq!(
        MCCL_SimPlaceSensor(0, 0, MCCL_SIM_LIMIT_PLUS, 3.0, 0.0),
        NO_ERR
    );
    for mode in [HLP_BIDIR, HLP_UNIDIR, HLP_BIDIR_GEN_ERR, HLP_UNIDIR_GEN_ERR] {
        assert_eq!(MCC_EnableLimitSwitchCheck(mode), NO_ERR);
        assert!(line_x(10.0) >= 0);
        run(2000);
        let stop = x();
        // 10 UU/s = 0.01 UU per tick: stopped in the tick the switch closed.
        assert!(
            (3.0..3.0 + 0.0101).contains(&stop),
            "mode {mode}: stopped at {stop}"
        );
        let mut st: WORD = 0;
        // SAFETY: valid pointer.
        unsafe {
            assert_eq!(MCC_GetLimitSwitchStatus(&mut st, 0, 0, 0), NO_ERR);
            assert_eq!(st, 1, "+ switch active");
            assert_eq!(MCC_GetLimitSwitchStatus(&mut st, 1, 0, 0), NO_ERR);
            assert_eq!(st, 0, "- switch not");
            assert_eq!(MCC_GetLatchedLimitSwitchStatus(&mut st, 0, 0, 0), NO_ERR);
            assert_eq!(st, 1);
        }
        let code = MCC_GetErrorCode(0);
        if mode >= HLP_BIDIR_GEN_ERR {
            assert_eq!(code, 0xF701, "mode {mode} records the X limit");
            // Further into the switch stays refused; ClearError, then back out.
            assert_eq!(MCC_ClearError(0), NO_ERR);
        } else {
            assert_eq!(code, 0, "mode {mode} only stops");
        }
        // Into the switch again: stopped at once.
        line_x(10.0);
        run(100);
        assert!(
            x() - stop < 0.0101,
            "mode {mode}: no deeper into the switch"
        );
        MCC_ClearError(0);
        // Back out.
        line_x(0.0);
        run(2000);
        assert_eq!(x(), 0.0, "mode {mode}: moved back out");
        assert_eq!(MCC_ClearLatchedLimitSwitchStatus(0, 0, 0), NO_ERR);
        let mut st: WORD = 9;
        // SAFETY: valid pointer.
        unsafe { MCC_GetLatchedLimitSwitchStatus(&mut st, 0, 0, 0) };
        assert_eq!(st, 0);
    }
    assert_eq!(MCC_EnableLimitSwitchCheck(4), PARAMETER_ERR);
    assert_eq!(MCC_DisableLimitSwitchCheck(), NO_ERR);
    line_x(10.0);
    run(2000);
    assert_eq!(x(), 10.0, "check off: through the switch");
    // Forcing the input from outside works the same.
    assert_eq!(MCCL_SimSetSensor(0, 0, MCCL_SIM_LIMIT_MINUS, 1), NO_ERR);
    let mut st: WORD = 0;
    // SAFETY: valid pointer.
    unsafe { MCC_GetLimitSwitchStatus(&mut st, 1, 0, 0) };
    assert_eq!(st, 1);
    assert_eq!(MCCL_SimSetSensor(0, 0, 3, 1), PARAMETER_ERR);
    assert_eq!(
        MCCL_SimSetSensor(0, 0, MCCL_SIM_LIMIT_MINUS, 2),
        PARAMETER_ERR
    );
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn emergency_stop_stops_every_group_of_the_card() {
    let _g = setup();
    assert_eq!(line_x(10.0), 0);
    run(100);
    assert_eq!(MCCL_SimSetEmergencyStop(0, 1), NO_ERR);
    run(1);
    let here = x();
    assert_eq!(status(), GMS_STOP);
    assert_eq!(MCC_GetErrorCode(0), 0xF102);
    let mut w: WORD = 0;
    // SAFETY: valid pointer.
    unsafe { MCC_GetEmgcStopStatus(&mut w, 0) };
    assert_eq!(w, 1);
    run(100);
    assert_eq!(x(), here);
    assert_eq!(MCCL_SimSetEmergencyStop(0, 0), NO_ERR);
    assert_eq!(MCC_ClearError(0), NO_ERR);
    line_x(10.0);
    run(2000);
    assert_eq!(x(), 10.0);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn tracking_error_with_a_lagging_motor() {
    let _g = setup();
    // A 50 ms lag: at 10 UU/s the motor trails by about 10 x 0.05 = 0.5 UU (250 pulses).
    MCCLPCI_IMP::system::active()
        .unwrap()
        .lock_machine()
        .cards_mut()[0][0]
        .set_plant_lag(Some(0.05));
    assert_eq!(MCC_SetTrackErrorLimit(0.3, 0, 0), NO_ERR);
    let mut lim = 0.0;
    // SAFETY: valid pointer.
    unsafe { MCC_GetTrackErrorLimit(&mut lim, 0, 0) };
    assert_eq!(lim, 0.3);
    assert_eq!(MCC_EnableTrackError(0, IMP_AXIS_X), NO_ERR);
    assert_eq!(line_x(10.0), 0);
    run(2000);
    assert_eq!(MCC_GetErrorCode(0), 0xF801);
    assert_eq!(status(), GMS_STOP);
    // The lag stays 0.5 UU < 0.6: no trip with a larger limit.
    assert_eq!(MCC_ClearError(0), NO_ERR);
    assert_eq!(MCC_SetTrackErrorLimit(0.6, 0, 0), NO_ERR);
    line_x(0.0);
    run(2000);
    assert_eq!(MCC_GetErrorCode(0), 0);
    let mut e = [0; 8];
    let [a, b, c, d, f, g, h, i] = &mut e;
    // SAFETY: eight valid pointers.
    unsafe { MCC_GetErrorCount(a, b, c, d, f, g, h, i, 0) };
    assert!(e[0].abs() <= 1, "settled: {}", e[0]);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn pulse_speed_limit() {
    let _g = setup();
    // 10 pulses per 1 ms tick = 20 UU/s at 500 pulses/UU; 30 UU/s trips it.
    assert_eq!(
        MCC_SetMaxPulseSpeed(10, 32767, 32767, 32767, 32767, 32767, 32767, 32767, 0),
        NO_ERR
    );
    assert_eq!(
        MCC_SetMaxPulseSpeed(0, 1, 1, 1, 1, 1, 1, 1, 0),
        PARAMETER_ERR
    );
    assert_eq!(MCC_SetFeedSpeed(30.0, 0), 30.0);
    line_x(10.0);
    run(100);
    assert_eq!(MCC_GetErrorCode(0), 0xF203);
    assert_eq!(status(), GMS_STOP);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn compensation_sends_15011_pulses() {
    let _g = setup();
    let mut p = SYS_COMP_PARAM {
        dwInterval: 10000,
        wHome_No: 4,
        wPaddle: 0,
        nForwardTable: [0; 256],
        nBackwardTable: [0; 256],
    };
    p.nForwardTable[..8].copy_from_slice(&[22, 20, 15, 11, 0, 10, 12, 15]);
    // SAFETY: valid pointer.
    assert_eq!(unsafe { MCC_SetCompParam(&mut p, 0, 0) }, NO_ERR);
    assert_eq!(MCC_UpdateCompParam(), NO_ERR);
    // +15000 pulses = 30 UU at 500 pulses/UU.
    assert_eq!(MCC_SetFeedSpeed(100.0, 0), 100.0);
    line_x(30.0);
    run(1000);
    let (mut pos, mut n) = (0.0, 0i64);
    // SAFETY: valid pointers.
    unsafe { MCCL_SimGetMotor(0, 0, &mut pos, &mut n) };
    assert_eq!(n, 15011, "user manual §2.7.5");
    // The command position and the pulse count include the compensation, as the
    // vendor's library counts them (scenario compensation): 15011 pulses = 30.022 UU;
    // the reference position does not.
    assert_eq!(x(), 15011.0 / 500.0, "the command position is compensated");
    let mut r = [0.0; 8];
    let [a, b, c, d, e, f, g, h] = &mut r;
    // SAFETY: eight valid pointers.
    unsafe { MCC_GetCurRefPos(a, b, c, d, e, f, g, h, 0) };
    assert_eq!(r[0], 30.0);
    let mut pl = [0 as c_long; 8];
    let [a, b, c, d, e, f, g, h] = &mut pl;
    // SAFETY: eight valid pointers.
    unsafe { MCC_GetPulsePos(a, b, c, d, e, f, g, h, 0) };
    assert_eq!(pl[0], 15011);
    assert_eq!(enc(0), 15011, "the encoder sees the compensated motor");
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn dry_run_moves_the_plan_not_the_machine() {
    let _g = setup();
    assert_eq!(MCC_EnableDryRun(), NO_ERR);
    line_x(5.0);
    run(1000);
    assert_eq!(x(), 5.0);
    assert_eq!(enc(0), 0, "encoders stay");
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn in_position_waits_for_the_motor() {
    let _g = setup();
    // A 50 ms lag: after a move at 10 UU/s the motor trails by 0.5 UU and closes in as
    // e^(-t / 50 ms): within 0.01 UU after 50 ms x ln(50) = 196 ms.
    MCCLPCI_IMP::system::active()
        .unwrap()
        .lock_machine()
        .cards_mut()[0][0]
        .set_plant_lag(Some(0.05));
    assert_eq!(MCC_SetInPosMode(IPM_ONETIME_BLOCK, 0), NO_ERR);
    assert_eq!(MCC_SetInPosMode(4, 0), PARAMETER_ERR);
    assert_eq!(MCC_SetInPosMaxCheckTime(1000, 0), NO_ERR);
    // A NaN tolerance is taken as the vendor's library takes it (its 32-bit pulse
    // conversion: 2^31 pulses, scenario setters_inpos_group); then 0.01 UU = 5 pulses.
    assert_eq!(
        MCC_SetInPosToleranceEx(f64::NAN, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0),
        NO_ERR
    );
    assert_eq!(
        MCC_SetInPosToleranceEx(0.01, 0.01, 0.01, 0.01, 0.01, 0.01, 0.01, 0.01, 0),
        NO_ERR
    );
    // The switch is a command of one period (type 11, scenario inpos_switches), then
    // the line's 500 periods (5 UU at 10 UU/s).
    assert!(MCC_EnableInPos(0, IMP_AXIS_X) >= 0);
    assert!(line_x(5.0) >= 0);
    assert!(line_x(6.0) >= 0);
    run(501);
    assert_eq!(x(), 5.0, "the first line ended");
    let mut st = [0u8; 8];
    let read = |st: &mut [u8; 8]| {
        let [a, b, c, d, e, f, g, h] = st;
        // SAFETY: eight valid pointers.
        unsafe { MCC_GetInPosStatus(a, b, c, d, e, f, g, h, 0) }
    };
    assert_eq!(read(&mut st), NO_ERR);
    assert_eq!(st[0], 0, "not yet in position");
    run(190);
    assert_eq!(x(), 5.0, "the next line waits for the motor");
    run(150);
    assert!(
        x() > 5.0,
        "in position after about 196 ms, then the next line runs"
    );
    run(1000);
    assert_eq!(MCC_GetErrorCode(0), 0);
    assert_eq!(read(&mut st), NO_ERR);
    assert_eq!(
        st[0], 0xFF,
        "the last line ended in position; held until the next one"
    );
    assert_eq!(st[1], 0, "Y is not checked");
    // A 100 ms limit fails: 0xF501, the rest of the queue is dropped.
    assert_eq!(MCC_SetInPosMaxCheckTime(100, 0), NO_ERR);
    assert!(line_x(7.0) >= 0);
    assert!(line_x(8.0) >= 0);
    run(2000);
    assert_eq!(MCC_GetErrorCode(0), 0xF501);
    assert_eq!(x(), 7.0, "the second line never ran");
    assert_eq!(status(), GMS_STOP);
    // UNBLOCK: the same failure lets the queue go on, without a record.
    assert_eq!(MCC_ClearError(0), NO_ERR);
    assert_eq!(MCC_SetInPosMode(IPM_ONETIME_UNBLOCK, 0), NO_ERR);
    assert!(line_x(9.0) >= 0);
    assert!(line_x(10.0) >= 0);
    run(3000);
    assert_eq!(MCC_GetErrorCode(0), 0);
    assert_eq!(x(), 10.0);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn queued_outputs_change_when_the_queue_reaches_them() {
    let _g = setup();
    use MCCLPCI_IMP::ffi::local_io::MCC_SetServoOn;
    use MCCLPCI_IMP::ffi::rio::*;
    assert_eq!(MCC_SetServoOn(0, 0), NO_ERR);
    assert!(line_x(1.0) >= 0); // 100 ms
                               // Servo 0 off, servo 2 on, after the line; remote port 1 of RIO set 0 bits 0..3 = 0x5.
    assert!(MCCLPCI_IMP::ffi::trajectory::MCC_QueueLIOOutputValue(0x05, 0x04, 0) >= 0);
    assert!(MCCLPCI_IMP::ffi::trajectory::MCC_QueueRIOOutputValue(0x000F, 0x0005, 0, 1, 0) >= 0);
    assert_eq!(
        MCCLPCI_IMP::ffi::trajectory::MCC_QueueRIOOutputValue(0xF, 5, 2, 1, 0),
        PARAMETER_ERR
    );
    assert_eq!(
        MCCLPCI_IMP::ffi::trajectory::MCC_QueueARIOOutputValue(0xF, 5, 0, 32, 0),
        PARAMETER_ERR
    );
    let servo = |ch: u16| {
        let mut v = -1;
        // SAFETY: valid pointer.
        unsafe { MCCL_SimGetOutput(0, ch, MCCL_SIM_OUT_SERVO, &mut v) };
        v
    };
    run(50);
    assert_eq!((servo(0), servo(2)), (1, 0), "not yet: the line runs");
    run(60);
    assert_eq!((servo(0), servo(2)), (0, 1), "after the line");
    let mut w: WORD = 0;
    // SAFETY: valid pointer.
    assert_eq!(unsafe { MCC_GetRIOOutputValue(&mut w, 0, 1, 0) }, NO_ERR);
    assert_eq!(w, 0x0005);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

fn led(ch: u16) -> WORD {
    let mut v: WORD = 9;
    // SAFETY: valid pointer.
    assert_eq!(unsafe { MCC_GetLedLightStatus(ch, &mut v, 0) }, NO_ERR);
    let mut sim = 9;
    assert_eq!(
        // SAFETY: valid pointer.
        unsafe { MCCL_SimGetOutput(0, ch, MCCL_SIM_OUT_LED, &mut sim) },
        NO_ERR
    );
    assert_eq!(i32::from(v), sim, "MCCL_SimGetOutput reads the same LED");
    v
}

fn led_settings() -> [(bool, bool, u16); 8] {
    MCCLPCI_IMP::system::active()
        .unwrap()
        .lock_machine()
        .triggers(0)
        .trig_out_settings(mccl_core::machine::triggers::TrigOutKind::Led)
        .map(|o| (o.enabled, o.value, o.source))
}

#[test]
fn led_trigger_out_checks_its_arguments() {
    let _g = fresh();
    assert_eq!(MCC_SetLedTrigOutEnable(1, 0, 0), INITIAL_MOTION_ERR);
    assert_eq!(MCC_SetLedTrigOutValue(1, 0, 0), INITIAL_MOTION_ERR);
    assert_eq!(MCC_SetLedTrigOutSource(1, 0, 0), INITIAL_MOTION_ERR);
    assert_eq!(
        MCC_SetLedTrigOutEnable(1, 8, 0),
        INITIAL_MOTION_ERR,
        "bad point"
    );
    assert_eq!(init_ms(1, 1), NO_ERR);
    let before = led_settings();
    let bad = [
        MCC_SetLedTrigOutEnable(2, 0, 0),
        MCC_SetLedTrigOutEnable(1, 8, 0),
        MCC_SetLedTrigOutEnable(1, 0, 1), // one card only
        MCC_SetLedTrigOutValue(2, 0, 0),
        MCC_SetLedTrigOutValue(1, 8, 0),
        MCC_SetLedTrigOutValue(1, 0, 12),
        MCC_SetLedTrigOutSource(0x100, 0, 0),
        MCC_SetLedTrigOutSource(1, 8, 0),
        MCC_SetLedTrigOutSource(1, 0, 1),
    ];
    assert!(bad.iter().all(|&r| r == PARAMETER_ERR), "{bad:?}");
    assert_eq!(led_settings(), before, "failed calls change nothing");
    // Every point, value and source bit in range is taken.
    assert_eq!(MCC_SetLedTrigOutEnable(1, 7, 0), NO_ERR);
    assert_eq!(MCC_SetLedTrigOutValue(1, 7, 0), NO_ERR);
    assert_eq!(MCC_SetLedTrigOutSource(0xFF, 7, 0), NO_ERR);
    assert_eq!(led_settings()[7], (true, true, 0xFF));
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn led_trigger_out_shows_its_value_for_the_trigger_period() {
    let _g = setup(); // 1 ms ticks, X at 10 UU/s with no acc/dec: 5 counts per tick
    assert_eq!(MCC_SetLedLightOn(3, 0), NO_ERR);
    // LED 3 (lit) goes dark, LED 4 lights on compare 0; LED 5 waits for compare 1; LED 6
    // has the source but is not enabled.
    for (pt, value, source, enable) in [
        (3, 0, LED_TRIG_ENC0, 1),
        (4, 1, LED_TRIG_ENC0, 1),
        (5, 1, LED_TRIG_ENC1, 1),
        (6, 1, LED_TRIG_ENC0, 0),
    ] {
        assert_eq!(MCC_SetLedTrigOutValue(value, pt, 0), NO_ERR);
        assert_eq!(MCC_SetLedTrigOutSource(source as WORD, pt, 0), NO_ERR);
        assert_eq!(MCC_SetLedTrigOutEnable(enable, pt, 0), NO_ERR);
    }
    assert_eq!(MCC_SetLIOTrigOutPeriod(5_000_000, 0), NO_ERR); // 5 ms, shared with the LIO
    assert_eq!(MCC_SetENCCompValue(100, 0, 0), NO_ERR);
    assert_eq!(MCC_EnableENCCompTrigger(0, 0), NO_ERR);
    assert!(line_x(1.0) >= 0);
    let mut rows = Vec::new();
    for _ in 0..40 {
        run(1);
        rows.push((enc(0), [led(3), led(4), led(5), led(6)]));
    }
    // X is at 0.01 n UU = 5 n counts after tick n: the count reaches 100 at tick 20, and
    // the LEDs hold for 5 ms: ticks 20..24; at 25 ms the hold has ended.
    assert_eq!(rows[19].0, 100);
    assert_eq!(rows[18].0, 95);
    for (i, (_, l)) in rows.iter().enumerate() {
        let tick = i + 1;
        let held = (20..25).contains(&tick);
        let want = if held { [0, 1, 0, 0] } else { [1, 0, 0, 0] };
        assert_eq!(*l, want, "tick {tick}");
    }
    // The servo-on outputs have no trigger-out: untouched.
    let mut v = 9;
    assert_eq!(
        // SAFETY: valid pointer.
        unsafe { MCCL_SimGetOutput(0, 4, MCCL_SIM_OUT_SERVO, &mut v) },
        NO_ERR
    );
    assert_eq!(v, 0);
    // While a trigger holds an LED, MCC_SetLedLightOff changes what it returns to.
    assert_eq!(MCC_SetENCCompValue(300, 0, 0), NO_ERR); // at tick 60
    run(20);
    assert_eq!((enc(0), led(3)), (300, 0), "tick 60: held dark");
    assert_eq!(MCC_SetLedLightOff(3, 0), NO_ERR);
    run(5);
    assert_eq!(led(3), 0, "returns to off");
    assert_eq!(MCC_SetLedLightOn(3, 0), NO_ERR);
    assert_eq!(led(3), 1);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn enc_filter_clock_is_kept_per_card_like_the_other_filter_clocks() {
    let _g = fresh();
    assert_eq!(MCC_SetENCFilterClock(3, 0), INITIAL_MOTION_ERR);
    assert_eq!(init_ms(2, 1), NO_ERR);
    let filters = |cd: usize| {
        MCCLPCI_IMP::system::active()
            .unwrap()
            .lock_machine()
            .card_settings(cd)
            .filters
    };
    assert_eq!(
        MCC_SetENCFilterClock(3, 2),
        PARAMETER_ERR,
        "card 2 not initialised"
    );
    assert_eq!(MCC_SetENCFilterClock(3, 12), PARAMETER_ERR);
    assert_eq!(
        (filters(0), filters(1)),
        ([0; 4], [0; 4]),
        "nothing changed"
    );
    // Any WORD, as for the limit, home and GPIO filter clocks (the manuals give no
    // range); kept beside them: [limit, home, GPIO, encoder].
    assert_eq!(MCC_SetENCFilterClock(0xFFFF, 1), NO_ERR);
    assert_eq!(MCC_SetENCFilterClock(0, 0), NO_ERR);
    assert_eq!(MCC_SetLimitFilterClk(2, 1), NO_ERR);
    assert_eq!(MCC_SetGpioFilterClk(4, 1), NO_ERR);
    assert_eq!((filters(0), filters(1)), ([0; 4], [2, 0, 4, 0xFFFF]));
    // The simulated encoder has no noise to filter: the count is unchanged by it.
    assert_eq!(MCC_SetFeedSpeed(10.0, 0), 10.0);
    assert!(line_x(1.0) >= 0);
    run(1000);
    assert_eq!(enc(0), 500, "1 UU at 500 pulses per UU, x4");
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}
