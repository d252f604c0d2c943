//! The MC3B C library (`mcl_*`, called as Rust functions) against the
//! `mc3b-emu` binary over a real pseudo-terminal.
//!
//! Every test takes `LOCK` (the library has one global state and the tests
//! set `MCL_COM1`), spawns its own emulator, and points COM1 at it.

mod common;
use common::emu::Emu;
use std::os::raw::c_int;
use std::process::Command;
use std::sync::{Mutex, MutexGuard};
use std::time::{Duration, Instant};

use MCCLPCI_IMP::ffi::mcl::*;
use MCCLPCI_IMP::mc3b::mcl::*;

static LOCK: Mutex<()> = Mutex::new(());

/// Lock, spawn an emulator, point COM1 at it and initialize the library.
fn setup() -> (MutexGuard<'static, ()>, Emu) {
    let guard = LOCK.lock().unwrap_or_else(|e| e.into_inner());
    let _ = mcl_deinitialize(); // leftovers of a failed test
    let emu = Emu::spawn();
    std::env::set_var("MCL_COM1", &emu.path);
    std::env::set_var("MCL_TIMEOUT_MS", "300");
    let mut n = -1;
    // SAFETY: valid pointer to a local.
    assert_eq!(unsafe { mcl_initialize(1, &mut n) }, MCL_NO_ERROR);
    assert_eq!(n, 1);
    (guard, emu)
}

fn status(motor: c_int) -> c_int {
    let mut st = -1;
    assert_eq!(
        // SAFETY: valid pointer to a local.
        unsafe { mcl_get_motor_status(0, motor, &mut st) },
        MCL_NO_ERROR
    );
    st
}

fn limits() -> c_int {
    let mut l = -1;
    // SAFETY: valid pointer to a local.
    assert_eq!(unsafe { mcl_get_limit_switches(0, &mut l) }, MCL_NO_ERROR);
    l
}

/// Poll until the motor is idle; returns the time it took.
fn wait_idle(motor: c_int, limit: Duration) -> Duration {
    let t0 = Instant::now();
    while status(motor) & 1 != 0 {
        assert!(t0.elapsed() < limit, "motor {motor} still running");
        std::thread::sleep(Duration::from_millis(5));
    }
    t0.elapsed()
}

fn fast(motor: c_int) {
    assert_eq!(mcl_set_motor_maximum_velocity(0, motor, 5000, 0), 0);
    assert_eq!(mcl_set_motor_acceleration(0, motor, 100_000), 0);
    assert_eq!(mcl_set_motor_deceleration(0, motor, 100_000), 0);
}

#[test]
fn every_call_before_initialize_is_not_initialized() {
    let _g = LOCK.lock().unwrap_or_else(|e| e.into_inner());
    let _ = mcl_deinitialize();
    let mut v = 0;
    let mut arr = [0 as c_int; 1];
    let p = arr.as_mut_ptr();
    // SAFETY: valid pointers to locals throughout.
    unsafe {
        assert_eq!(mcl_get_library_version(&mut v), MCL_NO_ERROR);
        assert_eq!(v, 100);
        assert_eq!(mcl_get_motor_status(0, 0, &mut v), 2);
        assert_eq!(mcl_get_limit_switches(0, &mut v), 2);
        assert_eq!(
            mcl_chained_synchronous_move_motor(0, 1, p, p, p, p, p, p),
            2
        );
    }
    assert_eq!(mcl_deinitialize(), 2);
    assert_eq!(mcl_set_motor_acceleration(0, 0, 5000), 2);
    assert_eq!(mcl_set_motor_deceleration(0, 0, 5000), 2);
    assert_eq!(mcl_set_motor_maximum_velocity(0, 0, 1000, 0), 2);
    assert_eq!(mcl_set_motor_half_steps_control(0, 0, true), 2);
    assert_eq!(mcl_set_motor_holding_current_control(0, 0, true), 2);
    assert_eq!(mcl_set_motor_limits(0, 0, -1, false, -1, false), 2);
    assert_eq!(mcl_set_limit_switch_debounce(0, 1), 2);
    assert_eq!(mcl_set_motor_current_limits(0, 0, 500, 2000), 2);
    assert_eq!(mcl_run_motor(0, 0, 0), 2);
    assert_eq!(mcl_move_motor(0, 0, 0, 10), 2);
    assert_eq!(mcl_home_motor(0, 0, 0), 2);
    assert_eq!(mcl_stop_motor(0, 0), 2);
    assert_eq!(mcl_synchronous_move_motor(0, 1, 0, 1, 0, 1, 0, true), 2);
    // Out-of-range values are still NOT INITIALIZED first.
    assert_eq!(mcl_set_motor_acceleration(5, 9, 1), 2);
}

#[test]
fn initialize_errors_and_repeat_calls() {
    let _g = LOCK.lock().unwrap_or_else(|e| e.into_inner());
    let _ = mcl_deinitialize();
    let mut n = -1;
    // SAFETY: valid pointers to a local (or null where tested).
    unsafe {
        assert_eq!(mcl_initialize(0, &mut n), MCL_SERIAL_PORT_ERROR);
        std::env::set_var("MCL_COM9", "/nonexistent/tty");
        assert_eq!(mcl_initialize(9, &mut n), MCL_SERIAL_PORT_ERROR);
        assert_eq!(mcl_initialize(1, std::ptr::null_mut()), 7);
    }
    assert_eq!(mcl_stop_motor(0, 0), 2);
    drop(_g);
    let (_g, _emu) = setup();
    // Second initialize: no effect, NO ERROR, count reported again.
    let mut n = -1;
    // SAFETY: valid pointer to a local.
    assert_eq!(unsafe { mcl_initialize(7, &mut n) }, MCL_NO_ERROR);
    assert_eq!(n, 1);
    assert_eq!(mcl_deinitialize(), MCL_NO_ERROR);
    assert_eq!(mcl_deinitialize(), 2);
}

#[test]
fn parameter_ranges_of_every_function() {
    let (_g, _emu) = setup();
    let e = MCL_PARAMETER_OUT_OF_RANGE_ERROR;
    // controller and motor ids
    assert_eq!(mcl_stop_motor(1, 0), e);
    assert_eq!(mcl_stop_motor(-1, 0), e);
    assert_eq!(mcl_stop_motor(0, 3), e);
    assert_eq!(mcl_stop_motor(0, -1), e);
    assert_eq!(mcl_stop_motor(0, 2), 0);
    for (f, lo, hi) in [
        (
            mcl_set_motor_acceleration as extern "C" fn(c_int, c_int, c_int) -> c_int,
            100,
            100_000,
        ),
        (mcl_set_motor_deceleration, 100, 100_000),
    ] {
        assert_eq!(f(0, 0, lo - 1), e);
        assert_eq!(f(0, 0, hi + 1), e);
        assert_eq!(f(0, 0, lo), 0);
        assert_eq!(f(0, 0, hi), 0);
        assert_eq!(f(0, 3, lo), e);
    }
    assert_eq!(mcl_set_motor_maximum_velocity(0, 0, 0, 0), e);
    assert_eq!(mcl_set_motor_maximum_velocity(0, 0, 5001, 0), e);
    assert_eq!(mcl_set_motor_maximum_velocity(0, 0, 10, 2), e);
    assert_eq!(mcl_set_motor_maximum_velocity(0, 0, 1, 0), 0);
    assert_eq!(mcl_set_motor_maximum_velocity(0, 0, 5000, 1), 0);
    assert_eq!(mcl_set_motor_half_steps_control(0, 3, true), e);
    assert_eq!(mcl_set_motor_half_steps_control(0, 1, false), 0);
    assert_eq!(mcl_set_motor_holding_current_control(0, 3, true), e);
    assert_eq!(mcl_set_motor_holding_current_control(0, 1, true), 0);
    assert_eq!(mcl_set_motor_limits(0, 0, 6, true, -1, false), e);
    assert_eq!(mcl_set_motor_limits(0, 0, -1, true, -2, false), e);
    assert_eq!(mcl_set_motor_limits(0, 0, 0, true, 5, false), 0);
    assert_eq!(mcl_set_limit_switch_debounce(0, 0), e);
    assert_eq!(mcl_set_limit_switch_debounce(0, 101), e);
    assert_eq!(mcl_set_limit_switch_debounce(1, 5), e);
    assert_eq!(mcl_set_limit_switch_debounce(0, 100), 0);
    assert_eq!(mcl_set_limit_switch_debounce(0, 1), 0);
    assert_eq!(mcl_set_motor_current_limits(0, 0, -1, 0), e);
    assert_eq!(mcl_set_motor_current_limits(0, 0, 0, 2001), e);
    assert_eq!(mcl_set_motor_current_limits(0, 0, 0, 2000), 0);
    assert_eq!(mcl_run_motor(0, 0, 2), e);
    assert_eq!(mcl_home_motor(0, 0, -1), e);
    assert_eq!(mcl_move_motor(0, 0, 2, 10), e);
    assert_eq!(mcl_move_motor(0, 0, 0, -10), e);
    assert_eq!(mcl_move_motor(0, 0, 0, 0), 0);
    assert_eq!(mcl_synchronous_move_motor(0, -1, 0, 0, 0, 0, 0, true), e);
    assert_eq!(mcl_synchronous_move_motor(0, 1, 2, 0, 0, 0, 0, true), e);
    assert_eq!(mcl_synchronous_move_motor(1, 1, 0, 0, 0, 0, 0, true), e);
    let s = [10 as c_int; 101];
    let d = [0 as c_int; 101];
    let bad = [0, 0, 3 as c_int];
    let (sp, dp) = (s.as_ptr(), d.as_ptr());
    let mut v = 0;
    // SAFETY: arrays of at least the passed length; valid locals.
    unsafe {
        assert_eq!(
            mcl_chained_synchronous_move_motor(0, 0, sp, dp, sp, dp, sp, dp),
            e
        );
        assert_eq!(
            mcl_chained_synchronous_move_motor(0, 101, sp, dp, sp, dp, sp, dp),
            e
        );
        let null = std::ptr::null();
        assert_eq!(
            mcl_chained_synchronous_move_motor(0, 1, sp, dp, null, dp, sp, dp),
            e
        );
        assert_eq!(
            mcl_chained_synchronous_move_motor(0, 3, sp, dp, sp, bad.as_ptr(), sp, dp),
            e
        );
        assert_eq!(mcl_get_motor_status(0, 3, &mut v), e);
        assert_eq!(mcl_get_motor_status(0, 0, std::ptr::null_mut()), e);
        assert_eq!(mcl_get_limit_switches(1, &mut v), e);
        assert_eq!(mcl_get_limit_switches(0, std::ptr::null_mut()), e);
        assert_eq!(mcl_get_library_version(std::ptr::null_mut()), e);
    }
    // Nothing started by the rejected calls.
    for m in 0..3 {
        assert_eq!(status(m) & 1, 0);
    }
    assert_eq!(mcl_deinitialize(), 0);
}

#[test]
fn move_run_stop_and_motor_running() {
    let (_g, mut emu) = setup();
    fast(0);
    // 3000 steps at 5000 steps/s, 100000 steps/s^2: 0.05 s ramps, 0.55 s
    // cruise -> 0.65 s.
    assert_eq!(mcl_move_motor(0, 0, 1, 3000), 0);
    assert_eq!(status(0) & 1, 1);
    let m = MCL_MOTOR_RUNNING_ERROR;
    assert_eq!(mcl_move_motor(0, 0, 1, 3000), m);
    assert_eq!(mcl_run_motor(0, 0, 0), m);
    assert_eq!(mcl_home_motor(0, 0, 0), m);
    assert_eq!(mcl_set_motor_half_steps_control(0, 0, false), m);
    assert_eq!(mcl_set_motor_acceleration(0, 0, 1000), m);
    assert_eq!(mcl_set_motor_maximum_velocity(0, 0, 1000, 0), m);
    assert_eq!(mcl_synchronous_move_motor(0, 1, 0, 1, 0, 1, 0, true), m);
    // Other settings and other motors are fine meanwhile.
    assert_eq!(mcl_set_motor_holding_current_control(0, 0, true), 0);
    assert_eq!(mcl_set_motor_current_limits(0, 0, 300, 1500), 0);
    assert_eq!(mcl_move_motor(0, 1, 0, 5), 0);
    let took = wait_idle(0, Duration::from_secs(5));
    assert!(took >= Duration::from_millis(500), "{took:?}");
    assert_eq!(emu.pos().0, -3000);
    // Free-running: on-the-fly changes are accepted, then stop.
    assert_eq!(mcl_run_motor(0, 0, 0), 0);
    std::thread::sleep(Duration::from_millis(50));
    assert_eq!(mcl_set_motor_maximum_velocity(0, 0, 2000, 0), 0);
    assert_eq!(mcl_set_motor_acceleration(0, 0, 50_000), 0);
    assert_eq!(mcl_set_motor_deceleration(0, 0, 50_000), 0);
    std::thread::sleep(Duration::from_millis(100));
    assert_eq!(mcl_stop_motor(0, 0), 0);
    assert_eq!(status(0), 0);
    let p1 = emu.pos().0;
    assert!(p1 > -3000 + 100, "{p1}");
    std::thread::sleep(Duration::from_millis(50));
    assert_eq!(emu.pos().0, p1, "stopped at once");
    // Direction modifier 1 reverses a free-running motion's direction.
    assert_eq!(mcl_set_motor_maximum_velocity(0, 0, 5000, 1), 0);
    assert_eq!(mcl_run_motor(0, 0, 0), 0);
    std::thread::sleep(Duration::from_millis(100));
    assert_eq!(mcl_stop_motor(0, 0), 0);
    assert!(emu.pos().0 < p1 - 50);
    // Full steps take effect while idle.
    assert_eq!(mcl_set_motor_half_steps_control(0, 0, false), 0);
    assert_eq!(mcl_deinitialize(), 0);
}

#[test]
fn limit_stop_tripped_through_the_control_channel() {
    let (_g, mut emu) = setup();
    fast(1);
    // Direction 0 limit: input 2 pulled to +5 V; direction 1: input 4 at 0 V.
    assert_eq!(mcl_set_motor_limits(0, 1, 2, true, 4, false), 0);
    assert_eq!(emu.ctl("input 4 1"), "ok");
    std::thread::sleep(Duration::from_millis(20));
    assert_eq!(status(1), 0);
    assert_eq!(mcl_run_motor(0, 1, 0), 0);
    std::thread::sleep(Duration::from_millis(200));
    assert_eq!(status(1), 1);
    assert_eq!(emu.ctl("input 2 1"), "ok");
    wait_idle(1, Duration::from_secs(1));
    assert_eq!(status(1), 0b010, "idle, at the direction 0 limit");
    assert_eq!(limits(), 0b10100);
    let p = emu.pos().1;
    assert!(p > 100, "{p}");
    // No motion into the active limit; the other way is free.
    assert_eq!(mcl_move_motor(0, 1, 0, 100), 0);
    std::thread::sleep(Duration::from_millis(50));
    assert_eq!(emu.pos().1, p);
    assert_eq!(mcl_move_motor(0, 1, 1, 100), 0);
    wait_idle(1, Duration::from_secs(2));
    assert_eq!(emu.pos().1, p - 100);
    // Direction 1 limit is active-low on input 4.
    assert_eq!(emu.ctl("input 4 0"), "ok");
    std::thread::sleep(Duration::from_millis(20));
    assert_eq!(status(1), 0b110);
    // Debounce: 100 samples at 1 kHz = 100 ms before a change registers.
    assert_eq!(mcl_set_limit_switch_debounce(0, 100), 0);
    assert_eq!(emu.ctl("inputs 0"), "ok");
    assert_eq!(limits(), 0b00100, "not yet registered");
    std::thread::sleep(Duration::from_millis(250));
    assert_eq!(limits(), 0);
    assert_eq!(mcl_deinitialize(), 0);
}

#[test]
fn guide_limit_example_maps_to_and_xor_masks() {
    let (_g, mut emu) = setup();
    // §6.5: motor 2, dir 0 on bit 3 high, dir 1 on bit 5 low (0L2,8,0,32,32).
    assert_eq!(mcl_set_motor_limits(0, 2, 3, true, 5, false), 0);
    std::thread::sleep(Duration::from_millis(10));
    assert_eq!(status(2), 0b100, "bit 5 low: at home 1");
    assert_eq!(emu.ctl("inputs 40"), "ok");
    std::thread::sleep(Duration::from_millis(10));
    assert_eq!(status(2), 0b010, "bit 3 high: at home 0");
    assert_eq!(limits(), 40);
    // Disabling with -1 clears both.
    assert_eq!(mcl_set_motor_limits(0, 2, -1, true, -1, false), 0);
    assert_eq!(status(2), 0);
    assert_eq!(mcl_deinitialize(), 0);
}

#[test]
fn homing_backs_off_and_approaches_slowly() {
    let (_g, mut emu) = setup();
    fast(0);
    // Home for direction 1 on input 0, active low.
    assert_eq!(mcl_set_motor_limits(0, 0, -1, true, 0, false), 0);
    assert_eq!(emu.ctl("home 0 1 0"), "ok input 0 1");
    std::thread::sleep(Duration::from_millis(10));
    assert_eq!(mcl_home_motor(0, 0, 1), 0);
    std::thread::sleep(Duration::from_millis(200));
    assert_eq!(emu.ctl("home 0 1 1"), "ok input 0 0");
    std::thread::sleep(Duration::from_millis(20));
    // Backing off at 10 steps/s: still running, at home 1.
    assert_eq!(status(0), 0b101);
    let p0 = emu.pos().0;
    std::thread::sleep(Duration::from_millis(450));
    let p1 = emu.pos().0;
    assert!((3..=6).contains(&(p1 - p0)), "back-off {p0} -> {p1}");
    assert_eq!(emu.ctl("home 0 1 0"), "ok input 0 1");
    std::thread::sleep(Duration::from_millis(20));
    assert_eq!(status(0), 0b001, "approaching");
    std::thread::sleep(Duration::from_millis(250));
    let p2 = emu.pos().0;
    assert!((1..=3).contains(&(p1 - p2)), "approach {p1} -> {p2}");
    assert_eq!(emu.ctl("home 0 1 1"), "ok input 0 0");
    wait_idle(0, Duration::from_millis(500));
    assert_eq!(status(0), 0b100, "homed: idle at home 1");
    let p3 = emu.pos().0;
    std::thread::sleep(Duration::from_millis(150));
    assert_eq!(emu.pos().0, p3);
    assert_eq!(mcl_deinitialize(), 0);
}

#[test]
fn synchronous_move_finishes_together() {
    let (_g, mut emu) = setup();
    for m in 0..3 {
        fast(m);
    }
    // Motor 1 capped at 1000 steps/s with 1000 steps dominates:
    // u: v = 1/s, a = min(100000/2000, 100000/1000, 100000/500) = 50/s^2
    // -> ramps 0.02 s, cruise 0.98 s: about 1.02 s for all three.
    assert_eq!(mcl_set_motor_maximum_velocity(0, 1, 1000, 0), 0);
    let t0 = Instant::now();
    assert_eq!(
        mcl_synchronous_move_motor(0, 2000, 0, 1000, 1, 500, 0, true),
        0
    );
    for m in 0..3 {
        assert_eq!(status(m) & 1, 1);
    }
    assert_eq!(mcl_move_motor(0, 2, 0, 1), MCL_MOTOR_RUNNING_ERROR);
    std::thread::sleep(Duration::from_millis(500));
    let (a, b, c) = emu.pos();
    // Linear: positions stay in the ratio 4 : -2 : 1.
    assert!(
        (a - 4 * c).abs() <= 4 && (b + 2 * c).abs() <= 2,
        "{a} {b} {c}"
    );
    assert!(a > 200 && a < 1800, "{a}");
    while status(0) & 1 != 0 {
        std::thread::sleep(Duration::from_millis(5));
    }
    let took = t0.elapsed();
    assert_eq!(status(1) & 1, 0);
    assert_eq!(status(2) & 1, 0);
    assert!(took >= Duration::from_millis(1000), "{took:?}");
    assert!(took < Duration::from_millis(1600), "{took:?}");
    assert_eq!(emu.pos(), (2000, -1000, 500));
    // execute=false stores; nothing moves until a move with execute=true.
    assert_eq!(mcl_synchronous_move_motor(0, 100, 1, 0, 0, 0, 0, false), 0);
    std::thread::sleep(Duration::from_millis(100));
    assert_eq!(status(0) & 1, 0);
    assert_eq!(mcl_synchronous_move_motor(0, 100, 1, 0, 0, 0, 0, true), 0);
    wait_idle(0, Duration::from_secs(2));
    assert_eq!(emu.pos(), (1800, -1000, 500));
    assert_eq!(mcl_deinitialize(), 0);
}

#[test]
fn chained_45_degree_square_from_the_guide() {
    let (_g, mut emu) = setup();
    fast(0);
    fast(1);
    // §6.12's square: (1000,0 / 1000,0), (1000,0 / 1000,1),
    // (1000,1 / 1000,1), (1000,1 / 1000,0). Each side: u speed 5/s,
    // accel 100/s^2 -> 0.05 s ramps + 0.15 s cruise = 0.25 s; 1 s in all.
    let s = [1000 as c_int; 4];
    let d0 = [0 as c_int, 0, 1, 1];
    let d1 = [0 as c_int, 1, 1, 0];
    let z = [0 as c_int; 4];
    let t0 = Instant::now();
    // SAFETY: six arrays of 4 ints each.
    let r = unsafe {
        mcl_chained_synchronous_move_motor(
            0,
            4,
            s.as_ptr(),
            d0.as_ptr(),
            s.as_ptr(),
            d1.as_ptr(),
            z.as_ptr(),
            z.as_ptr(),
        )
    };
    assert_eq!(r, 0);
    // Sample the path: every point lies on one side of the square.
    let mut samples = 0;
    let mut seen_sides = [false; 4];
    while status(0) & 1 != 0 {
        let (x, y, z) = emu.pos();
        assert_eq!(z, 0);
        let side = if x == y && (0..=1000).contains(&x) {
            0
        } else if x + y == 2000 && (1000..=2000).contains(&x) {
            1
        } else if x - y == 2000 && (1000..=2000).contains(&x) {
            2
        } else if x + y == 0 && (0..=1000).contains(&x) {
            3
        } else {
            panic!("({x},{y}) is off the square");
        };
        seen_sides[side] = true;
        samples += 1;
        assert!(t0.elapsed() < Duration::from_secs(4));
    }
    let took = t0.elapsed();
    assert!(samples > 10, "{samples}");
    assert_eq!(seen_sides, [true; 4], "all four sides traversed");
    assert!(took >= Duration::from_millis(950), "{took:?}");
    assert_eq!(emu.pos(), (0, 0, 0), "back at the start");
    assert_eq!(mcl_deinitialize(), 0);
}

#[test]
fn serial_port_error_when_the_emulator_is_gone() {
    // The device side of the pty closes: the port itself fails (a hang-up), which is
    // a SERIAL PORT ERROR at once, not a timeout (docs/mc3b.md, "A bad line").
    let (_g, mut emu) = setup();
    assert_eq!(status(0), 0);
    emu.kill();
    std::thread::sleep(Duration::from_millis(50));
    let mut st = 0;
    let t0 = Instant::now();
    assert_eq!(
        // SAFETY: valid pointer to a local.
        unsafe { mcl_get_motor_status(0, 0, &mut st) },
        MCL_SERIAL_PORT_ERROR
    );
    assert_eq!(mcl_move_motor(0, 0, 0, 10), MCL_SERIAL_PORT_ERROR);
    // Neither waited for the 300 ms timeout.
    assert!(
        t0.elapsed() < Duration::from_millis(290),
        "{:?}",
        t0.elapsed()
    );
    // Range errors are still caught locally.
    assert_eq!(
        mcl_move_motor(0, 0, 5, 10),
        MCL_PARAMETER_OUT_OF_RANGE_ERROR
    );
    // De-initialize releases the port even though the board is gone.
    assert_eq!(mcl_deinitialize(), MCL_SERIAL_PORT_ERROR);
    assert_eq!(mcl_stop_motor(0, 0), MCL_NOT_INITIALIZED_ERROR);
}

#[test]
fn timeout_when_the_emulator_is_silent() {
    // A stopped (SIGSTOP) emulator keeps the line up but never answers: a
    // true reply timeout rather than a hang-up.
    let (_g, emu) = setup();
    let pid = emu.child.id().to_string();
    let stop = Command::new("kill").args(["-STOP", &pid]).status();
    if !stop.is_ok_and(|s| s.success()) {
        return; // no kill(1): covered by the hang-up test
    }
    let t0 = Instant::now();
    assert_eq!(mcl_stop_motor(0, 0), MCL_TIMEOUT_ERROR);
    assert!(t0.elapsed() >= Duration::from_millis(250));
    let _ = Command::new("kill").args(["-CONT", &pid]).status();
    // Once it answers again the library recovers (stale replies dropped).
    std::thread::sleep(Duration::from_millis(50));
    assert_eq!(mcl_stop_motor(0, 0), 0);
    assert_eq!(mcl_deinitialize(), 0);
}

#[test]
fn a_chain_refused_while_a_motor_runs_leaves_nothing_to_run_later() {
    // A chain sent while motor 1 ran stored its first moves and
    // then had its execute refused (E1); a later 5-step synchronous move of motor 2
    // ran the stored moves too and moved motor 0 by +15 steps.
    let (_g, mut emu) = setup();
    for m in 0..3 {
        fast(m);
    }
    // Motor 1: 3000 steps at 5000 steps/s with 100000 steps/s² ramps: 0.65 s.
    assert_eq!(mcl_move_motor(0, 1, 0, 3000), 0);
    let s0 = [5 as c_int; 4];
    let z = [0 as c_int; 4];
    // SAFETY: six arrays of 4 ints each.
    let r = unsafe {
        mcl_chained_synchronous_move_motor(
            0,
            4,
            s0.as_ptr(),
            z.as_ptr(),
            z.as_ptr(),
            z.as_ptr(),
            z.as_ptr(),
            z.as_ptr(),
        )
    };
    assert_eq!(
        r, MCL_MOTOR_RUNNING_ERROR,
        "§4.16: all three motors must be idle"
    );
    wait_idle(1, Duration::from_secs(5));
    let before = emu.pos();
    assert_eq!(before, (0, 3000, 0));
    assert_eq!(mcl_synchronous_move_motor(0, 0, 0, 0, 0, 5, 0, true), 0);
    wait_idle(2, Duration::from_secs(2));
    // Only motor 2 moves, by 5 steps.
    assert_eq!(emu.pos(), (0, 3000, 5));
    assert_eq!(mcl_deinitialize(), 0);
}

#[test]
fn a_full_chain_of_100_moves_runs() {
    // §2.2(i), §4.17: 100 moves in one chain (99 stored, the last executes).
    let (_g, mut emu) = setup();
    fast(0);
    let s = [1 as c_int; 100];
    let z = [0 as c_int; 100];
    // SAFETY: six arrays of 100 ints each.
    let r = unsafe {
        mcl_chained_synchronous_move_motor(
            0,
            100,
            s.as_ptr(),
            z.as_ptr(),
            z.as_ptr(),
            z.as_ptr(),
            z.as_ptr(),
            z.as_ptr(),
        )
    };
    assert_eq!(r, 0);
    // 100 one-step moves (each a triangle of about 6 ms at 100000 steps/s²).
    wait_idle(0, Duration::from_secs(5));
    assert_eq!(emu.pos(), (100, 0, 0));
    assert_eq!(mcl_deinitialize(), 0);
}
