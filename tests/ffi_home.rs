//! Go home (user manual §2.8) through the C entry points on the simulated machine, stepped
//! clock at 1 ms. Sensors, limit switches and index pulses are placed by an `MCCL_SIM`
//! file; expected positions are worked out by hand in the comments.
//!
//! The common machine (channel 0 unless a test says otherwise): 500 pulses/UU (the
//! default mechanism), home sensor active on [-3, -2] UU, limit switches at -6 (−) and
//! +6 (+) wired normally open, an index pulse every 500 pulses from pulse 100, i.e. at
//! 0.2 + k UU (..., -0.8, -1.8, -2.8, -3.8, ...). Go-home parameters: negative direction,
//! dfHighSpeed 10 UU/s (0.01 UU = 5 pulses a tick), dfLowSpeed 2 UU/s (1 pulse a tick),
//! dfAccTime = dfDecTime = 100 ms, so reaching or leaving 10 UU/s covers 0.5 UU and 2
//! UU/s 0.1 UU. An event is seen in the tick after the one whose motion caused it: an
//! emergency stop stands at the first position sampled past the edge; a deceleration
//! starts there.

mod common;

use common::{fresh, init_ms};
use std::os::raw::{c_long, c_longlong};
use MCCLPCI_IMP::ffi::coordinate::*;
use MCCLPCI_IMP::ffi::home::*;
use MCCLPCI_IMP::ffi::sim::*;
use MCCLPCI_IMP::ffi::status::*;
use MCCLPCI_IMP::ffi::system::*;
use MCCLPCI_IMP::ffi::trajectory::*;
use MCCLPCI_IMP::vendor::consts::*;
use MCCLPCI_IMP::vendor::*;

const MACHINE: &str = r#"
[[card]]
index = 0
[[card.channel]]
index = 0
home = [-3.0, -2.0]
limit_minus = -6.0
limit_plus = 6.0
index_spacing = 500
index_phase = 100
"#;

fn cfg(mode: u16) -> SYS_HOME_CONFIG {
    SYS_HOME_CONFIG {
        wMode: mode,
        wDirection: 1,
        wSensorMode: SL_NORMAL_OPEN,
        nIndexCount: 0,
        dfAccTime: 100.0,
        dfDecTime: 100.0,
        dfHighSpeed: 10.0,
        dfLowSpeed: 2.0,
        dfOffset: 0.0,
        ..Default::default()
    }
}

/// Writes `sim` to a file, sets the mechanism (limit switches normally open) and go-home
/// parameters of channels `chans`, and starts a 1 ms card with it (and a trace when
/// `trace` is given).
fn start(sim: &str, chans: &[(u16, SYS_HOME_CONFIG)], trace: Option<&str>) {
    let path = std::env::temp_dir().join(format!("mccl-home-{}.toml", std::process::id()));
    std::fs::write(&path, sim).unwrap();
    for &(ch, mut h) in chans {
        let mut m = MCCLPCI_IMP::config::default_mac_param();
        m.wOverTravelUpSensorMode = SL_NORMAL_OPEN;
        m.wOverTravelDownSensorMode = SL_NORMAL_OPEN;
        // SAFETY: valid pointers.
        unsafe {
            assert_eq!(MCC_SetMacParam(&mut m, ch, 0), NO_ERR);
            assert_eq!(MCC_SetHomeConfig(&mut h, ch, 0), NO_ERR);
        }
    }
    std::env::set_var("MCCL_SIM", &path);
    if let Some(t) = trace {
        std::env::set_var("MCCL_TRACE", t);
    }
    let r = init_ms(1, 1);
    std::env::remove_var("MCCL_SIM");
    std::env::remove_var("MCCL_TRACE");
    let _ = std::fs::remove_file(&path);
    assert_eq!(r, NO_ERR);
}

/// Runs until the homing ends; returns the status and the ticks it took.
fn wait_home() -> (i32, u64) {
    let shared = MCCLPCI_IMP::system::active().unwrap();
    let t0 = shared.clock().ticks();
    for _ in 0..200_000 {
        let s = MCC_GetGoHomeStatus();
        if s != 0 {
            return (s, shared.clock().ticks() - t0);
        }
        MCC_TimeDelay(1);
    }
    panic!("homing did not end");
}

/// Machine position of channel `ch`'s motor, in pulses.
fn motor(ch: u16) -> i64 {
    let (mut p, mut n): (f64, c_longlong) = (0.0, 0);
    // SAFETY: valid pointers.
    assert_eq!(unsafe { MCCL_SimGetMotor(0, ch, &mut p, &mut n) }, NO_ERR);
    (p * 500.0).round() as i64
}

fn cur_pos() -> [f64; 8] {
    let mut p = [0.0; 8];
    let [a, b, c, d, e, f, g, h] = &mut p;
    // SAFETY: eight valid pointers.
    assert_eq!(unsafe { MCC_GetCurPos(a, b, c, d, e, f, g, h, 0) }, NO_ERR);
    p
}

fn counters(ch: u16) -> (i64, i64) {
    let mut e: c_long = 0;
    let mut p = [0 as c_long; 8];
    let [a, b, c, d, e2, f, g, h] = &mut p;
    // SAFETY: valid pointers.
    unsafe {
        assert_eq!(
            MCCLPCI_IMP::ffi::encoder::MCC_GetENCValue(&mut e, ch, 0),
            NO_ERR
        );
        assert_eq!(MCC_GetPulsePos(a, b, c, d, e2, f, g, h, 0), NO_ERR);
    }
    #[allow(clippy::useless_conversion)] // `long` is 32-bit on Windows
    (i64::from(e), i64::from(p[usize::from(ch)]))
}

/// Homes channel 0 alone in `h`'s mode on `sim`; returns the motor's final machine
/// position (pulses) and the ticks the homing took.
fn home_one(sim: &str, h: SYS_HOME_CONFIG) -> (i64, u64) {
    start(sim, &[(0, h)], None);
    assert_eq!(MCC_Home(0, 255, 255, 255, 255, 255, 255, 255, 0), NO_ERR);
    let (status, ticks) = wait_home();
    assert_eq!(status, 1, "mode {} completes", h.wMode);
    let end = motor(0);
    // Afterwards the command position, the pulse counter and the encoder read 0 at the
    // working home (§2.8: the working home is the reference of motion commands).
    assert_eq!(cur_pos()[0], 0.0);
    assert_eq!(counters(0), (0, 0));
    assert_eq!(MCC_GetMotionStatus(0), GMS_STOP);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
    (end, ticks)
}

/// Case 1 (§2.8.1): the common machine, starting at 0 outside the sensor.
/// Final machine positions of the motor (pulses), by hand:
/// * S1 of every home-sensor mode: 0.5 UU accelerating (tick 100, -250 p), then 5 p a
///   tick: the sensor's edge -2.0 UU (-1000 p) is reached at tick 250 exactly, seen at 251.
///   A deceleration from there ends 0.5 UU further, at -1250 p.
/// * S1 of the limit modes: the − switch (-6 UU, -3000 p) is reached at tick 650.
/// * Moving down, an index pulse at p is passed on reaching p - 1 (the count's interval
///   [p, p+500) is left); moving up, on reaching p.
const CASE1: [(u16, i64); 14] = [
    // 3: decelerate on entering the sensor: -1000 - 250.
    (3, -1250),
    // 4: S1 stops at -1250; S2 (+, high) leaves at -995 (accelerating from -1250 covers
    // 250 p to -1000, still active, next tick -995), stops at -745; S3 (−, low: 50 p
    // accelerating, then 1 p a tick) enters at -1000 and stops there at once.
    (4, -1000),
    // 5: enters at -1000 at 10 UU/s, slows to 2 UU/s over (10+2)/2 x 0.08 s = 0.48 UU
    // (-1240 p), then 1 p a tick; the first index pulse (-1400) is passed at -1401: stop.
    (5, -1401),
    // 6: enters at -1000 and goes on at 5 p a tick; -1400 is passed at -1405; a
    // deceleration adds 250 p.
    (6, -1655),
    // 7: S1 stops at -1250; S2 (+, low): 50 p accelerating to -1200, then 1 p a tick,
    // leaves the sensor at -999 and searches up: index -900 reached: stop.
    (7, -900),
    // 8: S1 stops at -1250; S2 (+, high) leaves at -995; index -900 reached after 19
    // ticks; a deceleration adds 250 p.
    (8, -650),
    // 9: stop at once on the − switch.
    (9, -3000),
    // 10: stop on the switch; S2 (+, low) 50 p accelerating to -2950, index -2900.
    (10, -2900),
    // 11: stop on the switch; S2 (+, high) accelerates at 100 UU/s²: 25000 t² p, the
    // index -2900 (100 p) is reached at t = 64 ms (102.4 p; 99.2 at 63 ms) at 6.4 UU/s;
    // decelerating at the rate of dfHighSpeed / dfDecTime (100 UU/s²) covers
    // 6.4²/200 = 0.2048 UU = 102.4 p: -2897.6 + 102.4.
    (11, -2795),
    // 12: S1 stops at -1250; S2 (+, low) leaves at -999: stop at once.
    (12, -999),
    // 13: as 6 to -1655 with the index latched at -1400; back there at low speed.
    (13, -1400),
    // 14: as 8 to -650 with the index latched at -900; back there at low speed.
    (14, -900),
    // 15: as 11 to -2795 with the index latched at -2900; back there.
    (15, -2900),
    // 16: decelerate on the switch: -3000 - 250; S2 (+, low) from -3250: 50 p
    // accelerating, then 1 p a tick; the switch is left at -2999: stop at once.
    (16, -2999),
];

/// The machines of the three cases: the sensor ahead (Case 1), around the start (Case 2),
/// behind the start (Case 3).
fn machine(case: u8) -> String {
    match case {
        2 => MACHINE.replace("[-3.0, -2.0]", "[-1.0, 1.0]"),
        3 => MACHINE.replace("[-3.0, -2.0]", "[1.0, 2.0]"),
        _ => MACHINE.to_owned(),
    }
}

/// One test per mode and case: homes channel 0 in `mode` on the machine of `case` and
/// compares the motor's final position with the table.
fn mode_case(mode: u16, case: u8, table: &[(u16, i64)]) {
    let _g = fresh();
    let want = table.iter().find(|(m, _)| *m == mode).map(|e| e.1);
    assert_eq!(
        Some(home_one(&machine(case), cfg(mode)).0),
        want,
        "mode {mode}, case {case}"
    );
}

macro_rules! mode_case_tests {
    ($($name:ident: $mode:expr, $case:expr, $table:expr;)*) => {$(
        #[test]
        fn $name() {
            mode_case($mode, $case, &$table);
        }
    )*};
}

mode_case_tests! {
    mode_3_case_1: 3, 1, CASE1;
    mode_4_case_1: 4, 1, CASE1;
    mode_5_case_1: 5, 1, CASE1;
    mode_6_case_1: 6, 1, CASE1;
    mode_7_case_1: 7, 1, CASE1;
    mode_8_case_1: 8, 1, CASE1;
    mode_9: 9, 1, CASE1;
    mode_10: 10, 1, CASE1;
    mode_11: 11, 1, CASE1;
    mode_12_case_1: 12, 1, CASE1;
    mode_13_case_1: 13, 1, CASE1;
    mode_14_case_1: 14, 1, CASE1;
    mode_15: 15, 1, CASE1;
    mode_16: 16, 1, CASE1;
    mode_3_case_2: 3, 2, CASE2;
    mode_4_case_2: 4, 2, CASE2;
    mode_5_case_2: 5, 2, CASE2;
    mode_6_case_2: 6, 2, CASE2;
    mode_7_case_2: 7, 2, CASE2;
    mode_8_case_2: 8, 2, CASE2;
    mode_12_case_2: 12, 2, CASE2;
    mode_13_case_2: 13, 2, CASE2;
    mode_14_case_2: 14, 2, CASE2;
    mode_3_case_3: 3, 3, CASE3;
    mode_4_case_3: 4, 3, CASE3;
    mode_5_case_3: 5, 3, CASE3;
    mode_6_case_3: 6, 3, CASE3;
    mode_7_case_3: 7, 3, CASE3;
    mode_8_case_3: 8, 3, CASE3;
    mode_12_case_3: 12, 3, CASE3;
    mode_13_case_3: 13, 3, CASE3;
    mode_14_case_3: 14, 3, CASE3;
}

/// Case 2 (starting inside the sensor): the sensor on [-1, 1] UU (-500..500 p) holds the
/// start. Recovery (§2.8.1 a, b): to the − switch at high speed (stop at once at -3000),
/// back up at high speed into the sensor and out of it (left at 505 p), decelerate: 755
/// p. Then Case 1 from 755 downwards: 250 p accelerating to 505, the sensor is entered at
/// 500 (the next tick) at 10 UU/s. Index pulses at 100 + 500k: 100, 600, -400.
const CASE2: [(u16, i64); 9] = [
    (3, 250),  // 500 - 250
    (4, 500),  // stop 250; leave up at 505, stop 755; enter down at 500 at low speed
    (5, 99),   // slow 500 -> 260, index 100 passed at 99
    (6, -155), // index 100 passed at 95; + 250 decelerating
    (7, 600),  // stop 250; up at low speed: leave at 501, index 600
    (8, 850),  // stop 250; up at high: leave at 505, index 600, + 250 decelerating
    (12, 501), // stop 250; up at low speed, leave at 501
    (13, 100), // as 6, back to the index 100
    (14, 600), // as 8, back to the index 600
];

/// Case 3 (the limit switch comes first): the sensor on [1, 2] UU (500..1000 p), behind
/// the start. Going down reaches the − switch at -3000: stop at once; recovery back up at
/// high speed through the sensor (left at 1005), decelerate: 1255. Then Case 1 from 1255
/// downwards: 250 p accelerating to 1005, the sensor entered at 1000 at 10 UU/s.
const CASE3: [(u16, i64); 9] = [
    (3, 750),   // 1000 - 250
    (4, 1000),  // stop 750; leave up at 1005, stop 1255; enter down at 1000, low speed
    (5, 599),   // slow 1000 -> 760, index 600 passed at 599
    (6, 345),   // index 600 passed at 595; - 250 decelerating
    (7, 1100),  // stop 750; up at low speed: leave at 1001, index 1100
    (8, 1350),  // stop 750; up at high: leave at 1005, index 1100, + 250
    (12, 1001), // stop 750; up at low speed, leave at 1001
    (13, 600),  // as 6, back to the index 600
    (14, 1100), // as 8, back to the index 1100
];

#[test]
fn limit_modes_have_no_case_2_or_3() {
    let _g = fresh();
    // Starting inside the home sensor changes nothing for the modes that do not use it.
    for (mode, want) in CASE1
        .iter()
        .filter(|(m, _)| matches!(m, 9 | 10 | 11 | 15 | 16))
    {
        assert_eq!(home_one(&machine(2), cfg(*mode)).0, *want, "mode {mode}");
    }
}

#[test]
fn index_count_and_offset() {
    let _g = fresh();
    // Mode 10, nIndexCount 2: from the switch (-3000) up at low speed the pulses -2900
    // (0), -2400 (1), -1900 (2): stop at the third.
    let mut h = cfg(10);
    h.nIndexCount = 2;
    assert_eq!(home_one(MACHINE, h).0, -1900);
    // Mode 3 with dfOffset 1.5 UU: phase 3 moves from the machine home (-1250) by +750
    // pulses; that is the working home, where everything reads 0.
    let mut h = cfg(3);
    h.dfOffset = 1.5;
    assert_eq!(home_one(MACHINE, h).0, -500);
    // Positive direction, mode 9: the + switch at 6 UU.
    let mut h = cfg(9);
    h.wDirection = 0;
    assert_eq!(home_one(MACHINE, h).0, 3000);
}

/// Per tick of group 0 from a trace: time (ms), the 8 axis positions, the path speed.
fn read_trace(path: &str) -> Vec<(f64, [f64; 8], f64)> {
    let text = std::fs::read_to_string(path).unwrap();
    let _ = std::fs::remove_file(path);
    text.lines()
        .skip(1)
        .map(|l| {
            let f: Vec<f64> = l.split(',').map(|x| x.parse().unwrap()).collect();
            (f[0], std::array::from_fn(|i| f[4 + i]), f[12])
        })
        .collect()
}

/// The speeds (UU/s, signed) of X where only X moves, from its speed read each period
/// (`MCC_GetSpeed`): at each peak (where the speed stops rising) and each plateau (held
/// 10 periods), in order, without repeats.
fn step_speeds(speeds: &[f64]) -> Vec<f64> {
    let v: Vec<f64> = speeds.iter().map(|x| (x * 1e3).round() / 1e3).collect();
    let mut out: Vec<f64> = Vec::new();
    let mut run = 0;
    for k in 1..v.len() {
        run = if v[k] == v[k - 1] { run + 1 } else { 0 };
        let peak =
            v[k].abs() >= v[k - 1].abs() && v.get(k + 1).is_some_and(|n| n.abs() < v[k].abs());
        if (run == 10 || peak) && v[k] != 0.0 && out.last() != Some(&v[k]) {
            out.push(v[k]);
        }
    }
    out
}

/// X's speed (`MCC_GetSpeed`) and position read after each period until the homing
/// ends.
fn sample_home() -> Vec<(f64, f64)> {
    let mut out = Vec::new();
    for _ in 0..200_000 {
        MCC_TimeDelay(1);
        let mut v = [0.0; 8];
        let [a, b, c, d, e, f, g, h] = &mut v;
        // SAFETY: eight valid pointers.
        let r = unsafe { MCCLPCI_IMP::ffi::motion::MCC_GetSpeed(a, b, c, d, e, f, g, h, 0) };
        assert_eq!(r, NO_ERR);
        out.push((v[0], cur_pos()[0]));
        if MCC_GetGoHomeStatus() != 0 {
            return out;
        }
    }
    panic!("homing did not end");
}

#[test]
fn speed_of_every_step() {
    let _g = fresh();
    // nIndexCount 1 puts the index searched 1 UU further, so every step reaches its speed.
    // Direction negative: forward steps are negative. High 10, low 2 UU/s.
    let want: [(u16, &[f64]); 14] = [
        (3, &[-10.0]),
        (4, &[-10.0, 10.0, -2.0]),
        (5, &[-10.0, -2.0]),
        (6, &[-10.0]),
        (7, &[-10.0, 2.0]),
        (8, &[-10.0, 10.0]),
        (9, &[-10.0]),
        (10, &[-10.0, 2.0]),
        (11, &[-10.0, 10.0]),
        (12, &[-10.0, 2.0]),
        (13, &[-10.0, 2.0]),
        (14, &[-10.0, 10.0, -2.0]),
        (15, &[-10.0, 10.0, -2.0]),
        (16, &[-10.0, 2.0]),
    ];
    for (mode, speeds) in want {
        let mut h = cfg(mode);
        h.nIndexCount = 1;
        start(MACHINE, &[(0, h)], None);
        assert_eq!(MCC_Home(0, 255, 255, 255, 255, 255, 255, 255, 0), NO_ERR);
        let rows = sample_home();
        assert_eq!(MCC_GetGoHomeStatus(), 1);
        assert_eq!(MCC_CloseSystem(), NO_ERR);
        let v: Vec<f64> = rows.iter().map(|r| r.0).collect();
        assert_eq!(step_speeds(&v), speeds, "mode {mode}");
        if mode == 3 {
            // dfAccTime 100 ms: 10 UU/s is reached at 100 ms (x = -0.5), not before (in
            // the 99th ms it is at least half a period's 100 UU/s² short of it);
            // dfDecTime: the stop takes 100 ms after the edge seen at 251 ms. Positions
            // read whole pulses.
            let x = |ms: usize| rows[ms - 1].1;
            let speed = |ms: usize| rows[ms - 1].0;
            assert!((x(100) + 0.5).abs() < 1e-9);
            assert!((speed(101) + 10.0).abs() < 1e-9, "cruising after 100 ms");
            assert!(speed(99) > -10.0 + 0.05, "still accelerating at 99 ms");
            assert!(
                (x(350) + 2.5).abs() < 1e-9 && x(349) > -2.5,
                "stopped at 350 ms"
            );
        }
    }
}

#[test]
fn phases_wait_for_every_channel_of_the_order() {
    let _g = fresh();
    // Channel 0: mode 6, sensor at [-3, -2]: enters at tick 250, while channel 1 (mode 6,
    // sensor [-5, -4]) enters only at tick 450 (-2000 p: 250 accelerating + 350 ticks of
    // 5 p). Channel 2: mode 3, sensor [-1.5, -1] entered at tick 150, stops at -1.5 UU at
    // tick 250; dfOffset 0.5 UU.
    let sim = r#"
[[card]]
index = 0
[[card.channel]]
index = 0
home = [-3.0, -2.0]
index_spacing = 500
index_phase = 100
[[card.channel]]
index = 1
home = [-5.0, -4.0]
index_spacing = 500
index_phase = 100
[[card.channel]]
index = 2
home = [-1.5, -1.0]
"#;
    let mut c2 = cfg(3);
    c2.dfOffset = 0.5;
    let path = std::env::temp_dir().join(format!("mccl-phase-{}.csv", std::process::id()));
    let path = path.to_str().unwrap();
    start(sim, &[(0, cfg(6)), (1, cfg(6)), (2, c2)], Some(path));
    assert_eq!(MCC_Home(0, 0, 0, 255, 255, 255, 255, 255, 0), NO_ERR);
    assert_eq!(MCC_GetMotionStatus(0), GMS_RUNNING);
    assert_eq!(wait_home().0, 1);
    // Channel 0 waited standing for channel 1 (it decelerated from -2.0 to -2.5 UU), then
    // searched its index from rest: 25000 t² p from -1250 passes -1400 at t = 78 ms
    // (-1402.1 p) at 7.8 UU/s, and 7.8²/(2 x 100) = 0.3042 UU (152.1 p) decelerating.
    // Channel 1 went on at 10 UU/s: -2400 passed at -2405, + 250 p decelerating.
    // Channel 2: -1.5 UU + 0.5 UU of phase 3.
    assert_eq!((motor(0), motor(1), motor(2)), (-1554, -2655, -500));
    assert_eq!(cur_pos()[..3], [0.0, 0.0, 0.0]);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
    let rows = read_trace(path);
    let x = |ms: usize, i: usize| rows[ms - 1].1[i];
    // Channel 1 enters its sensor at 450 ms; the others' phase 2 starts in the tick that
    // sees it (451 ms): until then channel 0 stands at -2.5 UU.
    assert!((x(450, 1) + 4.0).abs() < 1e-9 && x(449, 1) > -4.0);
    for ms in 350..=450 {
        assert!((x(ms, 0) + 2.5).abs() < 1e-9, "channel 0 waits at {ms} ms");
    }
    // From rest it covers 50 t² UU (dfAccTime 100 ms to 10 UU/s), t from 1 ms at 451
    // ms; positions read whole pulses toward 0 (500 per UU): trunc(0.025 k²) pulses
    // after k ms, the first at k = 7 (457 ms).
    assert!(
        (x(456, 0) + 2.5).abs() < 1e-9,
        "less than a pulse after 6 ms"
    );
    assert!(x(457, 0) < -2.5, "channel 0 moves again with the phase");
    // Channel 2 has no phase 2: it stands at -1.5 UU until the last channel ends phase 2
    // (channel 1's deceleration from 532 ms ends at 631 ms), then all start phase 3 in
    // the tick that sees it.
    for ms in 250..=631 {
        assert!((x(ms, 2) + 1.5).abs() < 1e-9, "channel 2 waits at {ms} ms");
    }
    assert!(x(632, 2) > -1.5, "phase 3 starts");
}

#[test]
fn orders_run_one_after_the_other() {
    let _g = fresh();
    // Channel 1 (order 1) starts only when channel 0 (order 0, mode 3: 352 ticks, see
    // `CASE1`) is done; both on the common machine.
    let sim = MACHINE.to_owned() + "[[card.channel]]\nindex = 1\nhome = [-3.0, -2.0]\n";
    let path = std::env::temp_dir().join(format!("mccl-order-{}.csv", std::process::id()));
    let path = path.to_str().unwrap();
    start(&sim, &[(0, cfg(3)), (1, cfg(3))], Some(path));
    assert_eq!(MCC_Home(0, 1, 255, 255, 255, 255, 255, 255, 0), NO_ERR);
    let (status, ticks) = wait_home();
    // The next order starts in the tick where the first is done (352): 352 + 351.
    assert_eq!((status, ticks), (1, 703));
    assert_eq!((motor(0), motor(1)), (-1250, -1250));
    assert_eq!(MCC_CloseSystem(), NO_ERR);
    let rows = read_trace(path);
    // Channel 1 starts at 352 ms from rest: trunc(0.025 k²) whole pulses after k ms
    // (see above), the first at k = 7, 358 ms.
    for (t, p, _) in &rows[..357] {
        assert_eq!(
            p[1], 0.0,
            "channel 1 stands (or moves less than a pulse) at {t} ms"
        );
    }
    assert!(rows[357].1[1] < 0.0, "channel 1 started at 352 ms");
}

#[test]
fn abort_emergency_stop_and_failure() {
    let _g = fresh();

    // Abort at 150 ms of mode 3: cruising since 100 ms at 5 p a tick, at -500 p; the
    // abort decelerates over dfDecTime: 250 p further. The status says "not homed".
    // Before any homing the status reads 1, as the vendor's library reads it right
    // after init (scenario state_after_init), and there is nothing to abort.
    start(MACHINE, &[(0, cfg(3))], None);
    assert_eq!(MCC_GetGoHomeStatus(), 1);
    assert_eq!(MCC_AbortGoHome(), NO_ERR);
    assert_eq!(MCC_GetGoHomeStatus(), 1);
    assert_eq!(MCC_Home(0, 255, 255, 255, 255, 255, 255, 255, 0), NO_ERR);
    MCC_TimeDelay(150);
    assert_eq!(MCC_GetGoHomeStatus(), 0);
    assert_eq!(MCC_AbortGoHome(), NO_ERR);
    MCC_TimeDelay(50);
    assert_eq!(MCC_GetGoHomeStatus(), 0, "decelerating");
    assert_eq!(MCC_GetMotionStatus(0), GMS_RUNNING);
    MCC_TimeDelay(60);
    assert_eq!(MCC_GetGoHomeStatus(), HOME_COMMAND_NOTCALLED_ERR);
    assert_eq!(MCC_GetMotionStatus(0), GMS_STOP);
    assert_eq!(motor(0), -750);
    assert!((cur_pos()[0] + 1.5).abs() < 1e-9, "not zeroed");
    assert_eq!(MCC_GetErrorCode(0), 0);
    // The group is free again; a new homing may start.
    assert_eq!(MCC_Home(0, 255, 255, 255, 255, 255, 255, 255, 0), NO_ERR);
    assert_eq!(wait_home().0, 1);
    assert_eq!(
        MCC_AbortGoHome(),
        NO_ERR,
        "nothing to stop after completion"
    );
    assert_eq!(MCC_CloseSystem(), NO_ERR);

    // The emergency-stop input stops the homing at once and records 0xF102.
    start(MACHINE, &[(0, cfg(3))], None);
    assert_eq!(MCC_Home(0, 255, 255, 255, 255, 255, 255, 255, 0), NO_ERR);
    MCC_TimeDelay(150);
    let before = motor(0);
    assert_eq!(MCCL_SimSetEmergencyStop(0, 1), NO_ERR);
    MCC_TimeDelay(5);
    assert_eq!(MCC_GetGoHomeStatus(), HOME_COMMAND_NOTCALLED_ERR);
    assert_eq!(motor(0), before, "stopped in the tick that saw the input");
    assert_eq!(MCC_GetErrorCode(0), 0xF102);
    assert_eq!(MCC_CloseSystem(), NO_ERR);

    // No home sensor: Case 3 at the − switch, back up through where the sensor should be,
    // and the + switch comes: the homing fails there with 0xF701 + axis.
    let no_home = MACHINE.replace("home = [-3.0, -2.0]\n", "");
    start(&no_home, &[(0, cfg(3))], None);
    assert_eq!(MCC_Home(0, 255, 255, 255, 255, 255, 255, 255, 0), NO_ERR);
    assert_eq!(wait_home().0, HOME_COMMAND_NOTCALLED_ERR);
    assert_eq!(motor(0), 3000, "stopped at once on the + switch");
    assert_eq!(MCC_GetErrorCode(0), 0xF701);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn wiring_of_the_home_sensor() {
    let _g = fresh();
    // A normally-closed contact read with SL_NORMAL_CLOSE homes as the normally-open one
    // (mode 3: -1250); read with SL_NORMAL_OPEN it is "active" where nothing is hit.
    let nc = MACHINE.replace(
        "home = [-3.0, -2.0]",
        "home = [-3.0, -2.0]\nhome_contact = \"nc\"",
    );
    let mut h = cfg(3);
    h.wSensorMode = SL_NORMAL_CLOSE;
    assert_eq!(home_one(&nc, h).0, -1250);
    start(&nc, &[(0, cfg(3))], None);
    let mut st: WORD = 9;
    assert_eq!(
        // SAFETY: valid pointer.
        unsafe { MCCLPCI_IMP::ffi::local_io::MCC_GetHomeSensorStatus(&mut st, 0, 0) },
        NO_ERR
    );
    assert_eq!(st, 1, "wrong wiring setting: reads active at 0 UU");
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn arguments_and_states() {
    let _g = fresh();
    assert_eq!(
        MCC_Home(0, 255, 255, 255, 255, 255, 255, 255, 0),
        INITIAL_MOTION_ERR
    );
    assert_eq!(MCC_GetGoHomeStatus(), INITIAL_MOTION_ERR);
    assert_eq!(MCC_AbortGoHome(), INITIAL_MOTION_ERR);
    start(MACHINE, &[(0, cfg(3))], None);
    for bad in [8, -1, 254, 256] {
        assert_eq!(
            MCC_Home(bad, 255, 255, 255, 255, 255, 255, 255, 0),
            PARAMETER_ERR
        );
        assert_eq!(
            MCC_Home(0, 255, 255, 255, 255, 255, 255, bad, 0),
            PARAMETER_ERR
        );
    }
    assert_eq!(
        MCC_Home(0, 255, 255, 255, 255, 255, 255, 255, 1),
        PARAMETER_ERR,
        "one card"
    );
    assert_eq!(
        MCC_Home(0, 255, 255, 255, 255, 255, 255, 255, 12),
        PARAMETER_ERR
    );
    // The status reads 1 before any homing (scenario state_after_init).
    assert_eq!(MCC_GetGoHomeStatus(), 1, "nothing changed");
    // A group with motion to do: not now, and nothing changes.
    assert_eq!(
        MCCLPCI_IMP::ffi::motion::MCC_Line(1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0, IMP_AXIS_ALL),
        0
    );
    assert_eq!(
        MCC_Home(0, 255, 255, 255, 255, 255, 255, 255, 0),
        COMMAND_NOTFINISHED_ERR
    );
    assert_eq!(MCC_GetGoHomeStatus(), 1);
    while MCC_GetMotionStatus(0) != GMS_STOP {
        MCC_TimeDelay(10);
    }
    // Dry run moves nothing, so no sensor could be found.
    assert_eq!(MCC_EnableDryRun(), NO_ERR);
    assert_eq!(
        MCC_Home(0, 255, 255, 255, 255, 255, 255, 255, 0),
        COMMAND_NOTACCEPTED_ERR
    );
    assert_eq!(MCC_DisableDryRun(), NO_ERR);
    // Every channel left out: done at once.
    assert_eq!(MCC_Home(255, 255, 255, 255, 255, 255, 255, 255, 0), NO_ERR);
    assert_eq!(MCC_GetGoHomeStatus(), 1);
    // While homing: one card at a time, and the group takes no motion command.
    assert_eq!(MCC_Home(0, 255, 255, 255, 255, 255, 255, 255, 0), NO_ERR);
    assert_eq!(MCC_GetGoHomeStatus(), 0);
    assert_eq!(
        MCC_Home(0, 255, 255, 255, 255, 255, 255, 255, 0),
        COMMAND_NOTFINISHED_ERR
    );
    assert_eq!(
        MCCLPCI_IMP::ffi::motion::MCC_Line(1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0, IMP_AXIS_ALL),
        COMMAND_NOTACCEPTED_ERR
    );
    let mut n = -1;
    // SAFETY: valid pointer.
    assert_eq!(unsafe { MCC_GetCommandCount(&mut n, 0) }, NO_ERR);
    assert_eq!(n, 0);
    // MCC_ResetMotion drops the homing: the axis stays where it is, nothing is homed.
    // A busy card answers COMMAND_NOTACCEPTED_ERR and is reset all the same, and the
    // go-home status then reads 0, as the vendor's library answers (scenario
    // state_after_reset), though nothing homes.
    MCC_TimeDelay(50);
    let here = motor(0);
    // The status reads running one more period, as after an abort (scenario
    // state_after_reset), then STOP.
    assert_eq!(MCC_ResetMotion(), COMMAND_NOTACCEPTED_ERR);
    assert_eq!(MCC_GetGoHomeStatus(), 0);
    MCC_TimeDelay(1);
    assert_eq!(MCC_GetMotionStatus(0), GMS_STOP);
    MCC_TimeDelay(50);
    assert_eq!(motor(0), here, "stands");
    assert_eq!(MCC_GetGoHomeStatus(), 0);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}
