//! The group's rate (its time scale) and the commands that ramp it: override and feed
//! changes, fixed speed, hold and continue, abort, and stopping at once.

use super::GroupState;
use crate::config::AXES;
use crate::engine::command::Plan;
use crate::engine::trace::Note;
use crate::error::{McclError, McclResult};
use crate::planner::RateRamp;

/// What the group is doing besides running commands.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Mode {
    /// Running normally.
    Normal,
    /// `MCC_HoldMotion`: decelerating to, or standing at, rate 0.
    Held,
    /// `MCC_HoldMotion(g, TRUE)`: stop when the running command ends.
    HoldAtBlockEnd,
    /// `MCC_AbortMotionEx(t)`: ramping to rate 0; then everything is dropped.
    Aborting,
}

/// The group's rate: its time scale (1.0 = 100 %, 0 while held or after an abort), the
/// ramp it is changing by, and an override waiting for the next command.
#[derive(Debug, Clone, Copy)]
pub(super) struct RateState {
    /// The time scale now.
    pub(super) value: f64,
    /// The rate change in progress.
    pub(super) ramp: Option<Ramp>,
    /// Override to apply when the next command starts (`MCC_OverrideSpeedEx(r, FALSE)`).
    pub(super) pending_override: Option<f64>,
}

impl RateState {
    /// The rates the ramp in progress goes from and to (custom motion, `custom.rs`).
    pub(super) fn ramp_ends(&self) -> Option<(f64, f64)> {
        self.ramp.map(|r| (r.ramp.from_rate(), r.ramp.to_rate()))
    }
}

impl Default for RateState {
    fn default() -> Self {
        RateState {
            value: 1.0,
            ramp: None,
            pending_override: None,
        }
    }
}

/// A rate change in progress.
#[derive(Debug, Clone, Copy)]
pub(super) struct Ramp {
    ramp: RateRamp,
    elapsed: f64,
}

impl GroupState {
    /// `MCC_HoldMotion`: `HOLD_ILLEGAL_ERR` when nothing runs or it is already held.
    pub fn hold(&mut self, at_block_end: bool) -> McclResult<()> {
        if !self.busy() || self.mode != Mode::Normal {
            return Err(McclError::HoldIllegal);
        }
        // An MC3B cannot pause a synchronous move and resume it: only at a job's end.
        if self.external.is_some() && !at_block_end {
            return Err(McclError::NotAccepted);
        }
        self.note(Note::Hold {
            block_end: at_block_end,
        });
        if at_block_end {
            self.mode = Mode::HoldAtBlockEnd;
        } else {
            self.mode = Mode::Held;
            let t = self.current_dec_s();
            self.ramp_to(0.0, t);
        }
        self.update_status();
        Ok(())
    }

    /// `MCC_ContiMotion`: `CONTI_ILLEGAL_ERR` unless held.
    pub fn conti(&mut self) -> McclResult<()> {
        match self.mode {
            Mode::Held | Mode::HoldAtBlockEnd => {
                self.note(Note::Continue);
                self.mode = Mode::Normal;
                let target = self.target_rate();
                let t = self.current_acc_s();
                self.ramp_to(target, t);
                self.update_status();
                Ok(())
            }
            _ => Err(McclError::ContiIllegal),
        }
    }

    /// `MCC_AbortMotionEx(t)`: empties the queue and stops within `dec_s` seconds (at
    /// once when 0, or when already held: then the deceleration is ignored, §2.6.2 IV).
    /// With `at_block_end`, the running command finishes and the queue is dropped.
    pub fn abort(&mut self, dec_s: f64, at_block_end: bool) {
        // The MC3B stops at once (`S`); it has no controlled stop.
        let dec_s = if self.external.is_some() { 0.0 } else { dec_s };
        self.note(Note::Abort {
            dec_s,
            block_end: at_block_end,
        });
        self.clear_queue();
        self.rate.pending_override = None;
        if at_block_end {
            self.queue_end = self.running.back().map_or(self.pos, |r| r.cmd.target);
            self.update_status();
            return;
        }
        let held = matches!(self.mode, Mode::Held) && self.rate.value == 0.0;
        if dec_s <= 0.0 || held || self.running.is_empty() {
            self.stop_here();
        } else {
            self.mode = Mode::Aborting;
            self.ramp_to(0.0, dec_s);
        }
        self.update_status();
    }

    pub(super) fn stop_here(&mut self) {
        if let Some(x) = self.external.as_mut() {
            x.stop();
        }
        self.inpos_wait = None;
        self.note_stopped();
        self.running.clear();
        self.info_touched();
        self.clear_queue();
        self.post_stopped();
        self.base = self.pos;
        self.queue_end = self.pos;
        self.vel = [0.0; AXES];
        self.rate.ramp = None;
        self.mode = Mode::Normal;
        self.rate.value = self.target_rate();
    }

    /// `MCC_OverrideSpeedEx`: the new ratio applies now (ramped with the acc or dec
    /// time) or when the next command starts.
    pub fn override_speed(&mut self, pct: f64, instant: bool) {
        self.override_pct = pct;
        if instant {
            self.rate.pending_override = None;
            if self.mode == Mode::Normal || self.mode == Mode::HoldAtBlockEnd {
                self.retarget_rate();
            }
        } else {
            self.rate.pending_override = Some(pct);
        }
    }

    /// `MCC_ChangeFeedSpeed`: later general motion uses feed `v`; the running general
    /// motion ramps to it through the override ratio (v / its feed).
    pub fn change_feed_speed(&mut self, v: f64) {
        self.settings.feed = v;
        if self.external.is_some() {
            // A running MC3B job keeps its speed: later commands get the new feed.
            return;
        }
        let running_feed = self.running.back().and_then(|r| match r.cmd.plan {
            Plan::Path(_) => Some(r.cmd.info_feed),
            _ => None,
        });
        if let Some(f) = running_feed {
            if f > 0.0 {
                self.override_speed(100.0 * v / f, true);
                self.rate.pending_override = Some(100.0);
            }
        }
    }

    /// `MCC_FixSpeed`.
    pub fn fix_speed(&mut self, fixed: bool) {
        self.fixed_speed = fixed;
        if self.mode == Mode::Normal {
            self.retarget_rate();
        }
    }

    pub(super) fn retarget_rate(&mut self) {
        let target = self.target_rate();
        let t = if target >= self.rate.value {
            self.current_acc_s()
        } else {
            self.current_dec_s()
        };
        self.ramp_to(target, t);
    }

    /// Time scale the group runs at when not held.
    pub(super) fn target_rate(&self) -> f64 {
        if self.fixed_speed {
            1.0
        } else {
            self.override_pct / 100.0
        }
    }

    fn current_acc_s(&self) -> f64 {
        self.running
            .back()
            .map_or(self.settings.acc_ms, |r| r.cmd.acc_ms)
            / 1000.0
    }

    fn current_dec_s(&self) -> f64 {
        self.running
            .back()
            .map_or(self.settings.dec_ms, |r| r.cmd.dec_ms)
            / 1000.0
    }

    fn ramp_to(&mut self, target: f64, secs: f64) {
        // With nothing moving there is no speed to smooth: the new rate holds at once.
        if secs <= 0.0 || (target - self.rate.value).abs() < 1e-15 || self.running.is_empty() {
            self.rate.value = target;
            self.rate.ramp = None;
        } else {
            self.rate.ramp = Some(Ramp {
                ramp: RateRamp::new(self.rate.value, target, secs),
                elapsed: 0.0,
            });
        }
    }

    /// Advances the rate by `dt`; returns ∫ rate dt over the tick.
    pub(super) fn advance_rate(&mut self, dt: f64) -> f64 {
        match &mut self.rate.ramp {
            None => self.rate.value * dt,
            Some(r) => {
                let d = r.ramp.integral(r.elapsed, r.elapsed + dt);
                r.elapsed += dt;
                self.rate.value = r.ramp.rate(r.elapsed);
                if r.ramp.done(r.elapsed) {
                    self.rate.value = r.ramp.to_rate();
                    self.rate.ramp = None;
                }
                d
            }
        }
    }
}
