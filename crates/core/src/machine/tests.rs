//! Unit tests of the channel: its steps (ideal and general, at rest), encoder, sensors,
//! plant and index pulses.

use super::index_pulses::floor_i64;
use super::*;
use crate::config::{default_encoder_config, default_mac_param};
use crate::vendor::consts as c;
use crate::vendor::SYS_MAC_PARAM;

fn ch(spec: ChannelSpec) -> Channel {
    Channel::new(spec, default_mac_param(), default_encoder_config())
}

/// What a step shows: the fields `step` writes, and the readings derived from them.
fn shown(
    c: &Channel,
) -> (
    i64,
    i64,
    i64,
    f64,
    SensorLevels,
    SensorLevels,
    (i64, i64),
    u32,
) {
    (
        c.command_pulses(),
        c.output_pulses(),
        c.encoder(),
        c.actual_pulses(),
        c.levels(),
        c.prev_levels(),
        c.pulse_rate(),
        c.index_events(),
    )
}

#[test]
fn a_channel_at_rest_skips_steps_that_would_change_nothing() {
    // Two channels with a 10 ms lag, one stepped through `step_commanded` (which skips
    // steps at rest), one always through `step`: a move of 1000 pulses, then the
    // command held while the motor closes in (by e^(-1 ms / 10 ms) a step, until
    // the floating-point iteration stands still a few ULP of 1000 short, after some
    // hundreds of steps), then held at rest. Every step shows the same on both, and
    // the steps from the first at rest on are skipped.
    let spec = ChannelSpec {
        lag_s: Some(0.01),
        ..ChannelSpec::default()
    };
    let (mut a, mut b) = (ch(spec), ch(spec));
    let mut first_rest = None;
    for n in 0..3000 {
        let cmd = if n < 10 { 100 * (n + 1) } else { 1000 };
        a.command(cmd);
        a.step_commanded(0.001);
        b.step(cmd, 0.001);
        assert_eq!(shown(&a), shown(&b), "step {n}");
        if a.resting() && first_rest.is_none() {
            first_rest = Some(n);
        }
    }
    let n = first_rest.unwrap_or_else(|| panic!("the motor comes to rest: {a:?}"));
    assert!(n > 300 && n < 3000, "{n}");
    assert!(
        (a.actual_pulses() - 1000.0).abs() < 1e-9,
        "{}",
        a.actual_pulses()
    );
}

#[test]
fn the_ideal_step_writes_what_the_general_step_writes() {
    // Two copies of an ideal channel (dwPPR 4: an index pulse every 4 counts), one
    // stepped by `step` (which takes the ideal path), one by `step_general`, through
    // moves up and down across index pulses, a stop, a standstill, a counter restart
    // and a wiring change that turns the − limit input active with nothing hit (NC on
    // an open contact, so the levels change between steps without a sensor placed).
    // Every field is the same after every step (`Debug` prints them all).
    let mac = SYS_MAC_PARAM {
        dwPPR: 4,
        ..default_mac_param()
    };
    let mut a = Channel::new(ChannelSpec::default(), mac, default_encoder_config());
    assert!(a.ideal(), "no lag, no compensation, no sensor");
    let mut b = a.clone();
    let cmds = [0, 3, 9, 17, 17, 17, 5, -7, -7, -7, 1_000_001, 1_000_001, 2];
    for (n, &cmd) in cmds.iter().enumerate() {
        if n == 8 {
            a.rezero();
            b.rezero();
        }
        if n == 11 {
            let nc = SYS_MAC_PARAM {
                wOverTravelDownSensorMode: c::SL_NORMAL_CLOSE,
                ..mac
            };
            a.set_params(nc, default_encoder_config());
            b.set_params(nc, default_encoder_config());
        }
        a.step(cmd, 0.001);
        b.step_general(cmd, 0.001);
        assert_eq!(format!("{a:?}"), format!("{b:?}"), "step {n}");
        if n == 11 {
            assert!(
                a.levels().minus && !a.prev_levels().minus,
                "the wiring edge"
            );
        }
    }
    // The restart at -7 put counter 0 at machine count -7: the last move, down from
    // counter 1,000,001 to 2 (machine -5), passed the machine's pulse at -4 last,
    // counter 3.
    assert_eq!(a.last_index_count(), Some(3));
}

#[test]
fn ideal_follows_what_a_step_depends_on() {
    // Each change that makes a step do more than the ideal path clears `ideal`, and
    // its undoing sets it again.
    let mut c = ch(ChannelSpec::default());
    assert!(c.ideal());
    c.set_plant_lag(Some(0.01));
    assert!(!c.ideal(), "a lagging plant");
    c.set_plant_lag(None);
    assert!(c.ideal());
    c.force(Sensor::Home, Some(true));
    assert!(!c.ideal(), "a forced sensor");
    c.force(Sensor::Home, None);
    assert!(c.ideal());
    c.place(Sensor::LimitPlus, 5.0, 5.0);
    assert!(!c.ideal(), "a placed sensor");
    let mut d = ch(ChannelSpec::default());
    let mut comp = compensation::off();
    comp.dwInterval = 100;
    d.set_compensation(&comp);
    assert!(!d.ideal(), "compensation");
    d.set_compensation(&compensation::off());
    assert!(d.ideal());
}

#[test]
fn a_sensor_forced_at_rest_shows_as_one_edge() {
    // At rest at 0, the home sensor forced active between steps: the next step shows the
    // edge (previous level low, level high), the one after shows no edge.
    let mut c = ch(ChannelSpec::default());
    for _ in 0..3 {
        c.step_commanded(0.001);
    }
    assert!(c.resting());
    c.force(Sensor::Home, Some(true));
    c.step_commanded(0.001);
    assert!(!c.prev_levels().home && c.levels().home);
    c.step_commanded(0.001);
    assert!(
        c.prev_levels().home && c.levels().home,
        "the edge shows once"
    );
}

#[test]
fn new_mechanism_parameters_count_index_pulses_on_the_new_grid() {
    // dwPPR 500: index pulses at counts 0, 500, ...; a motor at 10 sits in [0, 500).
    let mut c = ch(ChannelSpec::default());
    c.step(10, 0.001);
    assert_eq!(c.index_events(), 0);
    // dwPPR 4: index pulses at 0, 4, 8, 12, ...; 10 -> 13 passes the one at 12. The
    // interval cached on the old grid, [0, 500), holds both ends and must not be used.
    let mac = SYS_MAC_PARAM {
        dwPPR: 4,
        ..default_mac_param()
    };
    c.set_params(mac, default_encoder_config());
    c.step(13, 0.001);
    assert_eq!(c.index_events(), 1);
    assert_eq!(c.last_index_count(), Some(12));
}

#[test]
fn a_motor_standing_still_passes_no_index_pulse_on_a_new_grid() {
    // dwPPR 500, phase 100: 0 -> 600 passes the index pulses at 100 and 600.
    let mut c = ch(ChannelSpec {
        index_phase: 100,
        ..Default::default()
    });
    c.step(600, 0.001);
    assert_eq!((c.index_events(), c.last_index_count()), (2, Some(600)));
    // A new grid drops the cached interval; standing at 600 (a move from 600 to 600)
    // is looked up on the new grid and still passes nothing.
    let mac = SYS_MAC_PARAM {
        dwPPR: 4,
        ..default_mac_param()
    };
    c.set_params(mac, default_encoder_config());
    c.step(600, 0.001);
    assert_eq!((c.index_events(), c.last_index_count()), (0, Some(600)));
    c.step(600, 0.001);
    assert_eq!(c.index_events(), 0);
}

#[test]
fn ideal_encoder_counts_one_per_pulse_at_x4() {
    let mut c = ch(ChannelSpec::default());
    c.step(1234, 0.001);
    assert_eq!(c.encoder(), 1234);
    // A new input rate keeps the count where the motor is; the motor's pulses then
    // count at the new rate.
    c.set_input_rate(2);
    assert_eq!(c.encoder(), 1234, "the count keeps its value");
    c.step(1234 + 400, 0.001);
    assert_eq!(c.encoder(), 1234 + 200, "400 pulses at x2: half");
    c.set_input_rate(1);
    c.set_encoder(0);
    assert_eq!(c.encoder(), 0);
    c.step(1234 + 800, 0.001);
    assert_eq!(c.encoder(), 100, "400 pulses at x1: a quarter");
    // From 0 at x1, a raw count rounds half away from zero: 2034/4 = 508.5 counts 509,
    // so 1 pulse more counts one more (509.25 rounds to 509).
    c.set_encoder(0);
    c.step(1234 + 801, 0.001);
    assert_eq!(c.encoder(), 0, "508.5 -> 509, 508.75 -> 509");
    assert_eq!(c.position(), 2035.0 / 500.0);
}

#[test]
fn ab_swap_reverses_the_count() {
    let mut e = default_encoder_config();
    e.wABSwap = 1;
    let mut c = Channel::new(ChannelSpec::default(), default_mac_param(), e);
    c.step(100, 0.001);
    assert_eq!(c.encoder(), -100);
}

#[test]
fn lag_plant_follows_exponentially() {
    // tau = 10 ms, dt = 1 ms: after one step the motor covers 1 - e^-0.1 of the way.
    let mut c = ch(ChannelSpec {
        lag_s: Some(0.01),
        ..Default::default()
    });
    c.step(1000, 0.001);
    let expect = 1000.0 * (1.0 - (-0.1f64).exp());
    assert!((c.actual_pulses() - expect).abs() < 1e-9);
    assert_eq!(c.error_count(), (1000.0 - expect).round() as i64);
}

#[test]
fn sensors_and_wiring() {
    let mut m = default_mac_param();
    m.wOverTravelUpSensorMode = c::SL_NORMAL_OPEN;
    m.wOverTravelDownSensorMode = c::SL_NORMAL_CLOSE;
    let spec = ChannelSpec {
        home: Some((-0.5, 0.5)),
        limit_plus: Some(10.0),
        limit_minus: Some(-10.0),
        ..Default::default()
    };
    let mut c = Channel::new(spec, m, default_encoder_config());
    assert!(c.levels().home);
    assert!(!c.levels().plus);
    assert!(
        c.levels().minus,
        "NC setting on a normally-open switch reads active"
    );
    c.step(10 * 500, 0.001); // 10 UU
    assert!(c.levels().plus && !c.levels().home);
    assert!(c.latched_limit(0));
    c.step(0, 0.001);
    assert!(
        !c.levels().plus && c.latched_limit(0),
        "latched until cleared"
    );
    c.force(Sensor::LimitPlus, Some(true));
    assert!(c.levels().plus);
    c.force(Sensor::LimitPlus, None);
    assert!(!c.levels().plus);
    assert!(c.home_level(c::SL_NORMAL_OPEN) && !c.home_level(c::SL_NORMAL_CLOSE));
}

#[test]
fn floor_i64_is_floor_as_i64() {
    let xs = [
        0.0,
        -0.0,
        0.5,
        -0.5,
        1.0,
        -1.0,
        -1.5,
        2.5e-300,
        -2.5e-300,
        4503599627370495.5,
        -4503599627370495.5,
        9007199254740993.0,
        -9007199254740993.0,
        9.223372036854775e18,
        -9.223372036854775e18,
        9.3e18,
        -9.3e18,
        1e300,
        -1e300,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NAN,
        f64::MIN_POSITIVE,
        -f64::MIN_POSITIVE,
    ];
    for x in xs {
        assert_eq!(floor_i64(x), x.floor() as i64, "{x:e}");
        assert_eq!(floor_i64(x + 0.25), (x + 0.25).floor() as i64, "{x:e}");
        assert_eq!(floor_i64(x - 0.25), (x - 0.25).floor() as i64, "{x:e}");
    }
}

#[test]
fn index_interval_matches_the_division() {
    let mut c = ch(ChannelSpec::default());
    // A pseudo-random walk with small, fractional and large steps, several grids.
    let mut x: f64 = 0.0;
    let mut seed: u64 = 12345;
    for n in 0..40_000 {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        let step = match n % 7 {
            0 => ((seed >> 40) as i64 - (1 << 23)) as f64,
            1 => ((seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * 3.0,
            _ => ((seed >> 58) as i64 - 32) as f64,
        };
        x += step;
        let (spacing, phase) = match n / 10_000 {
            0 => (500, 0),
            1 => (500, 100),
            2 => (1, 0),
            _ => (4096, 7),
        };
        c.set_grid((spacing, phase));
        assert_eq!(
            c.index_interval(x),
            (x.floor() as i64 - phase).div_euclid(spacing),
            "x {x}, spacing {spacing}, phase {phase}"
        );
    }
    for x in [
        -9.2e18,
        4503599627370496.0,
        -4503599627370497.0,
        9.2e18,
        f64::NAN,
        7.5,
        8.0,
        -0.5,
        f64::INFINITY,
        499.999,
        500.0,
    ] {
        c.set_grid((500, 3));
        for _ in 0..2 {
            assert_eq!(
                c.index_interval(x),
                (x.floor() as i64 - 3).div_euclid(500),
                "{x}"
            );
        }
    }
}

#[test]
fn index_pulses_every_turn() {
    // dwPPR 500: an index every 500 counts, phase 100: at 100, 600, 1100, ...
    let mut c = ch(ChannelSpec {
        index_phase: 100,
        ..Default::default()
    });
    c.step(99, 0.001);
    assert_eq!(c.index_events(), 0);
    c.step(100, 0.001);
    assert_eq!(c.index_events(), 1);
    assert_eq!(c.last_index_count(), Some(100));
    c.step(1200, 0.001);
    assert_eq!(c.index_events(), 2);
    assert_eq!(c.last_index_count(), Some(1100));
    c.step(50, 0.001); // down past 1100, 600 and 100
    assert_eq!(c.index_events(), 3);
    assert_eq!(c.last_index_count(), Some(100));
}
