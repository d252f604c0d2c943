//! What a group does with its interpolated positions before they leave the card: the
//! after-interpolation filters (`MCC_EnableAccDecAfterIPO`, `MCC_EnableMovingAverage`)
//! and reverse interpolation (`MCC_SetReverseInterpRoutine`, `MCC_EnableReverseInterp`).
//! docs/compatibility.md, "Filters, reverse interpolation, cycle routine", states the
//! behaviour; this is how it is built.
//!
//! A group that never used these functions has no [`Post`] (`GroupState::post` is
//! `None`) and ticks exactly as before. With one, [`GroupState::tick_post`] wraps the
//! usual tick:
//!
//! 1. Reverse interpolation: the decision the INTERP routine returned after the previous
//!    tick moves the group one period back along its recorded path (< 0), keeps it
//!    where it is (0), or forward (> 0): along the recorded path while behind its front,
//!    else the usual tick runs the commands. The commands' own time stands still while
//!    the group is behind the front or paused.
//! 2. The filters: the per-period increments of the raw (interpolated) position go
//!    through FIR stages; the output position is `raw − lag`, where `lag` sums what the
//!    raw position moved and the output did not yet. When every stage holds only zero
//!    increments the lag is exactly 0, so a motion ends exactly at its planned end.
//!
//! The raw position stays in `GroupState::pos` (everything that plans, stops or redefines
//! positions works on it); pulses, the published motion, the trace and the safety
//! checks read the output ([`GroupState::out_pos`], [`GroupState::out_vel`]).

use super::{GroupState, Mode};
use crate::config::AXES;
use crate::planner::Axes;
use std::collections::VecDeque;

/// Positions the moving average (`MCC_EnableMovingAverage`) averages: the current
/// interpolated position and the 4 before it (docs/compatibility.md says why 5).
pub const MOVING_AVERAGE_TAPS: usize = 5;

/// The longest after-interpolation acc/dec filter, in periods (a longer acc time is
/// refused by `MCC_EnableAccDecAfterIPO`): 100 s at 1 ms, its buffer 6.4 MB.
pub const MAX_FILTER_PERIODS: usize = 100_000;

/// Periods of executed path kept for reverse interpolation (10 s at 1 ms, 640 kB).
pub const REVERSE_HISTORY: usize = 10_000;

const ZERO: Axes = [0.0; AXES];

/// One FIR stage over the per-period increments of every axis: the mean of the last
/// `taps` increments (moving average), or with `half_ends` the trapezoidal mean (the
/// oldest and the newest weigh ½, the others 1, divided by `taps − 1`). A running sum
/// makes it O(1) a tick; the sum restarts at exactly 0 whenever the stage holds only
/// zeros, so rounding never outlives a standstill.
#[derive(Debug)]
struct Stage {
    half_ends: bool,
    div: f64,
    /// The last `taps` increments, oldest first.
    ring: VecDeque<Axes>,
    sum: Axes,
    /// Entries of `ring` with a non-zero component.
    nonzero: usize,
}

impl Stage {
    fn new(taps: usize, half_ends: bool) -> Stage {
        let div = if half_ends { taps - 1 } else { taps } as f64;
        Stage {
            half_ends,
            div,
            ring: std::iter::repeat_n(ZERO, taps).collect(),
            sum: ZERO,
            nonzero: 0,
        }
    }

    /// Whether every increment but the oldest (which made its last contribution in the
    /// last push) is zero: all that entered the stage has come out.
    fn passed(&self) -> bool {
        self.nonzero == 0 || (self.nonzero == 1 && self.ring.front().is_some_and(|f| *f != ZERO))
    }

    /// Takes this period's increment `d`, returns the stage's output increment.
    fn push(&mut self, d: Axes) -> Axes {
        let old = self.ring.pop_front().unwrap_or(ZERO);
        if old != ZERO {
            self.nonzero -= 1;
        }
        if d != ZERO {
            self.nonzero += 1;
        }
        self.ring.push_back(d);
        if self.nonzero == 0 {
            self.sum = ZERO;
            return ZERO;
        }
        let oldest = self.ring.front().copied().unwrap_or(ZERO);
        let mut out = ZERO;
        for i in 0..AXES {
            self.sum[i] += d[i] - old[i];
            let s = if self.half_ends {
                self.sum[i] - 0.5 * (d[i] + oldest[i])
            } else {
                self.sum[i]
            };
            out[i] = s / self.div;
        }
        out
    }
}

/// The after-interpolation filters of a group.
#[derive(Debug, Default)]
struct Filters {
    /// After-IPO acc/dec: the acc time in whole periods `L` (the stage has `L + 1` taps).
    acc_periods: Option<usize>,
    moving_average: bool,
    stages: Vec<Stage>,
    /// Raw position − output position.
    lag: Axes,
    /// Output velocity: the output's increment of the last period / the period.
    vel: Axes,
}

impl Filters {
    fn rebuild(&mut self) {
        self.stages.clear();
        if let Some(l) = self.acc_periods.filter(|&l| l > 0) {
            self.stages.push(Stage::new(l + 1, true));
        }
        if self.moving_average {
            self.stages.push(Stage::new(MOVING_AVERAGE_TAPS, false));
        }
        self.lag = ZERO;
        self.vel = ZERO;
    }

    /// Whether the output has arrived: in every stage only the oldest increment may be
    /// non-zero, as it has just made its last contribution.
    fn settled(&self) -> bool {
        self.stages.iter().all(Stage::passed)
    }

    fn step(&mut self, delta: Axes, dt: f64) {
        if self.stages.is_empty() {
            return;
        }
        let mut d = delta;
        for s in &mut self.stages {
            d = s.push(d);
        }
        if self.settled() {
            self.lag = ZERO;
            self.vel = ZERO;
            return;
        }
        for i in 0..AXES {
            self.lag[i] += delta[i] - d[i];
            self.vel[i] = if dt > 0.0 { d[i] / dt } else { 0.0 };
        }
    }
}

/// Reverse interpolation of a group.
#[derive(Debug, Default)]
struct Reverse {
    /// The INTERP routine's address (0: none).
    routine: usize,
    enabled: bool,
    /// Positions at the end of the last executed periods, oldest first; the last one is
    /// the front (where the commands stand).
    hist: VecDeque<Axes>,
    /// Where the group stands in `hist`.
    cursor: usize,
    /// The routine's decision for the next tick (> 0 forward, < 0 back, 0 pause).
    decision: i32,
    /// The arguments of the routine's call after this tick.
    due: Option<(i32, i32)>,
    /// The command counted by `ticks` and the periods it has executed.
    cmd: i32,
    ticks: i32,
}

impl Reverse {
    fn behind_front(&self) -> bool {
        self.cursor + 1 < self.hist.len()
    }

    /// Where the group stands becomes the front (a stop dropped the commands).
    fn truncate(&mut self) {
        self.hist.truncate(self.cursor + 1);
    }
}

/// The after-interpolation state of a group (see the module documentation).
#[derive(Debug, Default)]
pub struct Post {
    filters: Filters,
    reverse: Reverse,
}

impl Post {
    fn active(&self) -> bool {
        !self.filters.settled() || self.reverse.behind_front()
    }
}

impl GroupState {
    fn post_mut(&mut self) -> &mut Post {
        self.features.post.get_or_insert_with(Box::default)
    }

    /// `MCC_EnableAccDecAfterIPO` (`Some(L)`: acc/dec over `L` periods) and its
    /// `Disable` (`None`); the caller checked that the group stands still.
    pub fn set_acc_after_ipo(&mut self, periods: Option<usize>) {
        self.settings.acc_after_ipo = periods.is_some();
        let f = &mut self.post_mut().filters;
        f.acc_periods = periods;
        f.rebuild();
    }

    /// `MCC_EnableMovingAverage` / `Disable`; the caller checked that the group stands
    /// still.
    pub fn set_moving_average(&mut self, on: bool) {
        let f = &mut self.post_mut().filters;
        f.moving_average = on;
        f.rebuild();
    }

    /// `MCC_SetReverseInterpRoutine`: the routine's address (0: none).
    pub fn set_reverse_routine(&mut self, f: usize) {
        self.post_mut().reverse.routine = f;
    }

    /// `MCC_EnableReverseInterp`.
    pub fn enable_reverse(&mut self, on: bool) {
        let r = &mut self.post_mut().reverse;
        r.enabled = on;
        if !on {
            r.decision = 0;
        }
    }

    /// The INTERP call due after this tick: `(routine, group, command index, time
    /// index)`, taken (the engine thread makes it without any lock held).
    pub fn take_reverse_call(&mut self) -> Option<(usize, i32, i32, i32)> {
        let index = i32::try_from(self.index).unwrap_or(i32::MAX);
        let r = &mut self.features.post.as_mut()?.reverse;
        let (cmd, time) = r.due.take()?;
        (r.routine != 0).then_some((r.routine, index, cmd, time))
    }

    /// The INTERP routine's return value, applied at the next tick.
    pub fn set_reverse_decision(&mut self, decision: i32) {
        if let Some(p) = self.features.post.as_mut() {
            if p.reverse.enabled {
                p.reverse.decision = decision;
            }
        }
    }

    /// The filters between the reference and the output, when they have a stage.
    fn output_filters(&self) -> Option<&Filters> {
        self.features
            .post
            .as_ref()
            .map(|p| &p.filters)
            .filter(|f| !f.stages.is_empty())
    }

    /// The position the card outputs (the raw position after the filters).
    #[cold]
    #[inline(never)]
    pub(super) fn out_pos(&self) -> Axes {
        match self.output_filters() {
            Some(f) => std::array::from_fn(|i| self.exec.pos[i] - f.lag[i]),
            None => self.exec.pos,
        }
    }

    /// Whether the output position and velocity are the reference's (no filter stage):
    /// [`GroupState::out_pos`] and [`GroupState::out_vel`] are then `pos` and `vel`.
    pub(super) fn output_is_reference(&self) -> bool {
        self.output_filters().is_none()
    }

    /// The output velocity (see [`GroupState::out_pos`]).
    pub(super) fn out_vel(&self) -> Axes {
        match self.output_filters() {
            Some(f) => f.vel,
            None => self.exec.vel,
        }
    }

    /// The output feed speed: the period's path speed, or the filtered speeds' (see
    /// [`GroupState::out_pos`]).
    pub(super) fn out_feed(&self) -> f64 {
        match self.output_filters() {
            Some(f) => crate::planner::compose::composed_speed(&f.vel, self.settings.compose),
            None => self.exec.feed_now,
        }
    }

    /// Whether the output still moves after the commands (a filter settling, the group
    /// behind its path's front): the motion status stays running.
    pub(super) fn post_active(&self) -> bool {
        self.features.post.as_ref().is_some_and(|p| p.active())
    }

    /// A stop (`stop_here`): where the group stands becomes the front of its path.
    pub(super) fn post_stopped(&mut self) {
        if let Some(p) = self.features.post.as_mut() {
            p.reverse.truncate();
        }
    }

    /// The tick of a group with a [`Post`]: reverse interpolation, the usual tick, the
    /// filters (module documentation).
    #[cold]
    #[inline(never)]
    pub(super) fn tick_post(&mut self, dt: f64) {
        let Some(mut post) = self.features.post.take() else {
            return;
        };
        let before = self.exec.pos;
        if self.reverse_step(&mut post.reverse, before) {
            self.exec.vel = if dt > 0.0 {
                std::array::from_fn(|i| (self.exec.pos[i] - before[i]) / dt)
            } else {
                ZERO
            };
        } else {
            // The usual tick (`self.features.post` is None meanwhile, so it does not come back
            // here), then the front of the path moves on.
            self.tick(dt);
            let r = &mut post.reverse;
            let idle = self.exec.running.is_empty() && self.exec.pos == before;
            if r.enabled && idle {
                // Nothing executed: nothing to record (the front stays where it is).
            } else if r.enabled {
                r.hist.push_back(self.exec.pos);
                if r.hist.len() > REVERSE_HISTORY {
                    r.hist.pop_front();
                }
                r.cursor = r.hist.len() - 1;
                let cmd = self.exec.running.back().map_or(-1, |c| c.cmd.index);
                if cmd != r.cmd {
                    r.cmd = cmd;
                    r.ticks = 0;
                }
                r.ticks = r.ticks.saturating_add(1);
            } else {
                r.hist.clear();
                r.cursor = 0;
            }
        }
        let delta: Axes = std::array::from_fn(|i| self.exec.pos[i] - before[i]);
        post.filters.step(delta, dt);
        let r = &mut post.reverse;
        r.due =
            (r.enabled && r.routine != 0 && (!self.exec.running.is_empty() || r.behind_front()))
                .then_some((r.cmd, r.ticks));
        self.features.post = Some(post);
        self.update_status();
    }

    /// Step 1 of [`GroupState::tick_post`]: returns whether the group moved along its
    /// recorded path (or paused) instead of running its commands this tick.
    fn reverse_step(&mut self, r: &mut Reverse, before: Axes) -> bool {
        let decision = std::mem::replace(&mut r.decision, 1);
        if !r.behind_front() {
            if !r.enabled {
                return false;
            }
            // Positions changed outside the commands (MCC_DefinePos, a go home): the
            // recorded path starts again here.
            if r.hist.back() != Some(&before) {
                r.hist.clear();
                r.hist.push_back(before);
                r.cursor = 0;
            }
            // Reverse or pause only a group that runs its commands normally and has
            // something to reverse from.
            let running = !self.exec.running.is_empty() || r.hist.len() > 1;
            if decision > 0 || self.rate.mode != Mode::Normal || !running {
                return false;
            }
        } else if self.rate.mode == Mode::Aborting {
            // An abort behind the front stops where the group stands.
            self.stop_here();
            r.truncate();
            return true;
        } else if matches!(self.rate.mode, Mode::Held | Mode::HoldAtBlockEnd) {
            return true;
        }
        // Disabled behind the front: back to the front, then on with the commands.
        let d = if r.enabled { decision } else { 1 };
        if d < 0 {
            r.cursor = r.cursor.saturating_sub(1);
        } else if d > 0 {
            r.cursor = (r.cursor + 1).min(r.hist.len().saturating_sub(1));
        }
        if let Some(p) = r.hist.get(r.cursor) {
            self.exec.pos = *p;
        }
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn x(v: f64) -> Axes {
        let mut a = ZERO;
        a[0] = v;
        a
    }

    #[test]
    fn moving_average_of_a_step_of_speed() {
        // 5 taps: increments 1,1,1,... come out 1/5, 2/5, ..., 5/5.
        let mut s = Stage::new(5, false);
        let outs: Vec<f64> = (0..6).map(|_| s.push(x(1.0))[0]).collect();
        assert_eq!(outs, [0.2, 0.4, 0.6, 0.8, 1.0, 1.0]);
    }

    #[test]
    fn trapezoid_is_the_sampled_linear_ramp() {
        // L = 4 (5 taps, ends ½, / 4): a step of 1 per period comes out as the mean over
        // each period of a ramp 0 -> 1 in 4 periods: 1/8, 3/8, 5/8, 7/8, then 1.
        let mut s = Stage::new(5, true);
        let outs: Vec<f64> = (0..6).map(|_| s.push(x(1.0))[0]).collect();
        assert_eq!(outs, [0.125, 0.375, 0.625, 0.875, 1.0, 1.0]);
        // The stop mirrors it, and ends exactly at 0.
        let outs: Vec<f64> = (0..6).map(|_| s.push(ZERO)[0]).collect();
        assert_eq!(outs, [0.875, 0.625, 0.375, 0.125, 0.0, 0.0]);
        assert_eq!(s.nonzero, 0);
    }
}
