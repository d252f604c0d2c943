//! The documented ranges (docs/compatibility.md "Ranges", `config::range`) through the C
//! entry points: a value whose consequence cannot be represented is `PARAMETER_ERR` and
//! changes nothing; a value just inside the range is taken and behaves.
//!
//! Ranges used below: times 0..=4,294,967,295 ms (2^32 − 1); speeds 1e-6..=1e9 UU/s
//! (a feed speed: any size above 0 up to 1e9, as the vendor's library takes it);
//! positions |x| × pulses per UU <= 1e15 pulses (default 500 pulses/UU: ±2e12 UU);
//! pulses per UU 1e-6..=1e9; encoder gear rate 1e-3..=1e3; encoder counts |n| <= 1e18;
//! percentages (override, PtP and jog ratios) above 0, at most 100 % (PtP, jog) or
//! 10^6 % (override).

mod common;

use common::{fresh, init_ms};
use std::os::raw::{c_int, c_long, c_longlong};
use MCCLPCI_IMP::ffi::coordinate::*;
use MCCLPCI_IMP::ffi::encoder::*;
use MCCLPCI_IMP::ffi::jog::*;
use MCCLPCI_IMP::ffi::motion::*;
use MCCLPCI_IMP::ffi::position::*;
use MCCLPCI_IMP::ffi::ptp::*;
use MCCLPCI_IMP::ffi::rio::*;
use MCCLPCI_IMP::ffi::sim::*;
use MCCLPCI_IMP::ffi::status::*;
use MCCLPCI_IMP::ffi::system::*;
use MCCLPCI_IMP::ffi::trajectory::*;
use MCCLPCI_IMP::vendor::consts::*;
use MCCLPCI_IMP::vendor::*;

/// 2^32 − 1 ms, the longest time.
const MAX_MS: f64 = 4_294_967_295.0;

fn x() -> f64 {
    let mut p = [0.0; 8];
    let [a, b, c, d, e, f, h, i] = &mut p;
    // SAFETY: eight valid pointers.
    assert_eq!(unsafe { MCC_GetCurPos(a, b, c, d, e, f, h, i, 0) }, NO_ERR);
    p[0]
}

fn pulses_x() -> i64 {
    let mut p = [0 as c_longlong; 8];
    let [a, b, c, d, e, f, h, i] = &mut p;
    assert_eq!(
        // SAFETY: eight valid pointers.
        unsafe { MCC_GetPulsePosEx(a, b, c, d, e, f, h, i, 0) },
        NO_ERR
    );
    p[0]
}

fn queued() -> c_int {
    let mut n = -1;
    // SAFETY: valid pointer.
    assert_eq!(unsafe { MCC_GetCommandCount(&mut n, 0) }, NO_ERR);
    n
}

fn status() -> i32 {
    MCCLPCI_IMP::system::active()
        .unwrap()
        .snapshot(0)
        .unwrap()
        .status
}

fn line_x(x: f64) -> c_int {
    MCC_Line(x, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0, IMP_AXIS_X)
}

fn enc(ch: u16) -> i64 {
    let mut v = 0;
    // SAFETY: valid pointer.
    assert_eq!(unsafe { MCC_GetENCValueEx(&mut v, ch, 0) }, NO_ERR);
    v
}

#[test]
fn abort_time_beyond_the_longest_time_is_refused() {
    let _g = fresh();
    assert_eq!(init_ms(1, 1), NO_ERR);
    assert_eq!(MCC_SetFeedSpeed(10.0, 0), 10.0);
    assert_eq!(MCC_SetAccTime(0.0, 0), NO_ERR);
    assert_eq!(MCC_SetDecTime(0.0, 0), NO_ERR);
    assert_eq!(line_x(100.0), 0);
    MCC_TimeDelay(1000);
    // 1 s at 10 UU/s (no ramps): X = 10.
    assert!((x() - 10.0).abs() < 1e-9, "{}", x());
    assert_eq!(MCC_AbortMotionEx(1e300, 0), PARAMETER_ERR);
    assert_eq!(MCC_AbortMotionEx(MAX_MS + 1.0, 0), PARAMETER_ERR);
    // Nothing changed: the line goes on at 10 UU/s and more commands are taken.
    MCC_TimeDelay(1000);
    assert!((x() - 20.0).abs() < 1e-9, "{}", x());
    assert_eq!(line_x(0.0), 1, "not aborting");
    // The longest time is taken. A timed abort runs as a hold with Td = t: from v0 = 10
    // (= F) over n = floor(Td v0/F/T) + 1 = 4,294,967,296 periods, more than the
    // 1,000,000,001 a profile counts: it ramps over those, starting at
    // v0 (n - 1)/n = 9.99999999 UU/s and falling as the line's deceleration (the default
    // S-curve: after 1000 of its periods the fall is (1000/n)^3 of it, nothing). 1 s
    // later X = 20 + 9.99999999, whole pulses toward 0: trunc(14999.999995) = 14999, and
    // it never ran faster than it did.
    assert_eq!(MCC_AbortMotionEx(MAX_MS, 0), NO_ERR);
    assert_eq!(line_x(0.0), ABORT_NOT_FINISH_ERR, "aborting");
    MCC_TimeDelay(1);
    let v = MCC_GetCurFeedSpeed(0);
    assert!(
        v <= 10.0 && v > 9.9999,
        "the abort's first period at {v} UU/s"
    );
    MCC_TimeDelay(999);
    assert_eq!(pulses_x(), 14_999, "X = {}", x());
    assert_eq!(MCC_AbortMotion(0, 0), NO_ERR);
    MCC_TimeDelay(2);
    assert_eq!(status(), GMS_STOP);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn acc_and_dec_times_beyond_the_longest_time_are_refused() {
    let _g = fresh();
    assert_eq!(init_ms(1, 1), NO_ERR);
    for bad in [1e300, MAX_MS * 2.0] {
        assert_eq!(MCC_SetAccTime(bad, 0), PARAMETER_ERR);
        assert_eq!(MCC_SetDecTime(bad, 0), PARAMETER_ERR);
        let mut t = [300.0; 8];
        t[5] = bad;
        let [a, b, c, d, e, f, h, i] = t;
        assert_eq!(MCC_SetPtPAccTime(a, b, c, d, e, f, h, i, 0), PARAMETER_ERR);
        assert_eq!(MCC_SetPtPDecTime(a, b, c, d, e, f, h, i, 0), PARAMETER_ERR);
    }
    assert_eq!(MCC_GetAccTime(0), 300.0, "unchanged");
    assert_eq!(MCC_GetDecTime(0), 300.0, "unchanged");
    let mut t = [0.0; 8];
    {
        let [a, b, c, d, e, f, h, i] = &mut t;
        assert_eq!(
            // SAFETY: eight valid pointers.
            unsafe { MCC_GetPtPAccTime(a, b, c, d, e, f, h, i, 0) },
            NO_ERR
        );
    }
    assert_eq!(t, [300.0; 8], "unchanged");
    // The longest acc time is taken. A line with it and the 300 ms deceleration would
    // last longer than the longest time (ramps keep their time, even in a short move):
    // refused, nothing queued.
    assert_eq!(MCC_SetFeedSpeed(100.0, 0), 100.0);
    assert_eq!(MCC_SetAccTime(MAX_MS, 0), NO_ERR);
    assert_eq!(MCC_GetAccTime(0), MAX_MS);
    assert_eq!(line_x(10.0), PARAMETER_ERR);
    assert_eq!(queued(), 0);
    // Ta = 2^32 - 2 ms and no deceleration: na = 4,294,967,294 periods of 1 ms, nd = 0
    // (even), 4,294,967.294 s: taken. A trapezoid ramp; L = 2e8 UU is short of
    // F (Ta + Td)/2 = 2.1e8, so it peaks at V = 2L/(Ta + Td) and after t = 60 s X =
    // V t^2/(2 Ta) = L t^2/Ta^2 = 2e8 x 3600/4294967.294^2 = 0.039031 UU: whole pulses,
    // trunc(19.516) = 19.
    assert_eq!(MCC_SetAccType(b'T' as std::os::raw::c_char, 0), NO_ERR);
    assert_eq!(MCC_SetAccTime(MAX_MS - 1.0, 0), NO_ERR);
    assert_eq!(MCC_SetDecTime(0.0, 0), NO_ERR);
    assert_eq!(line_x(2e8), 0);
    MCC_TimeDelay(60_000);
    assert_eq!(pulses_x(), 19, "X = {}", x());
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn sys_max_speed_outside_the_speed_range_is_refused() {
    let _g = fresh();
    assert_eq!(MCC_SetSysMaxSpeed(250.0), NO_ERR);
    for bad in [1e-12, 9.9e-7, 1.1e9, 1e300] {
        assert_eq!(MCC_SetSysMaxSpeed(bad), PARAMETER_ERR, "{bad}");
    }
    assert_eq!(MCC_GetSysMaxSpeed(), 250.0, "unchanged");
    // The slowest speed is taken; the feed comes back clamped to it. A 10 UU line
    // would last 10 / 1e-6 = 1e7 s, longer than 4,294,967.295 s: refused, nothing
    // queued. A 1 UU line (the default 300 ms ramps: na = nd = 300, nc = ceil(1e9 -
    // 300) = 999,999,700 periods, V = 1/(0.3 + 999,999.7) = 1e-6) is queued, and after
    // 1 s it cruises at 1e-6 UU/s (well short of a pulse: X still reads 0).
    assert_eq!(MCC_SetSysMaxSpeed(1e-6), NO_ERR);
    assert_eq!(init_ms(1, 1), NO_ERR);
    assert_eq!(MCC_SetFeedSpeed(10.0, 0), 1e-6);
    assert_eq!(line_x(10.0), PARAMETER_ERR);
    assert_eq!(queued(), 0);
    assert_eq!(status(), GMS_STOP);
    assert_eq!(line_x(1.0), 0);
    MCC_TimeDelay(1000);
    assert_eq!(status(), GMS_RUNNING);
    let v = MCC_GetCurFeedSpeed(0);
    assert!((v - 1e-6).abs() < 1e-15, "{v}");
    assert_eq!(x(), 0.0);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
    assert_eq!(MCC_SetSysMaxSpeed(1e9), NO_ERR, "the fastest speed");
}

#[test]
fn feed_and_ratios_outside_their_ranges_are_refused() {
    let _g = fresh();
    assert_eq!(init_ms(1, 1), NO_ERR);
    assert_eq!(MCC_SetFeedSpeed(20.0, 0), 20.0);
    // A feed of 0, NaN or above the speed range is refused; a negative one counts by
    // its size and a tiny one is taken, as the vendor's library takes them (scenario
    // setters_feed: -1 -> 1, 1e-9 taken, 0 refused).
    for bad in [0.0, f64::NAN, 1.1e9, 1e300] {
        assert_eq!(MCC_SetFeedSpeed(bad, 0), f64::from(PARAMETER_ERR), "{bad}");
        assert_eq!(MCC_ChangeFeedSpeed(bad, 0), f64::from(PARAMETER_ERR));
    }
    assert_eq!(MCC_GetFeedSpeed(0), 20.0, "unchanged");
    assert_eq!(MCC_SetFeedSpeed(-20.0, 0), 20.0);
    assert_eq!(MCC_SetFeedSpeed(1e-9, 0), 1e-9);
    // Above the system maximum (100 by default) but inside the range: clamped.
    assert_eq!(MCC_SetFeedSpeed(1e9, 0), 100.0);
    // Ratios: positive; a PtP ratio at most 100 %, an override up to 10^6 %: 0.001 %
    // and 5000 % are taken, 0, -1 and 100.5 % (PtP) refused, as the vendor's library
    // answers (scenarios setters_ptp_speed, setters_override).
    assert_eq!(MCC_SetPtPSpeed(50.0, 0), 50.0);
    for bad in [0.0, -1.0, f64::NAN, 100.5] {
        assert_eq!(MCC_SetPtPSpeed(bad, 0), f64::from(PARAMETER_ERR), "{bad}");
        assert_eq!(MCC_JogSpace(1.0, bad, 0, 0), PARAMETER_ERR);
        assert_eq!(MCC_JogConti(1, bad, 0, 0), PARAMETER_ERR);
    }
    for bad in [0.0, -1.0, f64::NAN, 1.1e6] {
        assert_eq!(MCC_OverrideSpeed(bad, 0), f64::from(PARAMETER_ERR), "{bad}");
    }
    assert_eq!(MCC_GetPtPSpeed(0), 50.0, "unchanged");
    MCC_TimeDelay(1);
    assert_eq!(MCC_GetOverrideRate(0), 1.0, "unchanged");
    assert_eq!(queued(), 0);
    assert_eq!(MCC_SetPtPSpeed(1e-3, 0), 1e-3);
    assert_eq!(MCC_OverrideSpeed(1e-3, 0), 1e-3);
    assert_eq!(MCC_OverrideSpeed(5000.0, 0), 5000.0);
    MCC_TimeDelay(1);
    assert_eq!(MCC_GetOverrideRate(0), 50.0, "5000 %, read as a fraction");
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn mac_param_whose_counts_overflow_is_refused() {
    let _g = fresh();
    let mut m = MCCLPCI_IMP::config::default_mac_param();
    m.dwPPR = 4_294_967_295;
    m.dfPitch = 1e-12;
    // SAFETY: valid pointer.
    assert_eq!(unsafe { MCC_SetMacParam(&mut m, 0, 0) }, PARAMETER_ERR);
    let mut got = SYS_MAC_PARAM::default();
    // SAFETY: valid pointer.
    assert_eq!(unsafe { MCC_GetMacParam(&mut got, 0, 0) }, NO_ERR);
    assert_eq!(got, MCCLPCI_IMP::config::default_mac_param(), "unchanged");
    // 500,000,000 × 1 / 0.5 = 1e9 pulses per UU, the most: taken with a work zone of
    // ±1e6 UU (1e15 pulses), refused with 1.5e6 UU (1.5e15 pulses) or a factor above.
    let mut m = MCCLPCI_IMP::config::default_mac_param();
    m.dwPPR = 500_000_000;
    m.dfPitch = 0.5;
    m.dfHighLimit = 1.5e6;
    // SAFETY: valid pointer.
    assert_eq!(unsafe { MCC_SetMacParam(&mut m, 0, 0) }, PARAMETER_ERR);
    m.dfHighLimit = 1e6;
    m.dfLowLimit = -1e6;
    m.dfPitch = 0.49;
    // SAFETY: valid pointer.
    assert_eq!(unsafe { MCC_SetMacParam(&mut m, 0, 0) }, PARAMETER_ERR);
    m.dfPitch = 0.5;
    // SAFETY: valid pointer.
    assert_eq!(unsafe { MCC_SetMacParam(&mut m, 0, 0) }, NO_ERR);
    // The fewest: 1 pulse per 1e6 UU.
    let mut f = MCCLPCI_IMP::config::default_mac_param();
    f.dwPPR = 1;
    f.dfPitch = 1e6;
    // SAFETY: valid pointer.
    assert_eq!(unsafe { MCC_SetMacParam(&mut f, 1, 0) }, NO_ERR);
    f.dfPitch = 1.1e6;
    // SAFETY: valid pointer.
    assert_eq!(unsafe { MCC_SetMacParam(&mut f, 1, 0) }, PARAMETER_ERR);
    // X at 1e9 pulses/UU: a target of 1e6 UU is 1e15 pulses (taken), 1.000001e6 is not.
    assert_eq!(init_ms(1, 1), NO_ERR);
    assert_eq!(line_x(1.000001e6), PARAMETER_ERR);
    assert_eq!(queued(), 0);
    // 1e-6 UU = 1000 pulses: 1e-6 UU at 10 UU/s with 300 ms ramps.
    assert_eq!(line_x(1e-6), 0);
    MCC_TimeDelay(1000);
    assert_eq!(pulses_x(), 1000);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn positions_beyond_the_pulse_counter_are_refused() {
    let _g = fresh();
    assert_eq!(MCC_SetSysMaxSpeed(1e9), NO_ERR);
    assert_eq!(init_ms(1, 50), NO_ERR);
    // Default 500 pulses/UU: positions up to 1e15 / 500 = 2e12 UU.
    let far = 2e12 * (1.0 + 1e-9);
    assert_eq!(line_x(1e300), PARAMETER_ERR);
    assert_eq!(line_x(far), PARAMETER_ERR);
    assert_eq!(MCC_LineB(far, 0), PARAMETER_ERR);
    assert_eq!(
        MCC_PtP(far, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0, IMP_AXIS_X),
        PARAMETER_ERR
    );
    assert_eq!(MCC_PtPU(1e300, 0), PARAMETER_ERR);
    assert_eq!(MCC_ArcXY(1e300, 1.0, 2.0, 0.0, 0), PARAMETER_ERR);
    assert_eq!(MCC_ArcXYZ(1.0, 1.0, 0.0, 1e300, 0.0, 0.0, 0), PARAMETER_ERR);
    assert_eq!(MCC_CircleXY(1e300, 0.0, CIR_CW as u8, 0), PARAMETER_ERR);
    // A circle around 1.5e12 through 0 reaches 3e12: beyond, though its center is inside.
    assert_eq!(MCC_CircleXY(1.5e12, 0.0, CIR_CW as u8, 0), PARAMETER_ERR);
    assert_eq!(MCC_ArcThetaXY(1.0, 0.0, 1e300, 0), PARAMETER_ERR);
    assert_eq!(MCC_HelicalXY_Z(1.0, 0.0, 1e300, 360.0, 0), PARAMETER_ERR);
    assert_eq!(
        MCC_HelicaXY_Z(1.0, 0.0, 1e300, 1.0, CIR_CW as u8, 0),
        PARAMETER_ERR
    );
    assert_eq!(MCC_JogSpace(far, 10.0, 0, 0), PARAMETER_ERR);
    assert_eq!(MCC_DefinePos(0, 1e300, 0), PARAMETER_ERR);
    assert_eq!(MCC_DefinePos(0, far, 0), PARAMETER_ERR);
    assert_eq!(queued(), 0);
    assert_eq!(status(), GMS_STOP);
    assert_eq!(x(), 0.0, "unchanged");
    assert_eq!(MCC_GetErrorCode(0), 0, "no error recorded (not a bad arc)");
    // A renamed position counts too. DefinePos(X = -1) renames the position, the
    // reference and the pulse count alike (-500 pulses), as the vendor's library does
    // (scenario define_origin); DefineOrigin then makes the reference 0 here and leaves
    // the position. Targets are in the reference, and both the reference and the
    // position (the pulse count) must stay within 1e15 pulses: reference 2e12 + 1 is
    // beyond, and so is reference -2e12 (position -2e12 - 1); -2e12 + 1 (position
    // -2e12, -1e15 pulses) is the farthest below.
    assert_eq!(MCC_DefinePos(0, -1.0, 0), NO_ERR);
    assert_eq!((x(), pulses_x()), (-1.0, -500));
    assert_eq!(MCC_DefineOrigin(0, 0), NO_ERR);
    assert_eq!((x(), pulses_x()), (-1.0, -500));
    assert_eq!(line_x(2e12 + 1.0), PARAMETER_ERR);
    assert_eq!(line_x(-2e12), PARAMETER_ERR);
    assert_eq!(queued(), 0);
    // From reference 0 to -2e12 + 1 at 1e9 UU/s (2e12 UU in 2000 s + 0.3 s, inside the
    // longest time): taken. (Its 2.5e10 pulses per 50 ms tick would trip the card's
    // pulse speed check at once; it is aborted before it runs.)
    assert_eq!(MCC_SetFeedSpeed(1e9, 0), 1e9);
    assert_eq!(line_x(-2e12 + 1.0), 0);
    assert_eq!(queued(), 1);
    assert_eq!(MCC_AbortMotion(0, 0), NO_ERR);
    MCC_TimeDelay(100);
    assert_eq!(status(), GMS_STOP);
    assert_eq!(x(), -1.0);
    // The reference may be renamed to the edge: DefinePos(X = 2e12 - 1) moves the
    // position and the pulse count by as much (position 2e12 - 2, 999,999,999,999,000
    // pulses). A move of -1 UU at 10 UU/s (50 ms periods, the default 300 ms S-curve
    // ramps: na = nd = 6; a short move, 1 < 10 x 0.6/2, so nc = 0 and 12 periods,
    // STOP in the 15th = 750 ms) ends on reference 2e12 - 2: position 2e12 - 3,
    // 999,999,999,998,500 pulses.
    assert_eq!(MCC_DefinePos(0, 2e12 - 1.0, 0), NO_ERR);
    assert_eq!(x(), 2e12 - 2.0);
    assert_eq!(pulses_x(), 999_999_999_999_000);
    assert_eq!(MCC_SetFeedSpeed(10.0, 0), 10.0);
    assert_eq!(line_x(2e12 - 2.0), 1);
    MCC_TimeDelay(700);
    assert_eq!(status(), GMS_RUNNING);
    MCC_TimeDelay(50);
    assert_eq!(status(), GMS_STOP);
    assert_eq!(x(), 2e12 - 3.0);
    assert_eq!(pulses_x(), 999_999_999_998_500);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn moves_longer_than_the_longest_time_are_refused() {
    let _g = fresh();
    assert_eq!(init_ms(1, 1), NO_ERR);
    // PtP ratio 0.01 % of 3000 rpm × 1 UU/turn = 50 UU/s: 5e-3 UU/s. 30,000 UU take
    // 6e6 s, longer than 4,294,967.295 s; 20,000 UU take 4e6 s + 0.3 s: taken.
    assert_eq!(MCC_SetPtPSpeed(0.01, 0), 0.01);
    assert_eq!(MCC_PtPX(30_000.0, 0), PARAMETER_ERR);
    assert_eq!(queued(), 0);
    assert_eq!(MCC_PtPX(20_000.0, 0), 0);
    assert_eq!(MCC_AbortMotion(0, 0), NO_ERR);
    // A helix of 1e9 turns of radius 1 at 10 UU/s: 2π × 1e9 / 10 = 6.3e8 s: refused.
    assert_eq!(
        MCC_HelicalXY_Z(-1.0, 0.0, 1.0, 360.0 * 1e9, 0),
        PARAMETER_ERR
    );
    assert_eq!(queued(), 0);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn encoder_values_outside_their_ranges_are_refused() {
    let _g = fresh();
    assert_eq!(init_ms(1, 1), NO_ERR);
    for bad in [1e300, 1001.0, 9.9e-4] {
        assert_eq!(MCC_SetENCGearRate(bad, 0, 0), PARAMETER_ERR, "{bad}");
    }
    assert_eq!(MCC_SetENCValue(i64::MAX as c_long, 0, 0), PARAMETER_ERR);
    assert_eq!(
        MCC_SetENCValue(-1_000_000_000_000_000_001, 0, 0),
        PARAMETER_ERR
    );
    assert_eq!(MCC_SetENCCompValue(i64::MIN as c_long, 0, 0), PARAMETER_ERR);
    assert_eq!(
        MCC_SetENCCompValueTab(i64::MIN as c_long, i64::MAX as c_long, 1 << 62, 0, 0),
        PARAMETER_ERR
    );
    let mut n: WORD = 9;
    // SAFETY: valid pointer.
    assert_eq!(unsafe { MCC_GetENCCompStockCount(&mut n, 0, 0) }, NO_ERR);
    assert_eq!(n, 0, "nothing stocked");
    // Unchanged gear rate 1: 1 UU = 500 pulses = 500 counts at x4.
    assert_eq!(line_x(1.0), 0);
    MCC_TimeDelay(2000);
    assert_eq!(enc(0), 500);
    // The largest rate: the next 1 UU counts 500 × 1000 more.
    assert_eq!(MCC_SetENCGearRate(1000.0, 0, 0), NO_ERR);
    assert_eq!(enc(0), 500, "the count keeps its value");
    assert_eq!(line_x(2.0), 1);
    MCC_TimeDelay(2000);
    assert_eq!(enc(0), 500 + 500_000);
    assert_eq!(MCC_SetENCValue(1_000_000_000_000_000_000, 0, 0), NO_ERR);
    assert_eq!(enc(0), 1_000_000_000_000_000_000);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn configuration_values_outside_their_ranges_are_refused() {
    let _g = fresh();
    let good = MCCLPCI_IMP::config::default_home_config();
    for bad in [
        SYS_HOME_CONFIG {
            dfHighSpeed: 1e300,
            ..good
        },
        SYS_HOME_CONFIG {
            dfLowSpeed: 1e-12,
            ..good
        },
        SYS_HOME_CONFIG {
            dfAccTime: 1e300,
            ..good
        },
        SYS_HOME_CONFIG {
            dfDecTime: MAX_MS * 2.0,
            ..good
        },
        SYS_HOME_CONFIG {
            dfOffset: 1e300,
            ..good
        },
    ] {
        let mut h = bad;
        // SAFETY: valid pointer.
        assert_eq!(unsafe { MCC_SetHomeConfig(&mut h, 0, 0) }, PARAMETER_ERR);
    }
    let mut got = SYS_HOME_CONFIG::default();
    // SAFETY: valid pointer.
    assert_eq!(unsafe { MCC_GetHomeConfig(&mut got, 0, 0) }, NO_ERR);
    assert_eq!(got, good, "unchanged");
    assert_eq!(init_ms(1, 1), NO_ERR);
    assert_eq!(MCC_SetTrackErrorLimit(1e300, 0, 0), PARAMETER_ERR);
    // The in-position tolerance is kept as the vendor's library keeps it, a 32-bit
    // pulse count: a value too large for one is taken as 2^31 pulses (its 32-bit
    // conversion's out-of-range answer, 0x80000000, by its size), 2^31/500 UU here
    // (scenario setters_inpos_group: 1e6 UU at 10000 pulses/UU reads 214748.3648).
    assert_eq!(
        MCC_SetInPosToleranceEx(1e300, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0),
        NO_ERR
    );
    let mut tol = [0.0; 8];
    {
        let [a, b, c, d, e, f, h, i] = &mut tol;
        assert_eq!(
            // SAFETY: eight valid pointers.
            unsafe { MCC_GetInPosToleranceEx(a, b, c, d, e, f, h, i, 0) },
            NO_ERR
        );
    }
    assert_eq!(tol[0], 2_147_483_648.0 / 500.0);
    assert_eq!(
        MCCL_SimPlaceSensor(0, 0, MCCL_SIM_HOME, 1e300, 1e301),
        PARAMETER_ERR
    );
    assert_eq!(MCC_SetARIOUpdateRate(1e-300, 0, 0), PARAMETER_ERR);
    // 1 / 2.4e-7 Hz = 4.17e6 s: inside the longest time.
    assert_eq!(MCC_SetARIOUpdateRate(2.4e-7, 0, 0), NO_ERR);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}
