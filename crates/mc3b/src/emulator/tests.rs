use super::*;

fn ms(n: u64) -> Duration {
    Duration::from_millis(n)
}

fn send(e: &mut Emulator, s: &str) -> String {
    let mut b = s.as_bytes().to_vec();
    b.push(b'\r');
    String::from_utf8_lossy(&e.receive(&b)).replace('\r', "|")
}

#[test]
fn acknowledgements_and_defaults() {
    let mut e = Emulator::new();
    assert_eq!(send(&mut e, "0I"), "0I|");
    assert_eq!(send(&mut e, "0P"), "0P1,100|");
    assert_eq!(send(&mut e, "0Q1"), "0Q0,0,0|");
    assert_eq!(send(&mut e, "0B"), "0B0|");
    let s = e.settings(2).unwrap_or_default();
    assert_eq!(s, MotorSettings::default());
    assert_eq!(
        (s.max_velocity, s.acceleration, s.deceleration),
        (1000, 5000, 5000)
    );
    assert_eq!((s.running_current, s.holding_current), (2000, 500));
    assert!(s.half_steps && !s.use_holding_current);
    for (c, a) in [
        ("0A0,100", "0A|"),
        ("0D1,100000", "0D|"),
        ("0V2,5000", "0V|"),
        ("0V2,1,1", "0V|"),
        ("0L2,8,0,32,32", "0L|"),
        ("0F0,0", "0F|"),
        ("0C0,1", "0C|"),
        ("0K0,0,2000", "0K|"),
        ("0N100", "0N|"),
        ("0S1", "0S|"),
        ("0Y0,0,0,0,0,0", "0Y|"),
        ("0Y1,0,1,0,1,0,0", "0Y|"),
    ] {
        assert_eq!(send(&mut e, c), a, "{c}");
    }
    assert_eq!(e.chain_len(), 1);
    let s = e.settings(0).unwrap_or_default();
    assert!(!s.half_steps && s.use_holding_current && s.holding_current == 0);
    assert!(e.is_energized(0), "holding current applied immediately");
    // Initialization restores every default and empties the buffer.
    assert_eq!(send(&mut e, "0I"), "0I|");
    assert_eq!(e.settings(0), Some(MotorSettings::default()));
    assert_eq!(e.chain_len(), 0);
}

#[test]
fn errors_e0_to_e3() {
    let mut e = Emulator::new();
    assert_eq!(send(&mut e, "0Z"), "0E0|");
    assert_eq!(send(&mut e, "0A0"), "0E2|");
    assert_eq!(send(&mut e, "0V0,1,0,0"), "0E2|");
    assert_eq!(send(&mut e, "0A0,99"), "0E3|");
    assert_eq!(send(&mut e, "0A0,100001"), "0E3|");
    assert_eq!(send(&mut e, "0V0,0"), "0E3|");
    assert_eq!(send(&mut e, "0V0,5001"), "0E3|");
    assert_eq!(send(&mut e, "0V0,10,2"), "0E3|");
    assert_eq!(send(&mut e, "0N0"), "0E3|");
    assert_eq!(send(&mut e, "0N101"), "0E3|");
    assert_eq!(send(&mut e, "0K0,2001,0"), "0E3|");
    assert_eq!(send(&mut e, "0M3,10,0"), "0E3|");
    assert_eq!(send(&mut e, "0M0,10,2"), "0E3|");
    assert_eq!(send(&mut e, "0G0,10,0,49"), "0E3|");
    assert_eq!(send(&mut e, "0L0,256,0,0,0"), "0E3|");
    // Running motor.
    assert_eq!(send(&mut e, "0M0,1000,0"), "0M|");
    e.advance(ms(10));
    for c in [
        "0M0,1,0",
        "0R0,0",
        "0H0,0",
        "0G0,1,0,50",
        "0F0,1",
        "0A0,200",
    ] {
        assert_eq!(send(&mut e, c), "0E1|", "{c}");
    }
    assert_eq!(send(&mut e, "0V0,200"), "0E1|");
    assert_eq!(send(&mut e, "0Y1,0,0,0,0,0"), "0E1|");
    assert_eq!(send(&mut e, "0Y1,0,0,0,0,0,1"), "0E1|");
    assert_eq!(send(&mut e, "0Y1,0,0,0,0,0,0"), "0Y|", "storing is allowed");
    assert_eq!(send(&mut e, "0C0,1"), "0C|");
    assert_eq!(send(&mut e, "0K0,100,100"), "0K|");
    // Other motors are not affected.
    assert_eq!(send(&mut e, "0M1,5,0"), "0M|");
    // Other IDs are ignored; lines without an ID are ignored.
    assert_eq!(send(&mut e, "1Q0"), "");
    assert_eq!(send(&mut e, "Q0"), "");
    assert_eq!(send(&mut e, "\n\n"), "");
    // Re-initialize with another ID.
    assert_eq!(send(&mut e, "3I"), "3I|");
    assert_eq!(send(&mut e, "0Q0"), "");
    assert_eq!(send(&mut e, "3Q0"), "3Q0,0,0|");
    assert!(!e.is_running(0) && !e.is_running(1));
}

#[test]
fn received_counts_the_frames_of_each_command() {
    let mut e = Emulator::new();
    assert_eq!(send(&mut e, "0V0,6000"), "0E3|");
    assert_eq!(send(&mut e, "0V1,200"), "0V|");
    assert_eq!(send(&mut e, "0Q0"), "0Q0,0,0|");
    assert_eq!(send(&mut e, "1V0,200"), "", "another controller's frame");
    assert_eq!(e.received(CommandCode::Velocity), 2);
    assert_eq!(e.received(CommandCode::QueryStatus), 1);
    assert_eq!(e.received(CommandCode::Move), 0);
    assert_eq!(send(&mut e, "0N7"), "0N|");
    assert_eq!(e.debounce_count(), 7);
    // I resets the device, not the count of what the line carried.
    assert_eq!(send(&mut e, "0I"), "0I|");
    assert_eq!(e.debounce_count(), 1);
    assert_eq!(e.received(CommandCode::Velocity), 2);
    assert_eq!(e.received(CommandCode::Initialize), 1);
}

#[test]
fn trapezoid_move_takes_the_hand_computed_time() {
    // N=2000, a=5000, d=2500, v=1000:
    // accel 1000/5000 = 0.2 s over 100 steps; decel 1000/2500 = 0.4 s
    // over 200 steps; cruise 1700 steps at 1000 steps/s = 1.7 s.
    // Total 2.3 s.
    let mut e = Emulator::new();
    send(&mut e, "0D0,2500");
    assert_eq!(send(&mut e, "0M0,2000,0"), "0M|");
    e.advance(ms(200));
    assert_eq!(e.position(0), 100);
    assert!((e.velocity(0) - 1000.0).abs() < 1e-6);
    e.advance(ms(1700));
    assert_eq!(e.position(0), 1800);
    e.advance(ms(399));
    assert!(e.is_running(0));
    assert_eq!(send(&mut e, "0Q0"), "0Q1,0,0|");
    e.advance(ms(1));
    assert!(!e.is_running(0));
    assert_eq!(e.position(0), 2000);
    assert_eq!(send(&mut e, "0Q0"), "0Q0,0,0|");
}

#[test]
fn short_move_is_a_triangle() {
    // N=100, a=d=5000, v=1000: 100 < 100+100, so triangle with
    // vp = sqrt(2*100*5000*5000/10000) = 707.1 steps/s, t = 2*vp/5000
    // = 0.2828 s -> done at tick 283, still running at 282.
    let mut e = Emulator::new();
    send(&mut e, "0M1,100,1");
    e.advance(ms(141));
    assert!((e.velocity(1) + 705.0).abs() < 5.0, "{}", e.velocity(1));
    e.advance(ms(141));
    assert!(e.is_running(1));
    e.advance(ms(1));
    assert!(!e.is_running(1));
    assert_eq!(e.position(1), -100);
}

#[test]
fn rate_move_has_no_acceleration() {
    // 0G1,100,0,75: one step every 750 us -> 75 ms for 100 steps.
    let mut e = Emulator::new();
    assert_eq!(send(&mut e, "0G1,100,0,75"), "0G|");
    e.advance(ms(3));
    assert_eq!(e.position(1), 4, "3 ms / 0.75 ms = 4 steps");
    assert!((e.velocity(1) - 1333.333).abs() < 0.01);
    e.advance(ms(71));
    assert!(e.is_running(1));
    e.advance(ms(1));
    assert!(!e.is_running(1));
    assert_eq!(e.position(1), 100);
}

#[test]
fn full_and_half_steps_count_steps_issued() {
    let mut e = Emulator::new();
    send(&mut e, "0F0,0");
    send(&mut e, "0G0,10,0,100");
    e.advance(ms(20));
    assert_eq!(e.position(0), 10);
    assert!(!e.settings(0).unwrap_or_default().half_steps);
}

#[test]
fn run_and_on_the_fly_changes_follow_the_guide_example() {
    let mut e = Emulator::new();
    send(&mut e, "0V0,500");
    assert_eq!(send(&mut e, "0R0,1"), "0R|");
    // 500/5000 = 0.1 s to reach 500 steps/s in direction 1.
    e.advance(ms(100));
    assert!((e.velocity(0) + 500.0).abs() < 1e-6);
    // Velocity change on the fly: 500 -> 1000 takes 0.1 s.
    assert_eq!(send(&mut e, "0V0,1000"), "0V|");
    e.advance(ms(50));
    assert!((e.velocity(0) + 750.0).abs() < 1e-6);
    e.advance(ms(50));
    assert!((e.velocity(0) + 1000.0).abs() < 1e-6);
    // Acceleration may change while free-running.
    assert_eq!(send(&mut e, "0A0,10000"), "0A|");
    // Modifier 1: decelerate (0.2 s at 5000) then run in direction 0.
    assert_eq!(send(&mut e, "0V0,1000,1"), "0V|");
    e.advance(ms(100));
    assert!((e.velocity(0) + 500.0).abs() < 1e-6);
    e.advance(ms(100));
    assert!(e.velocity(0).abs() < 1e-6);
    e.advance(ms(50)); // 10000 steps/s^2 for 50 ms
    assert!((e.velocity(0) - 500.0).abs() < 1e-6, "{}", e.velocity(0));
    // Same modifier again: no direction change.
    assert_eq!(send(&mut e, "0V0,1000,1"), "0V|");
    e.advance(ms(100));
    assert!((e.velocity(0) - 1000.0).abs() < 1e-6);
    // Modifier back to 0: reverse again, to direction 1.
    assert_eq!(send(&mut e, "0V0,1000,0"), "0V|");
    e.advance(ms(200 + 100));
    assert!(e.velocity(0) < -999.0);
    assert_eq!(send(&mut e, "0S0"), "0S|");
    assert!(!e.is_running(0));
    assert_eq!(e.velocity(0), 0.0);
}

#[test]
fn limit_masks_and_and_xor_stop_motion() {
    let mut e = Emulator::new();
    // Guide example: motor 2 dir 0 on bit 3 high, dir 1 on bit 5 low.
    send(&mut e, "0L2,8,0,32,32");
    e.advance(ms(1));
    assert_eq!(send(&mut e, "0Q2"), "0Q0,0,1|", "bit 5 low = home 1");
    e.set_input(5, true);
    e.advance(ms(1));
    assert_eq!(send(&mut e, "0Q2"), "0Q0,0,0|");
    assert_eq!(send(&mut e, "0B"), "0B32|");
    send(&mut e, "0V2,5000");
    assert_eq!(send(&mut e, "0R2,0"), "0R|");
    e.advance(ms(500));
    let p = e.position(2);
    assert!(p > 500, "{p}");
    e.set_input(3, true);
    e.advance(ms(1));
    assert!(!e.is_running(2));
    let stopped = e.position(2);
    e.advance(ms(100));
    assert_eq!(e.position(2), stopped);
    assert_eq!(send(&mut e, "0Q2"), "0Q0,1,0|");
    // No motion into the active home: starts and ends at once.
    assert_eq!(send(&mut e, "0M2,10,0"), "0M|");
    assert!(!e.is_running(2));
    e.advance(ms(10));
    assert_eq!(e.position(2), stopped);
    // The other direction is free.
    send(&mut e, "0M2,10,1");
    e.advance(ms(1000));
    assert_eq!(e.position(2), stopped - 10);
}

#[test]
fn debounce_counts_consecutive_1khz_samples() {
    let mut e = Emulator::new();
    send(&mut e, "0N5");
    e.set_input(0, true);
    e.advance(ms(4));
    assert_eq!(e.inputs(), 0);
    e.advance(ms(1));
    assert_eq!(e.inputs(), 1);
    // A glitch shorter than the count is ignored.
    e.set_input(0, false);
    e.advance(ms(3));
    e.set_input(0, true);
    e.advance(ms(10));
    assert_eq!(e.inputs(), 1);
    // Count 1 registers at the next sample.
    send(&mut e, "0N1");
    e.set_input(0, false);
    e.advance(ms(1));
    assert_eq!(e.inputs(), 0);
}

#[test]
fn debounce_delays_the_limit_stop() {
    // 5000 steps/s, debounce 10: the switch is registered 10 ms after it
    // closes, 50 steps later.
    let mut e = Emulator::new();
    send(&mut e, "0A0,100000");
    send(&mut e, "0V0,5000");
    send(&mut e, "0L0,1,0,0,0");
    send(&mut e, "0N10");
    send(&mut e, "0R0,0");
    e.advance(ms(100)); // at speed after 50 ms
    let p0 = e.position(0);
    e.set_input(0, true);
    e.advance(ms(9));
    assert!(e.is_running(0));
    e.advance(ms(1));
    assert!(!e.is_running(0));
    assert_eq!(e.position(0) - p0, 50);
}

#[test]
fn homing_backs_off_and_approaches_at_10_steps_per_second() {
    let mut e = Emulator::new();
    send(&mut e, "0V1,2000");
    send(&mut e, "0L1,0,0,4,4"); // dir 1 home: bit 2 low
    e.set_input(2, true);
    e.advance(ms(1));
    assert_eq!(send(&mut e, "0H1,1"), "0H|");
    e.advance(ms(1000));
    let switch_at = e.position(1);
    e.set_input(2, false); // switch closes
    e.advance(ms(1));
    assert_eq!(send(&mut e, "0Q1"), "0Q1,0,1|", "still homing");
    let hit = e.position(1);
    assert!(hit < switch_at);
    // Back-off: reverse at 10 steps/s (1 step per 100 ms).
    e.advance(ms(300));
    assert_eq!(e.position(1), hit + 3);
    e.set_input(2, true); // switch opens
    e.advance(ms(1));
    assert!(e.is_running(1));
    // Approach at 10 steps/s in the homing direction.
    e.advance(ms(200));
    let before = e.position(1);
    assert_eq!(before, hit + 3 - 2);
    e.set_input(2, false);
    e.advance(ms(1));
    assert!(!e.is_running(1));
    assert_eq!(send(&mut e, "0Q1"), "0Q0,0,1|");
    e.advance(ms(1000));
    assert_eq!(e.position(1), before);
}

#[test]
fn homing_honours_the_direction_modifier() {
    let mut e = Emulator::new();
    send(&mut e, "0V0,1000,1");
    send(&mut e, "0H0,0");
    e.advance(ms(500));
    assert!(e.position(0) < 0, "runs in direction 1");
    send(&mut e, "0S0");
    // Moves ignore the modifier.
    send(&mut e, "0M0,10,0");
    let p = e.position(0);
    e.advance(ms(1000));
    assert_eq!(e.position(0), p + 10);
}

#[test]
fn synchronous_move_finishes_together_within_limits() {
    // Motor 0: 1000 steps, vmax 1000; motor 1: 500 steps, vmax 1000.
    // Normalized limits: v = min(1000/1000, 1000/500) = 1/s,
    // a = d = min(5, 10) = 5/s^2 -> t = 0.2 + 0.8 + 0.2 = 1.2 s
    // (the time motor 0 would need alone). Motor 1 peaks at 500.
    let mut e = Emulator::new();
    assert_eq!(send(&mut e, "0Y1000,0,500,1,0,0"), "0Y|");
    e.advance(ms(600));
    assert!((e.velocity(0) - 1000.0).abs() < 1e-6);
    assert!((e.velocity(1) + 500.0).abs() < 1e-6);
    assert!(e.is_running(2), "all motors busy");
    assert_eq!(send(&mut e, "0M2,1,0"), "0E1|");
    e.advance(ms(599));
    assert!(e.is_running(0) && e.is_running(1));
    e.advance(ms(1));
    assert!(!e.is_running(0) && !e.is_running(1));
    assert_eq!((e.position(0), e.position(1)), (1000, -500));
}

#[test]
fn synchronous_move_respects_the_slowest_motor() {
    // Motor 1 vmax 100 with 1000 steps dominates: v = 0.1/s,
    // a = min(5000/200, 5000/1000) = 5 -> 0.02 s ramps covering
    // 0.001 each, cruise (1 - 0.002)/0.1 = 9.98 s: total 10.02 s.
    let mut e = Emulator::new();
    send(&mut e, "0V1,100");
    send(&mut e, "0Y200,0,1000,0,0,0");
    let mut peak = [0.0f64; 2];
    for _ in 0..10_019 {
        e.advance(ms(1));
        for (i, p) in peak.iter_mut().enumerate() {
            *p = p.max(e.velocity(i).abs());
        }
    }
    assert!(e.is_running(0));
    e.advance(ms(1));
    assert!(!e.is_running(0));
    assert!(
        peak[1] <= 100.0 + 1e-9 && peak[0] <= 20.0 + 1e-9,
        "{peak:?}"
    );
    assert_eq!((e.position(0), e.position(1)), (200, 1000));
}

#[test]
fn chained_45_degree_square_returns_to_start() {
    let mut e = Emulator::new();
    for c in [
        "0Y1000,0,1000,0,0,0,0",
        "0Y1000,0,1000,1,0,0,0",
        "0Y1000,1,1000,1,0,0,0",
    ] {
        assert_eq!(send(&mut e, c), "0Y|");
        e.advance(ms(100));
        assert!(!e.is_running(0), "stored moves do not start");
    }
    assert_eq!(e.chain_len(), 3);
    assert_eq!(send(&mut e, "0Y1000,1,1000,0,0,0,1"), "0Y|");
    assert_eq!(e.chain_len(), 0);
    // Each side: 1.2 s (see above) -> corners at 1.2, 2.4, 3.6, 4.8 s.
    let corners = [(1000, 1000), (2000, 0), (1000, -1000), (0, 0)];
    let mut prev = (0i64, 0i64);
    for (k, c) in corners.iter().enumerate() {
        // Mid-side (peeked on a clone): both motors have moved the same
        // number of steps, so the path is a 45 degree line.
        let mut peek = e.clone();
        peek.advance(ms(300));
        let (dx, dy) = (peek.position(0) - prev.0, peek.position(1) - prev.1);
        assert!(dx.abs() > 0 && dx.abs() == dy.abs(), "side {k}: {dx},{dy}");
        e.advance(ms(1200));
        assert_eq!((e.position(0), e.position(1)), *c, "corner {k}");
        prev = *c;
    }
    assert!(!e.is_running(0) && !e.is_running(1));
}

#[test]
fn stop_and_limit_abort_a_chain() {
    let mut e = Emulator::new();
    send(&mut e, "0L0,1,0,0,0");
    send(&mut e, "0Y1000,0,0,0,0,0,0");
    send(&mut e, "0Y1000,0,0,0,0,0,1");
    e.advance(ms(500));
    e.set_input(0, true);
    e.advance(ms(1));
    assert!(!e.is_running(0));
    let p = e.position(0);
    e.advance(ms(5000));
    assert_eq!(e.position(0), p);
    e.set_input(0, false);
    e.advance(ms(1));
    send(&mut e, "0Y1000,0,1000,0,0,0");
    e.advance(ms(100));
    assert_eq!(send(&mut e, "0S2"), "0S|");
    assert!(!e.is_running(0) && !e.is_running(1));
}

#[test]
fn plain_sync_discards_the_buffer_and_capacity_is_100() {
    // §2.2(i), §4.17: a chain is at most 100 moves: 99 stored with execute 0, the
    // 100th sent with execute 1. The 100th store is refused (E3); the execute still
    // fits and runs all 100.
    let mut e = Emulator::new();
    for k in 0..99 {
        assert_eq!(send(&mut e, "0Y1,0,0,0,0,0,0"), "0Y|", "store {k}");
    }
    assert_eq!(send(&mut e, "0Y1,0,0,0,0,0,0"), "0E3|");
    assert_eq!(e.chain_len(), 99);
    assert_eq!(send(&mut e, "0Y1,0,0,0,0,0,1"), "0Y|");
    assert_eq!(e.chain_len(), 0);
    // 100 moves of one step: each a short triangle (1 step at 5000 steps/s²: about
    // 28 ms), well within 10 s.
    e.advance(ms(10_000));
    assert!(!e.is_running(0));
    assert_eq!(e.position(0), 100);
    // A plain Y (execute omitted) discards what is stored and runs only itself.
    for _ in 0..3 {
        assert_eq!(send(&mut e, "0Y1,0,0,0,0,0,0"), "0Y|");
    }
    assert_eq!(send(&mut e, "0Y5,0,0,0,0,0"), "0Y|");
    assert_eq!(e.chain_len(), 0);
    e.advance(ms(1000));
    assert_eq!(e.position(0), 105);
}

#[test]
fn clock_is_exact_and_keeps_sub_millisecond_remainders() {
    let mut e = Emulator::new();
    e.advance(Duration::from_micros(600));
    assert_eq!(e.now(), Duration::ZERO);
    e.advance(Duration::from_micros(600));
    assert_eq!(e.now(), ms(1));
    e.advance(Duration::from_secs(86));
    assert_eq!(e.now(), ms(86_001));
}

#[test]
fn move_of_max_u32_steps_and_zero_steps() {
    let mut e = Emulator::new();
    send(&mut e, "0M0,0,0");
    assert!(!e.is_running(0));
    send(&mut e, "0V0,5000");
    send(&mut e, "0M0,4294967295,1");
    e.advance(ms(2000));
    assert!(e.is_running(0));
    send(&mut e, "0S0");
    // 1 s ramp to 5000 (2500 steps) + 1 s at 5000 = 7500 steps.
    assert_eq!(e.position(0), -7500);
}
