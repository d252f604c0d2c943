//! One channel of the card and the motor, encoder and sensors behind it: what the
//! simulation configuration says about it, its state, and its counters (command, output,
//! motor position, following error). The rest of its behaviour is in the files below:
//! encoder, sensors, index pulses, plant, compensation, stepping.

mod compensating;
mod deferring;
mod encoder;
mod index;
mod plant;
mod sensing;
mod stepping;

use super::deferred::Deferred;
use super::{PulseLimit, DEFAULT_PULSE_LIMIT};
use crate::vendor::{SYS_ENCODER_CONFIG, SYS_MAC_PARAM};
use compensating::GapCompensation;
use encoder::Encoder;
use index::IndexPulses;
use sensing::Sensors;

/// What the simulation configuration says about one channel.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ChannelSpec {
    /// Home sensor active region `[from, to]` (UU).
    pub home: Option<(f64, f64)>,
    /// + limit switch active at position >= this (UU).
    pub limit_plus: Option<f64>,
    /// − limit switch active at position <= this (UU).
    pub limit_minus: Option<f64>,
    /// Encoder counts (x4) between index pulses; `None`: one per motor turn (dwPPR).
    pub index_spacing: Option<u32>,
    /// Counts (x4) from 0 to the first index pulse.
    pub index_phase: u32,
    /// First-order lag time constant of the plant (s); `None`: ideal.
    pub lag_s: Option<f64>,
    /// The home sensor is a normally-closed contact: its input is low while hit.
    pub home_nc: bool,
}

impl ChannelSpec {
    /// The channel as the simulation configuration describes it.
    pub fn from_sim(c: &crate::sim::config::ChannelSim) -> ChannelSpec {
        ChannelSpec {
            home: c.home,
            limit_plus: c.limit_plus,
            limit_minus: c.limit_minus,
            index_spacing: c.index_spacing,
            index_phase: c.index_phase,
            lag_s: match c.plant {
                crate::sim::config::Plant::Ideal => None,
                crate::sim::config::Plant::Lag { tau_s } => Some(tau_s),
            },
            home_nc: c.home_nc,
        }
    }
}

/// One channel of the card and the motor, encoder and sensors behind it.
///
/// `repr(C)` with the fields every step reads and writes first, together, and the
/// settings only setters and status calls read after them.
#[derive(Debug, Clone)]
#[repr(C)]
pub struct Channel {
    /// Pulses the program commanded (before compensation).
    pub(super) cmd: i64,
    /// The command for the coming step: what [`Channel::command`] set during this tick
    /// (the group or homing driving the channel), else `cmd` (every step and counter
    /// restart sets both), so that a channel nobody commands holds.
    next: i64,
    /// The last step changed nothing, and another with the same command would change
    /// nothing either ([`Channel::step_commanded`] skips it). Cleared by whatever changes
    /// what a step reads: the counter's frame (`restart_counter`), the sensors
    /// (`update_sensors`, which placing, forcing and new parameters go through), the
    /// index grid (`set_grid`), the compensation and the plant.
    pub(super) resting: bool,
    /// The period of the step that found the channel resting.
    resting_dt: f64,
    /// An ideal motor (no plant lag) with no compensation and no sensor that follows it:
    /// a step is [`Channel::step_ideal`]. Kept by [`Channel::refresh_ideal`] wherever
    /// the compensation, the plant or the sensors change.
    pub(super) ideal: bool,
    /// Pulses output (command + compensation).
    pub(super) out: i64,
    pub(super) prev_out: i64,
    pub(super) prev_delta: i64,
    /// Motor position in pulses from where the command counter was last zeroed.
    pub(super) actual: f64,
    /// Motor position (pulses, machine coordinates) where the counter was last zeroed.
    base: f64,
    /// The index pulses of the last step and the grid they lie on.
    index: IndexPulses,
    /// Steps recorded and not yet made ([`deferred`](super::deferred)).
    pub(super) deferred: Deferred,
    /// The home sensor and limit switches.
    sensors: Sensors,
    /// Gap compensation.
    comp: GapCompensation,
    /// Simulation configuration.
    spec: ChannelSpec,
    mac: SYS_MAC_PARAM,
    /// The encoder that follows the motor.
    encoder: Encoder,
    /// Most pulses per interpolation period (`MCC_SetMaxPulseSpeed`).
    pub(crate) max_speed: i32,
    /// Most change of pulses per period between periods (`MCC_SetMaxPulseAcc`).
    pub(crate) max_acc: i32,
}

impl Channel {
    /// A channel at position 0.
    pub fn new(spec: ChannelSpec, mac: SYS_MAC_PARAM, enc: SYS_ENCODER_CONFIG) -> Channel {
        let mut ch = Channel {
            spec,
            mac,
            encoder: Encoder::new(enc),
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
            comp: GapCompensation::off(),
            index: IndexPulses::NONE,
            deferred: Deferred::NONE,
            max_speed: DEFAULT_PULSE_LIMIT,
            max_acc: DEFAULT_PULSE_LIMIT,
            sensors: Sensors::default(),
        };
        ch.refresh_grid();
        ch.refresh_sensors();
        ch.update_sensors();
        ch.sensors.without_edge();
        ch
    }

    /// Most pulses per interpolation period (`MCC_SetMaxPulseSpeed`).
    #[inline]
    pub fn max_speed(&self) -> i32 {
        self.max_speed
    }

    /// Most change of pulses per period between periods (`MCC_SetMaxPulseAcc`).
    #[inline]
    pub fn max_acc(&self) -> i32 {
        self.max_acc
    }

    /// Sets pulse limit `kind` (1..=[`MAX_PULSE_LIMIT`](super::MAX_PULSE_LIMIT), checked
    /// by the caller).
    pub(in crate::machine) fn set_pulse_limit(&mut self, kind: PulseLimit, x: i32) {
        match kind {
            PulseLimit::Speed => self.max_speed = x,
            PulseLimit::Acc => self.max_acc = x,
        }
    }

    /// Pulses per UU (signed: negative when wPosToEncoderDir reverses the output).
    pub fn factor(&self) -> f64 {
        let f = crate::config::conv_factor(&self.mac);
        if self.mac.wPosToEncoderDir != 0 {
            -f
        } else {
            f
        }
    }

    /// The motor's position in UU of the axis (machine coordinates).
    pub fn position(&self) -> f64 {
        self.assert_up_to_date();
        let f = self.factor();
        if f == 0.0 {
            0.0
        } else {
            (self.actual + self.base) / f
        }
    }

    /// `MCC_ResetMotion`/`MCC_UpdateParam`: the command counter restarts from 0 where the
    /// motor stands; the motor, its encoder count and the sensors do not move.
    pub fn rezero(&mut self) {
        let count = self.encoder();
        self.restart_counter(self.actual, count);
    }

    /// The command counter restarts from 0 `shift` pulses up the motor's frame (the
    /// motor, its sensors and its machine position do not move); the encoder then reads
    /// `count` and compensation starts again from its home point.
    pub(super) fn restart_counter(&mut self, shift: f64, count: i64) {
        self.resting = false;
        self.base += shift;
        self.actual -= shift;
        self.cmd = 0;
        self.next = 0;
        self.out = 0;
        self.prev_out = 0;
        self.prev_delta = 0;
        self.comp.restart();
        self.refresh_ideal();
        self.set_encoder(count);
        self.update_sensors();
    }

    /// Go home's end (user manual §2.8): the commanded position becomes the working home,
    /// pulse 0 of the command counter, and the encoder reads 0 there. The motor does not
    /// move (a lagging one keeps its following error); compensation restarts from its
    /// home point (`wHome_No`).
    pub fn home_here(&mut self) {
        self.restart_counter(self.out as f64, 0);
    }

    /// The motor's position in pulses.
    pub fn actual_pulses(&self) -> f64 {
        self.assert_up_to_date();
        self.actual
    }

    /// Pulses output so far (command + compensation).
    pub fn output_pulses(&self) -> i64 {
        self.out
    }

    /// Pulses commanded (without compensation).
    pub fn command_pulses(&self) -> i64 {
        self.assert_up_to_date();
        self.cmd
    }

    /// Following error in pulses: output − motor (what `MCC_GetErrorCount` reports).
    pub fn error_count(&self) -> i64 {
        self.assert_up_to_date();
        (self.out as f64 - self.actual).round() as i64
    }

    /// Pulses output in the last tick, and the change from the tick before (per-period
    /// pulse speed and acceleration).
    pub fn pulse_rate(&self) -> (i64, i64) {
        self.assert_up_to_date();
        let d = self.out - self.prev_out;
        (d, d - self.prev_delta)
    }

    /// Tests: whether the last step changed nothing and another with the same command
    /// would change nothing either (the coming step is skipped).
    #[cfg(test)]
    pub(in crate::machine) fn resting(&self) -> bool {
        self.resting
    }

    /// New mechanism and encoder parameters (`MCC_UpdateParam`).
    pub fn set_params(&mut self, mac: SYS_MAC_PARAM, enc: SYS_ENCODER_CONFIG) {
        self.assert_up_to_date();
        let motor = self.actual + self.base;
        self.mac = mac;
        self.refresh_grid();
        self.encoder.configure(enc, motor);
        self.update_sensors();
    }
}
