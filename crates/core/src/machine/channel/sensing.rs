//! A channel's home sensor and limit switches: where they are, forcing them, the levels the card reads after the program's wiring setting, and the limit switch latches.

use crate::error::McclResult;
use crate::machine::{Channel, Sensor, SensorLevels};
use crate::vendor::consts as c;

impl Channel {
    /// Forces a sensor's physical level (`Some`) or lets the position decide (`None`).
    pub fn force(&mut self, s: Sensor, level: Option<bool>) {
        self.forced[s as usize] = level;
        self.refresh_sensors();
        self.update_sensors();
    }

    /// `MCCL_SimPlaceSensor`: [`Channel::place`], refused (`PARAMETER_ERR`, nothing
    /// changed) where the channel could never count to: `from` and `to` must be
    /// positions of the channel ([`crate::config::range::position`]).
    pub fn place_sensor(&mut self, s: Sensor, from: f64, to: f64) -> McclResult<()> {
        let f = self.factor();
        crate::config::range::position(from, f)?;
        crate::config::range::position(to, f)?;
        self.place(s, from, to);
        Ok(())
    }

    /// Moves a sensor: the home region, or a limit switch's position (`from`).
    pub fn place(&mut self, s: Sensor, from: f64, to: f64) {
        match s {
            Sensor::Home => self.spec.home = Some((from, to)),
            Sensor::LimitPlus => self.spec.limit_plus = Some(from),
            Sensor::LimitMinus => self.spec.limit_minus = Some(from),
        }
        self.refresh_sensors();
        self.update_sensors();
    }

    /// Sensor inputs after the program's wiring setting (NO/NC/unused).
    pub fn levels(&self) -> SensorLevels {
        self.levels
    }

    /// Limit switch `side` (0: +, 1: −) as the wiring setting reads it now.
    pub fn limit_switch(&self, side: usize) -> bool {
        if side == 0 {
            self.levels.plus
        } else {
            self.levels.minus
        }
    }

    /// Whether limit switch `side` has been active since its latch was last cleared.
    pub fn latched_limit(&self, side: usize) -> bool {
        self.latched[side]
    }

    /// Clears the latch of limit switch `side`; it latches again at once while the
    /// switch is active.
    pub fn clear_latched_limit(&mut self, side: usize) {
        self.latched[side] = self.limit_switch(side);
    }

    /// Sensor inputs of the previous step (for edge detection).
    pub fn prev_levels(&self) -> SensorLevels {
        self.assert_up_to_date();
        self.prev_levels
    }

    /// Physical level of a sensor: a normally-open switch closes (level high) when hit.
    pub fn raw_level(&self, s: Sensor) -> bool {
        self.raw[s as usize]
    }

    pub(in crate::machine) fn update_sensors(&mut self) {
        self.resting = false;
        let x = self.position();
        let hit = [
            self.spec.home.is_some_and(|(a, b)| x >= a && x <= b),
            self.spec.limit_plus.is_some_and(|p| x >= p),
            self.spec.limit_minus.is_some_and(|m| x <= m),
        ];
        for (i, h) in hit.into_iter().enumerate() {
            self.raw[i] = self.forced[i].unwrap_or(h);
        }
        // The program's wiring setting: NO reads the level, NC its inverse (a wrong
        // setting reads "active" while nothing is hit, as the manual describes).
        let wired = |level: bool, mode: u16| match mode {
            c::SL_NORMAL_OPEN => level,
            c::SL_NORMAL_CLOSE => !level,
            _ => false,
        };
        self.levels = SensorLevels {
            home: self.raw[0],
            plus: wired(self.raw[1], self.mac.wOverTravelUpSensorMode),
            minus: wired(self.raw[2], self.mac.wOverTravelDownSensorMode),
        };
        if self.levels.plus {
            self.latched[0] = true;
        }
        if self.levels.minus {
            self.latched[1] = true;
        }
    }

    /// The home sensor as the card reads it with the go-home wiring `mode`: the input is
    /// high while a normally-open contact is hit (low for a normally-closed one,
    /// `home_contact = "nc"`); `SL_NORMAL_OPEN` reads high as active, `SL_NORMAL_CLOSE`
    /// low. A setting that does not match the contact reads active while nothing is hit.
    pub fn home_level(&self, mode: u16) -> bool {
        let input = self.raw[0] != self.spec.home_nc;
        match mode {
            c::SL_NORMAL_CLOSE => !input,
            _ => input,
        }
    }

    /// Recomputes [`Channel::sensors`] after a sensor was placed or forced.
    pub(in crate::machine) fn refresh_sensors(&mut self) {
        self.sensors = self.spec.home.is_some()
            || self.spec.limit_plus.is_some()
            || self.spec.limit_minus.is_some()
            || self.forced.iter().any(Option::is_some);
        self.refresh_ideal();
    }
}
