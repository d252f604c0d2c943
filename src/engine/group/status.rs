//! What the group shows: its motion status, the published motion and info parts, the
//! pulses of its axes.

use super::execution::Running;
use super::GroupState;
use super::Mode;
use crate::config::AXES;
use crate::engine::command::Plan;
use crate::engine::snapshot::{round_pulses, GroupSnapshot, Info, Motion, SnapshotCell};
use crate::machine::Channel;
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

    /// Pulse position of axis `i`: round(reference position x pulses per UU), halves away
    /// from zero.
    #[inline]
    pub fn pulses(&self, i: usize) -> i64 {
        if let Some(p) = self.kinematics_pulses(i) {
            return p;
        }
        let pos = if self.post.is_some() {
            self.out_pos()[i]
        } else {
            self.pos[i]
        };
        self.pulses_at(i, pos)
    }

    /// The pulses of axis `i` at output position `pos`: the reference position (with the
    /// offset) times the pulses per UU, rounded halves away from zero.
    #[inline]
    fn pulses_at(&self, i: usize, pos: f64) -> i64 {
        round_pulses((pos + self.offset[i]) * self.axes[i].factor)
    }

    /// Commands the channels of the axes in `axes` (a bit mask of this group's axes,
    /// each mapped to a channel) with their pulses this tick ([`GroupState::pulses`]);
    /// `cards` are the machine's channels. A group's axes map channels of its own card
    /// (`engine::axes_of`); an axis mapping another, or a card not in `cards`, is passed
    /// over.
    ///
    /// One loop for the whole group, with what [`GroupState::pulses`] asks of every axis
    /// (kinematics, filters) and the card asked once: this runs every tick for every
    /// commanding group.
    #[inline]
    pub fn command_channels(&self, axes: u32, cards: &mut [[Channel; AXES]]) {
        let own = self.def.card.0;
        let Some(chans) = cards.get_mut(own).filter(|_| axes != 0) else {
            return;
        };
        let plain = self.kin.is_none() && self.post.is_none();
        for (i, ax) in self.axes.iter().enumerate() {
            if axes >> i & 1 == 0 {
                continue;
            }
            let Some((card, ch)) = ax.channel else {
                continue;
            };
            debug_assert_eq!(card, own, "a group's axes map its own card's channels");
            let Some(chan) = chans.get_mut(ch).filter(|_| card == own) else {
                continue;
            };
            let p = if plain {
                self.pulses_at(i, self.pos[i])
            } else {
                self.pulses(i)
            };
            chan.command(p);
        }
    }

    /// The part of the published state that changes every tick.
    #[inline]
    pub fn motion(&self) -> Motion {
        // The output position and velocity (after the filters, `post.rs`); readers derive
        // the path speed from the velocities and the compose mask.
        Motion {
            status: self.status,
            pos: self.out_pos(),
            vel: self.out_vel(),
            compose: self.settings.compose,
        }
    }

    /// Publishes [`GroupState::motion`] to `cell`: straight from the group's fields when
    /// its output is its reference (no filter stage), which is what `motion` copies then.
    #[inline]
    pub fn store_motion(&self, cell: &SnapshotCell) {
        if self.output_is_reference() {
            cell.store_motion_parts(self.status, &self.pos, &self.vel, self.settings.compose);
        } else {
            cell.store_motion(&self.motion());
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
            cmd = COMMAND_INFO {
                nType: r.cmd.ctype,
                nCommandIndex: r.cmd.index,
                dfFeedSpeed: info_feed(r),
                dfPos: r.cmd.target,
                dfAcctime: r.cmd.acc_ms,
                dfDectime: r.cmd.dec_ms,
                nMotionPhase: motion_phase(r),
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

    /// What [`GroupState::info`] depends on that can change while the group runs: equal
    /// keys mean equal infos, so publishing compares these few words instead of building
    /// and comparing the whole info every tick. The rest of the info changes only with a
    /// command start (counted by `starts`) or a reset (which publishes afresh).
    #[inline]
    pub(super) fn info_key(&self) -> InfoKey {
        let back = self.running.back();
        InfoKey {
            error: self.error,
            queued: self.queue.len(),
            starts: self.starts,
            running: back.is_some(),
            phase: back.map_or(0, motion_phase),
            feed: back.map_or(0, |r| info_feed(r).to_bits()),
            touched: self.info_touched,
        }
    }

    /// Records a change of what the info shows that is not one of the key's own words:
    /// the running command's end (custom motion) or the offset between user and
    /// reference positions. Every writer of those calls it; test builds check after
    /// every publication that an unchanged key really means an unchanged info.
    pub(super) fn info_touched(&mut self) {
        self.info_touched = self.info_touched.wrapping_add(1);
    }

    /// The whole published state (as readers see it).
    pub fn snapshot(&self) -> GroupSnapshot {
        GroupSnapshot::from_parts(&self.motion(), &self.info())
    }

    /// Whether the info part changed since it was last published (`GroupState::info_key`);
    /// if so, it counts as published from now on.
    #[inline]
    pub fn info_changed(&mut self) -> bool {
        let key = self.info_key();
        if self.published_key == Some(key) {
            return false;
        }
        self.published_key = Some(key);
        true
    }
}

/// [`GroupState::info_key`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct InfoKey {
    error: i32,
    queued: usize,
    starts: u64,
    running: bool,
    phase: i32,
    feed: u64,
    touched: u64,
}

/// `COMMAND_INFO.nMotionPhase` of a running command: 0 accelerating, 1 at speed, 2
/// decelerating (general motion; 1 for the others).
fn motion_phase(r: &Running) -> i32 {
    match &r.cmd.plan {
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
    }
}

/// `COMMAND_INFO.dfFeedSpeed` of a running command: its feed, or what is left of a delay
/// (ms).
fn info_feed(r: &Running) -> f64 {
    match r.cmd.plan {
        Plan::Delay(s) => ((s - r.tau) * 1000.0).max(0.0),
        _ => r.cmd.info_feed,
    }
}
