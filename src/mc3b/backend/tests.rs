//! The backend's conversions and its worker over the in-process emulator (the
//! emulator's clock only moves when the worker waits, so every test is deterministic).

use super::*;
use ::mc3b::client::{EmulatorLink, Transport};
use ::mc3b::codec::Command;
use std::collections::VecDeque;
use std::io;
use std::sync::Arc;

/// An in-process MC3B that records every frame sent, can go silent after a number of
/// frames (a pulled cable), and can ask for a stop of a job at its n-th status query.
pub(crate) struct Rec {
    /// The device.
    pub link: EmulatorLink,
    /// Frames sent, without their CR.
    pub sent: Vec<String>,
    /// After this many frames, nothing reaches the device and nothing comes back.
    pub mute_after: Option<usize>,
    /// `(n, link, id)`: at the n-th `Q`, ask for a stop of job `id`.
    pub stop_at_query: Option<(usize, Arc<Link>, u64)>,
    /// Limit switches that follow a motor: `(motor, input bit, at)`: the input is high
    /// (active) while the motor's step counter is at or below `at` (`at` < 0) or at or
    /// above it (`at` > 0). Updated whenever the emulator's time moves.
    pub switches: Vec<(usize, u8, i64)>,
    /// `(prefix, delay)`: the reply to the next frame that starts with `prefix` comes
    /// `delay` late; later replies queue behind it (a slow host or device: replies
    /// stay in order).
    pub late: Option<(&'static str, Duration)>,
    held: VecDeque<u8>,
    held_due: Option<Duration>,
    queries: usize,
}

impl Rec {
    pub(crate) fn new() -> Rec {
        Rec {
            link: EmulatorLink::new(),
            sent: Vec::new(),
            mute_after: None,
            stop_at_query: None,
            switches: Vec::new(),
            late: None,
            held: VecDeque::new(),
            held_due: None,
            queries: 0,
        }
    }

    fn follow_switches(&mut self) {
        for &(m, bit, at) in &self.switches {
            let p = self.link.emulator.position(m);
            let hit = if at < 0 { p <= at } else { p >= at };
            self.link.emulator.set_input(bit, hit);
        }
    }

    /// Frames sent that start with `<id><letter>`.
    pub(crate) fn count(&self, prefix: &str) -> usize {
        self.sent.iter().filter(|s| s.starts_with(prefix)).count()
    }

    /// Step counters of the emulated device.
    pub(crate) fn pos(&self) -> [i64; MOTORS] {
        std::array::from_fn(|m| self.link.emulator.position(m))
    }
}

impl Transport for Rec {
    fn send(&mut self, data: &[u8]) -> io::Result<()> {
        let line = String::from_utf8_lossy(data).trim_end().to_string();
        let muted = self.mute_after.is_some_and(|n| self.sent.len() >= n);
        if line.starts_with("0Q") {
            self.queries += 1;
            if let Some((n, link, id)) = &self.stop_at_query {
                if self.queries == *n {
                    link.request_stop(*id);
                }
            }
        }
        let late = self.late.filter(|(p, _)| line.starts_with(p));
        self.sent.push(line);
        if muted {
            return Ok(());
        }
        if let Some((_, delay)) = late {
            self.late = None;
            self.held_due = Some(self.link.now() + delay);
        }
        if self.held_due.is_some() {
            let reply = self.link.emulator.receive(data);
            self.held.extend(reply);
            return Ok(());
        }
        self.link.send(data)
    }
    fn recv(&mut self, buf: &mut [u8], timeout: Duration) -> io::Result<usize> {
        if let Some(due) = self.held_due {
            let now = self.link.now();
            if now < due {
                self.link.idle(timeout.min(due - now));
                self.follow_switches();
                return Ok(0);
            }
            self.held_due = None;
            let n = self.held.len().min(buf.len());
            for (slot, b) in buf.iter_mut().zip(self.held.drain(..n)) {
                *slot = b;
            }
            return Ok(n);
        }
        let n = self.link.recv(buf, timeout);
        self.follow_switches();
        n
    }
    fn discard_input(&mut self) -> io::Result<()> {
        self.link.discard_input()
    }
    fn now(&self) -> Duration {
        self.link.now()
    }
    fn idle(&mut self, d: Duration) {
        self.link.idle(d);
        self.follow_switches();
    }
    fn is_realtime(&self) -> bool {
        false
    }
}

pub(crate) fn worker() -> (Arc<Link>, Worker<Rec>) {
    worker_with(Rec::new(), &[[0; 4]; MOTORS])
}

/// A worker over `rec` whose motors get the limit masks `limits`.
pub(crate) fn worker_with(rec: Rec, limits: &[LimitMasks; MOTORS]) -> (Arc<Link>, Worker<Rec>) {
    match connect_with(rec, Duration::from_millis(100), limits) {
        Ok(x) => x,
        Err(e) => panic!("connect: {e}"),
    }
}

#[test]
fn homing_seeks_backs_off_and_approaches_the_switch() {
    // Motor 0 homes in direction 1 onto bit 0 (active high) at 1000 steps/s; the switch
    // is active at or below -500. The MC3B stops on it, backs off at 10 steps/s until
    // it is off (-499) and comes back until it is on: it ends exactly at -500.
    let mut rec = Rec::new();
    rec.switches.push((0, 0, -500));
    let (link, mut w) = worker_with(rec, &[[0, 0, 1, 0], [0; 4], [0; 4]]);
    let sp = speeds_for(1000.0, Ramp::Fastest);
    link.post(
        1,
        Job::Home {
            dirs: [Some(1), None, None],
            speeds: [Some(sp), None, None],
        },
    );
    assert!(w.run_pending());
    let r = link.take_report(1).expect("report");
    assert_eq!(r.outcome, Outcome::Done);
    assert_eq!(w.transport().pos(), [-500, 0, 0]);
    assert_eq!(w.transport().count("0H0,1"), 1);
    // A move onward, into the active switch: the MC3B does not start it; the worker
    // says it ended on the limit switch.
    link.post(
        2,
        Job::Independent {
            steps: [-100, 0, 0],
            speeds: [Some(sp), None, None],
        },
    );
    assert!(w.run_pending());
    assert_eq!(
        link.take_report(2).map(|r| r.outcome),
        Some(Outcome::Failed(Fault::Limit(0)))
    );
    assert_eq!(w.transport().pos(), [-500, 0, 0]);
    // Away from it is fine.
    link.post(
        3,
        Job::Independent {
            steps: [300, 0, 0],
            speeds: [Some(sp), None, None],
        },
    );
    assert!(w.run_pending());
    assert_eq!(link.take_report(3).map(|r| r.outcome), Some(Outcome::Done));
    assert_eq!(w.transport().pos(), [-200, 0, 0]);
}

#[test]
fn a_single_move_is_a_plain_synchronous_move() {
    let (link, mut w) = worker();
    let ramp = Ramp::Times {
        acc_s: 0.05,
        dec_s: 0.05,
    };
    let speeds = [
        Some(speeds_for(2000.0, ramp)),
        Some(speeds_for(1000.0, ramp)),
        None,
    ];
    link.post(
        7,
        Job::Sync {
            segs: vec![[1000, -500, 0]],
            speeds,
        },
    );
    assert!(w.run_pending());
    assert!(!w.run_pending(), "one job only");
    let r = link.take_report(7);
    assert_eq!(
        r,
        Some(Report {
            id: 7,
            outcome: Outcome::Done,
            position: [1000, -500, 0]
        })
    );
    let t = w.transport();
    assert_eq!(t.pos(), [1000, -500, 0]);
    // 0I, 0P, then V/A/D of motors 0 and 1, the move, status queries.
    assert_eq!(&t.sent[..2], ["0I", "0P"]);
    assert!(t.sent.contains(&"0V0,2000".to_string()));
    assert!(t.sent.contains(&"0A0,40000".to_string()));
    assert_eq!(
        t.count("0V1"),
        0,
        "1000 steps/s is motor 1's setting already (0I)"
    );
    assert!(t.sent.contains(&"0D1,20000".to_string()));
    assert_eq!(t.count("0Y"), 1);
    assert!(t.sent.contains(&"0Y1000,0,500,1,0,0".to_string()));
    assert!(t.count("0Q") >= 2, "polled until idle");
    // The same settings again are not sent again.
    let before = t.sent.len();
    link.post(
        8,
        Job::Sync {
            segs: vec![[-1000, 500, 0]],
            speeds,
        },
    );
    assert!(w.run_pending());
    let t = w.transport();
    assert!(t.sent[before..].iter().all(|s| !s.starts_with("0V")));
    assert_eq!(t.pos(), [0, 0, 0]);
}

#[test]
fn several_moves_are_one_chain() {
    let (link, mut w) = worker();
    let segs = vec![[100, 0, 0], [0, 100, 0], [-100, 0, 0], [0, -100, 7]];
    link.post(
        1,
        Job::Sync {
            segs,
            speeds: [Some(speeds_for(5000.0, Ramp::Fastest)); MOTORS],
        },
    );
    assert!(w.run_pending());
    assert_eq!(link.take_report(1).map(|r| r.outcome), Some(Outcome::Done));
    let t = w.transport();
    let ys: Vec<&String> = t.sent.iter().filter(|s| s.starts_with("0Y")).collect();
    assert_eq!(
        ys,
        [
            "0Y100,0,0,0,0,0,0",
            "0Y0,0,100,0,0,0,0",
            "0Y100,1,0,0,0,0,0",
            "0Y0,0,100,1,7,0,1"
        ]
    );
    assert_eq!(t.pos(), [0, 0, 7]);
}

#[test]
fn a_point_to_point_job_moves_each_motor_on_its_own() {
    let (link, mut w) = worker();
    link.post(
        1,
        Job::Independent {
            steps: [300, 0, -40],
            speeds: [
                Some(speeds_for(3000.0, Ramp::Fastest)),
                None,
                Some(speeds_for(100.0, Ramp::Fastest)),
            ],
        },
    );
    assert!(w.run_pending());
    let r = link.take_report(1);
    assert_eq!(
        r.map(|r| (r.outcome, r.position)),
        Some((Outcome::Done, [300, 0, -40]))
    );
    let t = w.transport();
    assert!(t.sent.contains(&"0M0,300,0".to_string()));
    assert!(t.sent.contains(&"0M2,40,1".to_string()));
    assert_eq!(t.count("0M1"), 0);
    assert_eq!(t.pos(), [300, 0, -40]);
}

#[test]
fn a_stop_during_the_move_reports_the_models_estimate() {
    let (link, mut w) = worker();
    // 5000 steps at 1000 steps/s: still running at the 20th status query (~200 ms).
    w.transport().stop_at_query = Some((20, link.clone(), 3));
    link.post(
        3,
        Job::Sync {
            segs: vec![[5000, 2500, 0]],
            speeds: [
                Some(speeds_for(1000.0, Ramp::Fastest)),
                Some(speeds_for(500.0, Ramp::Fastest)),
                None,
            ],
        },
    );
    assert!(w.run_pending());
    let Some(r) = link.take_report(3) else {
        panic!("no report")
    };
    assert_eq!(r.outcome, Outcome::Stopped);
    let dev = w.transport().pos();
    assert!(dev[0] > 0 && dev[0] < 5000, "stopped on the way: {dev:?}");
    // Over the in-process device the model runs in lockstep: the estimate is exact.
    assert_eq!(r.position, dev);
    assert_eq!(w.steps(), dev);
    assert!(w.transport().sent.contains(&"0S0".to_string()));
}

#[test]
fn a_stop_before_the_start_moves_nothing() {
    let (link, mut w) = worker();
    link.post(
        4,
        Job::Sync {
            segs: vec![[10, 0, 0], [10, 0, 0]],
            speeds: [Some(speeds_for(100.0, Ramp::Fastest)), None, None],
        },
    );
    link.request_stop(4);
    assert!(w.run_pending());
    let r = link.take_report(4);
    assert_eq!(
        r.map(|r| (r.outcome, r.position)),
        Some((Outcome::Stopped, [0; 3]))
    );
    assert_eq!(w.transport().count("0Y"), 0);
}

#[test]
fn silence_is_a_link_fault_and_the_estimate_is_reported() {
    let (link, mut w) = worker();
    // 0I, 0P, V, A, D, Y reach the device; then the cable is pulled.
    let n = w.transport().sent.len() + 4;
    w.transport().mute_after = Some(n);
    link.post(
        5,
        Job::Sync {
            segs: vec![[2000, 0, 0]],
            speeds: [
                Some(speeds_for(
                    2000.0,
                    Ramp::Times {
                        acc_s: 0.1,
                        dec_s: 0.1,
                    },
                )),
                None,
                None,
            ],
        },
    );
    assert!(w.run_pending());
    let Some(r) = link.take_report(5) else {
        panic!("no report")
    };
    assert_eq!(r.outcome, Outcome::Failed(Fault::Link));
    assert_eq!(Fault::Link.record(), ERR_MC3B_LINK);
    // The move had started: the estimate is where the model thinks the motor is.
    assert!(r.position[0] > 0, "{:?}", r.position);
}

#[test]
fn a_refused_command_is_a_device_fault() {
    let (link, mut w) = worker();
    // Something else keeps motor 0 busy: its V answers E1.
    let _ = w.transport().link.emulator.handle(&Command::Move {
        id: 0,
        motor: 0,
        steps: 100_000,
        direction: 0,
    });
    link.post(
        6,
        Job::Sync {
            segs: vec![[10, 0, 0]],
            speeds: [Some(speeds_for(1234.0, Ramp::Fastest)), None, None],
        },
    );
    assert!(w.run_pending());
    let r = link.take_report(6);
    assert_eq!(r.map(|r| r.outcome), Some(Outcome::Failed(Fault::Device)));
    assert_eq!(Fault::Device.record(), ERR_MC3B_DEVICE);
}

#[test]
fn a_device_that_is_not_an_mc3b_is_refused() {
    struct Other;
    impl Transport for Other {
        fn send(&mut self, _: &[u8]) -> io::Result<()> {
            Ok(())
        }
        fn recv(&mut self, _: &mut [u8], _: Duration) -> io::Result<usize> {
            Ok(0)
        }
        fn now(&self) -> Duration {
            Duration::from_secs(1000)
        }
    }
    // Silent: the greeting times out (with a clock that never moves the deadline is
    // reached at once).
    let e = connect(Other, Duration::ZERO).err();
    assert!(e.is_some_and(|m| m.contains("0I")));
}

#[test]
fn a_device_thread_runs_jobs_and_stops_at_drop() {
    let dev = match Device::start(
        0,
        Box::new(EmulatorLink::new()),
        Duration::from_millis(50),
        &[[0; 4]; MOTORS],
    ) {
        Ok(d) => d,
        Err(e) => panic!("{e}"),
    };
    let link = dev.link();
    link.post(
        1,
        Job::Sync {
            segs: vec![[50, 0, 0]],
            speeds: [Some(speeds_for(5000.0, Ramp::Fastest)), None, None],
        },
    );
    // The in-process device needs no real time: the thread answers quickly, but it is
    // a thread; wait for it with a generous bound.
    let t0 = std::time::Instant::now();
    let r = loop {
        if let Some(r) = link.take_report(1) {
            break r;
        }
        assert!(t0.elapsed() < Duration::from_secs(10), "no report in 10 s");
        std::thread::sleep(Duration::from_millis(1));
    };
    assert_eq!((r.outcome, r.position), (Outcome::Done, [50, 0, 0]));
    assert_eq!(dev.card(), 0);
    drop(dev);
}

#[test]
fn a_late_reply_is_not_a_dead_device() {
    // On a loaded host a reply came after the timeout; the job
    // failed with 0xF901 and the estimate missed the command the device had carried
    // out. The acknowledgement of the single Y comes 150 ms late against a 100 ms
    // timeout: the line is resynced, the late "0Y" is found before the "0P" answer,
    // and the job ends Done at its target.
    let (link, mut w) = worker();
    w.transport().late = Some(("0Y", Duration::from_millis(150)));
    link.post(
        1,
        Job::Sync {
            segs: vec![[500, 0, 0]],
            speeds: [Some(speeds_for(5000.0, Ramp::Fastest)), None, None],
        },
    );
    assert!(w.run_pending());
    let r = link.take_report(1);
    assert_eq!(r.map(|r| r.outcome), Some(Outcome::Done), "{r:?}");
    assert_eq!(r.map(|r| r.position), Some([500, 0, 0]));
    let t = w.transport();
    assert_eq!(t.count("0Y"), 1, "sent once: {:?}", t.sent);
    assert_eq!(t.count("0P"), 2, "the greeting and the resync");
    assert_eq!(t.pos(), [500, 0, 0]);
    // The model took the Y at the time it was sent: it agrees with the device.
    w.catch_up();
    assert_eq!(w.model_pos(), [500, 0, 0]);
}

#[test]
fn a_late_reply_to_a_stop_keeps_the_estimate_with_the_device() {
    // A jog-like move stopped on request; the S's acknowledgement comes 150 ms late
    // (timeout 100 ms). The model must get the S at the time it was sent, so the
    // estimate is where the device stopped, not where a model that missed the S would
    // have run on to.
    let (link, mut w) = worker();
    link.post(
        2,
        Job::Independent {
            steps: [100_000, 0, 0],
            speeds: [
                Some(speeds_for(
                    1000.0,
                    Ramp::Times {
                        acc_s: 0.0,
                        dec_s: 0.0,
                    },
                )),
                None,
                None,
            ],
        },
    );
    // Stop at the 20th status query (after about 20 x 10 ms of polling).
    w.transport().stop_at_query = Some((20, link.clone(), 2));
    w.transport().late = Some(("0S", Duration::from_millis(150)));
    assert!(w.run_pending());
    let r = link.take_report(2);
    assert_eq!(r.map(|r| r.outcome), Some(Outcome::Stopped), "{r:?}");
    let t = w.transport();
    assert_eq!(t.count("0S"), 1, "{:?}", t.sent);
    let dev = t.pos();
    let est = r.map(|r| r.position).unwrap_or_default();
    assert!(dev[0] > 100, "{dev:?}");
    // Same model, same command times: no difference at all.
    assert_eq!(est, dev);
}

#[test]
fn no_chain_is_uploaded_while_a_motor_runs() {
    // On the card backend: something keeps motor 1 busy (a stop
    // that did not get through). A chain job must not store moves that a later
    // execute would run: every motor is asked first, the runner is stopped, the job
    // fails (0xF902), and the next job moves exactly its own steps.
    let (link, mut w) = worker();
    let _ = w.transport().link.emulator.handle(&Command::Move {
        id: 0,
        motor: 1,
        steps: 100_000,
        direction: 0,
    });
    let sp = [Some(speeds_for(5000.0, Ramp::Fastest)); MOTORS];
    link.post(
        3,
        Job::Sync {
            segs: vec![[5, 0, 0]; 4],
            speeds: sp,
        },
    );
    assert!(w.run_pending());
    let r = link.take_report(3);
    assert_eq!(
        r.map(|r| r.outcome),
        Some(Outcome::Failed(Fault::Device)),
        "{r:?}"
    );
    let t = w.transport();
    assert_eq!(t.count("0Y"), 0, "nothing stored: {:?}", t.sent);
    assert!(!t.link.emulator.is_running(1), "the runner was stopped");
    assert_eq!(t.link.emulator.chain_len(), 0);
    let p1 = t.pos()[1];
    link.post(
        4,
        Job::Sync {
            segs: vec![[0, 0, 5]],
            speeds: sp,
        },
    );
    assert!(w.run_pending());
    assert_eq!(link.take_report(4).map(|r| r.outcome), Some(Outcome::Done));
    assert_eq!(w.transport().pos(), [0, p1, 5]);
}
