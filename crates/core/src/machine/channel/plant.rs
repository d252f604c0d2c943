//! A channel's plant (an ideal motor or a first-order lag) and whether the channel is
//! ideal, which decides how it steps.

use crate::machine::Channel;

impl Channel {
    /// Recomputes whether the channel is ideal after the compensation, the plant or the
    /// sensors changed.
    pub(in crate::machine) fn refresh_ideal(&mut self) {
        let ideal = self.ideal_now();
        self.step.set_ideal(ideal);
    }

    /// Whether the channel is ideal: an ideal motor (no plant lag) with no compensation
    /// and no sensor that follows it, whose step is [`Channel::step_ideal`].
    pub(in crate::machine) fn ideal_now(&self) -> bool {
        !self.comp.active() && !self.lags() && !self.sensors.any()
    }

    /// Tests: whether the channel is ideal, as its steps read it (kept up to date by
    /// [`Channel::refresh_ideal`]).
    #[cfg(test)]
    pub(in crate::machine) fn ideal(&self) -> bool {
        self.step.ideal()
    }

    /// Whether the plant is a first-order lag (a positive time constant).
    fn lags(&self) -> bool {
        matches!(self.spec.lag_s, Some(tau) if tau > 0.0)
    }

    /// The plant: a first-order lag of `lag_s` seconds, or ideal (`None`) — what a
    /// `[plant]` table of the simulation configuration sets.
    pub fn set_plant_lag(&mut self, lag_s: Option<f64>) {
        self.step.wake();
        self.spec.lag_s = lag_s;
        self.refresh_ideal();
    }
}
