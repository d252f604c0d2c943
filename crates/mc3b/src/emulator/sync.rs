//! Synchronous moves (§6.12, §4.16) and the chains of them: every motor on one
//! normalized profile, so that all end together.

use std::collections::VecDeque;

use super::motor::{sign, step_pos};
use super::{Emulator, Profile, EPS, TICK_S};

/// One synchronous move: steps and direction of each motor.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct SyncSeg {
    pub(super) steps: [u32; 3],
    pub(super) dirs: [u8; 3],
}

/// The synchronous move under way and the rest of its chain.
#[derive(Debug, Clone)]
pub(super) struct SyncRun {
    pub(super) queue: VecDeque<SyncSeg>,
    pub(super) seg: SyncSeg,
    pub(super) start_tick: u64,
    pub(super) anchors: [f64; 3],
    /// Normalized profile (distance 1).
    pub(super) prof: Profile,
}

impl Emulator {
    pub(super) fn stop_sync(&mut self) {
        if let Some(s) = self.sync.take() {
            for (i, mo) in self.motors.iter_mut().enumerate() {
                let d = s.seg.dirs.get(i).copied().unwrap_or(0);
                mo.x = step_pos(mo.x, d);
                mo.energized = mo.settings.use_holding_current;
            }
        }
    }

    pub(super) fn start_sync(&mut self, queue: VecDeque<SyncSeg>) {
        for mo in &mut self.motors {
            mo.active = None;
            mo.x = mo.x.round();
            mo.energized = true;
        }
        let mut run = SyncRun {
            queue,
            seg: SyncSeg {
                steps: [0; 3],
                dirs: [0; 3],
            },
            start_tick: self.tick,
            anchors: [0.0; 3],
            prof: Profile::trapezoid(0.0, 1.0, 1.0, 1.0),
        };
        if self.next_sync_segment(&mut run) {
            self.sync = Some(run);
        } else {
            self.finish_sync();
        }
    }

    /// Load the next non-empty segment into `run`; false when none is left
    /// or the first one is blocked by an active home.
    fn next_sync_segment(&self, run: &mut SyncRun) -> bool {
        while let Some(seg) = run.queue.pop_front() {
            let moving: Vec<usize> = (0..3).filter(|&i| seg.steps[i] > 0).collect();
            if moving.is_empty() {
                continue;
            }
            if moving
                .iter()
                .any(|&i| Self::home_of(&self.motors[i].settings, self.inputs, seg.dirs[i]))
            {
                return false;
            }
            let (mut uv, mut ua, mut ud) = (f64::INFINITY, f64::INFINITY, f64::INFINITY);
            for &i in &moving {
                let s = &self.motors[i].settings;
                let n = f64::from(seg.steps[i]);
                uv = uv.min(f64::from(s.max_velocity) / n);
                ua = ua.min(f64::from(s.acceleration) / n);
                ud = ud.min(f64::from(s.deceleration) / n);
            }
            run.seg = seg;
            run.start_tick = self.tick;
            for i in 0..3 {
                run.anchors[i] = self.motors[i].x.round();
            }
            run.prof = Profile::trapezoid(1.0, ua, ud, uv);
            return true;
        }
        false
    }

    fn finish_sync(&mut self) {
        self.sync = None;
        for mo in &mut self.motors {
            mo.x = mo.x.round();
            mo.energized = mo.settings.use_holding_current;
        }
    }

    pub(super) fn tick_sync(&mut self) {
        let Some(mut run) = self.sync.take() else {
            return;
        };
        let t = (self.tick - run.start_tick) as f64 * TICK_S;
        let (u, _) = run.prof.eval(t);
        let done = t + EPS >= run.prof.duration();
        for i in 0..3 {
            let n = f64::from(run.seg.steps[i]);
            let frac = if done { 1.0 } else { u };
            self.motors[i].x = run.anchors[i] + sign(run.seg.dirs[i]) * n * frac;
        }
        // A home reached by any moving motor stops the whole move.
        let hit = (0..3).any(|i| {
            run.seg.steps[i] > 0
                && Self::home_of(&self.motors[i].settings, self.inputs, run.seg.dirs[i])
        });
        if hit {
            self.sync = Some(run);
            self.stop_sync();
            return;
        }
        if done {
            for i in 0..3 {
                self.motors[i].x = self.motors[i].x.round();
            }
            if self.next_sync_segment(&mut run) {
                self.sync = Some(run);
            } else {
                self.finish_sync();
            }
        } else {
            self.sync = Some(run);
        }
    }
}
