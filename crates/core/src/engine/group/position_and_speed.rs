//! The command position and the speeds a group's period shows: the base plus what the
//! running commands moved, the last period's distances over the period, the feed speed,
//! and the software over-travel check on the new position.

use super::running::Progress;
use super::{GroupState, ERR_OVER_TRAVEL};
use crate::config::AXES;
use crate::engine::command::Plan;
use crate::planner::Axes;

/// The group's supervision limits: software over-travel and tracking error.
#[derive(Debug)]
pub(super) struct Limits {
    /// Software over-travel check per axis (`MCC_SetOverTravelCheck`).
    pub(super) over_travel: [bool; AXES],
    /// Tracking error check per axis (`MCC_EnableTrackError` mask).
    pub(super) track_mask: u32,
    /// Tracking error limit per axis, UU (`MCC_SetTrackErrorLimit`).
    pub(super) track_limit: Axes,
}

impl Default for Limits {
    /// No check; tracking limits infinite until set.
    fn default() -> Limits {
        Limits {
            over_travel: [false; AXES],
            track_mask: 0,
            track_limit: [f64::INFINITY; AXES],
        }
    }
}

impl GroupState {
    /// The command position: the base plus what every running command moved.
    pub(super) fn compute_pos(&mut self) {
        if let (1, Some(r)) = (self.exec.running.len(), self.exec.running.front()) {
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
                let moved = self.exec.base[i] + (p[i] - s[i]);
                self.exec.pos[i] = if self.exec.base[i] == s[i] {
                    p[i]
                } else {
                    moved
                };
            }
            return;
        }
        let mut pos = self.exec.base;
        for r in &self.exec.running {
            if !r.cmd.is_motion() {
                continue;
            }
            let s = r.cmd.start();
            let p = r.position();
            for i in 0..AXES {
                pos[i] += p[i] - s[i];
            }
        }
        self.exec.pos = pos;
    }

    /// The speeds: the last period's distance over the period for the axes that moved
    /// (`mask`); 0 for those an ending command stops (`zero`); the others keep theirs.
    /// The feed speed: the master axis's speed for a PtP, the path speed otherwise.
    pub(super) fn compute_vel(&mut self, before: &Axes, dt: f64, mask: u32, zero: u32) {
        if mask == u32::MAX && zero == 0 && dt > 0.0 {
            // Every axis (a general motion's period): one straight pass, which the
            // compiler turns into paired divisions.
            for ((v, p), b) in self.exec.vel.iter_mut().zip(&self.exec.pos).zip(before) {
                *v = (p - b) / dt;
            }
        } else {
            self.compute_vel_masked(before, dt, mask, zero);
        }
        self.exec.feed_now = self.feed_speed();
    }

    /// [`GroupState::compute_vel`]'s speeds for the axes of `mask` and `zero`.
    fn compute_vel_masked(&mut self, before: &Axes, dt: f64, mask: u32, zero: u32) {
        for (i, ((v, p), b)) in self
            .exec
            .vel
            .iter_mut()
            .zip(&self.exec.pos)
            .zip(before)
            .enumerate()
        {
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
        match self.exec.running.back() {
            // Stopped by an error: the last period's feed speed stays (`vel_hold_idle`).
            None if self.error != 0 => self.exec.feed_now,
            None => 0.0,
            Some(r) => match (&r.progress, &r.cmd.plan) {
                // The last ending period of a PtP continued after a hold let it arrive
                // keeps its speeds but reads no feed (`mix_16`).
                (Progress::Axes { .. }, _) if r.quiet_end => 0.0,
                (Progress::Axes { master, .. }, _) => self.exec.vel[*master].abs(),
                (Progress::Path { track, sync: None }, Plan::Path(m)) if m.path.aux_only() => {
                    let _ = track;
                    let lead = m.path.lead_axis();
                    self.exec.vel[lead].abs()
                }
                (Progress::Path { sync: Some(i), .. }, _) => self.exec.vel[*i].abs(),
                (Progress::Path { .. }, _) => {
                    crate::planner::compose::composed_speed(&self.exec.vel, self.settings.compose)
                }
                _ => 0.0,
            },
        }
    }

    /// Software over-travel (user manual §2.6.1): with the check on, an axis never goes
    /// further out of its work zone (dfLowLimit..dfHighLimit). A tick that would take it
    /// out stops the group where it was, records 0xF301 + axis, and motion waits for
    /// `MCC_ClearError`; a move back into the zone is allowed.
    pub(super) fn check_over_travel(&mut self, before: &Axes) {
        for i in 0..AXES {
            if !self.limits.over_travel[i] || self.mech.axes[i].channel.is_none() {
                continue;
            }
            let (p, b) = (self.exec.pos[i], before[i]);
            let out = (p > self.mech.axes[i].high && p > b) || (p < self.mech.axes[i].low && p < b);
            if out {
                self.exec.pos = *before;
                self.stop_here();
                self.set_error(ERR_OVER_TRAVEL + i as i32);
                return;
            }
        }
    }
}
