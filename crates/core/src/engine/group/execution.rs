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
use super::{GroupState, Rezero};
use super::{InPosWait, Mode};
use crate::config::AXES;
use crate::engine::command::{Command, Plan};
use crate::engine::note::Note;
use crate::planner::Axes;
use crate::vendor::consts as c;
use std::collections::VecDeque;

/// The running commands and what they make of the group's position, period by period.
///
/// `repr(C)`: the running commands and the flags a tick reads first, then the positions.
#[derive(Debug)]
#[repr(C)]
pub(super) struct Execution {
    pub(super) running: VecDeque<Running>,
    /// Blending as the engine has reached it in the queue.
    pub(super) blend_on: bool,
    /// Periods the status still reads `GMS_RUNNING` with nothing running (the vendor's
    /// library shows one after the last command).
    pub(super) lag: u8,
    /// The period that just ran read running for `lag` (see [`GroupState::tick`]).
    pub(super) lag_shown: bool,
    /// When the pulse counters of the commanded channels restart from 0
    /// ([`GroupState::reset_motion`]).
    pub(super) rezero: Rezero,
    /// A jog by pulses: its displacement and the periods it still keeps the group running.
    pub(super) jump: Option<(Axes, u8)>,
    /// The feed speed of the last period (`MCC_GetCurFeedSpeed`).
    pub(super) feed_now: f64,
    /// The interpolation period, seconds.
    pub(super) period_s: f64,
    /// Position of everything finished (user coordinates).
    pub(super) base: Axes,
    /// Current command position (user coordinates).
    pub(super) pos: Axes,
    /// Current speed per axis (UU/s).
    pub(super) vel: Axes,
    /// Reference position = user position + offset (MCC_DefinePos moves the offset).
    pub(super) offset: Axes,
    /// Compensation pulses per axis ([`GroupState::read_compensation`]).
    pub(super) comp: [i32; AXES],
    /// What the cruise plan's periods along a line compute from (`group/cruise.rs`).
    pub(super) cruise: Option<super::cruise::CruiseLine>,
}

impl Execution {
    /// Nothing running, at position 0, with the interpolation period `period_s`.
    pub(super) fn new(period_s: f64) -> Execution {
        Execution {
            running: VecDeque::new(),
            blend_on: false,
            lag: 0,
            lag_shown: false,
            rezero: Rezero::No,
            jump: None,
            feed_now: 0.0,
            period_s,
            base: [0.0; AXES],
            pos: [0.0; AXES],
            vel: [0.0; AXES],
            offset: [0.0; AXES],
            comp: [0; AXES],
            cruise: None,
        }
    }
}

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
        self.exec.lag_shown = false;
        // Only cruise periods follow a cruise plan's line.
        self.exec.cruise = None;
        if self.exec.running.is_empty()
            && self.queued.commands.is_empty()
            && self.exec.jump.is_none()
            && self.steady()
            && self.exec.lag == 0
        {
            if let Some((pct, _)) = self.rate.override_next.take() {
                self.rate.override_pct = pct;
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
            && self.features.external.is_none()
            && self.features.post.is_none()
            && self.features.kin.is_none()
            && self.limits.over_travel == [false; AXES]
            && self.in_pos.wait.is_none()
            && !matches!(
                self.exec.rezero,
                super::Rezero::NextPeriod | super::Rezero::Channels
            )
    }

    /// An idle period: the speeds stay as the last command left them, the feed speed
    /// reads 0, unless an error stopped the group (the vendor's library then keeps
    /// reading the speeds of its last period, the feed speed too).
    fn vel_hold_idle(&mut self) {
        if self.error == 0 {
            self.exec.feed_now = 0.0;
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
            || self.rate.override_next.is_some()
            || self.rate.hold_pending
            || self.rate.retarget_pending
        {
            return 0;
        }
        if self.published_key_holds_below().is_none() {
            return 0;
        }
        if self.exec.running.is_empty() {
            let idle =
                self.queued.commands.is_empty() && self.exec.jump.is_none() && self.exec.lag == 0;
            return if idle && self.status == c::GMS_STOP {
                max
            } else {
                0
            };
        }
        if self.exec.running.len() != 1 || self.status != c::GMS_RUNNING {
            return 0;
        }
        let Some(r) = self.exec.running.front() else {
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
        if self.homing != 0 && self.features.external.is_none() {
            // The homing sets the positions (`set_homing_axis`).
            self.update_status();
            return;
        }
        if self.features.external.is_some() {
            return self.tick_external(dt);
        }
        if self.features.post.is_some() {
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
        if self.exec.rezero == super::Rezero::NextPeriod {
            self.exec.rezero = super::Rezero::Channels;
            self.exec.base = [0.0; AXES];
            self.exec.pos = [0.0; AXES];
        }
        let mut before = self.exec.pos;
        let mut vel_mask: u32 = 0;
        let mut zero_mask: u32 = 0;
        if self.rate.retarget_pending && self.exec.running.len() <= 1 {
            // The blend an override waited for ended a period ago (that period ran as
            // planned): the motion left re-plans now [`blend_ovr_*`].
            self.rate.retarget_pending = false;
            self.retarget_running();
        }
        self.apply_override();
        // What ended in the last period goes.
        let mut i = 0;
        let mut lag = false;
        while i < self.exec.running.len() {
            match self.exec.running[i].finished {
                Some(l) => {
                    lag |= l;
                    self.retire(i);
                }
                None => i += 1,
            }
        }
        if self.exec.running.is_empty() && lag {
            self.exec.lag = 1;
        }
        if self.rate.hold_pending && self.exec.running.len() <= 1 {
            // The blend a hold waited for has ended: the motion left stops now.
            self.rate.hold_pending = false;
            let _ = self.hold(false);
        }
        if let Some((d, left)) = self.exec.jump.take() {
            // A jog by pulses: the jump in its first period, then two at rest.
            if left == JUMP_PERIODS {
                for (b, di) in self.exec.base.iter_mut().zip(d) {
                    *b += di;
                }
            }
            if left > 1 {
                self.exec.jump = Some((d, left - 1));
            }
        }
        let mut started = false;
        if self.exec.running.is_empty() && self.may_start() {
            if let Some(cmd) = self.pop_next() {
                self.start(cmd);
                self.exec.lag = 0;
                started = true;
            }
        }
        let mut abort_done = false;
        let inpos_on = self.in_pos.mask != 0;
        let inpos_waiting = self.in_pos.wait.is_some();
        let mut start_inpos = false;
        let n = self.exec.running.len();
        for idx in 0..n {
            let newest = idx + 1 == n;
            let r = &mut self.exec.running[idx];
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
            self.note(Note::InPosBegin(self.in_pos.mask));
            self.in_pos.wait = Some(InPosWait {
                mask: self.in_pos.mask,
                elapsed: 0.0,
                settled: 0.0,
                settings: self.in_pos.settings,
            });
        }
        if abort_done {
            // The timed abort's last period: everything goes in the next.
            for r in self.exec.running.iter_mut() {
                r.finished = Some(false);
            }
            self.clear_queue();
        }
        self.try_blend(&mut vel_mask, started);
        if self.exec.rezero == super::Rezero::Channels {
            // Restarted from 0 (`GroupState::reset_motion`): no jump to show as speed.
            before = [0.0; AXES];
        }
        self.compute_pos();
        self.compute_vel(&before, dt, vel_mask, zero_mask);
        if self.limits.over_travel != [false; AXES] {
            self.check_over_travel(&before);
        }
        self.publishing.newest_own_time =
            self.exec.running.back().map_or(0.0, |r| r.periods as f64);
        self.update_status();
        if self.exec.running.is_empty() && self.exec.jump.is_none() && self.exec.lag > 0 {
            self.exec.lag -= 1;
            // This period still shows it, whoever looks again within it (the filters'
            // tick updates the status once more).
            self.exec.lag_shown = true;
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
    #[inline]
    pub fn cruise_period(&mut self, dt: f64) {
        #[cfg(debug_assertions)]
        let status = self.status;
        self.exec.lag_shown = false;
        if self.exec.running.is_empty() {
            self.vel_hold_idle();
        } else if !self.cruise_line_period(dt) && !self.one_path_period(dt, false) {
            self.tick(dt);
        }
        #[cfg(debug_assertions)]
        {
            self.update_status();
            debug_assert_eq!(status, self.status, "group {} cruises", self.index);
        }
    }

    /// The one running command, when its next period has nothing to do but move it on:
    /// nothing else runs, it is neither finished nor stopping, and no jog jump, override,
    /// pending re-plan, re-zeroing or over-travel check waits. What a one-path period and
    /// a cruise along a line (`GroupState::cruise_line`) both need.
    #[inline(always)]
    pub(super) fn plain_running(&self) -> Option<&Running> {
        let (Some(r), 1) = (self.exec.running.front(), self.exec.running.len()) else {
            return None;
        };
        let plain = r.finished.is_none()
            && r.stage == Stage::Moving
            && self.exec.jump.is_none()
            && self.rate.override_next.is_none()
            && !self.rate.retarget_pending
            && self.exec.rezero == super::Rezero::No
            && self.limits.over_travel == [false; AXES];
        plain.then_some(r)
    }

    /// The period of [`GroupState::tick_one_path`]; `status`: whether to update the
    /// status (a cruise period knows it stays).
    #[inline(always)]
    pub(super) fn one_path_period(&mut self, dt: f64, status: bool) -> bool {
        let Some(r) = self.plain_running() else {
            return false;
        };
        if !matches!(r.progress, Progress::Path { .. }) || r.arrived() {
            return false;
        }
        let before = self.exec.pos;
        let mut vel_mask = 0;
        let r = &mut self.exec.running[0];
        r.periods += 1;
        advance(r, &mut vel_mask);
        self.try_blend(&mut vel_mask, false);
        self.compute_pos();
        self.compute_vel(&before, dt, vel_mask, 0);
        self.publishing.newest_own_time =
            self.exec.running.back().map_or(0.0, |r| r.periods as f64);
        if status {
            self.update_status();
        }
        true
    }

    /// Blending: when the newest general motion has just started to decelerate and the
    /// next queued motion is general too, starts it now.
    fn try_blend(&mut self, vel_mask: &mut u32, just_started: bool) {
        if !self.exec.blend_on || !self.may_start() {
            return;
        }
        let Some(last) = self.exec.running.back() else {
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
        if let Some(Progress::Path { track, .. }) =
            self.exec.running.back_mut().map(|r| &mut r.progress)
        {
            track.blend_out();
        }
        self.start(next);
        if let Some(r) = self.exec.running.back_mut() {
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
            self.queued.index.last_started = Some((cmd.index, cmd.index));
            self.stop_here();
            self.set_error(code);
            return;
        }
        if self.exec.rezero == super::Rezero::OnStart {
            // Reset while busy: the group restarts from 0 with this command.
            self.exec.rezero = super::Rezero::Channels;
            self.exec.base = [0.0; AXES];
        }
        let cmd = self.kinematics_start(cmd);
        if cmd.is_motion() && self.in_pos.mask != 0 {
            self.in_pos.status = [0; AXES];
        }
        self.info_touched();
        // `nCommandIndex_LD`: the vendor's library shows the started command's index.
        self.queued.index.last_started = Some((cmd.index, cmd.index));
        self.queued.index.ld = self.queued.index.ld.wrapping_add(1);
        self.note(Note::Start {
            index: cmd.index,
            ctype: cmd.ctype,
        });
        if self.queued.single_block {
            self.queued.single_block_credit = false;
        }
        let mut r = Running::new(cmd);
        // A running override applies to the motion that starts.
        let k = self.speed_ratio();
        if k != 1.0 {
            r.retarget_tracks(k);
        }
        self.exec.running.push_back(r);
    }

    /// `MCC_JogPulse`: axis `a` moves `pulses` pulses in the next period (see
    /// `JUMP_PERIODS`); `COMMAND_NOTFINISHED_ERR` unless the group stands still.
    pub fn jog_pulses(&mut self, a: usize, pulses: i32) -> crate::error::McclResult<()> {
        if self.busy() || self.homing != 0 {
            return Err(crate::error::McclError::NotFinished);
        }
        let f = self.mech.axes[a].factor;
        if f == 0.0 {
            return Err(crate::error::McclError::Parameter);
        }
        let mut d = [0.0; AXES];
        d[a] = f64::from(pulses) / f.abs();
        crate::config::range::position(self.queued.end[a] + d[a], f)?;
        self.queued.end[a] += d[a];
        self.exec.jump = Some((d, JUMP_PERIODS));
        self.update_status();
        Ok(())
    }

    /// Takes command `i` off the running ones: its displacement joins the base.
    fn retire(&mut self, i: usize) {
        let Some(done) = self.exec.running.remove(i) else {
            return;
        };
        self.info_touched();
        if self.exec.running.len() == 1 {
            if let Some(r) = self.exec.running.front_mut() {
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
            for ((b, p), s) in self.exec.base.iter_mut().zip(p).zip(s) {
                *b += p - s;
            }
            if self.exec.running.is_empty() && matches!(done.stage, Stage::Ending { .. }) {
                self.exec.base = done.cmd.target;
            }
        }
        if self.exec.running.is_empty() && self.rate.mode == Mode::HoldAtBlockEnd {
            self.rate.mode = Mode::Held;
        }
    }
}
