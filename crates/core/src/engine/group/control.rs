//! Trajectory control of what runs (user manual §2.6.3), the way the vendor's library
//! does it: hold and continue, abort at once or over a deceleration, override, fixed
//! speed, feed changes. Each acts on the running commands' tracks ([`super::track`]).

use super::running::Stage;
use super::GroupState;
use crate::config::AXES;
use crate::engine::command::Plan;
use crate::engine::note::Note;
use crate::error::{McclError, McclResult};

/// The group's rate: hold and stop modes, the override and the fixed speed.
#[derive(Debug)]
pub(super) struct Rate {
    pub(super) mode: Mode,
    /// Override ratio, percent.
    pub(super) override_pct: f64,
    /// `MCC_FixSpeed(TRUE)`: the override does not change speeds.
    pub(super) fixed_speed: bool,
    /// An override set since the last period and whether it is instant
    /// (`MCC_OverrideSpeedEx`): in effect from the next period.
    pub(super) override_next: Option<(f64, bool)>,
    /// A hold that came while two motions blend, waiting for the blend to end.
    pub(super) hold_pending: bool,
    /// An override (or a fixed speed let go) that came while two motions blend: the
    /// motion left re-plans when the blend ends.
    pub(super) retarget_pending: bool,
}

impl Default for Rate {
    /// Running normally at 100 %.
    fn default() -> Rate {
        Rate {
            mode: Mode::Normal,
            override_pct: 100.0,
            fixed_speed: false,
            override_next: None,
            hold_pending: false,
            retarget_pending: false,
        }
    }
}

/// What the group is doing besides running commands.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Mode {
    /// Running normally.
    Normal,
    /// `MCC_HoldMotion`: decelerating to, or standing at, a stop.
    Held,
    /// `MCC_HoldMotion(g, TRUE)`: hold when the running command ends.
    HoldAtBlockEnd,
    /// `MCC_AbortMotionEx(t)`: decelerating; then everything is dropped.
    Aborting,
}

impl GroupState {
    /// `MCC_HoldMotion`: what runs decelerates to a stop and the group waits for
    /// `MCC_ContiMotion`; a motion already in its last deceleration finishes it first.
    /// Nothing running, already held, or the last command of the queue decelerating to
    /// its end: the vendor's library changes nothing and returns 0. It holds at once
    /// whatever `bBlockEnd` says (as the vendor's library does), but on an MC3B, which
    /// can only stop between jobs, `bBlockEnd` holds at the end of the running job.
    pub fn hold(&mut self, at_block_end: bool) -> McclResult<()> {
        if self.exec.running.is_empty() || self.rate.mode != Mode::Normal {
            return Ok(());
        }
        if self.features.external.is_some() {
            if !at_block_end {
                return Err(McclError::NotAccepted);
            }
            self.note(Note::Hold { block_end: true });
            self.rate.mode = Mode::HoldAtBlockEnd;
            return Ok(());
        }
        if self.exec.running.len() > 1 {
            // Two motions blend: the vendor's library lets the blend end and then holds
            // the motion left [`mix_42`, `mix_48`].
            self.rate.hold_pending = true;
            return Ok(());
        }
        let ending = self
            .exec
            .running
            .iter()
            .all(|r| r.path_track().is_some_and(|t| t.in_final_decel()) || !r.holds());
        if ending && self.queued.commands.is_empty() {
            return Ok(());
        }
        self.note(Note::Hold { block_end: false });
        self.rate.mode = Mode::Held;
        for r in self.exec.running.iter_mut() {
            // A hold pauses a delay, also one whose last period just ran: it stays the
            // current command until the continue [`hold_delay_*`, `mix_39`].
            if r.is_delay() {
                r.finished = None;
            }
        }
        self.stop_tracks(false, None);
        Ok(())
    }

    /// `MCC_ContiMotion`: what was held runs on from rest. Not held: nothing, 0.
    pub fn conti(&mut self) -> McclResult<()> {
        match self.rate.mode {
            // As the vendor's library: a continue while the hold still decelerates is
            // refused and the hold goes on (resuming from rest there would drop the speed
            // to 0 within a period).
            Mode::Held
                if self
                    .exec
                    .running
                    .iter()
                    .any(|r| matches!(r.stage, Stage::Stopping { .. })) =>
            {
                Err(McclError::ContiIllegal)
            }
            Mode::Held | Mode::HoldAtBlockEnd => {
                self.note(Note::Continue);
                self.rate.mode = Mode::Normal;
                let ratio = self.speed_ratio();
                for r in self.exec.running.iter_mut() {
                    if matches!(r.stage, Stage::Stopping { .. } | Stage::Held { .. }) {
                        if r.is_ptp() && r.arrived() {
                            // A PtP the hold let arrive spent the first of its two ending
                            // periods before holding: the last one follows (`mix_16`).
                            r.quiet_end = true;
                            r.stage = Stage::Ending { left: 1 };
                            continue;
                        }
                        r.stage = Stage::Moving;
                        if r.delay_done() {
                            // A delay held after its last period goes at once.
                            r.finished = Some(false);
                            continue;
                        }
                        r.resume_tracks(ratio);
                    }
                }
                self.info_touched();
                self.update_status();
                Ok(())
            }
            // A hold still waiting for a blend to end is as a hold decelerating: the
            // continue is refused and the hold goes on [`mix_42`].
            Mode::Normal if self.rate.hold_pending => Err(McclError::ContiIllegal),
            _ => Ok(()),
        }
    }

    /// Every running command with tracks decelerates to a stop: with its own
    /// deceleration time, or `dec_s`.
    fn stop_tracks(&mut self, abort: bool, dec_s: Option<f64>) {
        for r in self.exec.running.iter_mut() {
            if !r.holds() || matches!(r.stage, Stage::Ending { .. }) {
                continue;
            }
            // A motion in its last deceleration keeps it (it stops where it ends).
            if !r.in_final_decel() {
                let d = match dec_s {
                    // The vendor's library reads a timed abort's time as milliseconds
                    // for a PtP (measured: 0.1 s and 0.02 s both stop a PtP within the
                    // ramp of 1 ms).
                    Some(s) if abort && r.is_ptp() => crate::planner::whole_ms(s) / 1000.0,
                    Some(s) => s,
                    None => r.cmd.dec_ms / 1000.0,
                };
                r.stop_tracks(d, &self.exec.vel);
            }
            r.stage = Stage::Stopping { abort };
        }
        self.info_touched();
        self.update_status();
    }

    /// `MCC_AbortMotion(g, FALSE)`, `MCC_AbortMotionEx`: empties the queue and stops, at
    /// once (`dec_ms` 0, rounded up to whole ms as the vendor keeps times) or over the
    /// deceleration `dec_ms` gives. With `at_block_end` the running command finishes and
    /// the queue is dropped.
    pub fn abort(&mut self, dec_ms: f64, at_block_end: bool) {
        let dec_ms = crate::planner::whole_ms(dec_ms.max(0.0));
        // The MC3B stops at once (`S`); it has no controlled stop.
        let dec_ms = if self.features.external.is_some() {
            0.0
        } else {
            dec_ms
        };
        self.note(Note::Abort {
            dec_s: dec_ms / 1000.0,
            block_end: at_block_end,
        });
        self.clear_queue();
        if at_block_end {
            self.queued.end = self
                .exec
                .running
                .back()
                .map_or(self.exec.pos, |r| r.cmd.target);
            self.update_status();
            return;
        }
        let held = self.rate.mode == Mode::Held
            && self
                .exec
                .running
                .iter()
                .all(|r| matches!(r.stage, Stage::Held { .. }));
        if dec_ms <= 0.0 || held || self.exec.running.is_empty() {
            // Held at rest, the vendor's library stops at once without a running period.
            self.abort_now(!held);
        } else {
            self.rate.mode = Mode::Aborting;
            self.stop_tracks(true, Some(dec_ms / 1000.0));
        }
    }

    /// An abort at once that happens within a period (a card reset by its watchdog): the
    /// status reads running for this period and the next reads STOP, as after an abort
    /// called between periods.
    pub fn abort_within_period(&mut self) {
        self.abort(0.0, false);
        if self.exec.lag > 0 {
            self.exec.lag = 0;
            self.exec.lag_shown = true;
        }
    }

    /// Drops what runs and is queued where the group stands; `lag`: the status reads
    /// `GMS_RUNNING` for one more period (an abort, as the vendor's library shows it).
    pub(super) fn abort_now(&mut self, lag: bool) {
        let was_busy = !self.exec.running.is_empty();
        self.stop_here();
        self.exec.vel = [0.0; AXES];
        self.exec.feed_now = 0.0;
        // An external executor (the MC3B) reports its own stop: no period to show.
        if lag && was_busy && self.features.external.is_none() {
            self.exec.lag = 1;
            // Until that period has passed the abort is not finished: the vendor's
            // library refuses commands meanwhile (`ABORT_NOT_FINISH_ERR`, measured).
            self.rate.mode = Mode::Aborting;
        }
        self.update_status();
    }

    /// Stops at once where the group stands: nothing runs or waits afterwards. The
    /// speeds stay as the last period left them (the vendor's library, stopped by an
    /// error, keeps reading them); an abort sets them to 0.
    pub(super) fn stop_here(&mut self) {
        if let Some(x) = self.features.external.as_mut() {
            x.stop();
        }
        self.in_pos.wait = None;
        self.note_stopped();
        self.exec.running.clear();
        self.exec.jump = None;
        self.exec.lag = 0;
        self.exec.lag_shown = false;
        self.info_touched();
        self.clear_queue();
        self.post_stopped();
        self.exec.base = self.exec.pos;
        self.queued.end = self.exec.pos;
        self.rate.mode = Mode::Normal;
        self.rate.hold_pending = false;
        self.rate.retarget_pending = false;
    }

    /// `MCC_OverrideSpeedEx`: the new ratio is in effect from the next period; with
    /// `instant` what runs then re-plans its rest, otherwise it keeps its speed and the
    /// commands after it run at the new ratio.
    pub fn override_speed(&mut self, pct: f64, instant: bool) {
        self.rate.override_next = Some((pct, instant));
    }

    /// At the start of a period: an override set since the last one comes into effect.
    pub(super) fn apply_override(&mut self) {
        if let Some((pct, instant)) = self.rate.override_next.take() {
            // The rate already in effect re-plans nothing (the vendor's library leaves a
            // blend in progress as it is).
            let same = pct == self.rate.override_pct;
            self.rate.override_pct = pct;
            if instant && !same {
                self.retarget_running();
            }
        }
    }

    /// What runs at speed re-plans the rest of its length at its feed times the ratio
    /// (not with the speed fixed). A point-to-point move runs on at the rate it started
    /// with, as in the vendor's library [`mix_33`]: the ratio is the next moves'. Two
    /// motions blending run on as they are, and the motion left re-plans when the blend
    /// ends [`blend_ovr_*`, `mix_61`].
    pub(super) fn retarget_running(&mut self) {
        if self.rate.mode != Mode::Normal || self.rate.fixed_speed {
            return;
        }
        if self.exec.running.len() > 1 {
            self.rate.retarget_pending = true;
            return;
        }
        let k = self.speed_ratio();
        for r in self.exec.running.iter_mut() {
            if r.stage == Stage::Moving && !matches!(r.cmd.plan, Plan::Ptp(_)) {
                r.retarget_tracks(k);
            }
        }
        self.info_touched();
    }

    /// The ratio feed speeds run at: the override, or 1 with the speed fixed.
    pub(super) fn speed_ratio(&self) -> f64 {
        if self.rate.fixed_speed {
            1.0
        } else {
            self.rate.override_pct / 100.0
        }
    }

    /// `MCC_ChangeFeedSpeed`: later general motion uses feed `v`; the running general
    /// motion re-plans its rest at `v`.
    pub fn change_feed_speed(&mut self, v: f64) {
        self.settings.feed = v;
        if self.features.external.is_some() {
            // A running MC3B job keeps its speed: later commands get the new feed.
            return;
        }
        let k = self.speed_ratio();
        for r in self.exec.running.iter_mut() {
            if r.stage == Stage::Moving
                && matches!(r.cmd.plan, crate::engine::command::Plan::Path(_))
            {
                r.set_feed(v, k);
            }
        }
        self.info_touched();
    }

    /// `MCC_FixSpeed`: with the speed fixed the override changes no speed.
    pub fn fix_speed(&mut self, fixed: bool) {
        let was = self.rate.fixed_speed;
        self.rate.fixed_speed = fixed;
        if was && !fixed && self.rate.override_pct != 100.0 {
            self.retarget_running();
        }
    }
}
