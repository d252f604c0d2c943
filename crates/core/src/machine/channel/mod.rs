//! One channel of the card and the motor, encoder and sensors behind it: what the
//! simulation configuration says about it, the parts it is made of, and its counters
//! (command, output, motor position, following error). Each part, and the channel's
//! behaviour that goes with it, is in a file below: stepping (the state every step reads
//! first), index pulses, sensors, encoder, compensation, deferred steps, plant.

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
use stepping::StepState;

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

/// One channel of the card and the motor, encoder and sensors behind it: its parts,
/// each with the methods that keep it whole, and the settings several of them read.
///
/// `repr(C)` with the parts every step reads and writes first, together (the step's
/// state, its index pulses, its deferred steps, its sensors, its compensation), and the
/// settings only setters and status calls read after them.
#[derive(Debug, Clone)]
#[repr(C)]
pub struct Channel {
    /// Command, output, motor and whether the coming step is made, and how.
    step: StepState,
    /// The index pulses of the last step and the grid they lie on.
    index: IndexPulses,
    /// Steps recorded and not yet made ([`deferred`](super::deferred)).
    deferred: Deferred,
    /// The home sensor and limit switches.
    sensors: Sensors,
    /// Gap compensation.
    comp: GapCompensation,
    /// Simulation configuration.
    spec: ChannelSpec,
    /// Mechanism parameters.
    mac: SYS_MAC_PARAM,
    /// The encoder that follows the motor.
    encoder: Encoder,
    /// Most pulses per interpolation period (`MCC_SetMaxPulseSpeed`).
    max_speed: i32,
    /// Most change of pulses per period between periods (`MCC_SetMaxPulseAcc`).
    max_acc: i32,
}

impl Channel {
    /// A channel at position 0.
    pub fn new(spec: ChannelSpec, mac: SYS_MAC_PARAM, enc: SYS_ENCODER_CONFIG) -> Channel {
        let mut ch = Channel {
            step: StepState::AT_ZERO,
            index: IndexPulses::NONE,
            deferred: Deferred::NONE,
            sensors: Sensors::default(),
            comp: GapCompensation::off(),
            spec,
            mac,
            encoder: Encoder::new(enc),
            max_speed: DEFAULT_PULSE_LIMIT,
            max_acc: DEFAULT_PULSE_LIMIT,
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
            self.step.machine_pulses() / f
        }
    }

    /// `MCC_ResetMotion`/`MCC_UpdateParam`: the command counter restarts from 0 where the
    /// motor stands; the motor, its encoder count and the sensors do not move.
    pub fn rezero(&mut self) {
        let count = self.encoder();
        self.restart_counter(self.step.actual(), count);
    }

    /// The command counter restarts from 0 `shift` pulses up the motor's frame (the
    /// motor, its sensors and its machine position do not move); the encoder then reads
    /// `count` and compensation starts again from its home point.
    pub(super) fn restart_counter(&mut self, shift: f64, count: i64) {
        self.step.restart(shift);
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
        self.restart_counter(self.step.out() as f64, 0);
    }

    /// The motor's position in pulses.
    pub fn actual_pulses(&self) -> f64 {
        self.assert_up_to_date();
        self.step.actual()
    }

    /// Pulses output so far (command + compensation).
    pub fn output_pulses(&self) -> i64 {
        self.step.out()
    }

    /// Pulses commanded (without compensation).
    pub fn command_pulses(&self) -> i64 {
        self.assert_up_to_date();
        self.step.cmd()
    }

    /// Following error in pulses: output − motor (what `MCC_GetErrorCount` reports).
    pub fn error_count(&self) -> i64 {
        self.assert_up_to_date();
        self.step.following_error()
    }

    /// Pulses output in the last tick, and the change from the tick before (per-period
    /// pulse speed and acceleration).
    pub fn pulse_rate(&self) -> (i64, i64) {
        self.assert_up_to_date();
        self.step.pulse_rate()
    }

    /// Tests: whether the last step changed nothing and another with the same command
    /// would change nothing either (the coming step is skipped).
    #[cfg(test)]
    pub(in crate::machine) fn resting(&self) -> bool {
        self.step.resting()
    }

    /// New mechanism and encoder parameters (`MCC_UpdateParam`).
    pub fn set_params(&mut self, mac: SYS_MAC_PARAM, enc: SYS_ENCODER_CONFIG) {
        self.assert_up_to_date();
        let motor = self.step.machine_pulses();
        self.mac = mac;
        self.refresh_grid();
        self.encoder.configure(enc, motor);
        self.update_sensors();
    }
}
