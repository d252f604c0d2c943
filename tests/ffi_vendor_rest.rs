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
    // Defaults read through the old struct: 500 PPR, mode 3 approaching in direction 1,
    // so leaving in direction 0; encoder x4.
    let m = get_mach(0, 0);
    assert_eq!((m.dwPPR, m.wRPM, m.dfPitch), (500, 3000, 1.0));
    assert_eq!(
        (m.stHome.wType, m.stHome.wApproachDir, m.stHome.wLeaveDir),
        (3, 1, 0)
    );
    assert_eq!(m.stEncoder.wInputRate, 4);

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
        |m: &mut SYS_MACH_PARAM| m.stHome.wType = 17,
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

unsafe extern "C" fn hsk_count(p: *mut HSKINT) {
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
    let t0 = shared.clock.ticks();
    assert_eq!(MCC_HostInterrupt(1), NO_ERR);
    assert_eq!(MCC_HostInterrupt(1), NO_ERR);
    assert_eq!(MCC_SlaveInterrupt(1), NO_ERR);
    assert_eq!(HSK_CALLS.load(SeqCst), 0, "not before a tick");
    MCC_TimeDelay(1);
    assert_eq!(shared.clock.ticks(), t0 + 1);
    assert_eq!((HSK_CALLS.load(SeqCst), HSK_SUM.load(SeqCst)), (1, 3));
    assert_eq!(shared.periph[1].lock().handshake.received, 2);
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
