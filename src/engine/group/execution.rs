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
//! - A hold or a timed abort decelerates what runs ([`Track::stop`]); stopped, the group
//!   shows phase 22, reads `GMS_HOLD` from the third period, and a timed abort then
//!   drops everything.
//! - The speeds a program reads are the distances of the last period over the period.

use super::track::Track;
use super::GroupState;
use super::{InPosWait, Mode, ERR_OVER_TRAVEL};
use crate::config::AXES;
use crate::engine::command::{Command, Plan};
use crate::engine::trace::Note;
use crate::planner::{Axes, Shape};
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

/// How a running command advances.
#[derive(Debug, Clone)]
pub(super) enum Progress {
    /// General motion (and a synchronised PtP: `sync` is its master axis): one track
    /// along the path (the master's travel).
    Path { track: Track, sync: Option<usize> },
    /// Point-to-point: a track per moving axis (`moving`, one bit each), `master` the
    /// axis arriving last.
    Axes {
        tracks: Box<[Track; AXES]>,
        moving: u32,
        master: usize,
    },
    /// A delay: periods left.
    Delay { left: u64 },
    /// A blending switch, or a motion that does not move: one period.
    Switch,
    /// Custom motion and robot joint moves: their stages advance them.
    Staged,
}

/// Where a running command is in its life.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Stage {
    /// Moving along its plan (or a re-plan).
    Moving,
    /// Decelerating to a stop: a hold, or a timed abort.
    Stopping { abort: bool },
    /// Stopped by a hold or a timed abort, for `periods`.
    Held { periods: u32, abort: bool },
    /// Arrived: periods it is still shown before it is retired.
    Ending { left: u8 },
}

/// A command being executed.
#[derive(Debug, Clone)]
pub(crate) struct Running {
    pub(crate) cmd: Command,
    pub(super) progress: Progress,
    pub(super) stage: Stage,
    /// Periods it has run (its own clock; the published key's stretches count in it).
    pub(super) periods: u64,
    /// The type of the general motion it blended into, while that one still decelerates.
    pub(super) blended_from: Option<i32>,
    /// Set at the end of its last period: retired at the start of the next one, then with
    /// (`true`) or without a period of `GMS_RUNNING` if nothing follows.
    pub(super) finished: Option<bool>,
    /// Held where it ended and continued: its period of ending shows phase 0, not 21.
    pub(super) quiet_end: bool,
}

impl Running {
    fn new(cmd: Command) -> Running {
        let progress = match &cmd.plan {
            Plan::Path(m) if m.profile.is_empty() => Progress::Switch,
            Plan::Path(m) => Progress::Path {
                track: Track::new(m.profile, m.feed, m.ramps, m.shapes),
                sync: None,
            },
            Plan::Ptp(p) if p.periods() == 0 => Progress::Switch,
            Plan::Ptp(p) if p.is_sync() => {
                let i = p.master();
                let prof = *p.profile(i);
                Progress::Path {
                    track: Track::new(prof, prof.speed(), ramps_of(&prof), shapes_of(&cmd)),
                    sync: Some(i),
                }
            }
            Plan::Ptp(p) => {
                let mut moving = 0;
                let tracks = Box::new(std::array::from_fn(|i| {
                    let prof = *p.profile(i);
                    if !prof.is_empty() {
                        moving |= 1 << i;
                    }
                    Track::new(prof, prof.speed(), ramps_of(&prof), shapes_of(&cmd))
                }));
                Progress::Axes {
                    tracks,
                    moving,
                    master: p.master(),
                }
            }
            Plan::Delay(n) => Progress::Delay { left: *n },
            Plan::Custom(_) => Progress::Staged,
            Plan::Blend(_) | Plan::InPos(..) | Plan::Output(_) | Plan::Fault(_) => Progress::Switch,
        };
        Running {
            cmd,
            progress,
            stage: Stage::Moving,
            periods: 0,
            blended_from: None,
            finished: None,
            quiet_end: false,
        }
    }

    /// The general-motion track, if it is one.
    pub(super) fn path_track(&self) -> Option<&Track> {
        match &self.progress {
            Progress::Path { track, .. } => Some(track),
            _ => None,
        }
    }

    /// Every track it has (one for general motion and custom motion, one per moving axis
    /// for PtP).
    fn tracks_mut(&mut self) -> impl Iterator<Item = &mut Track> {
        let (one, many, moving): (Option<&mut Track>, Option<&mut [Track; AXES]>, u32) =
            match (&mut self.progress, &mut self.cmd.plan) {
                (Progress::Path { track, .. }, _) => (Some(track), None, 0),
                (Progress::Axes { tracks, moving, .. }, _) => (None, Some(&mut **tracks), *moving),
                (Progress::Staged, Plan::Custom(m)) => (m.track_mut(), None, 0),
                _ => (None, None, 0),
            };
        one.into_iter().chain(
            many.into_iter()
                .flat_map(|t| t.iter_mut())
                .enumerate()
                .filter(move |(i, _)| moving & (1 << i) != 0)
                .map(|(_, t)| t),
        )
    }

    /// Whether it is in its last deceleration: its path's, or its master axis's for a
    /// PtP (a hold or abort then lets it end where it ends).
    pub(super) fn in_final_decel(&self) -> bool {
        match &self.progress {
            Progress::Path { track, .. } => track.in_final_decel(),
            Progress::Axes { tracks, master, .. } => tracks[*master].in_final_decel(),
            _ => false,
        }
    }

    /// Whether it is a point-to-point move.
    pub(super) fn is_ptp(&self) -> bool {
        matches!(self.cmd.plan, Plan::Ptp(_))
    }

    /// Every track decelerates to a stop over `dec_s` ([`Track::stop`]).
    pub(super) fn stop_tracks(&mut self, dec_s: f64) {
        let chord = self.chord_ratio();
        for t in self.tracks_mut() {
            t.stop(dec_s, chord);
        }
    }

    /// The last period's chord over its length along the path: on an arc the vendor's
    /// library stops (a hold, a timed abort) and re-plans (an override, a new feed) from
    /// the speed along the chord (the distance between the last two positions over the
    /// period), a little less than the speed along the arc (measured: `arc_hold_cruise_t`,
    /// `mix_3`, `mix_6`); 1 on anything else.
    fn chord_ratio(&self) -> f64 {
        match (&self.progress, &self.cmd.plan) {
            (Progress::Path { track, sync: None }, Plan::Path(m)) => {
                m.path.chord_ratio(track.last_speed() * m.profile.period())
            }
            _ => 1.0,
        }
    }

    /// Every track runs what is left from rest ([`Track::resume`]); one held where it
    /// arrived ends quietly.
    pub(super) fn resume_tracks(&mut self) {
        if self.has_tracks() && self.arrived() {
            self.quiet_end = true;
        }
        for t in self.tracks_mut() {
            if !t.arrived() {
                t.resume();
            }
        }
    }

    /// Every track re-plans its rest at its feed times `ratio` ([`Track::retarget`]), also
    /// in its final deceleration (the vendor's library does: `mix_6`); a custom motion
    /// only when it follows the override.
    pub(super) fn retarget_tracks(&mut self, ratio: f64) {
        if matches!(&self.cmd.plan, Plan::Custom(m) if !m.follows_override()) {
            return;
        }
        let chord = self.chord_ratio();
        for t in self.tracks_mut() {
            if !t.arrived() {
                t.retarget(ratio, chord);
            }
        }
    }

    /// A new feed for a general motion, at `ratio`.
    pub(super) fn set_feed(&mut self, feed: f64, ratio: f64) {
        let chord = self.chord_ratio();
        if let Progress::Path { track, sync: None } = &mut self.progress {
            if !track.arrived() {
                track.set_base_feed(feed, ratio, chord);
            }
        }
    }

    /// Whether it moves axes along tracks of its own (general motion or PtP).
    pub(super) fn has_tracks(&self) -> bool {
        matches!(self.progress, Progress::Path { .. } | Progress::Axes { .. })
    }

    /// Whether a hold stops it: it moves along tracks (its own or its stage's).
    pub(super) fn holds(&self) -> bool {
        self.has_tracks() || matches!(self.cmd.plan, Plan::Custom(_))
    }

    /// Where it has taken the axes (its own start plus its displacement).
    fn position(&self) -> Axes {
        match (&self.progress, &self.cmd.plan) {
            (Progress::Path { track, sync: None }, Plan::Path(m)) => {
                m.path.point_at(track.fraction())
            }
            (
                Progress::Path {
                    track,
                    sync: Some(_),
                },
                Plan::Ptp(p),
            ) => {
                let frac = track.fraction();
                let (s, e) = (p.start(), p.end());
                if track.arrived() {
                    e
                } else {
                    std::array::from_fn(|i| s[i] + (e[i] - s[i]) * frac)
                }
            }
            (Progress::Axes { tracks, moving, .. }, Plan::Ptp(p)) => {
                let (s, e) = (p.start(), p.end());
                std::array::from_fn(|i| {
                    if moving & (1 << i) == 0 || tracks[i].arrived() {
                        e[i]
                    } else {
                        s[i] + (e[i] - s[i]) * tracks[i].fraction()
                    }
                })
            }
            (_, Plan::Custom(m)) => m.sample().0,
            _ => self.cmd.target,
        }
    }

    /// Whether it has ended its motion (all its tracks arrived).
    fn arrived(&self) -> bool {
        match &self.progress {
            Progress::Path { track, .. } => track.arrived(),
            Progress::Axes { tracks, moving, .. } => (0..AXES)
                .filter(|i| moving & (1 << i) != 0)
                .all(|i| tracks[i].arrived()),
            Progress::Delay { left } => *left == 0,
            Progress::Switch => self.periods >= 1,
            Progress::Staged => match &self.cmd.plan {
                Plan::Custom(m) => m.ended(),
                _ => false,
            },
        }
    }

    /// Whether its tracks are all at rest at the end of a stop.
    fn stopped(&mut self) -> bool {
        self.tracks_mut().all(|t| t.stretch_done())
    }
}

/// The ramp periods a PtP track re-plans with.
fn ramps_of(p: &crate::planner::TickProfile) -> (u32, u32) {
    (p.acc_periods(), p.dec_periods())
}

/// The ramp shapes a command's tracks re-plan with.
fn shapes_of(cmd: &Command) -> (Shape, Shape) {
    match &cmd.plan {
        Plan::Path(m) => m.shapes,
        Plan::Ptp(p) => p.shapes(),
        _ => (Shape::S, Shape::S),
    }
}

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

    /// The command position: the base plus what every running command moved.
    fn compute_pos(&mut self) {
        if let (1, Some(r)) = (self.running.len(), self.running.front()) {
            let (s, p) = match (&r.progress, &r.cmd.plan) {
                // A general motion (most periods): its path's start and point, asked
                // directly.
                (Progress::Path { track, sync: None }, Plan::Path(m)) => {
                    (m.path.start_ref(), m.path.point_at(track.fraction()))
                }
                _ => (&r.cmd.start(), r.position()),
            };
            for i in 0..AXES {
                // Both sides computed, one taken: a select the compiler pairs up.
                let moved = self.base[i] + (p[i] - s[i]);
                self.pos[i] = if self.base[i] == s[i] { p[i] } else { moved };
            }
            return;
        }
        let mut pos = self.base;
        for r in &self.running {
            if !r.cmd.is_motion() {
                continue;
            }
            let s = r.cmd.start();
            let p = r.position();
            for i in 0..AXES {
                pos[i] += p[i] - s[i];
            }
        }
        self.pos = pos;
    }

    /// The speeds: the last period's distance over the period for the axes that moved
    /// (`mask`); 0 for those an ending command stops (`zero`); the others keep theirs.
    /// The feed speed: the master axis's speed for a PtP, the path speed otherwise.
    fn compute_vel(&mut self, before: &Axes, dt: f64, mask: u32, zero: u32) {
        if mask == u32::MAX && zero == 0 && dt > 0.0 {
            // Every axis (a general motion's period): one straight pass, which the
            // compiler turns into paired divisions.
            for ((v, p), b) in self.vel.iter_mut().zip(&self.pos).zip(before) {
                *v = (p - b) / dt;
            }
        } else {
            self.compute_vel_masked(before, dt, mask, zero);
        }
        self.feed_now = self.feed_speed();
    }

    /// [`GroupState::compute_vel`]'s speeds for the axes of `mask` and `zero`.
    fn compute_vel_masked(&mut self, before: &Axes, dt: f64, mask: u32, zero: u32) {
        for (i, ((v, p), b)) in self.vel.iter_mut().zip(&self.pos).zip(before).enumerate() {
            if zero & (1 << i) != 0 {
                *v = 0.0;
            } else if mask & (1 << i) != 0 && dt > 0.0 {
                *v = (p - b) / dt;
            }
        }
    }

    /// The feed speed from the speeds: the master axis's for a PtP, the path speed
    /// otherwise.
    #[inline]
    fn feed_speed(&self) -> f64 {
        match self.running.back() {
            // Stopped by an error: the last period's feed speed stays (`vel_hold_idle`).
            None if self.error != 0 => self.feed_now,
            None => 0.0,
            Some(r) => match (&r.progress, &r.cmd.plan) {
                (Progress::Axes { master, .. }, _) => self.vel[*master].abs(),
                (Progress::Path { track, sync: None }, Plan::Path(m)) if m.path.aux_only() => {
                    let _ = track;
                    let lead = m.path.lead_axis();
                    self.vel[lead].abs()
                }
                (Progress::Path { sync: Some(i), .. }, _) => self.vel[*i].abs(),
                (Progress::Path { .. }, _) => {
                    crate::planner::compose::composed_speed(&self.vel, self.settings.compose)
                }
                _ => 0.0,
            },
        }
    }

    /// Software over-travel (user manual §2.6.1): with the check on, an axis never goes
    /// further out of its work zone (dfLowLimit..dfHighLimit). A tick that would take it
    /// out stops the group where it was, records 0xF301 + axis, and motion waits for
    /// `MCC_ClearError`; a move back into the zone is allowed.
    fn check_over_travel(&mut self, before: &Axes) {
        for i in 0..AXES {
            if !self.ot_check[i] || self.axes[i].channel.is_none() {
                continue;
            }
            let (p, b) = (self.pos[i], before[i]);
            let out = (p > self.axes[i].high && p > b) || (p < self.axes[i].low && p < b);
            if out {
                self.pos = *before;
                self.stop_here();
                self.set_error(ERR_OVER_TRAVEL + i as i32);
                return;
            }
        }
    }
}

/// Moves a running command one period on; marks the axes whose speeds it sets.
fn advance(r: &mut Running, vel_mask: &mut u32) {
    match &mut r.progress {
        Progress::Path { track, .. } => {
            track.step();
            *vel_mask = u32::MAX;
        }
        Progress::Axes { tracks, moving, .. } => {
            for i in 0..AXES {
                if *moving & (1 << i) != 0 && tracks[i].step() {
                    *vel_mask |= 1 << i;
                }
            }
        }
        Progress::Delay { left } => *left = left.saturating_sub(1),
        Progress::Switch | Progress::Staged => {}
    }
}
