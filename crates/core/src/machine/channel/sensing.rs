//! A channel's home sensor and limit switches ([`Sensors`]): where they are, forcing
//! them, the levels the card reads after the program's wiring setting, and the limit
//! switch latches.

use super::ChannelSpec;
use crate::error::McclResult;
use crate::machine::{Channel, Sensor, SensorLevels};
use crate::vendor::consts as c;
use crate::vendor::SYS_MAC_PARAM;

/// A channel's sensors: their physical levels and what the card reads of them (now, at
/// the start and at the end of the last step), the levels forced, and the limit
/// switches' latches. The default: nothing hit, forced or latched (the channel reads its
/// levels at once).
///
/// `repr(C)`: the levels every step moves on and compares first, with the flag that
/// says whether they follow the motor at all.
#[derive(Debug, Clone, Default)]
#[repr(C)]
pub(super) struct Sensors {
    /// Sensor inputs after the program's wiring setting.
    levels: SensorLevels,
    /// `levels` at the start of the last step (for edge detection).
    prev_levels: SensorLevels,
    /// Levels at the end of the last step: a level forced between steps shows as an edge.
    step_levels: SensorLevels,
    /// Physical levels forced (`Some`) or left to the position (`None`), per [`Sensor`].
    forced: [Option<bool>; 3],
    /// Whether a sensor is placed or forced: only then do the levels follow the motor
    /// ([`Sensors::refresh_any`]).
    any: bool,
    /// Physical sensor levels (before the program's wiring setting), per [`Sensor`].
    raw: [bool; 3],
    /// Latched limit switch activity (`MCC_GetLatchedLimitSwitchStatus`): + and −.
    latched: [bool; 2],
}

impl Sensors {
    /// Sensor inputs after the program's wiring setting.
    #[inline(always)]
    pub(super) fn levels(&self) -> SensorLevels {
        self.levels
    }

    /// Sensor inputs at the start of the last step.
    #[inline]
    pub(super) fn prev_levels(&self) -> SensorLevels {
        self.prev_levels
    }

    /// Levels at the end of the last step.
    #[inline]
    pub(super) fn step_levels(&self) -> SensorLevels {
        self.step_levels
    }

    /// Whether a sensor is placed or forced (the levels follow the motor).
    #[inline(always)]
    pub(super) fn any(&self) -> bool {
        self.any
    }

    /// Recomputes [`Sensors::any`] after a sensor was placed or forced.
    pub(super) fn refresh_any(&mut self, spec: &ChannelSpec) {
        self.any = spec.home.is_some()
            || spec.limit_plus.is_some()
            || spec.limit_minus.is_some()
            || self.forced.iter().any(Option::is_some);
    }

    /// Forces a sensor's physical level (`Some`) or lets the position decide (`None`).
    pub(super) fn force(&mut self, s: Sensor, level: Option<bool>) {
        self.forced[s as usize] = level;
    }

    /// The start of every step: the levels the last step ended with become the
    /// previous ones.
    #[inline(always)]
    pub(super) fn begin_step(&mut self) {
        self.prev_levels = self.step_levels;
    }

    /// The end of every step: the levels it ends with.
    #[inline(always)]
    pub(super) fn end_step(&mut self) {
        self.step_levels = self.levels;
    }

    /// Whether the levels at the end of the last step are those at its start.
    #[inline(always)]
    pub(super) fn unchanged(&self) -> bool {
        self.prev_levels == self.step_levels
    }

    /// The previous levels of deferred steps brought up to date: `first`, the levels
    /// before the first of them, when there was one step; otherwise the levels (which no
    /// deferred step changes).
    #[inline]
    pub(super) fn catch_up(&mut self, first: Option<SensorLevels>) {
        self.prev_levels = first.unwrap_or(self.levels);
    }

    /// The levels now stand for the levels before and at the end of the last step: no
    /// edge shows at the next.
    pub(super) fn without_edge(&mut self) {
        self.prev_levels = self.levels;
        self.step_levels = self.levels;
    }

    /// Limit switch `side` (0: +, 1: −) as the wiring setting reads it now.
    pub(super) fn limit_switch(&self, side: usize) -> bool {
        if side == 0 {
            self.levels.plus
        } else {
            self.levels.minus
        }
    }

    /// Whether limit switch `side` has been active since its latch was last cleared.
    pub(super) fn latched(&self, side: usize) -> bool {
        self.latched[side]
    }

    /// Clears the latch of limit switch `side`; it latches again at once while the
    /// switch is active.
    pub(super) fn clear_latched(&mut self, side: usize) {
        self.latched[side] = self.limit_switch(side);
    }

    /// Physical level of a sensor.
    pub(super) fn raw(&self, s: Sensor) -> bool {
        self.raw[s as usize]
    }

    /// The levels of a motor at `x` (UU, machine coordinates), with the sensors where
    /// `spec` places them and the wiring `mac` sets; an active limit switch latches.
    pub(super) fn update(&mut self, x: f64, spec: &ChannelSpec, mac: &SYS_MAC_PARAM) {
        let hit = [
            spec.home.is_some_and(|(a, b)| x >= a && x <= b),
            spec.limit_plus.is_some_and(|p| x >= p),
            spec.limit_minus.is_some_and(|m| x <= m),
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
            plus: wired(self.raw[1], mac.wOverTravelUpSensorMode),
            minus: wired(self.raw[2], mac.wOverTravelDownSensorMode),
        };
        if self.levels.plus {
            self.latched[0] = true;
        }
        if self.levels.minus {
            self.latched[1] = true;
        }
    }
}

impl Channel {
    /// Forces a sensor's physical level (`Some`) or lets the position decide (`None`).
    pub fn force(&mut self, s: Sensor, level: Option<bool>) {
        self.sensors.force(s, level);
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
        self.sensors.levels()
    }

    /// Limit switch `side` (0: +, 1: −) as the wiring setting reads it now.
    pub fn limit_switch(&self, side: usize) -> bool {
        self.sensors.limit_switch(side)
    }

    /// Whether limit switch `side` has been active since its latch was last cleared.
    pub fn latched_limit(&self, side: usize) -> bool {
        self.sensors.latched(side)
    }

    /// Clears the latch of limit switch `side`; it latches again at once while the
    /// switch is active.
    pub fn clear_latched_limit(&mut self, side: usize) {
        self.sensors.clear_latched(side);
    }

    /// Sensor inputs of the previous step (for edge detection).
    pub fn prev_levels(&self) -> SensorLevels {
        self.assert_up_to_date();
        self.sensors.prev_levels()
    }

    /// Physical level of a sensor: a normally-open switch closes (level high) when hit.
    pub fn raw_level(&self, s: Sensor) -> bool {
        self.sensors.raw(s)
    }

    /// The levels where the motor is now.
    pub(in crate::machine) fn update_sensors(&mut self) {
        self.step.wake();
        let x = self.position();
        self.sensors.update(x, &self.spec, &self.mac);
    }

    /// The home sensor as the card reads it with the go-home wiring `mode`: the input is
    /// high while a normally-open contact is hit (low for a normally-closed one,
    /// `home_contact = "nc"`); `SL_NORMAL_OPEN` reads high as active, `SL_NORMAL_CLOSE`
    /// low. A setting that does not match the contact reads active while nothing is hit.
    pub fn home_level(&self, mode: u16) -> bool {
        let input = self.sensors.raw(Sensor::Home) != self.spec.home_nc;
        match mode {
            c::SL_NORMAL_CLOSE => !input,
            _ => input,
        }
    }

    /// Recomputes whether the levels follow the motor after a sensor was placed or
    /// forced.
    pub(in crate::machine) fn refresh_sensors(&mut self) {
        self.sensors.refresh_any(&self.spec);
        self.refresh_ideal();
    }
}
