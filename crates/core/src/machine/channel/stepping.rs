//! Stepping a channel: the command set during a tick, one interpolation period of the
//! motor, its encoder and sensors (the ideal fast step or the general one), and skipping
//! the steps of a channel at rest.

use crate::machine::Channel;

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
        self.next = pulses;
    }

    /// One step of `dt` seconds to the pulses set by [`Channel::command`] this tick, or
    /// holding the last command when none was set.
    ///
    /// A channel at rest (see `resting`) held at its command is not stepped: the step
    /// would leave every field as it is. Most channels of a machine stand still most of
    /// the time; this keeps a tick from touching them.
    #[inline]
    pub fn step_commanded(&mut self, dt: f64) {
        let cmd = self.next;
        if self.resting && cmd == self.cmd && dt == self.resting_dt {
            return;
        }
        self.step(cmd, dt);
    }

    /// One interpolation period: the channel is commanded `cmd` pulses; the motor follows
    /// (ideal or lagging), the encoder and sensors follow the motor.
    #[inline]
    pub fn step(&mut self, cmd: i64, dt: f64) {
        debug_assert_eq!(self.ideal, self.ideal_now(), "Channel::ideal is stale");
        if self.ideal {
            self.step_ideal(cmd, dt);
        } else {
            self.step_general(cmd, dt);
        }
    }

    /// [`Channel::step`] of an ideal channel ([`Channel::ideal`]): the same fields
    /// written with the same values as [`Channel::step_general`] writes them when the
    /// output is the command, the motor is where the output is and no sensor follows
    /// the motor. Most channels of a running machine are such, and this is every tick's
    /// cost for each of them.
    #[inline]
    pub(in crate::machine) fn step_ideal(&mut self, cmd: i64, dt: f64) {
        self.begin_step(cmd);
        self.out = cmd;
        let before = self.actual;
        self.actual = cmd as f64;
        let base = self.base;
        self.index.count(before + base, self.actual + base, base);
        self.end_step(dt, true);
    }

    /// [`Channel::step`] of any channel: compensation, a lagging plant, sensors.
    #[inline(never)]
    pub(in crate::machine) fn step_general(&mut self, cmd: i64, dt: f64) {
        self.begin_step(cmd);
        self.out = if self.comp.active() {
            cmd + self.comp.offset(cmd)
        } else {
            cmd
        };
        let before = self.actual;
        let target = self.out as f64;
        self.actual = match self.spec.lag_s {
            Some(tau) if tau > 0.0 => target + (self.actual - target) * (-dt / tau).exp(),
            _ => target,
        };
        let base = self.base;
        self.index.count(before + base, self.actual + base, base);
        // Sensors only change with position if there are any (or one is forced).
        if self.sensors.any() {
            self.update_sensors();
        }
        self.end_step(dt, !self.comp.active());
    }

    /// The start of every step: the output's history moves on one period (pulse speed
    /// and acceleration) and `cmd` becomes the command.
    #[inline(always)]
    pub(in crate::machine) fn begin_step(&mut self, cmd: i64) {
        self.sensors.begin_step();
        self.prev_delta = self.out - self.prev_out;
        self.prev_out = self.out;
        self.cmd = cmd;
        self.next = cmd;
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
        self.resting = comp_still
            && self.out == self.prev_out
            && self.prev_delta == 0
            && self.index.stood_still()
            && self.sensors.unchanged();
        // Read only while resting (`step_commanded`): a moving channel skips the store.
        if self.resting {
            self.resting_dt = dt;
        }
    }

    /// Sets the motor where the command is (for a channel that is stopped and reset).
    pub fn settle(&mut self) {
        self.actual = self.out as f64;
        self.update_sensors();
    }
}
