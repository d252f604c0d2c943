//! Stepping a channel: the command set during a tick, one interpolation period of the
//! motor, its encoder and sensors (the ideal fast step or the general one), and skipping
//! the steps of a channel at rest; and [`StepState`], what every step reads and writes
//! first.

use crate::machine::Channel;

/// What every step of a channel reads and writes first: the command (the last step's
/// and the coming one's), the output and its history (pulse speed and acceleration), the
/// motor's position and the frame of the command counter, and the two flags that decide
/// how the coming step goes (skipped at rest, the fast step when ideal).
///
/// `repr(C)`, first in [`Channel`]: the fields in the order a step reads them, together.
#[derive(Debug, Clone)]
#[repr(C)]
pub(super) struct StepState {
    /// Pulses the program commanded (before compensation).
    cmd: i64,
    /// The command for the coming step: what [`Channel::command`] set during this tick
    /// (the group or homing driving the channel), else `cmd` (every step and counter
    /// restart sets both), so that a channel nobody commands holds.
    next: i64,
    /// The last step changed nothing, and another with the same command would change
    /// nothing either ([`StepState::rests_at`]). Cleared ([`StepState::wake`]) by whatever
    /// changes what a step reads: the counter's frame (`restart`), the sensors
    /// (`Channel::update_sensors`, which placing, forcing and new parameters go
    /// through), the index grid (`Channel::set_grid`), the compensation and the plant.
    resting: bool,
    /// The period of the step that found the channel resting.
    resting_dt: f64,
    /// An ideal motor (no plant lag) with no compensation and no sensor that follows it:
    /// a step is [`Channel::step_ideal`]. The channel keeps it up to date wherever the
    /// compensation, the plant or the sensors change.
    ideal: bool,
    /// Pulses output (command + compensation).
    out: i64,
    /// The output of the step before.
    prev_out: i64,
    /// The change of the output in the step before.
    prev_delta: i64,
    /// Motor position in pulses from where the command counter was last zeroed.
    actual: f64,
    /// Motor position (pulses, machine coordinates) where the counter was last zeroed.
    base: f64,
}

impl StepState {
    /// A channel at pulse 0 of its machine frame, neither resting nor ideal yet (the
    /// channel decides both).
    pub(super) const AT_ZERO: StepState = StepState {
        cmd: 0,
        next: 0,
        resting: false,
        resting_dt: 0.0,
        ideal: false,
        out: 0,
        prev_out: 0,
        prev_delta: 0,
        actual: 0.0,
        base: 0.0,
    };

    /// Pulses the program commanded (before compensation).
    #[inline(always)]
    pub(super) fn cmd(&self) -> i64 {
        self.cmd
    }

    /// The command for the coming step.
    #[inline(always)]
    pub(super) fn next(&self) -> i64 {
        self.next
    }

    /// Sets the command for the coming step.
    #[inline(always)]
    pub(super) fn command(&mut self, pulses: i64) {
        self.next = pulses;
    }

    /// Pulses output (command + compensation).
    #[inline(always)]
    pub(super) fn out(&self) -> i64 {
        self.out
    }

    /// The output of the step before.
    #[inline(always)]
    pub(super) fn prev_out(&self) -> i64 {
        self.prev_out
    }

    /// Motor position in pulses from where the command counter was last zeroed.
    #[inline(always)]
    pub(super) fn actual(&self) -> f64 {
        self.actual
    }

    /// Motor position (pulses, machine coordinates) where the counter was last zeroed.
    #[inline(always)]
    pub(super) fn base(&self) -> f64 {
        self.base
    }

    /// Motor position in pulses of the machine frame.
    #[inline(always)]
    pub(super) fn machine_pulses(&self) -> f64 {
        self.actual + self.base
    }

    /// Whether the channel is ideal (its step is [`Channel::step_ideal`]).
    #[inline(always)]
    pub(super) fn ideal(&self) -> bool {
        self.ideal
    }

    /// Notes whether the channel is ideal.
    #[inline(always)]
    pub(super) fn set_ideal(&mut self, ideal: bool) {
        self.ideal = ideal;
    }

    /// Tests: whether the last step changed nothing and another with its command would
    /// change nothing either.
    #[cfg(test)]
    pub(super) fn resting(&self) -> bool {
        self.resting
    }

    /// Whether a step of `dt` to `cmd` would leave every field as it is: at rest, held
    /// at the command and period it came to rest with.
    #[inline(always)]
    pub(super) fn rests_at(&self, cmd: i64, dt: f64) -> bool {
        self.resting && cmd == self.cmd && dt == self.resting_dt
    }

    /// Something a step reads changed: the coming step is made.
    #[inline(always)]
    pub(super) fn wake(&mut self) {
        self.resting = false;
    }

    /// The start of every step: the output's history moves on one period and `cmd`
    /// becomes the command.
    #[inline(always)]
    pub(super) fn begin(&mut self, cmd: i64) {
        self.prev_delta = self.out - self.prev_out;
        self.prev_out = self.out;
        self.cmd = cmd;
        self.next = cmd;
    }

    /// The step's output.
    #[inline(always)]
    pub(super) fn output(&mut self, out: i64) {
        self.out = out;
    }

    /// The motor's position after the step (pulses from where the counter was zeroed).
    #[inline(always)]
    pub(super) fn move_motor(&mut self, actual: f64) {
        self.actual = actual;
    }

    /// Whether the output stood still for two steps (no pulse speed or acceleration).
    #[inline(always)]
    pub(super) fn output_still(&self) -> bool {
        self.out == self.prev_out && self.prev_delta == 0
    }

    /// The end of every step: whether the channel now rests, with the step's period.
    #[inline(always)]
    pub(super) fn end(&mut self, resting: bool, dt: f64) {
        self.resting = resting;
        // Read only while resting (`rests_at`): a moving channel skips the store.
        if resting {
            self.resting_dt = dt;
        }
    }

    /// Deferred steps brought up to date: the last output, and the two before it; the
    /// command and the motor are where the last output is (the next command stays).
    #[inline]
    pub(super) fn take_outputs(&mut self, last: i64, before: i64, before_that: i64) {
        self.out = last;
        self.prev_out = before;
        self.prev_delta = before - before_that;
        self.cmd = last;
        self.actual = last as f64;
    }

    /// The command counter restarts from 0 `shift` pulses up the motor's frame: the
    /// motor does not move, the command, output and its history are 0.
    pub(super) fn restart(&mut self, shift: f64) {
        self.resting = false;
        self.base += shift;
        self.actual -= shift;
        self.cmd = 0;
        self.next = 0;
        self.out = 0;
        self.prev_out = 0;
        self.prev_delta = 0;
    }

    /// Sets the motor where the output is.
    pub(super) fn settle(&mut self) {
        self.actual = self.out as f64;
    }

    /// Following error in pulses: output − motor.
    pub(super) fn following_error(&self) -> i64 {
        (self.out as f64 - self.actual).round() as i64
    }

    /// Pulses output in the last step, and the change from the step before.
    pub(super) fn pulse_rate(&self) -> (i64, i64) {
        let d = self.out - self.prev_out;
        (d, d - self.prev_delta)
    }
}

impl Channel {
    /// Debug builds: a reader of what the steps make finds no step deferred (the engine
    /// brings channels up to date before anything but its own tick can read them,
    /// [`deferred`](crate::machine::deferred)).
    #[inline(always)]
    pub(in crate::machine) fn assert_up_to_date(&self) {
        debug_assert!(!self.deferring(), "a channel read with its steps deferred");
    }

    /// Sets the pulses the coming [`Channel::step_commanded`] moves to (the last call in
    /// a tick wins).
    pub fn command(&mut self, pulses: i64) {
        self.step.command(pulses);
    }

    /// One step of `dt` seconds to the pulses set by [`Channel::command`] this tick, or
    /// holding the last command when none was set.
    ///
    /// A channel at rest (its last step changed nothing, and nothing a step reads has
    /// changed since) held at its command and period is not stepped: the step would
    /// leave every field as it is. Most channels of a machine stand still
    /// most of the time; this keeps a tick from touching them.
    #[inline]
    pub fn step_commanded(&mut self, dt: f64) {
        let cmd = self.step.next();
        if self.step.rests_at(cmd, dt) {
            return;
        }
        self.step(cmd, dt);
    }

    /// One interpolation period: the channel is commanded `cmd` pulses; the motor follows
    /// (ideal or lagging), the encoder and sensors follow the motor.
    #[inline]
    pub fn step(&mut self, cmd: i64, dt: f64) {
        debug_assert_eq!(self.step.ideal(), self.ideal_now(), "ideal is stale");
        if self.step.ideal() {
            self.step_ideal(cmd, dt);
        } else {
            self.step_general(cmd, dt);
        }
    }

    /// [`Channel::step`] of an ideal channel: the same fields written with the same
    /// values as [`Channel::step_general`] writes them when the output is the command,
    /// the motor is where the output is and no sensor follows the motor. Most channels
    /// of a running machine are such, and this is every tick's cost for each of them.
    #[inline]
    pub(in crate::machine) fn step_ideal(&mut self, cmd: i64, dt: f64) {
        self.begin_step(cmd);
        self.step.output(cmd);
        let before = self.step.actual();
        self.step.move_motor(cmd as f64);
        let base = self.step.base();
        self.index
            .count(before + base, self.step.actual() + base, base);
        self.end_step(dt, true);
    }

    /// [`Channel::step`] of any channel: compensation, a lagging plant, sensors.
    #[inline(never)]
    pub(in crate::machine) fn step_general(&mut self, cmd: i64, dt: f64) {
        self.begin_step(cmd);
        self.step.output(if self.comp.active() {
            cmd + self.comp.offset(cmd)
        } else {
            cmd
        });
        let before = self.step.actual();
        let target = self.step.out() as f64;
        self.step.move_motor(match self.spec.lag_s {
            Some(tau) if tau > 0.0 => target + (before - target) * (-dt / tau).exp(),
            _ => target,
        });
        let base = self.step.base();
        self.index
            .count(before + base, self.step.actual() + base, base);
        // Sensors only change with position if there are any (or one is forced).
        if self.sensors.any() {
            self.update_sensors();
        }
        self.end_step(dt, !self.comp.active());
    }

    /// The start of every step: the levels and the output's history move on one period
    /// (pulse speed and acceleration) and `cmd` becomes the command.
    #[inline(always)]
    pub(in crate::machine) fn begin_step(&mut self, cmd: i64) {
        self.sensors.begin_step();
        self.step.begin(cmd);
    }

    /// The end of every step, once the output, the motor, the index count and the levels
    /// are up to date: whether the channel now rests (`comp_still`: no compensation state
    /// follows the motion).
    ///
    /// Resting is a fixed point of `step` with this command and period: the output stood
    /// still for two steps (no pulse speed or acceleration), the motor did not move (the
    /// plant's next position depends only on this one, the command and the period; a lag
    /// ends on a fixed point of its floating-point iteration, which need not be the
    /// command), so no index pulse and the same sensor levels.
    #[inline(always)]
    pub(in crate::machine) fn end_step(&mut self, dt: f64, comp_still: bool) {
        self.sensors.end_step();
        let resting = comp_still
            && self.step.output_still()
            && self.index.stood_still()
            && self.sensors.unchanged();
        self.step.end(resting, dt);
    }

    /// Sets the motor where the command is (for a channel that is stopped and reset).
    pub fn settle(&mut self) {
        self.step.settle();
        self.update_sensors();
    }
}
