//! Execution of the queued commands, period by period, the way the vendor's library runs
//! them (measured with its DLL; docs/decisions.md "Motion as the vendor's library runs
//! it"):
//!
//! - An idle group takes its next command at the start of a period and moves it in the
//!   same period. A general motion moves for its profile's periods, then shows phase 21
//!   for one period at rest, and the next command starts the period after; a
//!   point-to-point move stands still one period more (its feed speed still the last),
//!   then shows speed 0; a delay waits its periods; a blending switch takes one period.
//! - With blending on, the next general motion starts in the period the running one
//!   starts to decelerate; both ramps of the overlap are S ramps and the displacements
//!   add. The one blended out ends without a period of rest.
//! - After the last command the status reads `GMS_RUNNING` for one more period.
//! - A hold or a timed abort decelerates what runs
//!   ([`Track::stop`](super::track::Track::stop)); stopped, the group shows phase 22,
//!   reads `GMS_HOLD` from the third period, and a timed abort then drops everything.
//! - The speeds a program reads are the distances of the last period over the period.

use super::running::{advance, Progress, Running, Stage};
use super::GroupState;
use super::{InPosWait, Mode};
use crate::config::AXES;
use crate::engine::command::{Command, Plan};
use crate::engine::trace::Note;
use crate::vendor::consts as c;

/// Periods a point-to-point move stays after its last axis arrived: one unchanged, one
/// with the master axis's speed 0.
const PTP_ENDING: u8 = 2;

/// Periods a motion with the in-position check on is shown ending before the check can
/// pass (the vendor's library shows phase 21 for them).
const INPOS_PERIODS: u8 = 3;

/// Held periods from which the status reads `GMS_HOLD` (a timed abort then ends).
pub(super) const HOLD_SHOWN_AFTER: u32 = 3;

/// Periods a jog by pulses keeps the group's status running, as the vendor's library
/// shows it (measured): the jump's period, then two at rest (and the status reads one
/// period late, as after any command).
pub(super) const JUMP_PERIODS: u8 = 4;

impl GroupState {
    /// One interpolation period of `dt` seconds.
    pub fn tick(&mut self, dt: f64) {
        self.lag_shown = false;
        if self.running.is_empty()
            && self.queue.is_empty()
            && self.jump.is_none()
            && self.steady()
            && self.lag == 0
        {
            if let Some((pct, _)) = self.override_next.take() {
                self.override_pct = pct;
            }
            // Idle: nothing moves; the status is STOP (unless an error holds the queue).
            self.vel_hold_idle();
            self.update_status();
            return;
        }
        self.tick_full(dt);
    }

    /// Whether the group's tick is only its commands: not homing, no external executor,
    /// filters or kinematics, no over-travel check, not in an in-position check.
    fn steady(&self) -> bool {
        self.homing == 0
            && self.external.is_none()
            && self.post.is_none()
            && self.kin.is_none()
            && self.ot_check == [false; AXES]
            && self.inpos_wait.is_none()
            && !matches!(
                self.rezero,
                super::Rezero::NextPeriod | super::Rezero::Channels
            )
    }

    /// An idle period: the speeds stay as the last command left them, the feed speed
    /// reads 0, unless an error stopped the group (the vendor's library then keeps
    /// reading the speeds of its last period, the feed speed too).
    fn vel_hold_idle(&mut self) {
        if self.error == 0 {
            self.feed_now = 0.0;
        }
    }

    /// How many of the next ticks, up to `max`, change nothing but positions and speeds:
    /// no command starts or ends, no phase changes, no output, no safety check, the
    /// status and the published info stay as they are. Only the program changes what this
    /// depends on (under the groups' lock), besides the ticks.
    pub fn quiet_ticks_ahead(&self, _dt: f64, max: u32) -> u32 {
        if !self.steady()
            || self.has_outputs()
            || self.has_safety_checks()
            || self.override_next.is_some()
        {
            return 0;
        }
        if self.published_key_holds_below().is_none() {
            return 0;
        }
        if self.running.is_empty() {
            let idle = self.queue.is_empty() && self.jump.is_none() && self.lag == 0;
            return if idle && self.status == c::GMS_STOP {
                max
            } else {
                0
            };
        }
        if self.running.len() != 1 || self.status != c::GMS_RUNNING {
            return 0;
        }
        let Some(r) = self.running.front() else {
            return 0;
        };
        if r.stage != Stage::Moving {
            return 0;
        }
        // The periods in which its phase stays (then its info does too: a next command
        // blends in, or it ends, only where the phase changes).
        let ahead = match &r.progress {
            Progress::Path { track, .. } => track.periods_in_phase(),
            // A PtP shows no phases: its info holds until its master axis arrives.
            Progress::Axes { tracks, master, .. } => {
                tracks[*master].periods_left().saturating_sub(1)
            }
            _ => 0,
        };
        u32::try_from(ahead).unwrap_or(u32::MAX).min(max)
    }

    /// [`GroupState::tick`] when the group does more than stand idle.
    #[inline(never)]
    fn tick_full(&mut self, dt: f64) {
        if self.homing != 0 && self.external.is_none() {
            // The homing sets the positions (`set_homing_axis`).
            self.update_status();
            return;
        }
        if self.external.is_some() {
            return self.tick_external(dt);
        }
        if self.post.is_some() {
            return self.tick_post(dt);
        }
        self.tick_commands(dt);
    }

    /// The commands' period: retire what ended in the last one, start, advance, blend,
    /// stop; the position and the speeds; the status.
    pub(super) fn tick_commands(&mut self, dt: f64) {
        if self.tick_one_path(dt) {
            return;
        }
        if self.rezero == super::Rezero::NextPeriod {
            self.rezero = super::Rezero::Channels;
            self.base = [0.0; AXES];
            self.pos = [0.0; AXES];
        }
        let mut before = self.pos;
        let mut vel_mask: u32 = 0;
        let mut zero_mask: u32 = 0;
        self.apply_override();
        // What ended in the last period goes.
        let mut i = 0;
        let mut lag = false;
        while i < self.running.len() {
            match self.running[i].finished {
                Some(l) => {
                    lag |= l;
                    self.retire(i);
                }
                None => i += 1,
            }
        }
        if self.running.is_empty() && lag {
            self.lag = 1;
        }
        if let Some((d, left)) = self.jump.take() {
            // A jog by pulses: the jump in its first period, then two at rest.
            if left == JUMP_PERIODS {
                for (b, di) in self.base.iter_mut().zip(d) {
                    *b += di;
                }
            }
            if left > 1 {
                self.jump = Some((d, left - 1));
            }
        }
        let mut started = false;
        if self.running.is_empty() && self.may_start() {
            if let Some(cmd) = self.pop_next() {
                self.start(cmd);
                self.lag = 0;
                started = true;
            }
        }
        let mut abort_done = false;
        let inpos_on = self.inpos_mask != 0;
        let inpos_waiting = self.inpos_wait.is_some();
        let mut start_inpos = false;
        let n = self.running.len();
        for idx in 0..n {
            let newest = idx + 1 == n;
            let r = &mut self.running[idx];
            r.periods += 1;
            match r.stage {
                Stage::Moving => {
                    if r.arrived() && r.has_tracks() {
                        // The period after arriving: at rest, shown as ending (longer
                        // while the in-position check runs).
                        let left = if matches!(r.progress, Progress::Axes { .. }) {
                            PTP_ENDING
                        } else {
                            1
                        };
                        let left = if inpos_on { left + INPOS_PERIODS } else { left };
                        r.stage = Stage::Ending { left };
                        if inpos_on {
                            start_inpos = true;
                        }
                    } else {
                        advance(r, &mut vel_mask);
                        let ends = match r.progress {
                            Progress::Delay { left } => left == 0,
                            Progress::Switch => true,
                            Progress::Staged => r.arrived(),
                            _ => false,
                        };
                        if ends {
                            let empty = matches!(&r.cmd.plan, Plan::Path(_) | Plan::Ptp(_));
                            r.finished = Some(!empty);
                        } else if !newest && r.has_tracks() && r.arrived() {
                            // Blended out: it goes without a period of rest.
                            r.finished = Some(false);
                        }
                    }
                }
                Stage::Stopping { abort } => {
                    if r.stopped() {
                        r.stage = Stage::Held { periods: 1, abort };
                        // A general motion held reads speed 0; a PtP keeps its last.
                        if r.path_track().is_some() {
                            zero_mask = u32::MAX;
                        }
                    } else {
                        advance(r, &mut vel_mask);
                    }
                }
                Stage::Held { periods, abort } => {
                    r.stage = Stage::Held {
                        periods: periods + 1,
                        abort,
                    };
                    if r.path_track().is_some() {
                        zero_mask = u32::MAX;
                    }
                }
                Stage::Ending { .. } => {}
            }
            // A PtP's axes that do not move read speed 0 from its first period.
            if let (1, Progress::Axes { moving, .. }) = (r.periods, &r.progress) {
                zero_mask |= !moving;
            }
            if let Stage::Ending { left } = r.stage {
                match (&r.progress, left) {
                    // Continued after a hold let it arrive, its last ending period
                    // keeps the speeds the hold kept (`mix_16`).
                    (Progress::Axes { .. }, 1) if r.quiet_end => {}
                    (Progress::Axes { master, .. }, 1) => zero_mask |= 1 << master,
                    (Progress::Axes { .. }, _) => {}
                    _ => zero_mask = u32::MAX,
                }
                if left <= 1 && !inpos_waiting {
                    r.finished = Some(true);
                } else if left <= 1 {
                    // The in-position check still runs: still shown ending.
                } else {
                    r.stage = Stage::Ending { left: left - 1 };
                }
            }
            if let Stage::Held {
                periods,
                abort: true,
            } = r.stage
            {
                abort_done |= periods >= HOLD_SHOWN_AFTER;
            }
        }
        if start_inpos {
            self.note(Note::InPosBegin(self.inpos_mask));
            self.inpos_wait = Some(InPosWait {
                mask: self.inpos_mask,
                elapsed: 0.0,
                settled: 0.0,
                settings: self.inpos,
            });
        }
        if abort_done {
            // The timed abort's last period: everything goes in the next.
            for r in self.running.iter_mut() {
                r.finished = Some(false);
            }
            self.clear_queue();
        }
        self.try_blend(&mut vel_mask, started);
        if self.rezero == super::Rezero::Channels {
            // Restarted from 0 (`GroupState::reset_motion`): no jump to show as speed.
            before = [0.0; AXES];
        }
        self.compute_pos();
        self.compute_vel(&before, dt, vel_mask, zero_mask);
        if self.ot_check != [false; AXES] {
            self.check_over_travel(&before);
        }
        self.newest_own_time = self.running.back().map_or(0.0, |r| r.periods as f64);
        self.update_status();
        if self.running.is_empty() && self.jump.is_none() && self.lag > 0 {
            self.lag -= 1;
            // This period still shows it, whoever looks again within it (the filters'
            // tick updates the status once more).
            self.lag_shown = true;
        }
    }

    /// The period of a group whose one running command is a general motion on its way
    /// (not arriving, not stopping, nothing else to do this period): what
    /// [`GroupState::tick_commands`] does then, without asking what cannot be. Most
    /// periods of most groups are such periods. Returns false, having changed nothing,
    /// for any other period.
    #[inline]
    fn tick_one_path(&mut self, dt: f64) -> bool {
        self.one_path_period(dt, true)
    }

    /// A cruise period (see `engine/cruise.rs`): one the plan
    /// ([`GroupState::quiet_ticks_ahead`]) found steady, in which the status cannot
    /// change. An idle group's period then only keeps its feed speed at rest; a general
    /// motion's is `GroupState::tick_one_path`'s without the status; anything else (a
    /// PtP) takes the ordinary period.
    pub fn cruise_period(&mut self, dt: f64) {
        #[cfg(debug_assertions)]
        let status = self.status;
        self.lag_shown = false;
        if self.running.is_empty() {
            self.vel_hold_idle();
        } else if !self.one_path_period(dt, false) {
            self.tick(dt);
        }
        #[cfg(debug_assertions)]
        {
            self.update_status();
            debug_assert_eq!(status, self.status, "group {} cruises", self.index);
        }
    }

    /// The period of [`GroupState::tick_one_path`]; `status`: whether to update the
    /// status (a cruise period knows it stays).
    #[inline(always)]
    fn one_path_period(&mut self, dt: f64, status: bool) -> bool {
        let (Some(r), 1) = (self.running.front(), self.running.len()) else {
            return false;
        };
        let plain = r.finished.is_none()
            && r.stage == Stage::Moving
            && matches!(r.progress, Progress::Path { .. })
            && !r.arrived()
            && self.jump.is_none()
            && self.override_next.is_none()
            && self.rezero == super::Rezero::No
            && self.ot_check == [false; AXES];
        if !plain {
            return false;
        }
        let before = self.pos;
        let mut vel_mask = 0;
        let r = &mut self.running[0];
        r.periods += 1;
        advance(r, &mut vel_mask);
        self.try_blend(&mut vel_mask, false);
        self.compute_pos();
        self.compute_vel(&before, dt, vel_mask, 0);
        self.newest_own_time = self.running.back().map_or(0.0, |r| r.periods as f64);
        if status {
            self.update_status();
        }
        true
    }

    /// Blending: when the newest general motion has just started to decelerate and the
    /// next queued motion is general too, starts it now.
    fn try_blend(&mut self, vel_mask: &mut u32, just_started: bool) {
        if !self.blend_on || !self.may_start() {
            return;
        }
        let Some(last) = self.running.back() else {
            return;
        };
        if last.stage != Stage::Moving || !matches!(last.cmd.plan, Plan::Path(_)) {
            return;
        }
        let Some(track) = last.path_track() else {
            return;
        };
        // The first period of its deceleration (one that decelerates from its first
        // period runs that period alone).
        if track.decel_periods_done() != 1 || just_started {
            return;
        }
        if !matches!(self.peek_motion(), Some(Plan::Path(m)) if !m.profile.is_empty()) {
            return;
        }
        let from = last.cmd.ctype;
        let Some(next) = self.pop_next() else {
            return;
        };
        if let Some(Progress::Path { track, .. }) = self.running.back_mut().map(|r| &mut r.progress)
        {
            track.blend_out();
        }
        self.start(next);
        if let Some(r) = self.running.back_mut() {
            r.blended_from = Some(from);
            if let Progress::Path { track, .. } = &mut r.progress {
                track.blend_in();
            }
            r.periods = 1;
            advance(r, vel_mask);
        }
    }

    pub(super) fn start(&mut self, cmd: Command) {
        if let Plan::Fault(code) = cmd.plan {
            // A curve with no geometry fails as it starts.
            self.cmd_index.last_started = Some((cmd.index, cmd.index));
            self.stop_here();
            self.set_error(code);
            return;
        }
        if self.rezero == super::Rezero::OnStart {
            // Reset while busy: the group restarts from 0 with this command.
            self.rezero = super::Rezero::Channels;
            self.base = [0.0; AXES];
        }
        let cmd = self.kinematics_start(cmd);
        if cmd.is_motion() && self.inpos_mask != 0 {
            self.inpos_status = [0; AXES];
        }
        self.info_touched();
        // `nCommandIndex_LD`: the vendor's library shows the started command's index.
        self.cmd_index.last_started = Some((cmd.index, cmd.index));
        self.cmd_index.ld = self.cmd_index.ld.wrapping_add(1);
        self.note(Note::Start {
            index: cmd.index,
            ctype: cmd.ctype,
        });
        if self.single_block {
            self.single_block_credit = false;
        }
        let mut r = Running::new(cmd);
        // A running override applies to the motion that starts.
        let k = self.speed_ratio();
        if k != 1.0 {
            r.retarget_tracks(k);
        }
        self.running.push_back(r);
    }

    /// `MCC_JogPulse`: axis `a` moves `pulses` pulses in the next period (see
    /// `JUMP_PERIODS`); `COMMAND_NOTFINISHED_ERR` unless the group stands still.
    pub fn jog_pulses(&mut self, a: usize, pulses: i32) -> crate::error::McclResult<()> {
        if self.busy() || self.homing != 0 {
            return Err(crate::error::McclError::NotFinished);
        }
        let f = self.axes[a].factor;
        if f == 0.0 {
            return Err(crate::error::McclError::Parameter);
        }
        let mut d = [0.0; AXES];
        d[a] = f64::from(pulses) / f.abs();
        crate::config::range::position(self.queue_end[a] + d[a], f)?;
        self.queue_end[a] += d[a];
        self.jump = Some((d, JUMP_PERIODS));
        self.update_status();
        Ok(())
    }

    /// Takes command `i` off the running ones: its displacement joins the base.
    fn retire(&mut self, i: usize) {
        let Some(done) = self.running.remove(i) else {
            return;
        };
        self.info_touched();
        if self.running.len() == 1 {
            if let Some(r) = self.running.front_mut() {
                // Blended in and now alone: no longer blending.
                r.blended_from = None;
            }
        }
        self.note(Note::End {
            index: done.cmd.index,
            ctype: done.cmd.ctype,
            stopped: false,
        });
        if done.cmd.is_motion() {
            let s = done.cmd.start();
            let p = done.position();
            for ((b, p), s) in self.base.iter_mut().zip(p).zip(s) {
                *b += p - s;
            }
            if self.running.is_empty() && matches!(done.stage, Stage::Ending { .. }) {
                self.base = done.cmd.target;
            }
        }
        if self.running.is_empty() && self.mode == Mode::HoldAtBlockEnd {
            self.mode = Mode::Held;
        }
    }
}
