//! Tests of the C entry points called as C would call them: every bad index, NULL pointer
//! and NaN gets the vendor code (docs/decisions.md, "Return values") and changes nothing.

mod common;

use common::{cards, fresh};
use std::ptr::null_mut;
use MCCLPCI_IMP::ffi::status::*;
use MCCLPCI_IMP::ffi::system::*;
use MCCLPCI_IMP::ffi::trajectory::*;
use MCCLPCI_IMP::vendor::consts::*;
use MCCLPCI_IMP::vendor::*;

fn init(n: usize) -> i32 {
    let mut c = cards(n);
    // SAFETY: c holds n valid SYS_CARD_CONFIG.
    unsafe { MCC_InitSystem(2, c.as_mut_ptr(), n as u16) }
}

fn get_mac(ch: u16, card: u16) -> SYS_MAC_PARAM {
    let mut m = SYS_MAC_PARAM::default();
    // SAFETY: m is a valid SYS_MAC_PARAM.
    assert_eq!(unsafe { MCC_GetMacParam(&mut m, ch, card) }, NO_ERR);
    m
}

#[test]
fn version_string() {
    let _g = fresh();
    let mut buf = [0x55 as std::os::raw::c_char; 8];
    // SAFETY: 8-byte buffer.
    unsafe { MCC_GetVersion(buf.as_mut_ptr()) };
    // SAFETY: MCC_GetVersion wrote a NUL-terminated string.
    let s = unsafe { std::ffi::CStr::from_ptr(buf.as_ptr()) };
    assert_eq!(s.to_str().unwrap(), "6.00");
    assert_eq!(buf[5], 0x55, "writes 5 bytes only");
    // SAFETY: NULL is allowed and ignored.
    unsafe { MCC_GetVersion(null_mut()) };
}

#[test]
fn sys_max_speed_checks() {
    let _g = fresh();
    assert_eq!(MCC_SetSysMaxSpeed(250.0), NO_ERR);
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY, 0.0, -1.0] {
        assert_eq!(MCC_SetSysMaxSpeed(bad), PARAMETER_ERR);
    }
    assert_eq!(MCC_GetSysMaxSpeed(), 250.0);
}

#[test]
fn mac_param_checks_and_round_trip() {
    let _g = fresh();
    let mut m = get_mac(0, 0);
    m.dwPPR = 1000;
    m.dfPitch = 5.0;
    m.dfGearRatio = 2.0;
    // SAFETY: valid pointers or NULL throughout.
    unsafe {
        assert_eq!(MCC_SetMacParam(&mut m, 7, 11), NO_ERR);
        assert_eq!(get_mac(7, 11), m);
        let before = get_mac(1, 0);
        assert_eq!(MCC_SetMacParam(null_mut(), 1, 0), PARAMETER_ERR);
        assert_eq!(MCC_SetMacParam(&mut m, 8, 0), PARAMETER_ERR);
        assert_eq!(MCC_SetMacParam(&mut m, 1, 12), PARAMETER_ERR);
        let mut nan = SYS_MAC_PARAM {
            dfPitch: f64::NAN,
            ..m
        };
        assert_eq!(MCC_SetMacParam(&mut nan, 1, 0), PARAMETER_ERR);
        let mut inf = SYS_MAC_PARAM {
            dfHighLimit: f64::INFINITY,
            ..m
        };
        assert_eq!(MCC_SetMacParam(&mut inf, 1, 0), PARAMETER_ERR);
        assert_eq!(get_mac(1, 0), before, "a failed call changes nothing");
        assert_eq!(MCC_GetMacParam(null_mut(), 0, 0), PARAMETER_ERR);
        let mut out = SYS_MAC_PARAM::default();
        assert_eq!(MCC_GetMacParam(&mut out, 8, 0), PARAMETER_ERR);
        assert_eq!(MCC_GetMacParam(&mut out, 0, 12), PARAMETER_ERR);
        assert_eq!(out, SYS_MAC_PARAM::default(), "nothing written on error");
    }
    // 1000 x 2 / 5 = 400 pulses per UU; a bad channel or card reads 0, as the vendor's
    // library answers (scenario convfactor).
    assert_eq!(MCC_GetConvFactor(7, 11), 400.0);
    assert_eq!(MCC_GetConvFactor(8, 0), 0.0);
    assert_eq!(MCC_GetConvFactor(0, 12), 0.0);
}

#[test]
fn encoder_and_home_config_checks() {
    let _g = fresh();
    // SAFETY: valid pointers or NULL throughout.
    unsafe {
        let mut e = SYS_ENCODER_CONFIG::default();
        assert_eq!(MCC_GetEncoderConfig(&mut e, 2, 0), NO_ERR);
        assert_eq!((e.wType, e.wInputRate), (ENC_TYPE_AB, 4));
        e.wInputRate = 2;
        assert_eq!(MCC_SetEncoderConfig(&mut e, 2, 0), NO_ERR);
        let mut bad = SYS_ENCODER_CONFIG { wInputRate: 5, ..e };
        assert_eq!(MCC_SetEncoderConfig(&mut bad, 2, 0), PARAMETER_ERR);
        assert_eq!(MCC_SetEncoderConfig(null_mut(), 2, 0), PARAMETER_ERR);
        assert_eq!(MCC_SetEncoderConfig(&mut e, 8, 0), PARAMETER_ERR);
        assert_eq!(MCC_GetEncoderConfig(null_mut(), 2, 0), PARAMETER_ERR);
        let mut r = SYS_ENCODER_CONFIG::default();
        assert_eq!(MCC_GetEncoderConfig(&mut r, 2, 0), NO_ERR);
        assert_eq!(r.wInputRate, 2);

        let mut h = SYS_HOME_CONFIG::default();
        assert_eq!(MCC_GetHomeConfig(&mut h, 0, 0), NO_ERR);
        assert_eq!(h.wMode, 3);
        h.wMode = 16;
        h.dfOffset = 12.5;
        assert_eq!(MCC_SetHomeConfig(&mut h, 0, 0), NO_ERR);
        for m in [20u16, 0xFFFF] {
            let mut b = SYS_HOME_CONFIG { wMode: m, ..h };
            assert_eq!(MCC_SetHomeConfig(&mut b, 0, 0), PARAMETER_ERR, "mode {m}");
        }
        let mut b = SYS_HOME_CONFIG {
            dfHighSpeed: f64::NAN,
            ..h
        };
        assert_eq!(MCC_SetHomeConfig(&mut b, 0, 0), PARAMETER_ERR);
        assert_eq!(MCC_SetHomeConfig(null_mut(), 0, 0), PARAMETER_ERR);
        assert_eq!(MCC_SetHomeConfig(&mut h, 0, 12), PARAMETER_ERR);
        assert_eq!(MCC_GetHomeConfig(null_mut(), 0, 0), PARAMETER_ERR);
        let mut r = SYS_HOME_CONFIG::default();
        assert_eq!(MCC_GetHomeConfig(&mut r, 0, 0), NO_ERR);
        assert_eq!((r.wMode, r.dfOffset), (16, 12.5));
    }
}

#[test]
fn group_table_rules() {
    let _g = fresh();
    assert_eq!(MCC_CloseAllGroups(), NO_ERR);
    // Before any group is created the default group 0 exists (queue 10000); a group
    // that does not exist has a queue of 0, as the vendor's library answers (scenarios
    // groups_table, overlap_groups).
    assert_eq!(MCC_GetCmdQueueSize(0), MOTION_QUEUE_SIZE);
    assert_eq!(MCC_GetCmdQueueSize(1), 0);
    assert_eq!(MCC_CreateGroup(0, 1, 2, -1, -1, -1, -1, -1, 0), 0);
    assert_eq!(MCC_CreateGroupEx(3, 4, 5, -1, -1, -1, -1, -1, 0, 50), 1);
    assert_eq!(MCC_GetCmdQueueSize(1), 50);
    // Bad mappings, cards and queue sizes: PARAMETER_ERR and nothing is created
    // (scenario create_group_odd), a channel another group has as well (scenario
    // overlap_groups).
    for (map, card) in [
        ([0, 0, -1, -1, -1, -1, -1, -1], 0),
        ([8, -1, -1, -1, -1, -1, -1, -1], 0),
        ([-7, 6, -1, -1, -1, -1, -1, -1], 0),
        ([6, -1, -1, -1, -1, -1, -1, -1], 12),
        ([6, -1, -1, -1, -1, -1, -1, -1], -1),
        ([2, 6, -1, -1, -1, -1, -1, -1], 0),
    ] {
        let [x, y, z, u, v, w, a, b] = map;
        assert_eq!(
            MCC_CreateGroup(x, y, z, u, v, w, a, b, card),
            PARAMETER_ERR,
            "{map:?} on card {card}"
        );
    }
    assert_eq!(
        MCC_CreateGroupEx(6, -1, -1, -1, -1, -1, -1, -1, 0, 0),
        PARAMETER_ERR
    );
    assert_eq!(
        MCC_CreateGroupEx(6, -1, -1, -1, -1, -1, -1, -1, 0, -5),
        PARAMETER_ERR
    );
    assert_eq!(MCC_GetCmdQueueSize(2), 0, "none was created");
    assert_eq!(
        MCC_CreateGroup(6, -1, -1, -1, -1, -1, -1, -1, 0),
        2,
        "next free slot"
    );
    // A group of no axis is a group (the vendor's library creates it).
    assert_eq!(MCC_CreateGroup(-1, -1, -1, -1, -1, -1, -1, -1, 0), 3);
    // Closing: a group that does not exist, or an index outside the table, is
    // PARAMETER_ERR (scenario create_group_odd).
    assert_eq!(MCC_CloseGroup(-1), PARAMETER_ERR);
    assert_eq!(MCC_CloseGroup(96), PARAMETER_ERR);
    assert_eq!(MCC_CloseGroup(5), PARAMETER_ERR);
    assert_eq!(MCC_CloseGroup(1), NO_ERR);
    assert_eq!(MCC_CloseGroup(1), PARAMETER_ERR);
    assert_eq!(
        MCC_CreateGroup(7, -1, -1, -1, -1, -1, -1, -1, 0),
        1,
        "reuses slot 1"
    );
    // Queue size: set only by MCC_CreateGroupEx; MCC_SetCmdQueueSize changes nothing
    // (GROUP_PARAMETER_ERR below 1, else RUN_TIME_ERR, whatever the group: scenario
    // queue_size_before_init).
    assert_eq!(MCC_SetCmdQueueSize(0, 0), GROUP_PARAMETER_ERR);
    assert_eq!(MCC_SetCmdQueueSize(-1, 0), GROUP_PARAMETER_ERR);
    assert_eq!(MCC_SetCmdQueueSize(100, 9), RUN_TIME_ERR);
    assert_eq!(MCC_SetCmdQueueSize(100, 0), RUN_TIME_ERR);
    assert_eq!(MCC_GetCmdQueueSize(0), MOTION_QUEUE_SIZE, "unchanged");
    // The 96-group table fills up: one channel each, 12 cards x 8 channels. Then a
    // channel already in a group is refused first (PARAMETER_ERR), and a group of no
    // axis finds no free slot (GROUP_PARAMETER_ERR).
    assert_eq!(MCC_CloseAllGroups(), NO_ERR);
    for i in 0..96 {
        assert_eq!(MCC_CreateGroup(i % 8, -1, -1, -1, -1, -1, -1, -1, i / 8), i);
    }
    assert_eq!(
        MCC_CreateGroup(0, -1, -1, -1, -1, -1, -1, -1, 0),
        PARAMETER_ERR
    );
    assert_eq!(
        MCC_CreateGroup(-1, -1, -1, -1, -1, -1, -1, -1, 0),
        GROUP_PARAMETER_ERR
    );
}

#[test]
fn init_argument_checks_leave_the_system_closed() {
    let _g = fresh();
    let mut c = cards(2);
    // SAFETY: c holds 2 valid entries; a NULL table is read as IMP-III cards.
    unsafe {
        // Periods 1..=50 ms (scenario init_periods: 0, -1, 51 and 100 refused).
        for ms in [0, 51, -1] {
            assert_eq!(
                MCC_InitSystem(ms, c.as_mut_ptr(), 1),
                PARAMETER_ERR,
                "{ms} ms"
            );
        }
        for ms in [f64::NAN, f64::INFINITY, 0.5, 50.5] {
            assert_eq!(MCC_InitSystemEx(ms, c.as_mut_ptr(), 1), PARAMETER_ERR);
        }
        // 1..=12 cards (scenarios card_count0, card_count13).
        assert_eq!(MCC_InitSystem(2, c.as_mut_ptr(), 0), PARAMETER_ERR);
        assert_eq!(MCC_InitSystem(2, c.as_mut_ptr(), 13), PARAMETER_ERR);
        assert_eq!(MCC_InitSystem(2, null_mut(), 13), PARAMETER_ERR);
        // Card types the vendor's library does not know (scenarios card_type6,
        // card_type99), and an ISA card (types 0, 1) without a valid address and IRQ
        // (card_type0).
        for t in [6, 99, EPCIO_4_AXIS_ISA_CARD, EPCIO_6_AXIS_ISA_CARD] {
            c[1].wCardType = t;
            assert_eq!(
                MCC_InitSystem(2, c.as_mut_ptr(), 2),
                PARAMETER_ERR,
                "card type {t}"
            );
        }
        assert_eq!(MCC_GetMotionStatus(0), INITIAL_MOTION_ERR, "still closed");
        // The PCI types 2..5 are taken (scenarios card_type2..card_type5), and a NULL
        // table (card_null_table).
        c[1].wCardType = EPCIO_6_AXIS_PCI_CARD;
        assert_eq!(MCC_InitSystem(2, c.as_mut_ptr(), 2), NO_ERR);
        assert_eq!(MCC_CloseSystem(), NO_ERR);
        assert_eq!(MCC_InitSystem(2, null_mut(), 3), NO_ERR);
        assert_eq!(MCC_CloseSystem(), NO_ERR);
        c[1].wCardType = IMP_II_8_AXIS_PCI_CARD;
        assert_eq!(MCC_InitSystem(2, c.as_mut_ptr(), 2), NO_ERR);
        // A second init while the system runs is refused with RUN_TIME_ERR (scenario
        // init_twice), a bad one with its argument's error; either leaves the running
        // system running.
        assert_eq!(MCC_InitSystemEx(1.5, c.as_mut_ptr(), 2), RUN_TIME_ERR);
        assert_eq!(MCC_InitSimulation(50, c.as_mut_ptr(), 1), RUN_TIME_ERR);
        assert_eq!(MCC_InitSystem(99, c.as_mut_ptr(), 1), PARAMETER_ERR);
        assert_eq!(MCC_GetMotionStatus(0), GMS_STOP);
    }
    // Closing a closed system answers NO_ERR, as the vendor's library does (scenarios
    // close_twice, close_without_init).
    assert_eq!(MCC_CloseSystem(), NO_ERR);
    assert_eq!(MCC_GetMotionStatus(0), INITIAL_MOTION_ERR);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn unknown_clock_mode_refuses_to_start() {
    let _g = fresh();
    std::env::set_var("MCCL_CLOCK", "warp");
    assert_eq!(init(1), INITIAL_MOTION_ERR);
    assert_eq!(MCC_GetMotionStatus(0), INITIAL_MOTION_ERR);
    std::env::set_var("MCCL_CLOCK", "stepped");
    assert_eq!(init(1), NO_ERR);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn calls_that_need_a_running_system() {
    let _g = fresh();
    assert_eq!(MCC_ResetMotion(), INITIAL_MOTION_ERR);
    assert_eq!(MCC_UpdateParam(), INITIAL_MOTION_ERR);
    assert_eq!(MCC_EnableDryRun(), INITIAL_MOTION_ERR);
    assert_eq!(MCC_DisableDryRun(), INITIAL_MOTION_ERR);
    assert_eq!(MCC_CheckDryRun(), INITIAL_MOTION_ERR);
    assert_eq!(MCC_GetMotionStatus(0), INITIAL_MOTION_ERR);
    assert_eq!(init(1), NO_ERR);
    assert_eq!(MCC_GetMotionStatus(0), GMS_STOP);
    assert_eq!(MCC_GetMotionStatus(1), GROUP_PARAMETER_ERR);
    assert_eq!(MCC_GetMotionStatus(96), GROUP_PARAMETER_ERR);
    assert_eq!(MCC_GetMotionStatus(u16::MAX), GROUP_PARAMETER_ERR);
    assert_eq!(MCC_CheckDryRun(), 1, "off: 1, as MCC_CheckBlend");
    assert_eq!(MCC_EnableDryRun(), NO_ERR);
    assert_eq!(MCC_CheckDryRun(), 0);
    assert_eq!(MCC_DisableDryRun(), NO_ERR);
    assert_eq!(MCC_CheckDryRun(), 1);
    assert_eq!(MCC_ResetMotion(), NO_ERR);
    // Groups are made and closed while the card runs, as the vendor's library lets a
    // program (scenario groups_after_init). The default group (X..B on channels 0..7
    // of card 0) has every channel of the card, so a new group needs it closed first;
    // with every group closed the card runs none until the next init.
    assert_eq!(
        MCC_CreateGroup(3, 4, -1, -1, -1, -1, -1, -1, 0),
        PARAMETER_ERR
    );
    assert_eq!(MCC_CloseGroup(0), NO_ERR);
    assert_eq!(MCC_GetMotionStatus(0), GROUP_PARAMETER_ERR);
    assert_eq!(MCC_CreateGroup(3, 4, -1, -1, -1, -1, -1, -1, 0), 0);
    assert_eq!(MCC_GetMotionStatus(0), GMS_STOP);
    assert_eq!(
        MCC_CreateGroupEx(3, 4, -1, -1, -1, -1, -1, -1, 0, 10),
        PARAMETER_ERR,
        "channels 3 and 4 are group 0's"
    );
    assert_eq!(MCC_CloseAllGroups(), NO_ERR);
    assert_eq!(MCC_GetMotionStatus(0), GROUP_PARAMETER_ERR);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn update_param_applies_mechanism_changes() {
    let _g = fresh();
    assert_eq!(init(1), NO_ERR);
    assert_eq!(
        MCC_GetConvFactor(0, 0),
        500.0,
        "default PPR 500, gear 1, pitch 1"
    );
    let mut m = get_mac(0, 0);
    m.dwPPR = 2000;
    // SAFETY: valid pointer.
    assert_eq!(unsafe { MCC_SetMacParam(&mut m, 0, 0) }, NO_ERR);
    assert_eq!(MCC_GetConvFactor(0, 0), 500.0, "not before MCC_UpdateParam");
    assert_eq!(MCC_UpdateParam(), NO_ERR);
    assert_eq!(MCC_GetConvFactor(0, 0), 2000.0);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
    assert_eq!(
        MCC_GetConvFactor(0, 0),
        2000.0,
        "closed: the parameters set"
    );
}

#[test]
fn time_delay_runs_virtual_time_in_stepped_mode() {
    let _g = fresh();
    assert_eq!(init(1), NO_ERR); // 2 ms period
    let shared = MCCLPCI_IMP::system::active().unwrap();
    assert_eq!(
        shared.clock().ticks(),
        0,
        "stepped: nothing runs until the program waits"
    );
    MCC_TimeDelay(7); // ceil(7 / 2) = 4 ticks
    assert_eq!(shared.clock().ticks(), 4);
    MCC_TimeDelay(0);
    assert_eq!(shared.clock().ticks(), 4);
    MCC_TimeDelay(1000);
    assert_eq!(shared.clock().ticks(), 504);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn fast_clock_idles_without_work() {
    let _g = fresh();
    std::env::set_var("MCCL_CLOCK", "fast");
    assert_eq!(init(1), NO_ERR);
    let shared = MCCLPCI_IMP::system::active().unwrap();
    MCC_TimeDelay(100); // 50 ticks of 2 ms
    assert_eq!(shared.clock().ticks(), 50);
    assert_eq!(shared.clock().now(), std::time::Duration::from_millis(100));
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}
