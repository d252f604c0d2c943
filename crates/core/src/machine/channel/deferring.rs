//! A channel's deferred steps (`machine::deferred`): recording a step instead of making it, and catching up.

use crate::machine::deferred::{slot, Deferred, DeferredSteps, OutputWindow};
use crate::machine::index_pulses::CELL_LIMIT;
use crate::machine::Channel;

impl Channel {
    /// [`Channel::step_commanded`] of a channel on a card that defers, at the engine's
    /// tick `n`: an ideal channel records the step, any other steps. Returns whether it
    /// stepped (only then can it have passed an index pulse this tick: a channel
    /// deferring or at rest has none).
    #[inline]
    pub fn step_or_defer(&mut self, dt: f64, n: u64) -> bool {
        // (The steps of a run are consecutive: `Machine::set_deferred` asserts it.)
        if self.step.ideal() {
            self.defer_step(dt, n);
            false
        } else {
            self.step_commanded(dt);
            true
        }
    }

    /// Whether [`Channel::step_or_defer`] of `dt` would change nothing as long as its
    /// command stays: an ideal channel not deferring, at rest at its command.
    #[inline]
    pub fn stays_at_rest(&self, dt: f64) -> bool {
        self.step.ideal() && !self.deferred.active && self.step.rests_at(self.step.next(), dt)
    }

    /// Records a step of `dt` to the command set this tick instead of making it (a channel
    /// at rest held at its command records nothing, as it would not step). Nothing of
    /// the channel moves on: its output, command and motor follow the recorded steps
    /// when it is brought up to date.
    #[inline]
    fn defer_step(&mut self, dt: f64, n: u64) {
        if !self.deferred.active {
            if self.step.rests_at(self.step.next(), dt) {
                return;
            }
            self.begin_deferring(n);
        }
        self.record(n);
    }

    /// Before the first deferred step, `n`: what the steps before it left (the two
    /// outputs before it, in the slots of the two steps before it). The index pulses of
    /// the last step made were counted by the tick that made it. Out of line: inlined,
    /// its slots were worked out ahead of every tick's recording loop.
    #[inline(never)]
    fn begin_deferring(&mut self, n: u64) {
        let mut outputs = [0; 4];
        outputs[slot(n.wrapping_sub(1))] = self.step.out();
        outputs[slot(n.wrapping_sub(2))] = self.step.prev_out();
        let start = self.step.actual();
        let window = self.start_window(start);
        self.deferred = Deferred {
            active: true,
            first: n,
            outputs,
            window,
            passed: false,
            start,
            step_levels: self.sensors.step_levels(),
        };
        self.index.clear_events();
        self.step.wake();
    }

    /// [`Channel::step_or_defer`] of a channel known to record its steps (an ideal
    /// channel with steps deferred since it was last brought up to date, see
    /// [`Recording`](crate::machine::deferred::Recording)): the step recorded without asking.
    #[inline]
    pub fn record_step(&mut self, n: u64) {
        debug_assert!(
            self.step.ideal() && self.deferring(),
            "record_step: not recording"
        );
        self.record(n);
    }

    /// Records this tick's command as deferred step `n`.
    #[inline]
    fn record(&mut self, n: u64) {
        let cmd = self.step.next();
        let d = &mut self.deferred;
        d.outputs[slot(n)] = cmd;
        if !d.window.holds(cmd) {
            self.look_outside_window(cmd);
        }
    }

    /// The outputs that lie, with the channel's frame (`base`), in the index interval of
    /// motor position `start`, two pulses short of its ends (so that the rounding of
    /// `output + base` cannot carry an output of the window out of the interval); none
    /// when the interval's bounds are not exact or too far out to subtract exactly.
    fn start_window(&mut self, start: f64) -> OutputWindow {
        let base = self.step.base();
        self.index.interval(start + base);
        let cell = self.index.cell();
        let (lo, hi) = (cell.lo - base, cell.hi - base);
        let limit = CELL_LIMIT as f64;
        // (The cell of no interval has its bounds the wrong way round.)
        if !(lo > -limit && hi < limit && lo < hi) {
            return OutputWindow::NONE;
        }
        // Whole numbers below 2^52 in magnitude: exact as i64.
        let first = lo.ceil() as i64 + 2;
        let last = hi.floor() as i64 - 2;
        OutputWindow::new(first, last)
    }

    /// A recorded output outside the window: whether it lies in another index interval
    /// than the run's start, looked up. Once one does, the run has passed an index pulse
    /// and no later output need be looked at (the window then holds every output but
    /// `i64::MAX`, which is looked at again and changes nothing). Out of line: a motor
    /// turn of steps records between two calls.
    #[inline(never)]
    fn look_outside_window(&mut self, out: i64) {
        if self.deferred.passed {
            return;
        }
        let base = self.step.base();
        let start = self.index.interval(self.deferred.start + base);
        if self.index.interval(out as f64 + base) != start {
            self.deferred.passed = true;
            self.deferred.window = OutputWindow::ALL;
        }
    }

    /// Whether steps are deferred.
    pub fn deferring(&self) -> bool {
        self.deferred.active
    }

    /// Tests: forgets what only deferring keeps and the last index count (kept only for
    /// the step that passed it), so that two channels compare by what their steps left.
    #[cfg(test)]
    pub(in crate::machine) fn forget_deferring(&mut self) {
        self.deferred = Deferred::NONE;
        self.index.forget_last_count();
    }

    /// Brings a channel with deferred steps up to date (`steps`: their period and the
    /// number of the last): every field as the steps would have left it (but the last
    /// index count of a pulse passed before the last step, see the module). Returns
    /// whether the deferred steps passed an index pulse.
    pub fn catch_up(&mut self, steps: DeferredSteps) -> bool {
        let DeferredSteps { dt, last } = steps;
        let d = self.deferred;
        if !d.active {
            return false;
        }
        self.deferred.active = false;
        // The last output and the two before it.
        let out = d.outputs[slot(last)];
        let history = (
            d.outputs[slot(last.wrapping_sub(1))],
            d.outputs[slot(last.wrapping_sub(2))],
        );
        let passed = d.passed;
        // The last step, from the state the one before it left (`begin_step`); the
        // output is the last step's already.
        let from = if last == d.first {
            self.sensors.catch_up(Some(d.step_levels));
            d.start
        } else {
            self.sensors.catch_up(None);
            history.0 as f64
        };
        self.step.take_outputs(out, history.0, history.1);
        let base = self.step.base();
        self.index
            .count(from + base, self.step.actual() + base, base);
        self.end_step(dt, true);
        passed
    }
}
