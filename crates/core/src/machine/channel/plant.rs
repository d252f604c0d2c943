//! A channel's plant (an ideal motor or a first-order lag) and whether the channel is
//! ideal, which decides how it steps.

use crate::machine::Channel;

impl Channel {
    /// Recomputes [`Channel::ideal`] after the compensation, the plant or the sensors
    /// changed.
    pub(in crate::machine) fn refresh_ideal(&mut self) {
        self.ideal = self.ideal_now();
    }

    /// What [`Channel::ideal`] should be.
    pub(in crate::machine) fn ideal_now(&self) -> bool {
        !self.comp.active() && !self.lags() && !self.sensors.any()
    }

    /// Tests: whether the channel is ideal, as its steps read it (kept up to date by
    /// [`Channel::refresh_ideal`]).
    #[cfg(test)]
    pub(in crate::machine) fn ideal(&self) -> bool {
        self.ideal
    }

    /// Whether the plant is a first-order lag (a positive time constant).
    fn lags(&self) -> bool {
        matches!(self.spec.lag_s, Some(tau) if tau > 0.0)
    }

    /// The plant: a first-order lag of `lag_s` seconds, or ideal (`None`) — what a
    /// `[plant]` table of the simulation configuration sets.
    pub fn set_plant_lag(&mut self, lag_s: Option<f64>) {
        self.resting = false;
        self.spec.lag_s = lag_s;
        self.refresh_ideal();
    }
}
