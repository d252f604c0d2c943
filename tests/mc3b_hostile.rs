//! The `mcl_*` library against a hostile MC3B: an in-test fake device on a real
//! pseudo-terminal (the library's own emulator behind a layer that misbehaves on
//! purpose) that garbles replies, sends overlong lines, answers late, answers for
//! another controller or out of turn, loses replies, or closes the port mid-call.
//!
//! Regression tests (a chain stored while a motor ran, a reply for another controller),
//! then a seeded, replayable fuzz
//! test: `MC3B_FUZZ_SEED=<n>` replays a run (the seed is printed), and
//! `MC3B_FUZZ_ITERATIONS=<n>` sets its length (default 500; a run also stops after
//! 40 s of wall time, so a loaded host makes it shorter, never longer).
//!
//! Every test takes `LOCK` (the library has one global state) and a watchdog that
//! ends the process with a message if the test hangs.

mod common;
use common::Watchdog;
use std::collections::VecDeque;
use std::io::{Read, Write};
use std::os::raw::c_int;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{Arc, Mutex, MutexGuard};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

use mc3b::emulator::Emulator;
use serialport::{SerialPort, TTYPort};
use MCCLPCI_IMP::ffi::mcl::*;
use MCCLPCI_IMP::mc3b::mcl::*;

static LOCK: Mutex<()> = Mutex::new(());
static PANICS: AtomicUsize = AtomicUsize::new(0);

/// How the fake device treats one command frame.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Fault {
    /// Acts and answers correctly.
    None,
    /// Never gets the command (lost on the way): no action, no reply.
    Dropped,
    /// Acts; the reply is lost.
    Silent,
    /// Acts; the reply arrives as garbage (a CR-terminated line of noise).
    Garbage,
    /// Acts; a noise line comes before the correct reply.
    Noise,
    /// Acts; the reply is a line of 300 bytes, with or without its CR.
    Overlong { cr: bool },
    /// Acts; the reply comes `ms` late (replies stay in order: later ones wait).
    Late { ms: u64 },
    /// Acts; the reply carries controller ID 1.
    Foreign,
    /// Acts; the reply is another command's (`0M`, or `0Q0,0,0` to an `M`).
    WrongReply,
    /// Closes the port instead of answering (the device side vanishes).
    Vanish,
}

impl Fault {
    /// What the reply can make a call return (besides what the device itself says).
    fn codes(self, timeout_ms: u64) -> &'static [c_int] {
        match self {
            Fault::None => &[],
            Fault::Dropped | Fault::Silent => &[MCL_TIMEOUT_ERROR],
            Fault::Overlong { .. }
            | Fault::Garbage
            | Fault::Noise
            | Fault::Foreign
            | Fault::WrongReply => &[MCL_INVALID_COMMAND_ERROR],
            Fault::Late { ms } if ms > timeout_ms / 2 => &[MCL_TIMEOUT_ERROR],
            Fault::Late { .. } => &[],
            Fault::Vanish => &[MCL_SERIAL_PORT_ERROR],
        }
    }
}

/// splitmix64: deterministic, no crates.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    fn below(&mut self, n: u64) -> u64 {
        self.next() % n.max(1)
    }
    fn chance(&mut self, percent: u64) -> bool {
        self.below(100) < percent
    }
}

struct DeviceState {
    emu: Emulator,
    /// Faults for the next frames, in order (then `None`).
    plan: VecDeque<Fault>,
    /// Only frames of this command letter take faults from the plan.
    only: Option<u8>,
    /// Faults applied so far.
    applied: Vec<Fault>,
}

/// A fake MC3B on a pty: the emulator in real time behind a misbehaving layer.
struct Fake {
    state: Arc<Mutex<DeviceState>>,
    path: String,
    alive: Arc<AtomicBool>,
    thread: Option<JoinHandle<()>>,
}

fn lock<T>(m: &Mutex<T>) -> MutexGuard<'_, T> {
    m.lock().unwrap_or_else(|e| e.into_inner())
}

impl Fake {
    fn spawn() -> Fake {
        let (mut master, slave) = TTYPort::pair().expect("pty pair");
        let path = slave.name().expect("pty name");
        master
            .set_timeout(Duration::from_millis(1))
            .expect("pty timeout");
        let state = Arc::new(Mutex::new(DeviceState {
            emu: Emulator::new(),
            plan: VecDeque::new(),
            only: None,
            applied: Vec::new(),
        }));
        let alive = Arc::new(AtomicBool::new(true));
        let (st, al) = (state.clone(), alive.clone());
        let thread = std::thread::spawn(move || {
            // The slave end stays open here while the device lives, so the master
            // never sees a hang-up between clients.
            let _slave = slave;
            let mut last = Instant::now();
            let mut line = Vec::new();
            let mut out: VecDeque<(Instant, Vec<u8>)> = VecDeque::new();
            let mut last_due = Instant::now();
            let mut buf = [0u8; 512];
            while al.load(Ordering::SeqCst) {
                // A read that times out (nothing sent) is 0 bytes.
                let n: usize = master.read(&mut buf).unwrap_or_default();
                let now = Instant::now();
                lock(&st).emu.advance(now - last);
                last = now;
                for &b in buf.get(..n).unwrap_or(&[]) {
                    line.push(b);
                    if b != b'\r' {
                        continue;
                    }
                    let frame = std::mem::take(&mut line);
                    let mut s = lock(&st);
                    let letter = frame.iter().copied().find(|b| b.is_ascii_alphabetic());
                    let fault = if s.only.is_none() || s.only == letter {
                        s.plan.pop_front().unwrap_or(Fault::None)
                    } else {
                        Fault::None
                    };
                    s.applied.push(fault);
                    if fault == Fault::Vanish {
                        al.store(false, Ordering::SeqCst);
                        break;
                    }
                    if fault == Fault::Dropped {
                        continue;
                    }
                    let reply = s.emu.receive(&frame);
                    drop(s);
                    let is_m = frame.get(1) == Some(&b'M');
                    let bytes: Option<Vec<u8>> = match fault {
                        Fault::None | Fault::Late { .. } => Some(reply),
                        Fault::Silent | Fault::Dropped | Fault::Vanish => None,
                        Fault::Garbage => Some(b"\x07#0?%\xff\x00Q\r".to_vec()),
                        Fault::Noise => {
                            let mut v = b"~~noise~~\r".to_vec();
                            v.extend_from_slice(&reply);
                            Some(v)
                        }
                        Fault::Overlong { cr } => {
                            let mut v = vec![b'0'; 300];
                            if cr {
                                v.push(b'\r');
                            }
                            Some(v)
                        }
                        Fault::Foreign => {
                            let mut v = reply;
                            if let Some(b) = v.first_mut() {
                                *b = b'1';
                            }
                            Some(v)
                        }
                        Fault::WrongReply => Some(if is_m {
                            b"0Q0,0,0\r".to_vec()
                        } else {
                            b"0M\r".to_vec()
                        }),
                    };
                    if let Some(bytes) = bytes.filter(|b| !b.is_empty()) {
                        let delay = match fault {
                            Fault::Late { ms } => Duration::from_millis(ms),
                            _ => Duration::ZERO,
                        };
                        last_due = last_due.max(now + delay);
                        out.push_back((last_due, bytes));
                    }
                }
                while out.front().is_some_and(|(due, _)| *due <= Instant::now()) {
                    if let Some((_, bytes)) = out.pop_front() {
                        let _ = master.write_all(&bytes).and_then(|_| master.flush());
                    }
                }
            }
            // Dropping `master` (and the slave) here: the port vanishes.
        });
        Fake {
            state,
            path,
            alive,
            thread: Some(thread),
        }
    }

    fn plan(&self, faults: &[Fault]) {
        self.plan_for(None, faults);
    }

    /// Faults for the next frames of command letter `only` (all frames: `None`).
    fn plan_for(&self, only: Option<u8>, faults: &[Fault]) {
        let mut s = lock(&self.state);
        s.plan = faults.iter().copied().collect();
        s.only = only;
        s.applied.clear();
    }

    fn applied(&self) -> Vec<Fault> {
        lock(&self.state).applied.clone()
    }

    fn pos(&self) -> [i64; 3] {
        let s = lock(&self.state);
        [s.emu.position(0), s.emu.position(1), s.emu.position(2)]
    }

    fn running(&self) -> bool {
        let s = lock(&self.state);
        (0..3).any(|m| s.emu.is_running(m))
    }

    fn alive(&self) -> bool {
        self.alive.load(Ordering::SeqCst)
    }

    /// Waits until no motor runs (the device's own view), at most `limit`.
    fn wait_idle(&self, limit: Duration) {
        let t0 = Instant::now();
        while self.running() {
            assert!(t0.elapsed() < limit, "device still running after {limit:?}");
            std::thread::sleep(Duration::from_millis(2));
        }
    }
}

impl Drop for Fake {
    fn drop(&mut self) {
        self.alive.store(false, Ordering::SeqCst);
        if let Some(t) = self.thread.take() {
            let _ = t.join();
        }
    }
}

fn count_panics() {
    static HOOK: std::sync::Once = std::sync::Once::new();
    HOOK.call_once(|| {
        let prev = std::panic::take_hook();
        std::panic::set_hook(Box::new(move |info| {
            PANICS.fetch_add(1, Ordering::SeqCst);
            prev(info);
        }));
    });
}

/// Lock, start a fake device, point COM1 at it with reply timeout `timeout_ms`, and
/// initialize the library.
fn setup(timeout_ms: u64) -> (MutexGuard<'static, ()>, Fake) {
    let guard = lock(&LOCK);
    count_panics();
    PANICS.store(0, Ordering::SeqCst);
    let _ = mcl_deinitialize();
    let fake = Fake::spawn();
    attach(&fake, timeout_ms);
    (guard, fake)
}

fn attach(fake: &Fake, timeout_ms: u64) {
    std::env::set_var("MCL_COM1", &fake.path);
    std::env::set_var("MCL_TIMEOUT_MS", timeout_ms.to_string());
    let mut n = -1;
    // SAFETY: valid pointer to a local.
    assert_eq!(unsafe { mcl_initialize(1, &mut n) }, MCL_NO_ERROR);
    for m in 0..3 {
        assert_eq!(mcl_set_motor_maximum_velocity(0, m, 5000, 0), 0);
        assert_eq!(mcl_set_motor_acceleration(0, m, 100_000), 0);
        assert_eq!(mcl_set_motor_deceleration(0, m, 100_000), 0);
    }
}

fn status(motor: c_int) -> c_int {
    let mut st = -1;
    // SAFETY: valid pointer to a local.
    let r = unsafe { mcl_get_motor_status(0, motor, &mut st) };
    if r == 0 {
        st
    } else {
        -r
    }
}

/// Runs `f`, returning its status and how long it took.
fn timed(f: impl FnOnce() -> c_int) -> (c_int, Duration) {
    let t0 = Instant::now();
    let r = f();
    (r, t0.elapsed())
}

/// A chained move of `moves` (steps per motor, direction from the sign).
fn chain(moves: &[[i64; 3]]) -> c_int {
    let n = moves.len();
    let mut a: [Vec<c_int>; 6] = Default::default();
    for mv in moves {
        for m in 0..3 {
            a[2 * m].push(mv[m].unsigned_abs() as c_int);
            a[2 * m + 1].push(c_int::from(mv[m] < 0));
        }
    }
    // SAFETY: six arrays of n ints each.
    unsafe {
        mcl_chained_synchronous_move_motor(
            0,
            n as c_int,
            a[0].as_ptr(),
            a[1].as_ptr(),
            a[2].as_ptr(),
            a[3].as_ptr(),
            a[4].as_ptr(),
            a[5].as_ptr(),
        )
    }
}

fn sync(mv: [i64; 3], execute: bool) -> c_int {
    let s = |m: usize| mv[m].unsigned_abs() as c_int;
    let d = |m: usize| c_int::from(mv[m] < 0);
    mcl_synchronous_move_motor(0, s(0), d(0), s(1), d(1), s(2), d(2), execute)
}

fn sub(a: [i64; 3], b: [i64; 3]) -> [i64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

#[test]
fn a_garbled_reply_returns_at_once_with_invalid_command() {
    let _w = Watchdog::new("mc3b_hostile: garbled replies", Duration::from_secs(30));
    // A long timeout (1 s) makes "at once" plain: a garbled, overlong or foreign
    // reply must not be waited out (before the fix: 1 s, then TIMEOUT).
    let (_g, fake) = setup(1000);
    for fault in [
        Fault::Garbage,
        Fault::Noise,
        Fault::Overlong { cr: false },
        Fault::Overlong { cr: true },
        Fault::Foreign,
        Fault::WrongReply,
    ] {
        fake.plan(&[fault]);
        let (r, took) = timed(|| status(0));
        assert_eq!(r, -MCL_INVALID_COMMAND_ERROR, "{fault:?}");
        assert!(
            took < Duration::from_millis(400),
            "{fault:?}: took {took:?}"
        );
        // The next call is good again (the line resyncs first).
        fake.plan(&[]);
        assert_eq!(status(0), 0, "after {fault:?}");
    }
    assert_eq!(mcl_deinitialize(), 0);
    assert_eq!(PANICS.load(Ordering::SeqCst), 0);
}

#[test]
fn a_vanished_port_returns_serial_port_error_at_once() {
    let _w = Watchdog::new("mc3b_hostile: vanishing port", Duration::from_secs(30));
    let (_g, fake) = setup(1000);
    fake.plan(&[Fault::Vanish]);
    let (r, took) = timed(|| mcl_move_motor(0, 0, 0, 10));
    assert_eq!(r, MCL_SERIAL_PORT_ERROR);
    assert!(took < Duration::from_millis(400), "took {took:?}");
    // Every later call says so too, at once, until mcl_deinitialize.
    let (r, took) = timed(|| status(1));
    assert_eq!(r, -MCL_SERIAL_PORT_ERROR);
    assert!(took < Duration::from_millis(400), "took {took:?}");
    assert_eq!(mcl_deinitialize(), MCL_SERIAL_PORT_ERROR);
    assert_eq!(mcl_stop_motor(0, 0), MCL_NOT_INITIALIZED_ERROR);
    assert_eq!(PANICS.load(Ordering::SeqCst), 0);
}

#[test]
fn a_late_reply_is_never_taken_for_the_next_commands() {
    let _w = Watchdog::new("mc3b_hostile: late replies", Duration::from_secs(30));
    let (_g, fake) = setup(200);
    // The ack of M comes 300 ms late: TIMEOUT. Motor 0 runs 3000 steps (0.65 s).
    fake.plan(&[Fault::Late { ms: 300 }]);
    assert_eq!(mcl_move_motor(0, 0, 0, 3000), MCL_TIMEOUT_ERROR);
    // A second M to the running motor is refused by the device (E1); the late "0M"
    // that arrives meanwhile must not pass for its acknowledgement (before the fix
    // it did: NO ERROR for a move that never happened).
    assert_eq!(mcl_move_motor(0, 0, 0, 10), MCL_MOTOR_RUNNING_ERROR);
    fake.wait_idle(Duration::from_secs(5));
    assert_eq!(fake.pos(), [3000, 0, 0]);
    assert_eq!(mcl_deinitialize(), 0);
}

#[test]
fn a_chain_cut_short_by_a_lost_reply_leaves_nothing_stored() {
    let _w = Watchdog::new("mc3b_hostile: cut chain", Duration::from_secs(30));
    let (_g, fake) = setup(200);
    // A 4-move chain of motor 0 (+5 each): the first two stores answer, the third
    // store's reply is lost: TIMEOUT, with 3 moves stored in the device.
    let none = Fault::None;
    fake.plan_for(Some(b'Y'), &[none, none, Fault::Silent]);
    assert_eq!(chain(&[[5, 0, 0]; 4]), MCL_TIMEOUT_ERROR);
    assert_eq!(lock(&fake.state).emu.chain_len(), 3);
    fake.plan(&[]);
    std::thread::sleep(Duration::from_millis(50));
    assert_eq!(fake.pos(), [0, 0, 0], "nothing ran yet");
    // A 5-step synchronous move of motor 2 moves motor 2 only.
    assert_eq!(sync([0, 0, 5], true), 0);
    fake.wait_idle(Duration::from_secs(2));
    assert_eq!(fake.pos(), [0, 0, 5]);
    assert_eq!(mcl_deinitialize(), 0);
}

/// One call of the fuzz: a random `mcl_*` function with valid arguments.
#[derive(Debug, Clone)]
enum Call {
    Status(c_int),
    Limits,
    Move(c_int, i64),
    Run(c_int, c_int),
    Home(c_int, c_int),
    Stop(c_int),
    Velocity(c_int, c_int),
    Sync([i64; 3], bool),
    Chain(Vec<[i64; 3]>),
}

fn random_move(rng: &mut Rng) -> [i64; 3] {
    let mut mv = [0i64; 3];
    for v in &mut mv {
        if rng.chance(60) {
            *v = rng.below(41) as i64 - 20;
        }
    }
    mv
}

fn random_call(rng: &mut Rng, stored: usize) -> Call {
    let m = rng.below(3) as c_int;
    match rng.below(11) {
        0 => Call::Status(m),
        1 => Call::Limits,
        2 => Call::Move(m, rng.below(61) as i64 - 30),
        3 => Call::Run(m, rng.below(2) as c_int),
        4 => Call::Home(m, rng.below(2) as c_int),
        5 => Call::Stop(m),
        6 => Call::Velocity(m, 2000 + rng.below(3001) as c_int),
        7 => Call::Sync(random_move(rng), stored >= 20 || rng.chance(50)),
        _ => Call::Chain((0..1 + rng.below(8)).map(|_| random_move(rng)).collect()),
    }
}

fn perform(call: &Call) -> c_int {
    match call {
        Call::Status(m) => status(*m).min(0).abs(),
        Call::Limits => {
            let mut l = -1;
            // SAFETY: valid pointer to a local.
            unsafe { mcl_get_limit_switches(0, &mut l) }
        }
        Call::Move(m, n) => mcl_move_motor(0, *m, c_int::from(*n < 0), n.unsigned_abs() as c_int),
        Call::Run(m, d) => mcl_run_motor(0, *m, *d),
        Call::Home(m, d) => mcl_home_motor(0, *m, *d),
        Call::Stop(m) => mcl_stop_motor(0, *m),
        Call::Velocity(m, v) => mcl_set_motor_maximum_velocity(0, *m, *v, 0),
        Call::Sync(mv, execute) => sync(*mv, *execute),
        Call::Chain(moves) => chain(moves),
    }
}

/// Frames a call may send at most: a resync, the chain's Q x 3 and discard, its moves.
fn frames(call: &Call) -> u32 {
    2 + match call {
        Call::Chain(moves) => 4 + moves.len() as u32,
        Call::Sync(..) => 1,
        _ => 0,
    }
}

fn random_fault(rng: &mut Rng, timeout_ms: u64) -> Fault {
    match rng.below(100) {
        0..=1 => Fault::Vanish,
        2..=13 => Fault::Dropped,
        14..=25 => Fault::Silent,
        26..=37 => Fault::Garbage,
        38..=47 => Fault::Noise,
        48..=57 => Fault::Overlong { cr: rng.chance(50) },
        58..=71 => Fault::Late {
            ms: if rng.chance(50) {
                rng.below(timeout_ms / 3)
            } else {
                timeout_ms + rng.below(timeout_ms)
            },
        },
        72..=85 => Fault::Foreign,
        _ => Fault::WrongReply,
    }
}

#[test]
fn fuzz_mcl_against_a_hostile_device() {
    let _w = Watchdog::new("mc3b_hostile: the fuzz test", Duration::from_secs(120));
    const TIMEOUT_MS: u64 = 100;
    let seed = std::env::var("MC3B_FUZZ_SEED")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(0x6d63_3362_u64);
    let iterations: usize = std::env::var("MC3B_FUZZ_ITERATIONS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(500);
    let budget = Duration::from_secs(40);
    println!("mc3b fuzz: seed {seed} (MC3B_FUZZ_SEED), {iterations} iterations at most");
    let mut rng = Rng(seed);
    let (_g, mut fake) = setup(TIMEOUT_MS);
    let t_start = Instant::now();
    // Moves the library has stored in the device with execute = false and that the
    // next execute will run (the library discards them after a failed Y call).
    let mut stored: Vec<[i64; 3]> = Vec::new();
    let mut done = 0;
    let mut faults_injected = 0;
    let mut vanished = 0;
    let mut slowest = Duration::ZERO;
    for it in 0..iterations {
        if t_start.elapsed() > budget {
            break;
        }
        // 1. A call through a misbehaving line.
        let call = random_call(&mut rng, stored.len());
        let plan: Vec<Fault> = (0..frames(&call))
            .map(|_| {
                if rng.chance(35) {
                    random_fault(&mut rng, TIMEOUT_MS)
                } else {
                    Fault::None
                }
            })
            .collect();
        fake.plan(&plan);
        let (code, took) = timed(|| perform(&call));
        let applied = fake.applied();
        let ctx = format!("iteration {it} (seed {seed}): {call:?} faults {applied:?} -> {code}");
        // Bound: every frame it sent waited at most the timeout (counted while
        // watching), plus scheduling slack.
        let bound =
            Duration::from_millis(TIMEOUT_MS) * 2 * (frames(&call) + 1) + Duration::from_secs(2);
        assert!(took < bound, "{ctx}: took {took:?} (bound {bound:?})");
        slowest = slowest.max(took);
        let injected: Vec<Fault> = applied
            .iter()
            .copied()
            .filter(|f| !f.codes(TIMEOUT_MS).is_empty())
            .collect();
        faults_injected += injected.len();
        let mut allowed = vec![MCL_NO_ERROR, MCL_MOTOR_RUNNING_ERROR];
        for f in &injected {
            allowed.extend_from_slice(f.codes(TIMEOUT_MS));
        }
        if !fake.alive() {
            allowed.push(MCL_SERIAL_PORT_ERROR);
        }
        assert!(allowed.contains(&code), "{ctx}: not among {allowed:?}");
        if injected.is_empty() && fake.alive() {
            // No fault reached this call: it did what a good line does.
            assert!(
                code == MCL_NO_ERROR || code == MCL_MOTOR_RUNNING_ERROR,
                "{ctx}"
            );
        }
        // What the library promises about the chained-move buffer.
        // A stored move waits for the next execute; an execute runs and empties
        // the buffer; after a failed synchronous or chained move the library
        // discards it before the next one.
        match (&call, code) {
            (Call::Sync(mv, false), 0) => stored.push(*mv),
            (Call::Sync(..) | Call::Chain(_), _) => stored.clear(),
            _ => {}
        }
        // 2. The port vanished: every call says so at once; start over on a new one.
        if !fake.alive() {
            vanished += 1;
            let (r, took) = timed(|| mcl_stop_motor(0, 0));
            assert_eq!(r, MCL_SERIAL_PORT_ERROR, "{ctx}: after the port vanished");
            assert!(took < Duration::from_millis(500), "{ctx}: {took:?}");
            assert_eq!(mcl_deinitialize(), MCL_SERIAL_PORT_ERROR, "{ctx}");
            fake = Fake::spawn();
            attach(&fake, TIMEOUT_MS);
            stored.clear();
        }
        // 3. A good line again: stop whatever the call started, wait for rest.
        // (The first call may still fail once: a late answer to a resync that timed
        // out is taken for the next resync's, and that one's for the call's reply.)
        fake.plan(&[]);
        for m in 0..3 {
            let r = (0..3)
                .map(|_| mcl_stop_motor(0, m))
                .find(|&r| r == 0)
                .unwrap_or(-1);
            assert_eq!(r, 0, "{ctx}: stop {m} on a good line");
        }
        fake.wait_idle(Duration::from_secs(5));
        // 4. A good command moves exactly what it asks (plus what the program
        // stored), never another motor.
        let before = fake.pos();
        let is_sync = rng.chance(50);
        let (mv, r) = if is_sync {
            let mv = random_move(&mut rng);
            (mv, sync(mv, true))
        } else {
            let m = rng.below(3) as usize;
            let n = rng.below(41) as i64 - 20;
            let mut mv = [0; 3];
            mv[m] = n;
            (mv, perform(&Call::Move(m as c_int, n)))
        };
        assert_eq!(r, 0, "{ctx}: the good command after it failed");
        fake.wait_idle(Duration::from_secs(5));
        // A synchronous execute runs what is stored first (§6.12), an M does not.
        let mut want = mv;
        if is_sync {
            for st in &stored {
                for m in 0..3 {
                    want[m] += st[m];
                }
            }
            stored.clear();
        }
        let moved = sub(fake.pos(), before);
        assert_eq!(
            moved, want,
            "{ctx}: the good command {mv:?} (sync: {is_sync}) moved the motors by {moved:?}"
        );
        done = it + 1;
    }
    println!(
        "mc3b fuzz: {done} iterations in {:.1} s, {faults_injected} faults reached the \
         library, the port vanished {vanished} times, slowest call {slowest:?}",
        t_start.elapsed().as_secs_f64()
    );
    assert!(done >= 20, "only {done} iterations ran");
    assert_eq!(PANICS.load(Ordering::SeqCst), 0, "a panic happened");
    let _ = mcl_deinitialize();
}
