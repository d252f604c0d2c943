//! A command being executed: how it advances (a path's track, a track per axis, a
//! delay, a switch, a stage), where it is in its life, where it has taken the axes, and
//! the re-plans of its tracks that hold, continue, override and feed changes ask for.

use super::track::Track;
use crate::config::AXES;
use crate::engine::command::{Command, Plan};
use crate::planner::{Axes, Shape};

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
pub struct Running {
    pub(in crate::engine) cmd: Command,
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
    pub(super) fn new(cmd: Command) -> Running {
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
                    track: Track::with_nominal(prof, p.speed(i), ramps_of(&prof), shapes_of(&cmd)),
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
                    Track::with_nominal(prof, p.speed(i), ramps_of(&prof), shapes_of(&cmd))
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

    /// Every track decelerates to a stop over `dec_s` ([`Track::stop`]). A
    /// point-to-point axis stops from the speed the group shows for it, `vel` (its
    /// positions' difference over the period, as the vendor's library measures it: a
    /// hair under the speed along the track on an axis moving toward −∞ [`mix_34`]).
    pub(super) fn stop_tracks(&mut self, dec_s: f64, vel: &Axes) {
        if let Progress::Axes { tracks, moving, .. } = &mut self.progress {
            for (i, t) in tracks.iter_mut().enumerate() {
                // An axis that arrived shows the speed of its last period, and stays; one
                // in its own final deceleration keeps it, as a motion does [`mix_49`].
                if *moving & (1 << i) != 0 && !t.arrived() && !t.in_final_decel() {
                    t.stop_from(vel[i].abs(), dec_s);
                }
            }
            return;
        }
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

    /// Every track runs what is left from rest, at the speed it was planned at times
    /// `ratio`, the override in effect ([`Track::resume_nominal`]); a custom motion's
    /// at its own feed ([`Track::resume`]). One held where it arrived ends quietly.
    pub(super) fn resume_tracks(&mut self, ratio: f64) {
        if self.has_tracks() && self.arrived() {
            self.quiet_end = true;
        }
        let nominal = !matches!(self.cmd.plan, Plan::Custom(_));
        for t in self.tracks_mut() {
            // A track the hold let keep its final deceleration goes on with it
            // [`mix_49`].
            if !t.arrived() && !t.in_final_decel() {
                if nominal {
                    t.resume_nominal(ratio);
                } else {
                    t.resume();
                }
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
        self.has_tracks() || matches!(self.cmd.plan, Plan::Custom(_) | Plan::Delay(_))
    }

    /// Whether it is a delay (`MCC_DelayMotion`).
    pub(super) fn is_delay(&self) -> bool {
        matches!(self.cmd.plan, Plan::Delay(_))
    }

    /// Whether it is a delay with no time left.
    pub(super) fn delay_done(&self) -> bool {
        matches!(self.progress, Progress::Delay { left: 0 })
    }

    /// Where it has taken the axes (its own start plus its displacement).
    pub(super) fn position(&self) -> Axes {
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
    pub(super) fn arrived(&self) -> bool {
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
    pub(super) fn stopped(&mut self) -> bool {
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

/// Moves a running command one period on; marks the axes whose speeds it sets.
pub(super) fn advance(r: &mut Running, vel_mask: &mut u32) {
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
