//! A group on an MC3B, driven tick by tick against the in-process emulator. The test
//! runs the device's worker itself ([`Worker::run_pending`]), so what the group sees
//! between ticks is exactly determined.

use super::*;
use crate::config::{default_mac_param, GroupDef};
use crate::engine::command::AxisMech;
use crate::engine::group::GroupState;
use crate::mc3b::backend::tests::{worker, Rec};
use crate::mc3b::backend::Ramp;
use crate::mc3b::backend::{chord_count, Worker, ERR_MC3B_LINK};
use crate::planner::{Path, Plane};
use crate::vendor::consts as c;

/// 100 steps per UU on every axis.
const K: f64 = 100.0;

struct Rig {
    g: GroupState,
    link: Arc<Link>,
    w: Worker<Rec>,
}

/// Group 0 on card 0: X, Y, Z on channels 0..2 (the MC3B's motors), U on channel 3.
fn rig() -> Rig {
    let def = GroupDef::new([0, 1, 2, 3, -1, -1, -1, -1], 0, 10_000).expect("group");
    let mut mac = default_mac_param();
    mac.dwPPR = 100;
    let axes = std::array::from_fn(|i| match def.channels[i] {
        Some(ch) => AxisMech::new(&mac, Some((0, ch.0))),
        None => AxisMech::new(&mac, None),
    });
    let mut g = GroupState::new(0, def, axes, 0.001);
    let (link, w) = worker();
    let x = Executor::new(link.clone(), g.axes());
    g.attach_external(Box::new(x));
    g.settings_mut().feed = 20.0;
    g.settings_mut().acc_ms = 20.0;
    g.settings_mut().dec_ms = 20.0;
    Rig { g, link, w }
}

impl Rig {
    fn line(&mut self, x: f64, y: f64) -> McclResult<i32> {
        let mut t = self.g.ctx().from;
        t[0] = x;
        t[1] = y;
        let cmd = self.g.ctx().line(t)?;
        self.g.enqueue(cmd)
    }

    fn circle(&mut self, cx: f64, cy: f64) -> McclResult<i32> {
        let from = self.g.ctx().from;
        let path = Path::circle(Plane::XY, &from, [cx, cy], true, None).expect("circle");
        let cmd = self
            .g
            .ctx()
            .curve(path, crate::engine::command::Curve::Arc)?;
        self.g.enqueue(cmd)
    }

    /// Ticks and runs the device until the group stops; returns the number of jobs.
    fn run(&mut self) -> usize {
        let mut jobs = 0;
        for _ in 0..100_000 {
            self.g.tick(0.001);
            if self.w.run_pending() {
                jobs += 1;
            } else if self.g.status() == c::GMS_STOP {
                return jobs;
            }
        }
        panic!("group never stopped (status {})", self.g.status());
    }

    fn pos(&self) -> [f64; 2] {
        let p = self.g.pos();
        [p[0], p[1]]
    }

    fn dev(&mut self) -> [i64; 3] {
        self.w.transport().pos()
    }

    fn ys(&mut self) -> Vec<String> {
        let t = self.w.transport();
        t.sent
            .iter()
            .filter(|s| s.starts_with("0Y"))
            .cloned()
            .collect()
    }
}

fn close(a: [f64; 2], b: [f64; 2]) -> bool {
    (a[0] - b[0]).abs() < 1e-9 && (a[1] - b[1]).abs() < 1e-9
}

#[test]
fn a_line_is_one_synchronous_move_and_its_position_is_confirmed() {
    let mut r = rig();
    assert_eq!(r.line(10.0, 5.0), Ok(0));
    r.g.tick(0.001);
    assert_eq!(r.g.status(), c::GMS_RUNNING);
    // The plan would be over after 0.58 s; the device has not confirmed anything: the
    // position stays where the move started, however long the engine runs.
    for _ in 0..5000 {
        r.g.tick(0.001);
    }
    assert_eq!(r.g.status(), c::GMS_RUNNING);
    assert!(close(r.pos(), [0.0, 0.0]), "{:?}", r.pos());
    assert!(r.w.run_pending());
    r.g.tick(0.001);
    assert_eq!(r.g.status(), c::GMS_STOP);
    assert!(close(r.pos(), [10.0, 5.0]), "{:?}", r.pos());
    assert_eq!(r.g.pulses(0), 1000);
    assert_eq!(r.dev(), [1000, 500, 0]);
    assert_eq!(r.ys(), ["0Y1000,0,500,0,0,0"]);
    // Feed 20 UU/s along (10, 5): X at 17.89 UU/s = 1789 steps/s, Y 894; 20 ms ramps.
    let t = r.w.transport();
    assert!(t.sent.contains(&"0V0,1789".to_string()), "{:?}", t.sent);
    assert!(t.sent.contains(&"0V1,894".to_string()));
    assert!(t.sent.contains(&"0A0,89450".to_string()));
}

#[test]
fn consecutive_lines_are_one_chained_batch() {
    let mut r = rig();
    for (x, y) in [(10.0, 0.0), (10.0, 10.0), (0.0, 10.0), (0.0, 0.0)] {
        r.line(x, y).expect("line");
    }
    assert_eq!(r.run(), 1, "one job");
    assert_eq!(
        r.ys(),
        [
            "0Y1000,0,0,0,0,0,0",
            "0Y0,0,1000,0,0,0,0",
            "0Y1000,1,0,0,0,0,0",
            "0Y0,0,1000,1,0,0,1"
        ]
    );
    assert_eq!(r.dev(), [0, 0, 0]);
    // Every side is along one axis: each runs at exactly the feed, 2000 steps/s.
    let t = r.w.transport();
    assert!(t.sent.contains(&"0V0,2000".to_string()));
    assert!(t.sent.contains(&"0V1,2000".to_string()));
}

#[test]
fn more_than_100_moves_split_into_batches() {
    let mut r = rig();
    // 250 lines: a staircase of 0.25 UU steps.
    let (mut x, mut y) = (0.0, 0.0);
    for i in 0..250 {
        if i % 2 == 0 {
            x += 0.25;
        } else {
            y += 0.25;
        }
        r.line(x, y).expect("line");
    }
    assert_eq!(r.run(), 3, "100 + 100 + 50");
    let ys = r.ys();
    assert_eq!(ys.len(), 250);
    assert_eq!(ys.iter().filter(|s| s.ends_with(",1")).count(), 3);
    assert!(ys[99].ends_with(",1") && ys[199].ends_with(",1") && ys[249].ends_with(",1"));
    assert_eq!(r.dev(), [3125, 3125, 0]);
    assert!(close(r.pos(), [31.25, 31.25]));
    assert_eq!(r.g.queued(), 0);
}

/// The device's path: the step counts after every synchronous move sent.
fn corners(ys: &[String]) -> Vec<(f64, f64)> {
    let mut p = (0.0, 0.0);
    let mut out = vec![p];
    for y in ys {
        let v: Vec<i64> = y[2..]
            .split(',')
            .map(|f| f.parse().expect("number"))
            .collect();
        let sgn = |d: i64| if d == 0 { 1.0 } else { -1.0 };
        p.0 += v[0] as f64 * sgn(v[1]);
        p.1 += v[2] as f64 * sgn(v[3]);
        out.push(p);
    }
    out
}

/// Largest distance (steps) from the circle around `c` of radius `r` to the polyline.
fn deviation(pts: &[(f64, f64)], c: (f64, f64), r: f64) -> f64 {
    let mut worst = 0.0f64;
    for w in pts.windows(2) {
        for k in 0..=100 {
            let t = f64::from(k) / 100.0;
            let x = w[0].0 + (w[1].0 - w[0].0) * t - c.0;
            let y = w[0].1 + (w[1].1 - w[0].1) * t - c.1;
            worst = worst.max(((x * x + y * y).sqrt() - r).abs());
        }
    }
    worst
}

#[test]
fn a_circle_becomes_chords_within_the_tolerance() {
    let mut r = rig();
    r.circle(5.0, 0.0).expect("circle");
    assert_eq!(r.run(), 1);
    let ys = r.ys();
    // 1 step of sagitta on a radius of 500 steps: 50 chords.
    assert_eq!(ys.len(), chord_count(5.0, std::f64::consts::TAU, 0.01));
    assert_eq!(ys.len(), 50);
    let dev = deviation(&corners(&ys), (500.0, 0.0), 500.0);
    println!(
        "circle r=500 steps: {} chords, deviation {dev:.3} steps",
        ys.len()
    );
    assert!(dev <= 1.0 + 0.5 * std::f64::consts::SQRT_2, "{dev}");
    assert_eq!(r.dev(), [0, 0, 0], "a circle ends where it starts");
    // Chords run at the MC3B's fastest ramps.
    assert!(r.w.transport().sent.contains(&"0A0,100000".to_string()));
}

#[test]
fn a_large_circle_continues_over_several_batches() {
    let mut r = rig();
    // Radius 50 UU = 5000 steps: 158 chords, so 100 + 58.
    r.circle(50.0, 0.0).expect("circle");
    assert_eq!(r.g.queued(), 1);
    assert_eq!(r.run(), 2);
    let ys = r.ys();
    assert_eq!(ys.len(), chord_count(50.0, std::f64::consts::TAU, 0.01));
    assert!(ys.len() > 100);
    assert!(deviation(&corners(&ys), (5000.0, 0.0), 5000.0) <= 1.0 + 0.71);
    assert_eq!(r.dev(), [0, 0, 0]);
}

#[test]
fn point_to_point_moves_each_motor_independently() {
    let mut r = rig();
    let mut t = r.g.ctx().from;
    t[0] = 3.0;
    t[2] = -1.5;
    let cmd = r.g.ctx().ptp(t, 10.0, false).expect("ptp");
    r.g.enqueue(cmd).expect("enqueue");
    assert_eq!(r.run(), 1);
    let sent = r.w.transport().sent.clone();
    assert!(sent.contains(&"0M0,300,0".to_string()), "{sent:?}");
    assert!(sent.contains(&"0M2,150,1".to_string()));
    assert_eq!(r.dev(), [300, 0, -150]);
    // 10 % of 3000 rpm at 100 pulses/turn: 5 UU/s = 500 steps/s.
    assert!(sent.contains(&"0V0,500".to_string()));
}

#[test]
fn a_silent_device_stops_the_group_with_an_error_record() {
    let mut r = rig();
    let n = r.w.transport().sent.len();
    r.w.transport().mute_after = Some(n + 2);
    r.line(10.0, 0.0).expect("line");
    r.line(0.0, 0.0).expect("line");
    r.g.tick(0.001);
    // A command queued behind the job is dropped when it fails.
    r.line(5.0, 5.0).expect("line");
    assert!(r.w.run_pending());
    r.g.tick(0.001);
    assert_eq!(r.g.error(), ERR_MC3B_LINK);
    assert_eq!(r.g.status(), c::GMS_STOP);
    assert_eq!(r.g.queued(), 0);
    // Nothing moved (the device went silent while being configured).
    assert!(close(r.pos(), [0.0, 0.0]));
    // No command is taken until the error is cleared (as the vendor's library
    // answers: RUN_TIME_ERR), and nothing reaches the device.
    assert_eq!(r.line(1.0, 0.0), Err(McclError::RunTime));
    r.g.tick(0.001);
    assert!(!r.w.run_pending());
    assert_eq!(r.g.status(), c::GMS_STOP);
    r.w.transport().mute_after = None;
    r.g.clear_error();
    r.line(1.0, 0.0).expect("line");
    r.run();
    assert_eq!(r.dev(), [100, 0, 0]);
}

#[test]
fn a_stop_on_the_way_reports_the_estimated_position() {
    let mut r = rig();
    // Job 1 is asked to stop at the 8th status query (about 80 ms into the move).
    r.w.transport().stop_at_query = Some((8, r.link.clone(), 1));
    r.line(10.0, 0.0).expect("line");
    r.line(0.0, 0.0).expect("line");
    r.run();
    let dev = r.dev();
    assert!(dev[0] > 0 && dev[0] < 1000, "{dev:?}");
    assert!(
        close(r.pos(), [dev[0] as f64 / K, 0.0]),
        "{:?} {dev:?}",
        r.pos()
    );
    assert_eq!(r.g.error(), 0, "a requested stop is no error");
    assert_eq!(r.g.queued(), 0);
    // The next move starts from there.
    r.line(2.0, 0.0).expect("line");
    r.run();
    assert_eq!(r.dev(), [200, 0, 0]);
}

#[test]
fn abort_stops_the_device_and_waits_for_it() {
    let mut r = rig();
    r.line(10.0, 0.0).expect("line");
    r.g.tick(0.001);
    r.g.abort(0.5, false);
    assert_eq!(
        r.g.status(),
        c::GMS_RUNNING,
        "until the MC3B confirms the stop"
    );
    assert_eq!(r.line(1.0, 0.0), Err(McclError::AbortNotFinished));
    assert!(r.w.run_pending());
    r.g.tick(0.001);
    assert_eq!(r.g.status(), c::GMS_STOP);
    assert!(close(r.pos(), [0.0, 0.0]));
    assert_eq!(r.w.transport().count("0Y"), 0);
}

#[test]
fn what_the_mc3b_cannot_do_is_refused() {
    let mut r = rig();
    let blend = r.g.ctx().marker(Plan::Blend(true));
    assert_eq!(r.g.enqueue(blend), Err(McclError::NotAccepted));
    let inpos = r.g.ctx().marker(Plan::InPos(true, 1));
    assert_eq!(r.g.enqueue(inpos), Err(McclError::NotAccepted));
    let off = r.g.ctx().marker(Plan::Blend(false));
    assert!(
        r.g.enqueue(off).is_ok(),
        "switching blending off is harmless"
    );
    // U is on channel 3: the MC3B has no motor 3.
    let mut t = r.g.ctx().from;
    t[3] = 1.0;
    let cmd = r.g.ctx().line(t).expect("line");
    assert_eq!(r.g.enqueue(cmd), Err(McclError::Parameter));
    // More than 2^32 - 1 steps in one move.
    assert_eq!(r.line(5.0e7, 0.0), Err(McclError::Parameter));
    // Go home runs on the simulated machine, not on the MC3B: refused.
    assert_eq!(r.g.begin_homing(1), Err(McclError::NotAccepted));
    assert_eq!(r.g.homing(), 0);
    // Hold now: refused; hold at the end of the job: accepted.
    r.line(1.0, 0.0).expect("line");
    r.g.tick(0.001);
    assert_eq!(r.g.hold(false), Err(McclError::NotAccepted));
    assert!(r.g.is_external());
    assert!(r.g.external_busy());
}

#[test]
fn hold_at_block_end_holds_after_the_job() {
    let mut r = rig();
    r.line(1.0, 0.0).expect("line");
    r.g.tick(0.001);
    r.line(2.0, 0.0).expect("line");
    assert_eq!(r.g.hold(true), Ok(()));
    assert!(r.w.run_pending());
    for _ in 0..10 {
        r.g.tick(0.001);
    }
    assert_eq!(r.g.status(), c::GMS_HOLD);
    assert!(!r.w.run_pending(), "the held command is not sent");
    assert!(close(r.pos(), [1.0, 0.0]));
    assert_eq!(r.g.conti(), Ok(()));
    r.run();
    assert_eq!(r.dev(), [200, 0, 0]);
}

#[test]
fn software_over_travel_stops_before_the_move() {
    let mut r = rig();
    let mut axes = *r.g.axes();
    axes[0].high = 5.0;
    r.g.reset(axes);
    r.g.set_over_travel_check([true, false, false, false, false, false, false, false]);
    r.line(4.0, 0.0).expect("line");
    r.line(10.0, 0.0).expect("line");
    r.run();
    assert_eq!(r.g.error(), ERR_OVER_TRAVEL);
    assert_eq!(
        r.dev(),
        [400, 0, 0],
        "the first line ran, the second never left"
    );
}

#[test]
fn reset_makes_the_device_position_the_new_zero() {
    let mut r = rig();
    r.line(10.0, 5.0).expect("line");
    r.run();
    let axes = *r.g.axes();
    r.g.reset(axes);
    assert!(close(r.pos(), [0.0, 0.0]));
    assert!(r.g.is_external());
    r.line(1.0, 0.0).expect("line");
    r.run();
    assert_eq!(r.dev(), [1100, 500, 0]);
    assert!(close(r.pos(), [1.0, 0.0]));
}

#[test]
fn a_delay_waits_between_jobs() {
    let mut r = rig();
    r.line(1.0, 0.0).expect("line");
    let d = r.g.ctx().delay(50.0);
    r.g.enqueue(d).expect("delay");
    r.line(0.0, 0.0).expect("line");
    r.g.tick(0.001);
    assert!(r.w.run_pending());
    r.g.tick(0.001);
    assert_eq!(r.g.status(), c::GMS_DELAYING);
    let mut ticks = 1;
    while r.g.status() == c::GMS_DELAYING {
        r.g.tick(0.001);
        ticks += 1;
        assert!(ticks < 1000);
    }
    assert_eq!(ticks, 50);
    assert_eq!(r.ys().len(), 1, "the second line waits for the delay");
    r.run();
    assert_eq!(r.dev(), [0, 0, 0]);
    assert_eq!(r.ys().len(), 2);
}

/// Go home on the MC3B (modes 9 and 16): the group of `rig()` with X's motor given a −
/// limit switch on input 0 (active high) that the motor meets at or below -500 steps.
fn homing_rig() -> Rig {
    use crate::mc3b::backend::tests::worker_with;
    let mut r = rig();
    let mut rec = Rec::new();
    rec.switches.push((0, 0, -500));
    let (link, w) = worker_with(rec, &[[0, 0, 1, 0], [0; 4], [0; 4]]);
    let mut x = Executor::new(link.clone(), r.g.axes());
    x.set_limits(HOMING_LIMITS);
    r.g.attach_external(Box::new(x));
    r.link = link;
    r.w = w;
    r
}

fn home_cfg(mode: u16) -> crate::vendor::SYS_HOME_CONFIG {
    crate::vendor::SYS_HOME_CONFIG {
        wMode: mode,
        wDirection: 1,
        dfAccTime: 100.0,
        dfDecTime: 100.0,
        dfHighSpeed: 10.0,
        dfLowSpeed: 2.0,
        ..Default::default()
    }
}

const X_ONLY: [i32; 8] = [0, 255, 255, 255, 255, 255, 255, 255];

/// The limit switches of `homing_rig()`: X's motor has a − switch.
const HOMING_LIMITS: [[bool; 2]; MOTORS] = [[false, true], [false, false], [false, false]];

impl Rig {
    /// The jobs of a go home of `homing_rig()`'s group with `orders` and `cfgs`, with the
    /// axes mask and the motors homed (planned by an executor set up as the group's).
    #[allow(clippy::type_complexity)]
    fn plan_home(
        &self,
        orders: &[i32; AXES],
        cfgs: &[crate::vendor::SYS_HOME_CONFIG; AXES],
    ) -> McclResult<(u32, Vec<Job>, [bool; MOTORS])> {
        let mut x = Executor::new(self.link.clone(), self.g.axes());
        x.set_limits(HOMING_LIMITS);
        x.plan_home(orders, cfgs, self.g.axes())
    }

    /// Ticks and runs the device until the homing ends; its result.
    fn run_home(&mut self) -> i32 {
        for _ in 0..100_000 {
            self.g.tick(0.001);
            if let Some(r) = self.g.take_home_result() {
                self.g.end_homing();
                return r;
            }
            self.w.run_pending();
        }
        panic!("homing never ended");
    }
}

#[test]
fn go_home_uses_the_mc3b_homing_then_moves_to_the_working_home() {
    use crate::engine::homing::{HOME_DONE, HOME_NONE};
    let mut r = homing_rig();
    let mut cfgs = [home_cfg(9); 8];
    cfgs[0].dfOffset = 2.0;
    let (mask, stages, motors) = r.plan_home(&X_ONLY, &cfgs).expect("plan");
    // X (axis 0) homes in direction 1 at 10 UU/s = 1000 steps/s, reached in 100 ms;
    // then phase 3: 2 UU = 200 steps up at the same speed.
    assert_eq!((mask, motors), (1, [true, false, false]));
    let sp = backend::speeds_for(
        1000.0,
        Ramp::Times {
            acc_s: 0.1,
            dec_s: 0.1,
        },
    );
    assert_eq!(
        stages,
        [
            Job::Home {
                dirs: [Some(1), None, None],
                speeds: [Some(sp), None, None]
            },
            Job::Independent {
                steps: [200, 0, 0],
                speeds: [Some(sp), None, None]
            }
        ]
    );
    r.line(1.0, 1.0).expect("line");
    assert_eq!(
        r.g.begin_external_home(&X_ONLY, &cfgs),
        Err(McclError::NotFinished),
        "the group has motion to do"
    );
    r.run();
    r.g.begin_external_home(&X_ONLY, &cfgs).expect("home");
    assert_eq!(r.g.status(), c::GMS_RUNNING);
    assert_eq!(
        r.line(5.0, 0.0),
        Err(McclError::NotAccepted),
        "no motion while homing"
    );
    assert_eq!(r.run_home(), HOME_DONE);
    // The MC3B ends its homing exactly on the switch's edge (-500, found at 10 steps/s),
    // the working home is 200 steps above: X reads 0 there, Y kept its position.
    assert_eq!(r.dev(), [-300, 100, 0]);
    assert!(close(r.pos(), [0.0, 1.0]), "{:?}", r.pos());
    assert_eq!(r.g.pulses(0), 0);
    assert_eq!(r.g.status(), c::GMS_STOP);
    assert_eq!(r.line(1.0, 1.0), Ok(1));
    r.run();
    assert_eq!(r.dev(), [-200, 100, 0]);
    assert_eq!(r.w.transport().count("0H"), 1);

    // MCC_AbortGoHome before the device took the job: nothing moves, nothing is zeroed.
    let mut r = homing_rig();
    r.g.begin_external_home(&X_ONLY, &cfgs).expect("home");
    r.g.tick(0.001);
    r.g.abort_external_home();
    assert_eq!(r.run_home(), HOME_NONE);
    assert_eq!((r.dev(), r.w.transport().count("0H")), ([0, 0, 0], 0));

    // A stop while it seeks (the switch is far: 1000 s away), as the abort asks for it,
    // at the job's 30th status query (about 300 ms of device time): the homing ends
    // without completing, with no error record and the position estimated.
    let mut r = homing_rig();
    r.w.transport().switches = vec![(0, 0, -1_000_000)];
    r.g.begin_external_home(&X_ONLY, &cfgs).expect("home");
    r.w.transport().stop_at_query = Some((30, r.link.clone(), 1));
    assert_eq!(r.run_home(), HOME_NONE);
    assert_eq!(r.g.error(), 0);
    let x = r.g.pos()[0];
    assert!(x < -1.0, "it had moved: estimate {x}");
    assert!(
        (x * K - r.dev()[0] as f64).abs() <= 1.0,
        "estimate {x} vs {:?}",
        r.dev()
    );
}

#[test]
fn go_home_refusals_on_the_mc3b() {
    let r = homing_rig();
    let ok = [home_cfg(16); 8];
    assert!(
        r.plan_home(&X_ONLY, &ok).is_ok(),
        "mode 16 is the same search"
    );
    for mode in [3, 4, 5, 6, 7, 8, 10, 11, 12, 13, 14, 15] {
        // The MC3B has no home sensor and no index input.
        let cfgs = [home_cfg(mode); 8];
        assert_eq!(
            r.plan_home(&X_ONLY, &cfgs).map(|_| ()),
            Err(McclError::NotAccepted),
            "mode {mode}"
        );
    }
    // X up: no + switch is set; Y: none at all; channel 3 (U) is not on the MC3B.
    let mut up = ok;
    up[0].wDirection = 0;
    assert_eq!(
        r.plan_home(&X_ONLY, &up).map(|_| ()),
        Err(McclError::NotAccepted)
    );
    let y = [255, 0, 255, 255, 255, 255, 255, 255];
    assert_eq!(
        r.plan_home(&y, &ok).map(|_| ()),
        Err(McclError::NotAccepted)
    );
    let u = [255, 255, 255, 0, 255, 255, 255, 255];
    assert_eq!(
        r.plan_home(&u, &ok).map(|_| ()),
        Err(McclError::NotAccepted)
    );
}

#[test]
fn a_move_stopped_by_a_limit_switch_records_0xf701() {
    let mut r = homing_rig();
    // X down to -10 UU (-1000 steps): the MC3B stops it on the switch at -500.
    r.line(-10.0, 0.0).expect("line");
    r.run();
    assert_eq!(r.g.error(), 0xF701, "axis X");
    assert_eq!(r.g.status(), c::GMS_STOP);
    assert!(r.dev()[0] <= -500 && r.dev()[0] > -520, "{:?}", r.dev());
}
