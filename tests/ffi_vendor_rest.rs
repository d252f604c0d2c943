//! Tests of vendor functions the manuals do not describe (docs/undocumented-functions.md):
//! the old machine parameters, the handshake interrupts, the converter and remote I/O
//! timing, the cone. Called as C calls them; numbers derived by hand in the comments.

mod common;

use common::fresh;
use std::ptr::null_mut;
use MCCLPCI_IMP::ffi::legacy_params::*;
use MCCLPCI_IMP::ffi::system::*;
use MCCLPCI_IMP::ffi::trajectory::*;
use MCCLPCI_IMP::vendor::consts::*;
use MCCLPCI_IMP::vendor::*;

fn get_mach(ch: u16, card: u16) -> SYS_MACH_PARAM {
    let mut m = SYS_MACH_PARAM::default();
    // SAFETY: m is a valid SYS_MACH_PARAM.
    assert_eq!(unsafe { MCC_GetMachParam(&mut m, ch, card) }, NO_ERR);
    m
}

fn pulses(group: u16) -> [std::os::raw::c_long; 8] {
    let mut p = [0 as std::os::raw::c_long; 8];
    let [a, b, c, d, e, f, g, h] = &mut p;
    // SAFETY: eight valid pointers.
    let r = unsafe { MCCLPCI_IMP::ffi::coordinate::MCC_GetPulsePos(a, b, c, d, e, f, g, h, group) };
    assert_eq!(r, NO_ERR);
    p
}

fn wait_stop(group: u16) {
    while MCCLPCI_IMP::ffi::status::MCC_GetMotionStatus(group) != GMS_STOP {
        MCC_TimeDelay(1);
    }
}

#[test]
fn mach_param_is_the_three_newer_setters_in_one() {
    let _g = fresh();
    // Defaults read through the old struct: 500 PPR, mode 3 approaching in direction 0
    // (the vendor's library's default home direction), so leaving in direction 1;
    // encoder x4.
    let m = get_mach(0, 0);
    assert_eq!((m.dwPPR, m.wRPM, m.dfPitch), (500, 3000, 1.0));
    assert_eq!(
        (m.stHome.wType, m.stHome.wApproachDir, m.stHome.wLeaveDir),
        (3, 0, 1)
    );
    assert_eq!(m.stEncoder.wInputRate, 4);

    // Go-home values the old struct has no field for (the defaults are 1 UU/s and no
    // index pulse, as the vendor's library reads them): set first, kept after.
    let mut h = MCCLPCI_IMP::config::default_home_config();
    h.dfHighSpeed = 10.0;
    h.nIndexCount = 2;
    // SAFETY: valid pointer.
    assert_eq!(unsafe { MCC_SetHomeConfig(&mut h, 1, 0) }, NO_ERR);
    let mut m = get_mach(1, 0);
    m.dwPPR = 1000;
    m.dfPitch = 2.0; // 1000 x 4 / 2 = 2000 pulses per UU
    m.dfGearRatio = 4.0;
    m.stHome.wType = HM_SENSOR_ONLY as WORD;
    m.stHome.wApproachDir = 0;
    m.stHome.wLeaveDir = 1;
    m.stHome.dfOffset = -2.5;
    m.stEncoder.wInputRate = 1;
    m.wOverTravelDownSensorMode = SL_NORMAL_OPEN;
    // SAFETY: valid pointer.
    assert_eq!(unsafe { MCC_SetMachParam(&mut m, 1, 0) }, NO_ERR);
    // The newer getters see each part.
    let mut mac = SYS_MAC_PARAM::default();
    let mut home = SYS_HOME_CONFIG::default();
    let mut enc = SYS_ENCODER_CONFIG::default();
    // SAFETY: valid pointers.
    unsafe {
        assert_eq!(MCC_GetMacParam(&mut mac, 1, 0), NO_ERR);
        assert_eq!(MCC_GetHomeConfig(&mut home, 1, 0), NO_ERR);
        assert_eq!(MCC_GetEncoderConfig(&mut enc, 1, 0), NO_ERR);
    }
    assert_eq!((mac.dwPPR, mac.dfPitch, mac.dfGearRatio), (1000, 2.0, 4.0));
    assert_eq!(mac.wOverTravelDownSensorMode, SL_NORMAL_OPEN);
    assert_eq!((home.wMode, home.wDirection, home.dfOffset), (3, 0, -2.5));
    assert_eq!((home.dfHighSpeed, home.nIndexCount), (10.0, 2), "kept");
    assert_eq!(enc.wInputRate, 1);
    assert_eq!(
        get_mach(1, 0).stHome.wType,
        3,
        "HM_SENSOR_ONLY reads back as mode 3"
    );

    // Refused: nothing of the three changes.
    let before = get_mach(1, 0);
    for bad in [
        |m: &mut SYS_MACH_PARAM| m.dwPPR = 0,
        |m: &mut SYS_MACH_PARAM| m.dfPitch = f64::NAN,
        |m: &mut SYS_MACH_PARAM| m.dfHighLimit = f64::INFINITY,
        |m: &mut SYS_MACH_PARAM| m.stHome.wType = HM_INDEX_ONLY as WORD,
        // The old form's home types run 3..19 (HM_FIRST..HM_LAST); 20 is past them.
        |m: &mut SYS_MACH_PARAM| m.stHome.wType = 20,
        |m: &mut SYS_MACH_PARAM| m.stHome.wLeaveDir = 2,
        |m: &mut SYS_MACH_PARAM| m.stHome.dfOffset = f64::NAN,
        |m: &mut SYS_MACH_PARAM| m.stEncoder.wInputRate = 0,
        |m: &mut SYS_MACH_PARAM| m.wOverTravelUpSensorMode = 3,
    ] {
        let mut m = before;
        m.dwPPR = 7; // a valid change that must not land either
        bad(&mut m);
        // SAFETY: valid pointer.
        assert_eq!(unsafe { MCC_SetMachParam(&mut m, 1, 0) }, PARAMETER_ERR);
        assert_eq!(get_mach(1, 0), before);
    }
    // SAFETY: NULL and bad indices are refused before anything is read or written.
    unsafe {
        assert_eq!(MCC_SetMachParam(null_mut(), 1, 0), PARAMETER_ERR);
        assert_eq!(MCC_GetMachParam(null_mut(), 1, 0), PARAMETER_ERR);
        let mut m = before;
        assert_eq!(MCC_SetMachParam(&mut m, 8, 0), PARAMETER_ERR);
        assert_eq!(MCC_SetMachParam(&mut m, 0, 12), PARAMETER_ERR);
        assert_eq!(MCC_GetMachParam(&mut m, 8, 0), PARAMETER_ERR);
        assert_eq!(MCC_GetMachParam(&mut m, 0, 12), PARAMETER_ERR);
    }
    assert_eq!(MCC_UpdateMachParam(), INITIAL_MOTION_ERR);
}

#[test]
fn update_mach_param_applies_them_to_the_running_card() {
    let _g = fresh();
    assert_eq!(common::init(1), NO_ERR);
    let mut m = get_mach(0, 0);
    m.dwPPR = 2000; // 2000 pulses per UU with pitch 1 and gear 1
                    // SAFETY: valid pointer.
    assert_eq!(unsafe { MCC_SetMachParam(&mut m, 0, 0) }, NO_ERR);
    assert_eq!(MCC_GetConvFactor(0, 0), 500.0, "not before the update");
    assert_eq!(MCC_UpdateMachParam(), NO_ERR);
    assert_eq!(MCC_GetConvFactor(0, 0), 2000.0);
    // A line of 1.5 UU on X: 1.5 x 2000 = 3000 pulses; Y keeps 500 per UU: 0.5 -> 250.
    assert!(
        MCCLPCI_IMP::ffi::motion::MCC_Line(1.5, 0.5, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0, 0xFF) >= 0
    );
    wait_stop(0);
    assert_eq!(&pulses(0)[..2], &[3000, 250]);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

// ---- handshake ----

use std::sync::atomic::{AtomicU32, Ordering::SeqCst};

static HSK_CALLS: AtomicU32 = AtomicU32::new(0);
static HSK_SUM: AtomicU32 = AtomicU32::new(0);

unsafe extern "system" fn hsk_count(p: *mut HSKINT) {
    HSK_CALLS.fetch_add(1, SeqCst);
    // SAFETY: valid for the call.
    HSK_SUM.fetch_add(u32::from(unsafe { (*p).HANDSHAKE }), SeqCst);
}

fn handshake_under(clock: &str) {
    use MCCLPCI_IMP::ffi::handshake::*;
    use MCCLPCI_IMP::ffi::isr::MCC_SetHSKRoutine;
    let _g = fresh();
    std::env::set_var("MCCL_CLOCK", clock);
    assert_eq!(MCC_HostInterrupt(0), INITIAL_MOTION_ERR);
    assert_eq!(MCC_SlaveInterrupt(0), INITIAL_MOTION_ERR);
    assert_eq!(common::init_ms(2, 1), NO_ERR);
    let shared = MCCLPCI_IMP::system::active().unwrap();
    HSK_CALLS.store(0, SeqCst);
    HSK_SUM.store(0, SeqCst);
    // No routine: the causes are dropped, nothing is called.
    assert_eq!(MCC_SlaveInterrupt(0), NO_ERR);
    MCC_TimeDelay(1);
    assert_eq!(MCC_SetHSKRoutine(Some(hsk_count), 1), NO_ERR);
    // Two host interrupts and one slave interrupt between ticks: the card acknowledges
    // both requests in its next tick and the slave's own interrupt is delivered after it
    // too: one call with HANDSHAKE = 3, after exactly one tick.
    let t0 = shared.clock().ticks();
    assert_eq!(MCC_HostInterrupt(1), NO_ERR);
    assert_eq!(MCC_HostInterrupt(1), NO_ERR);
    assert_eq!(MCC_SlaveInterrupt(1), NO_ERR);
    assert_eq!(HSK_CALLS.load(SeqCst), 0, "not before a tick");
    MCC_TimeDelay(1);
    assert_eq!(shared.clock().ticks(), t0 + 1);
    assert_eq!((HSK_CALLS.load(SeqCst), HSK_SUM.load(SeqCst)), (1, 3));
    assert_eq!(shared.periph(1).unwrap().lock().handshake().received(), 2);
    // Nothing more: each request is acknowledged once.
    MCC_TimeDelay(5);
    assert_eq!(HSK_CALLS.load(SeqCst), 1);
    // Card 0's routine is not registered: its handshakes call nothing.
    assert_eq!(MCC_HostInterrupt(0), NO_ERR);
    MCC_TimeDelay(2);
    assert_eq!(HSK_CALLS.load(SeqCst), 1);
    // Bad cards: card 2 was not initialised, 12 does not exist; nothing raised.
    for bad in [2, 12, 0xFFFF] {
        assert_eq!(MCC_HostInterrupt(bad), PARAMETER_ERR);
        assert_eq!(MCC_SlaveInterrupt(bad), PARAMETER_ERR);
    }
    MCC_TimeDelay(2);
    assert_eq!(HSK_CALLS.load(SeqCst), 1);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn handshake_interrupts_stepped() {
    handshake_under("stepped");
}

#[test]
fn handshake_interrupts_fast() {
    handshake_under("fast");
}

// ---- converter and RIO timing ----

fn adc_in(ch: u16) -> f32 {
    let mut v = f32::NAN;
    assert_eq!(
        // SAFETY: valid pointer.
        unsafe { MCCLPCI_IMP::ffi::adc::MCC_GetADCInput(&mut v, ch, 0) },
        NO_ERR
    );
    v
}

fn timing_under(clock: &str) {
    use MCCLPCI_IMP::ffi::adc::*;
    use MCCLPCI_IMP::ffi::converter_timing::*;
    use MCCLPCI_IMP::ffi::dac::MCC_SetDACOutput;
    use MCCLPCI_IMP::ffi::rio::*;
    let _g = fresh();
    std::env::set_var("MCCL_CLOCK", clock);
    assert_eq!(MCC_SetDACClockDivider(10, 0), INITIAL_MOTION_ERR);
    assert_eq!(MCC_SetRIOUpdateRate(10.0, 0, 0), INITIAL_MOTION_ERR);
    assert_eq!(common::init_ms(1, 1), NO_ERR); // 1 ms ticks

    // DAC at 100 Hz (10 ms per update), read through ADC 0 (wired to DAC 0) in single
    // mode, 0..10 V. Value k/4 V written at k ms (k = 0..29), a tick, a conversion: the
    // first write shows at once; later ones wait for the cycle from the last change:
    // k/4 of k = 9 shows in the tick ending at 10 ms, of k = 19 at 20 ms, of 29 at 30 ms.
    assert_eq!(MCC_SetDACUpdateRate(100.0, 0), NO_ERR);
    assert_eq!(MCC_SetADCConvType(ADC_TYPE_UNI_DIFF, 0, 0), NO_ERR);
    assert_eq!(MCC_SetADCConvMode(ADC_MODE_SINGLE, 0), NO_ERR);
    assert_eq!(MCC_SetADCSingleChannel(0, 0), NO_ERR);
    let mut seen = Vec::new();
    for k in 0..30 {
        assert_eq!(MCC_SetDACOutput(k as f32 / 4.0, 0, 0), NO_ERR);
        MCC_TimeDelay(1);
        assert_eq!(MCC_StartADCConv(0), NO_ERR);
        seen.push(adc_in(0));
    }
    let mut want = vec![0.0; 9];
    want.extend([2.25; 10]);
    want.extend([4.75; 10]);
    want.push(7.25);
    assert_eq!(seen, want, "DAC output at 100 Hz");

    // ADC free-running: 4 channels at divider 12500 scan in 4 x 16 x 12500 x 10 ns =
    // 8 ms, counted from MCC_StartADCConv. DAC 0 (default timing again: each write shows
    // at once) takes t/4 V before tick t; the scans in ticks 8 and 16 read 2 V and 4 V.
    assert_eq!(MCC_SetDACUpdateRate(1e9, 0), NO_ERR); // 1 ns: bus-bound 1.6 us again
    assert_eq!(MCC_SetADCConvMode(ADC_MODE_FREE, 0), NO_ERR);
    assert_eq!(MCC_SetADCClockDivider(12_500, 0), NO_ERR);
    for ch in 0..4 {
        assert_eq!(MCC_EnableADCConvChannel(ch, 0), NO_ERR);
    }
    assert_eq!(MCC_SetDACOutput(0.0, 0, 0), NO_ERR);
    MCC_TimeDelay(1);
    assert_eq!(MCC_StartADCConv(0), NO_ERR);
    let before = adc_in(0);
    let mut seen = Vec::new();
    for t in 1..=16 {
        assert_eq!(MCC_SetDACOutput(t as f32 / 4.0, 0, 0), NO_ERR);
        MCC_TimeDelay(1);
        seen.push(adc_in(0));
    }
    let mut want = vec![before; 7];
    want.extend([2.0; 8]);
    want.push(4.0);
    assert_eq!(seen, want, "ADC scans every 8 ms");
    // 500 Hz with divider 50 (bus 32 us): a scan every 2 ms from the call.
    assert_eq!(MCC_SetADCClockDivider(50, 0), NO_ERR);
    assert_eq!(MCC_SetADCUpdateRate(500.0, 0), NO_ERR);
    let mut seen = Vec::new();
    for t in 1..=4 {
        assert_eq!(MCC_SetDACOutput(5.0 + t as f32, 0, 0), NO_ERR);
        MCC_TimeDelay(1);
        seen.push(adc_in(0));
    }
    assert_eq!(seen, [4.0, 7.0, 7.0, 9.0], "scans in ticks 2 and 4");
    assert_eq!(MCC_StopADCConv(0), NO_ERR);

    // RIO set 0, slave 1 loops back; 300 Hz: a cycle of 3333333 ns from the call ends in
    // the ticks ending at 4, 7 and 10 ms (3.33, 6.67, 9.999999 ms).
    assert_eq!(MCC_EnableRIOSetControl(0, 0), NO_ERR);
    assert_eq!(MCC_EnableRIOSlaveControl(0, 1, 0), NO_ERR);
    assert_eq!(MCC_SetRIOUpdateRate(300.0, 0, 0), NO_ERR);
    let mut seen = Vec::new();
    for t in 1..=10u16 {
        assert_eq!(MCC_SetRIOOutputValue(t, 0, 1, 0), NO_ERR);
        MCC_TimeDelay(1);
        let mut v = 0xFFFF;
        // SAFETY: valid pointer.
        assert_eq!(unsafe { MCC_GetRIOInputValue(&mut v, 0, 1, 0) }, NO_ERR);
        seen.push(v);
    }
    assert_eq!(
        seen,
        [0, 0, 0, 4, 4, 4, 7, 7, 7, 10],
        "RIO transfers at 300 Hz"
    );
    // Divider 6000 with 2 slaves: 2 x 32 x 6000 x 10 ns = 3.84 ms > 3.33 ms: ticks 4, 8.
    assert_eq!(MCC_EnableRIOSlaveControl(0, 3, 0), NO_ERR);
    assert_eq!(MCC_SetRIOClockDivider(6000, 0, 0), NO_ERR);
    let mut seen = Vec::new();
    for t in 11..=18u16 {
        assert_eq!(MCC_SetRIOOutputValue(t, 0, 1, 0), NO_ERR);
        MCC_TimeDelay(1);
        let mut v = 0xFFFF;
        // SAFETY: valid pointer.
        assert_eq!(unsafe { MCC_GetRIOInputValue(&mut v, 0, 1, 0) }, NO_ERR);
        seen.push(v);
    }
    assert_eq!(seen, [10, 10, 10, 14, 14, 14, 14, 18]);

    // Refusals change nothing.
    let shared = MCCLPCI_IMP::system::active().unwrap();
    let snap = |s: &std::sync::Arc<MCCLPCI_IMP::engine::Shared>| {
        let p = s.periph(0).unwrap().lock();
        (
            *p.dac().cadence(),
            *p.adc().cadence(),
            *p.remote_io().rio_timing(),
        )
    };
    let before = snap(&shared);
    for bad in [0.0, -1.0, f64::NAN, f64::INFINITY, f64::NEG_INFINITY, 1e-9] {
        assert_eq!(MCC_SetDACUpdateRate(bad, 0), PARAMETER_ERR, "{bad}");
        assert_eq!(MCC_SetADCUpdateRate(bad, 0), PARAMETER_ERR, "{bad}");
        assert_eq!(MCC_SetRIOUpdateRate(bad, 0, 0), PARAMETER_ERR, "{bad}");
    }
    assert_eq!(MCC_SetDACClockDivider(0, 0), PARAMETER_ERR);
    assert_eq!(MCC_SetADCClockDivider(0, 0), PARAMETER_ERR);
    assert_eq!(MCC_SetRIOClockDivider(0, 0, 0), PARAMETER_ERR);
    assert_eq!(MCC_SetRIOClockDivider(10, 2, 0), PARAMETER_ERR);
    assert_eq!(MCC_SetRIOUpdateRate(10.0, 2, 0), PARAMETER_ERR);
    for card in [1, 12, 0xFFFF] {
        assert_eq!(MCC_SetDACClockDivider(10, card), PARAMETER_ERR);
        assert_eq!(MCC_SetDACUpdateRate(10.0, card), PARAMETER_ERR);
        assert_eq!(MCC_SetADCClockDivider(10, card), PARAMETER_ERR);
        assert_eq!(MCC_SetADCUpdateRate(10.0, card), PARAMETER_ERR);
        assert_eq!(MCC_SetRIOClockDivider(10, 0, card), PARAMETER_ERR);
        assert_eq!(MCC_SetRIOUpdateRate(10.0, 0, card), PARAMETER_ERR);
    }
    let after = snap(&shared);
    assert_eq!(
        (
            before.0.divider(),
            before.0.update_ns(),
            before.1.divider(),
            before.1.update_ns()
        ),
        (
            after.0.divider(),
            after.0.update_ns(),
            after.1.divider(),
            after.1.update_ns()
        )
    );
    assert_eq!(
        before.2.map(|c| (c.divider(), c.update_ns())),
        after.2.map(|c| (c.divider(), c.update_ns()))
    );
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn converter_and_rio_timing_stepped() {
    timing_under("stepped");
}

#[test]
fn converter_and_rio_timing_fast() {
    timing_under("fast");
}

// ---- cone ----

fn cur_pos(group: u16) -> [f64; 8] {
    let mut p = [f64::NAN; 8];
    let [a, b, c, d, e, f, g, h] = &mut p;
    // SAFETY: eight valid pointers.
    let r = unsafe { MCCLPCI_IMP::ffi::coordinate::MCC_GetCurPos(a, b, c, d, e, f, g, h, group) };
    assert_eq!(r, NO_ERR);
    p
}

fn command_count(group: u16) -> i32 {
    let mut n = -1;
    // SAFETY: valid pointer.
    let r = unsafe { MCCLPCI_IMP::ffi::status::MCC_GetCommandCount(&mut n, group) };
    assert_eq!(r, NO_ERR);
    n
}

/// Samples a cone in plane axes (a, b) about (ca, cb) with normal axis n that starts at
/// `p0` (read before it was queued: a status poll may already run ticks), every tick
/// until the group stops: the unwrapped angle turned (signed), the radius, the normal
/// coordinate and the path speed read (`MCC_GetCurFeedSpeed`) of each sample.
fn sample_cone(
    p0: [f64; 8],
    a: usize,
    b: usize,
    n: usize,
    ca: f64,
    cb: f64,
) -> Vec<(f64, f64, f64, f64)> {
    let mut prev = (p0[b] - cb).atan2(p0[a] - ca);
    let mut turned = 0.0;
    let mut out = vec![(0.0, (p0[a] - ca).hypot(p0[b] - cb), p0[n], 0.0)];
    let mut stopped = false;
    while !stopped {
        stopped = MCCLPCI_IMP::ffi::status::MCC_GetMotionStatus(0) == GMS_STOP;
        let p = cur_pos(0);
        let ang = (p[b] - cb).atan2(p[a] - ca);
        let mut d = ang - prev;
        while d > std::f64::consts::PI {
            d -= std::f64::consts::TAU;
        }
        while d < -std::f64::consts::PI {
            d += std::f64::consts::TAU;
        }
        turned += d;
        prev = ang;
        let v = MCCLPCI_IMP::ffi::motion::MCC_GetCurFeedSpeed(0);
        out.push((turned, (p[a] - ca).hypot(p[b] - cb), p[n], v));
        MCC_TimeDelay(1);
    }
    out
}

fn cone_under(clock: &str) {
    use std::f64::consts::TAU;
    use MCCLPCI_IMP::ffi::cone::*;
    use MCCLPCI_IMP::ffi::motion::*;
    let _g = fresh();
    std::env::set_var("MCCL_CLOCK", clock);
    // Positions read whole pulses (toward 0): 10^7 pulses per UU on X, Y, Z keep them
    // within 1e-7 UU of the path (at 20 UU/s that is 2e5 pulses a period, inside the
    // card's default limit of 1e6).
    for ch in 0..3 {
        let mut m = MCCLPCI_IMP::config::default_mac_param();
        m.dwPPR = 10_000_000;
        // SAFETY: valid pointer.
        assert_eq!(unsafe { MCC_SetMacParam(&mut m, ch, 0) }, NO_ERR);
    }
    assert_eq!(common::init_ms(1, 1), NO_ERR);
    assert_eq!(MCC_SetFeedSpeed(20.0, 0), 20.0);
    assert_eq!(MCC_SetAccTime(100.0, 0), NO_ERR);
    assert_eq!(MCC_SetDecTime(100.0, 0), NO_ERR);
    assert!(MCC_Line(10.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0, 0xFF) >= 0);
    wait_stop(0);

    // Counter-clockwise about (0, 0) from (10, 0, 0) to Z = 6 at pitch 2: 3 turns; the
    // radius grows 2 per turn, 10 -> 16; the end is (16, 0, 6) (3 whole turns).
    let p0 = cur_pos(0);
    assert!(MCC_ConeXY_Z(0.0, 0.0, 6.0, 2.0, 2.0, CIR_CCW as BYTE, 0) >= 0);
    let s = sample_cone(p0, 0, 1, 2, 0.0, 0.0);
    let end = cur_pos(0);
    assert!(
        (end[0] - 16.0).abs() <= 1e-12 && end[1].abs() <= 1e-12,
        "{end:?}"
    );
    assert_eq!(end[2], 6.0, "the normal axis ends exactly at dfPos");
    assert!(
        ((s.last().unwrap().0 / TAU) - 3.0).abs() <= 1e-12,
        "3 turns"
    );
    // Every tick: radius = 10 + 2 x turns and Z = 2 x turns within 1e-6 (each axis
    // reads up to 1e-7 UU short: the radius up to 1.5e-7, the angle up to 1.5e-8 rad,
    // 5e-9 UU of the radius's growth); counter-clockwise: the angle never decreases
    // (beyond that 1.5e-8 rad).
    for (k, w) in s.windows(2).enumerate() {
        let (turned, r, z, _) = w[1];
        let turns = turned / TAU;
        assert!(
            (r - (10.0 + 2.0 * turns)).abs() <= 1e-6,
            "radius at tick {k}"
        );
        assert!((z - 2.0 * turns).abs() <= 1e-6, "Z at tick {k}");
        assert!(turned >= w[0].0 - 1e-7, "counter-clockwise at tick {k}");
    }
    // Path speed. The length, integrated independently here (Simpson, 6000 intervals,
    // of |dp/dφ| = sqrt(r² + k² + h²) with k = 2/2π, h = 2/2π, over 3 turns): about
    // 6π x 13 = 245 UU. On the grid of 1 ms periods with 100 ms ramps (na = nd = 100)
    // it cruises nc = ceil(L/20/0.001 - 100) periods at V = L/(0.1 + nc x 0.001) (at
    // most 20), and the status reads STOP three periods after its N = nc + 200. The
    // speed read is the chord of a period over the period: at cruise V short by at most
    // V θ²/24 with θ = V T/r <= 0.002 rad, 3.4e-6 UU/s; a ramp's periods next to the
    // cruise differ from V by about V/100² = 2e-3 UU/s.
    let k = 2.0 / TAU;
    let f = |t: f64| ((10.0 + k * t).powi(2) + 2.0 * k * k).sqrt();
    let n = 6000;
    let h = 3.0 * TAU / f64::from(n);
    let mut acc = f(0.0) + f(3.0 * TAU);
    for i in 1..n {
        acc += f(f64::from(i) * h) * if i % 2 == 1 { 4.0 } else { 2.0 };
    }
    let len = acc * h / 3.0;
    let nc = (len / 20.0 / 0.001 - 100.0).ceil();
    let v_cruise = len / (0.1 + nc * 0.001);
    let speeds: Vec<f64> = s.iter().map(|w| w.3).collect();
    assert!(
        speeds.iter().all(|&v| v <= v_cruise + 1e-9),
        "never above the cruise speed {v_cruise}"
    );
    let cruise = speeds
        .iter()
        .filter(|&&v| (v - v_cruise).abs() <= 1e-5)
        .count();
    assert_eq!(cruise as f64, nc, "cruise periods at {v_cruise} UU/s");
    // The command ran N periods, STOP read three later (the samples start before the
    // first period; the clock's polls may add one).
    let ticks = s.len() - 1;
    let want = nc as usize + 200 + 3;
    assert!(ticks.abs_diff(want) <= 1, "{ticks} ticks, {want} expected");

    // Clockwise in ZX (first coordinate Z), shrinking: about (Z, X) = (0, 0) from
    // (X, Y, Z) = (16, 6, 0)... the group stands at (16, 0, 6): Z = 6, X = 16 in plane
    // (Z, X) coordinates, radius sqrt(36 + 256). Y goes to -1 at pitch 0.5: 2 turns,
    // the radius shrinking 1 per turn.
    let r0 = (36.0f64 + 256.0).sqrt();
    let p0 = cur_pos(0);
    assert!(MCC_ConeZX_Y(0.0, 0.0, -1.0, 0.5, -1.0, CIR_CW as BYTE, 0) >= 0);
    let s = sample_cone(p0, 2, 0, 1, 0.0, 0.0);
    for (k, w) in s.windows(2).enumerate() {
        let (turned, r, y, _) = w[1];
        let turns = -turned / TAU;
        assert!(
            (r - (r0 - turns)).abs() <= 1e-6,
            "radius at tick {k}: {r} {turns} {w:?}"
        );
        assert!((y - -0.5 * turns).abs() <= 1e-6, "Y at tick {k}");
        assert!(turned <= w[0].0 + 1e-7, "clockwise at tick {k}");
    }
    // The end: 2 whole turns back on the start's ray at radius r0 − 2, read in whole
    // pulses of 1e-7 UU.
    let end = cur_pos(0);
    assert!((end[2] - 6.0 * (r0 - 2.0) / r0).abs() <= 1e-7, "{end:?}");
    assert!((end[0] - 16.0 * (r0 - 2.0) / r0).abs() <= 1e-7, "{end:?}");
    assert_eq!(end[1], -1.0);
    // YZ, incremental: center 1 UU from the start in Y, X rises 1 at pitch 1: 1 turn.
    assert_eq!(MCCLPCI_IMP::ffi::coordinate::MCC_SetIncrease(0), NO_ERR);
    let p = cur_pos(0);
    assert!(MCC_ConeYZ_X(1.0, 0.0, 1.0, 1.0, 0.5, CIR_CCW as BYTE, 0) >= 0);
    wait_stop(0);
    let q = cur_pos(0);
    // One whole turn from angle π about (Y+1, Z): back at angle π, radius 1.5 (both
    // readings whole pulses of 1e-7 UU).
    assert!((q[1] - (p[1] + 1.0 - 1.5)).abs() <= 2e-7 && (q[2] - p[2]).abs() <= 2e-7);
    assert_eq!(q[0], p[0] + 1.0);
    assert_eq!(MCCLPCI_IMP::ffi::coordinate::MCC_SetAbsolute(0), NO_ERR);

    // Refusals: nothing queued, and only the degenerate center records 0xF104. (A
    // direction other than 0 is counter-clockwise, as the vendor's library takes a
    // circle's: not refused.)
    let before = command_count(0);
    let ok = (0.0, 0.0, 1.0, 1.0, 0.0, CIR_CCW as BYTE);
    type Args = (f64, f64, f64, f64, f64, BYTE);
    let bads: Vec<Args> = vec![
        (f64::NAN, ok.1, ok.2, ok.3, ok.4, ok.5),
        (ok.0, f64::INFINITY, ok.2, ok.3, ok.4, ok.5),
        (ok.0, ok.1, f64::NAN, ok.3, ok.4, ok.5),
        (ok.0, ok.1, ok.2, f64::NEG_INFINITY, ok.4, ok.5),
        (ok.0, ok.1, ok.2, ok.3, f64::NAN, ok.5),
        (ok.0, ok.1, ok.2, 0.0, ok.4, ok.5),   // zero pitch
        (ok.0, ok.1, 100.0, 1.0, -1.0, ok.5),  // 100 turns, radius < 0
        (ok.0, ok.1, ok.2, ok.3, 1e300, ok.5), // beyond the position range
    ];
    for (i, a) in bads.iter().enumerate() {
        for f in [MCC_ConeXY_Z, MCC_ConeYZ_X, MCC_ConeZX_Y] {
            assert_eq!(
                f(a.0, a.1, a.2, a.3, a.4, a.5, 0),
                PARAMETER_ERR,
                "case {i}"
            );
        }
    }
    assert_eq!(MCCLPCI_IMP::ffi::status::MCC_GetErrorCode(0), 0);
    // The start on the center (incremental: a center 0 away; the position read is
    // whole pulses, not where the axes stand): a bad arc, as a helix: queued (the
    // vendor's library takes a curve's points as they come), it fails when it starts
    // with error record 0xF104 and the group stops where it stood.
    let p = cur_pos(0);
    assert_eq!(MCCLPCI_IMP::ffi::coordinate::MCC_SetIncrease(0), NO_ERR);
    assert_eq!(MCC_ConeXY_Z(0.0, 0.0, 1.0, 1.0, 0.0, 1, 0), 4);
    assert_eq!(MCCLPCI_IMP::ffi::coordinate::MCC_SetAbsolute(0), NO_ERR);
    MCC_TimeDelay(1);
    assert_eq!(MCCLPCI_IMP::ffi::status::MCC_GetErrorCode(0), 0xF104);
    wait_stop(0);
    assert_eq!(cur_pos(0), p, "did not move");
    assert_eq!(MCCLPCI_IMP::ffi::status::MCC_ClearError(0), NO_ERR);
    assert_eq!(command_count(0), before);
    // Bad groups answer as the helix does.
    for g in [1, 96, 0xFFFF] {
        assert_eq!(
            MCC_ConeXY_Z(0.0, 0.0, 1.0, 1.0, 0.0, 1, g),
            MCC_HelicaXY_Z(0.0, 0.0, 1.0, 1.0, 1, g)
        );
    }
    assert_eq!(MCC_CloseSystem(), NO_ERR);
    assert_eq!(
        MCC_ConeXY_Z(0.0, 0.0, 1.0, 1.0, 0.0, 1, 0),
        INITIAL_MOTION_ERR
    );
}

#[test]
fn cone_stepped() {
    cone_under("stepped");
}

#[test]
fn cone_fast() {
    cone_under("fast");
}

// ---- units ----

fn speeds(group: u16) -> [f64; 8] {
    let mut v = [f64::NAN; 8];
    let [a, b, c, d, e, f, g, h] = &mut v;
    // SAFETY: eight valid pointers.
    let r = unsafe { MCCLPCI_IMP::ffi::motion::MCC_GetSpeed(a, b, c, d, e, f, g, h, group) };
    assert_eq!(r, NO_ERR);
    v
}

fn units_under(clock: &str) {
    use MCCLPCI_IMP::ffi::motion::*;
    use MCCLPCI_IMP::ffi::units::*;
    let _g = fresh();
    std::env::set_var("MCCL_CLOCK", clock);
    // Closed: the implicit group 0 exists, no other.
    assert_eq!(MCC_GetUnit(0), UNIT_MM);
    assert_eq!(MCC_GetUnit(1), GROUP_PARAMETER_ERR);
    for bad in [0, 3, -1, c_int_max()] {
        assert_eq!(MCC_SetUnit(bad, 0), PARAMETER_ERR);
    }
    assert_eq!(MCC_SetUnit(UNIT_INCH, 1), GROUP_PARAMETER_ERR);
    assert_eq!(MCC_SetUnit(UNIT_INCH, 0xFFFF), GROUP_PARAMETER_ERR);
    assert_eq!(MCC_GetUnit(0), UNIT_MM, "refusals change nothing");
    assert_eq!(MCC_SetUnit(UNIT_INCH, 0), NO_ERR);
    assert_eq!(MCC_GetUnit(0), UNIT_INCH);
    // X's work zone ends at 50.8 mm = 2 inch.
    let mut m = get_mach(0, 0);
    m.dfHighLimit = 50.8;
    // SAFETY: valid pointer.
    assert_eq!(unsafe { MCC_SetMachParam(&mut m, 0, 0) }, NO_ERR);
    assert_eq!(common::init_ms(1, 1), NO_ERR);
    assert_eq!(MCC_GetUnit(0), UNIT_INCH);

    // A line of 0.5 inch = 12.7 mm: 12.7 x 500 pulses per mm = 6350 pulses. Feed 2
    // inch/s, 100 ms ramps: na = nd = 100 periods of 1 ms, nc = ceil(0.5/2/0.001 -
    // 100) = 150 at V = 0.5/(0.1 + 0.15) = 2 inch/s, N = 350; STOP reads in period 353.
    assert_eq!(MCC_SetFeedSpeed(2.0, 0), 2.0);
    assert_eq!(MCC_SetAccTime(100.0, 0), NO_ERR);
    assert_eq!(MCC_SetDecTime(100.0, 0), NO_ERR);
    let shared = MCCLPCI_IMP::system::active().unwrap();
    let t0 = shared.clock().ticks();
    assert!(MCC_Line(0.5, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0, 0xFF) >= 0);
    let mut peak: f64 = 0.0;
    while MCCLPCI_IMP::ffi::status::MCC_GetMotionStatus(0) != GMS_STOP {
        MCC_TimeDelay(1);
        peak = peak.max(speeds(0)[0]);
    }
    assert_eq!(pulses(0)[0], 6350);
    assert_eq!(cur_pos(0)[0], 0.5);
    assert!((peak - 2.0).abs() <= 1e-9, "feed in inch/s: {peak}");
    let ticks = shared.clock().ticks() - t0;
    assert!(ticks.abs_diff(353) <= 1, "{ticks} ticks");
    // A continuous jog travels the work zone end's distance, 2 inch (50.8 mm / 25.4),
    // from where the axis stands (as the vendor's library runs it), so to 2.5 inch =
    // 63.5 mm = 31750 pulses, at 30 % of the maximum safe speed 3000 rpm / 60 x 1 mm =
    // 50 mm/s: F = 15/25.4 inch/s, with the group's 100 ms ramps: nc = ceil(2/F/0.001 -
    // 100) = ceil(3286.67) = 3287 periods at V = 2/(0.1 + 3.287) = 0.59049 inch/s.
    assert!(MCCLPCI_IMP::ffi::jog::MCC_JogConti(1, 30.0, 0, 0) >= 0);
    let mut peak: f64 = 0.0;
    while MCCLPCI_IMP::ffi::status::MCC_GetMotionStatus(0) != GMS_STOP {
        MCC_TimeDelay(1);
        peak = peak.max(speeds(0)[0]);
    }
    assert_eq!(cur_pos(0)[0], 2.5);
    assert_eq!(pulses(0)[0], 31750);
    let v = 2.0 / (0.1 + 3.287);
    assert!((peak - v).abs() <= 1e-9, "safe speed in inch/s: {peak}");

    // Back to mm: read at once, in effect from MCC_UpdateParam (positions start at 0).
    assert_eq!(MCC_SetUnit(UNIT_MM, 0), NO_ERR);
    assert_eq!(MCC_GetUnit(0), UNIT_MM);
    assert!(MCC_Line(0.5, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0, 0xFF) >= 0);
    wait_stop(0);
    // Back to X = 0.5 inch: 6350 pulses.
    assert_eq!(pulses(0)[0], 6350, "still inches until the update");
    assert_eq!(MCC_UpdateParam(), NO_ERR);
    let p0 = pulses(0)[0];
    assert!(MCC_Line(0.5, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0, 0xFF) >= 0);
    wait_stop(0);
    assert_eq!(pulses(0)[0] - p0, 250, "0.5 mm = 250 pulses");
    // Running: a group that does not run is refused.
    assert_eq!(MCC_SetUnit(UNIT_INCH, 1), GROUP_PARAMETER_ERR);
    assert_eq!(MCC_GetUnit(1), GROUP_PARAMETER_ERR);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
    // A group created anew starts in mm; closing groups forgets their units.
    assert_eq!(MCC_SetUnit(UNIT_INCH, 0), NO_ERR);
    assert_eq!(MCC_CloseAllGroups(), NO_ERR);
    assert_eq!(MCC_GetUnit(0), UNIT_MM);
    assert_eq!(MCC_CreateGroup(0, 1, 2, -1, -1, -1, -1, -1, 0), 0);
    assert_eq!(MCC_SetUnit(UNIT_INCH, 0), NO_ERR);
    assert_eq!(MCC_CloseGroup(0), NO_ERR);
    assert_eq!(MCC_CreateGroup(0, 1, 2, -1, -1, -1, -1, -1, 0), 0);
    assert_eq!(MCC_GetUnit(0), UNIT_MM);
    assert_eq!(MCC_CloseAllGroups(), NO_ERR);
}

fn c_int_max() -> std::os::raw::c_int {
    std::os::raw::c_int::MAX
}

#[test]
fn units_stepped() {
    units_under("stepped");
}

#[test]
fn units_fast() {
    units_under("fast");
}
