//! What the group shows: its motion status, the published motion and info parts, the
//! pulses of its axes.

use super::GroupState;
use super::Mode;
use crate::engine::command::Plan;
use crate::engine::snapshot::{round_pulses, GroupSnapshot, Info, Motion};
use crate::vendor::consts as c;
use crate::vendor::COMMAND_INFO;

impl GroupState {
    pub(super) fn update_status(&mut self) {
        if self.homing != 0 {
            // Homing axes move (or wait for the others) until the homing ends.
            self.status = c::GMS_RUNNING;
            return;
        }
        let active = !self.running.is_empty()
            || !self.queue.is_empty()
            || self.inpos_wait.is_some_and(|w| w.blocks())
            || self.external.as_ref().is_some_and(|x| x.active())
            || self.post_active();
        self.status = if !active && self.mode != Mode::Aborting {
            if matches!(self.mode, Mode::Held | Mode::HoldAtBlockEnd) {
                self.mode = Mode::Normal;
                self.rate.value = self.target_rate();
                self.rate.ramp = None;
            }
            c::GMS_STOP
        } else if matches!(self.mode, Mode::Held)
            || (self.running.is_empty()
                && (self.error != 0 || (self.single_block && !self.single_block_credit)))
        {
            // Held, or commands waiting that an error or single-block mode keeps back.
            c::GMS_HOLD
        } else if matches!(
            self.running.front().map(|r| &r.cmd.plan),
            Some(Plan::Delay(_))
        ) {
            c::GMS_DELAYING
        } else {
            c::GMS_RUNNING
        };
    }

    /// Tangential speed: the X/Y/Z speed, or the fastest aux axis when X/Y/Z stand still.
    fn path_speed(&self) -> f64 {
        let xyz = (self.vel[0].powi(2) + self.vel[1].powi(2) + self.vel[2].powi(2)).sqrt();
        if xyz > 0.0 {
            xyz
        } else {
            self.vel[3..].iter().fold(0.0f64, |m, v| m.max(v.abs()))
        }
    }

    /// Pulse position of axis `i`: round(reference position x pulses per UU), halves away
    /// from zero.
    pub fn pulses(&self, i: usize) -> i64 {
        if let Some(p) = self.kinematics_pulses(i) {
            return p;
        }
        let pos = if self.post.is_some() {
            self.out_pos()[i]
        } else {
            self.pos[i]
        };
        round_pulses((pos + self.offset[i]) * self.axes[i].factor)
    }

    /// The part of the published state that changes every tick.
    pub fn motion(&self) -> Motion {
        if self.post.is_some() || self.settings.compose != crate::planner::compose::XYZ_MASK {
            return self.post_motion();
        }
        Motion {
            status: self.status,
            pos: self.pos,
            vel: self.vel,
            path_speed: self.path_speed(),
        }
    }

    /// The part of the published state that changes when commands start or end.
    pub fn info(&self) -> Info {
        let mut cmd = COMMAND_INFO {
            nType: -1,
            nCommandIndex: -1,
            ..Default::default()
        };
        if let Some(r) = self.running.back() {
            let phase = match &r.cmd.plan {
                Plan::Path(m) => {
                    if r.tau < m.profile.acc_time().min(m.decel_start()) {
                        0
                    } else if r.tau < m.decel_start() {
                        1
                    } else {
                        2
                    }
                }
                _ => 1,
            };
            cmd = COMMAND_INFO {
                nType: r.cmd.ctype,
                nCommandIndex: r.cmd.index,
                dfFeedSpeed: match r.cmd.plan {
                    Plan::Delay(s) => ((s - r.tau) * 1000.0).max(0.0),
                    _ => r.cmd.info_feed,
                },
                dfPos: r.cmd.target,
                dfAcctime: r.cmd.acc_ms,
                dfDectime: r.cmd.dec_ms,
                nMotionPhase: phase,
                nCommandIndex_LD: self.cmd_index.last_started.map_or(0, |l| l.1),
            };
        }
        Info {
            error: self.error,
            queued: i32::try_from(self.queue.len()).unwrap_or(i32::MAX),
            cmd,
            offset: self.offset,
            factor: self.axes.map(|a| a.factor),
        }
    }

    /// The whole published state (as readers see it).
    pub fn snapshot(&self) -> GroupSnapshot {
        GroupSnapshot::from_parts(&self.motion(), &self.info())
    }

    /// The info part last published, so an unchanged one is not stored again.
    pub fn published_info(&mut self) -> &mut Option<Info> {
        &mut self.published_info
    }
}
