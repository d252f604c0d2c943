//! What the group shows: its motion status, the published motion and info parts, the
//! pulses of its axes.

use super::execution::HOLD_SHOWN_AFTER;
use super::running::{Progress, Running, Stage};
use super::track::Phase;
use super::GroupState;
use super::Mode;
use crate::config::AXES;
use crate::engine::command::ctype;
use crate::engine::snapshot::{axis_pulses, GroupSnapshot, Info, Motion, SnapshotCell};
use crate::machine::Channel;
use crate::vendor::consts as c;
use crate::vendor::COMMAND_INFO;

/// What the group last published and what tells whether its info changed since.
#[derive(Debug)]
pub(super) struct Publishing {
    /// Changes of the info other than its running command's phase and feed: a command
    /// queued, taken from the queue, started or ended, the queue dropped, the error
    /// record set or cleared, the running command's end or the offset changed
    /// ([`GroupState::info_touched`]).
    pub(super) info_changes: u64,
    /// The own time of the newest running command (the back of `running`), kept by every
    /// writer of an own time, for the published key's check
    /// ([`GroupState::info_changed`]): finding the back of the deque cost it 11
    /// instructions a publication. Meaningless while nothing runs.
    pub(super) newest_own_time: f64,
    /// The info key last published and how long it holds ([`GroupState::info_changed`]).
    pub(super) key: PublishedKey,
    /// The info last published, kept in test builds to check the key against it.
    #[cfg(debug_assertions)]
    pub(super) info: Option<crate::engine::snapshot::Info>,
}

impl Default for Publishing {
    /// Nothing published yet.
    fn default() -> Publishing {
        Publishing {
            info_changes: 0,
            newest_own_time: 0.0,
            key: PublishedKey::NONE,
            #[cfg(debug_assertions)]
            info: None,
        }
    }
}

impl GroupState {
    pub(super) fn update_status(&mut self) {
        if self.homing != 0 {
            // Homing axes move (or wait for the others) until the homing ends.
            self.status = c::GMS_RUNNING;
            return;
        }
        let active = !self.exec.running.is_empty()
            || !self.queued.commands.is_empty()
            || self.exec.jump.is_some()
            || self.exec.lag > 0
            || self.exec.lag_shown
            || self.in_pos.wait.is_some_and(|w| w.blocks())
            || self.features.external.as_ref().is_some_and(|x| x.active())
            || self.post_active();
        // A held motion reads held from its third held period, a held delay from its
        // second (the vendor's library shows the first as running) [`hold_delay_*`].
        let held_shown = self.exec.running.iter().any(|r| match r.stage {
            Stage::Held { periods, .. } if r.is_delay() => periods >= 2,
            Stage::Held { periods, .. } => periods >= HOLD_SHOWN_AFTER,
            _ => false,
        });
        self.status = if !active {
            if matches!(
                self.rate.mode,
                Mode::Held | Mode::HoldAtBlockEnd | Mode::Aborting
            ) {
                if self.rate.mode == Mode::Aborting {
                    // A timed abort stopped off the plan: what comes next starts here.
                    self.queued.end = self.exec.pos;
                }
                self.rate.mode = Mode::Normal;
            }
            c::GMS_STOP
        } else if held_shown
            || (self.exec.running.is_empty()
                && ((self.error != 0 && !self.queued.commands.is_empty())
                    || self.rate.mode == Mode::Held
                    || (self.queued.single_block && !self.queued.single_block_credit)))
        {
            // Held and at rest, or commands waiting that an error, a hold at a block's
            // end or single-block mode keeps back.
            c::GMS_HOLD
        } else if self
            .exec
            .running
            .front()
            .is_some_and(|r| r.is_delay() && r.stage == Stage::Moving)
        {
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
        let pos = if self.features.post.is_some() {
            self.out_pos()[i]
        } else {
            self.exec.pos[i]
        };
        self.pulses_at(i, pos)
    }

    /// The pulses of axis `i` at output position `pos`: the reference position (with the
    /// offset) times the pulses per UU, rounded halves away from zero.
    #[inline]
    fn pulses_at(&self, i: usize, pos: f64) -> i64 {
        axis_pulses(pos, self.exec.offset[i], self.mech.axes[i].factor)
    }

    /// The card of the channels this group commands and those channels, one bit each
    /// (what [`GroupState::command_channels`] may set).
    pub fn commanded_channels(&self) -> (usize, u8) {
        let c = &self.mech.commanded;
        (c.card(), c.channel_mask())
    }

    /// Commands the channels this group commands (`commanded`: axes each with a channel
    /// of its card) with their axes' pulses this tick ([`GroupState::pulses`]); `cards`
    /// are the machine's channels. A card not in `cards` is passed over.
    ///
    /// One loop for the whole group, with what [`GroupState::pulses`] asks of every axis
    /// (kinematics, filters) and the card asked once: this runs every tick for every
    /// commanding group.
    #[inline(always)]
    pub fn command_channels(&mut self, cards: &mut [[Channel; AXES]]) {
        if self.exec.rezero == super::Rezero::Channels {
            self.exec.rezero = super::Rezero::No;
            if let Some(chans) = cards.get_mut(self.mech.commanded.card()) {
                for (_, ch) in self.mech.commanded.pairs() {
                    chans[ch].rezero();
                }
            }
        }
        let commanded = &self.mech.commanded;
        // Most groups sharing a card's channels command none of them (the last mapping
        // wins): asked first, before the card is looked up.
        if commanded.is_empty() {
            return;
        }
        let Some(chans) = cards.get_mut(commanded.card()) else {
            return;
        };
        if self.features.kin.is_none() && self.features.post.is_none() {
            if commanded.is_identity() {
                // Every axis to its own channel: no pair to look up, the same pulses.
                for (i, chan) in chans.iter_mut().enumerate() {
                    chan.command(self.pulses_at(i, self.exec.pos[i]));
                }
            } else {
                for (i, ch) in commanded.pairs() {
                    chans[ch].command(self.pulses_at(i, self.exec.pos[i]));
                }
            }
        } else {
            for (i, ch) in commanded.pairs() {
                chans[ch].command(self.pulses(i));
            }
        }
    }

    /// The compensation pulses the channels it commands add to their commands this tick
    /// (0 for the others), kept for [`GroupState::comp_pulses`].
    pub fn read_compensation(&mut self, cards: &mut [[Channel; AXES]]) {
        let mut comp = [0; AXES];
        if let Some(chans) = cards.get_mut(self.mech.commanded.card()) {
            for (i, ch) in self.mech.commanded.pairs() {
                comp[i] = chans[ch].compensation_now();
            }
        }
        self.exec.comp = comp;
    }

    /// The compensation pulses per axis of the last [`GroupState::read_compensation`].
    pub fn comp_pulses(&self) -> [i32; AXES] {
        self.exec.comp
    }

    /// The part of the published state that changes every tick.
    #[inline]
    pub fn motion(&self) -> Motion {
        // A kinematic group whose planner is in Cartesian space publishes its joints.
        if let Some(m) = self.kinematics_published() {
            return m;
        }
        // The output position and velocity (after the filters, `post.rs`); readers derive
        // the path speed from the velocities and the compose mask.
        Motion {
            status: self.status,
            pos: self.out_pos(),
            vel: self.out_vel(),
            feed: self.out_feed(),
        }
    }

    /// Publishes [`GroupState::motion`] to `cell`: straight from the group's fields when
    /// its output is its reference (no filter stage, no kinematics), which is what
    /// `motion` copies then.
    #[inline]
    pub fn store_motion(&self, cell: &SnapshotCell) {
        if self.output_is_reference() && self.features.kin.is_none() {
            cell.store_motion_parts(
                self.status,
                &self.exec.pos,
                &self.exec.vel,
                self.exec.feed_now,
            );
        } else {
            self.store_filtered_motion(cell);
        }
    }

    /// [`GroupState::store_motion`] of a group with filter stages or kinematics, out of
    /// line: the motion it assembles would give every publication a stack frame.
    #[inline(never)]
    fn store_filtered_motion(&self, cell: &SnapshotCell) {
        cell.store_motion(&self.motion());
    }

    /// The part of the published state that changes when commands start or end. With
    /// nothing running, `MCC_GetCurCommand` reports `RUN_TIME_ERR` with the index of the
    /// last command started (as the vendor's library does).
    pub fn info(&self) -> Info {
        let blending = self.exec.running.len() > 1;
        let last = self.queued.index.last_started;
        let cmd = match self.exec.running.back() {
            Some(r) => COMMAND_INFO {
                nType: r.cmd.ctype,
                nCommandIndex: r.cmd.index,
                dfFeedSpeed: info_feed(r, self.exec.period_s),
                // A delay or a switch has no target: the vendor's library shows zeros.
                dfPos: if r.cmd.is_motion() {
                    r.cmd.target
                } else {
                    [0.0; AXES]
                },
                dfAcctime: r.cmd.acc_ms,
                dfDectime: r.cmd.dec_ms,
                nMotionPhase: motion_phase(r, blending),
                nCommandIndex_LD: last.map_or(0, |l| l.1),
            },
            None => COMMAND_INFO {
                nType: 0,
                nCommandIndex: last.map_or(0, |l| l.0),
                nCommandIndex_LD: last.map_or(0, |l| l.1),
                ..Default::default()
            },
        };
        Info {
            error: self.error,
            queued: i32::try_from(self.queued.commands.len()).unwrap_or(i32::MAX),
            running: self.exec.running.back().is_some(),
            cmd,
            offset: self.exec.offset,
            factor: self.mech.axes.map(|a| a.factor),
        }
    }

    /// What [`GroupState::info`] depends on that can change while the group runs: equal
    /// keys mean equal infos, so publishing compares a count of changes instead of building
    /// and comparing the whole info every tick. The rest of the info changes only with a
    /// command start (counted with the other changes, [`GroupState::info_touched`]) or
    /// a reset (which publishes afresh).
    #[inline]
    pub(super) fn info_key(&self) -> InfoKey {
        let back = self.exec.running.back();
        let blending = self.exec.running.len() > 1;
        InfoKey {
            changes: self.publishing.info_changes,
            running: back.is_some(),
            phase: back.map_or(0, |r| motion_phase(r, blending)),
            feed: back.map_or(0, |r| info_feed(r, self.exec.period_s).to_bits()),
        }
    }

    /// Records a change of what the info shows other than the running command's phase
    /// and feed: the queue's length (`enqueue`, `pop_queued`, `clear_queue`), a command
    /// started or ended, the error record set or cleared, the running command's end
    /// (custom motion), the offset between user and reference positions. Every writer of
    /// those calls it; test builds check after every publication that an unchanged key
    /// really means an unchanged info.
    pub(super) fn info_touched(&mut self) {
        self.publishing.info_changes = self.publishing.info_changes.wrapping_add(1);
    }

    /// The whole published state (as readers see it).
    pub fn snapshot(&self) -> GroupSnapshot {
        GroupSnapshot::from_parts(&self.motion(), &self.info())
    }

    /// Whether the info part changed since it was last published (`GroupState::info_key`);
    /// if so, it counts as published from now on.
    #[inline]
    pub fn info_changed(&mut self) -> bool {
        if self.published_key_holds() {
            debug_assert_eq!(
                self.publishing.key.key,
                self.info_key(),
                "group {}: the published key was taken to hold",
                self.index
            );
            return false;
        }
        self.renew_published_key()
    }

    /// [`GroupState::info_changed`] once the quick check found the key may have changed:
    /// builds it and keeps it with the stretch it holds for. Out of line: the quick check
    /// is all most publications need.
    #[inline(never)]
    fn renew_published_key(&mut self) -> bool {
        let key = self.info_key();
        let until = self
            .exec
            .running
            .back()
            .map_or(f64::INFINITY, key_holds_until);
        let renewed = PublishedKey {
            key,
            until,
            published: true,
        };
        // Two stores of the same record, not one after a `changed` flag: compiled that
        // way, every publication paid 4 instructions more (callgrind).
        if self.publishing.key.published && self.publishing.key.key == key {
            self.publishing.key = renewed;
            return false;
        }
        self.publishing.key = renewed;
        true
    }

    /// Whether `GroupState::info_key` is still the key last published, found without
    /// building it: the count of changes is the same (so no command started or ended
    /// since: each counts as a change), and the own time of the running command at the
    /// back, kept as `newest_own_time`, has not reached the
    /// end of the stretch over which its phase and feed stay as published
    /// (`key_holds_until`); with no command running that end is infinite. Nothing was
    /// published yet: the end is −∞, which no own time is below.
    #[inline]
    pub fn published_key_holds(&self) -> bool {
        let p = &self.publishing.key;
        debug_assert_eq!(
            self.exec
                .running
                .back()
                .map(|r| (r.periods as f64).to_bits()),
            (!self.exec.running.is_empty()).then_some(self.publishing.newest_own_time.to_bits()),
            "group {}: newest_own_time is stale",
            self.index
        );
        p.key.changes == self.publishing.info_changes && self.publishing.newest_own_time < p.until
    }

    /// While the published key holds, the own time of the running command from which it
    /// may not ([`GroupState::published_key_holds`]); `None` when it does not hold now.
    pub(super) fn published_key_holds_below(&self) -> Option<f64> {
        self.published_key_holds()
            .then_some(self.publishing.key.until)
    }
}

/// The info key last published ([`GroupState::info_changed`]) and the own time of the
/// running command up to which its time-dependent words (phase, feed) stay the same.
#[derive(Debug, Clone, Copy)]
pub(super) struct PublishedKey {
    key: InfoKey,
    /// Own times below this hold the key ([`key_holds_until`]); −∞ before the first
    /// publication.
    until: f64,
    /// Whether `key` was published (not [`PublishedKey::NONE`]).
    published: bool,
}

impl PublishedKey {
    /// Nothing published yet: no own time holds it.
    pub(super) const NONE: PublishedKey = PublishedKey {
        key: InfoKey {
            changes: 0,
            running: false,
            phase: 0,
            feed: 0,
        },
        until: f64::NEG_INFINITY,
        published: false,
    };
}

/// The own time (periods run) of running command `r` up to which [`motion_phase`] and
/// [`info_feed`] give what they give now: the end of the acceleration, the start of the
/// deceleration, the arrival of a general motion or of a PtP's last axis; the current
/// period for anything else (a delay's time left changes every period; stages change).
fn key_holds_until(r: &Running) -> f64 {
    let now = r.periods as f64;
    if r.stage != Stage::Moving || r.blended_from.is_some() {
        return now;
    }
    let more = match &r.progress {
        Progress::Path { track, .. } => track.periods_in_phase(),
        Progress::Axes { tracks, master, .. } => tracks[*master].periods_left().saturating_sub(1),
        _ => 0,
    };
    now + more as f64 + 1.0
}

/// [`GroupState::info_key`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct InfoKey {
    /// [`GroupState::info_touched`]'s count.
    changes: u64,
    /// What the running command at the back of `running` shows (none: false, 0, 0).
    running: bool,
    phase: i32,
    feed: u64,
}

/// `COMMAND_INFO.nMotionPhase` of a running command, as the vendor's library numbers
/// them: 11 accelerating, 13 at speed, 12 decelerating, 21 the period after arriving, 22
/// a general motion held (a held PtP reads 0, as the vendor's library shows it); while a
/// general motion blends out of the one before, 17 (line after line), 18
/// (line after arc) or 19 (arc after line); 0 for what has no phases (PtP, delay,
/// switches).
fn motion_phase(r: &Running, blending: bool) -> i32 {
    match r.stage {
        Stage::Ending { .. } if r.quiet_end => return 0,
        Stage::Ending { .. } if r.path_track().is_some() => return 21,
        Stage::Held { .. } if r.path_track().is_some() => return 22,
        Stage::Stopping { .. } if r.path_track().is_some() => return 12,
        _ => {}
    }
    let Some(track) = r.path_track() else {
        return 0;
    };
    if let (true, Some(from)) = (blending, r.blended_from) {
        let arc = |t: i32| (ctype::ARC_CW..=ctype::HELIX_CCW).contains(&t);
        return match (arc(from), arc(r.cmd.ctype)) {
            (true, false) => 18,
            (false, true) => 19,
            _ => 17,
        };
    }
    match track.phase() {
        Phase::Accelerating => 11,
        Phase::Cruising => 13,
        Phase::Decelerating => 12,
    }
}

/// `COMMAND_INFO.dfFeedSpeed` of a running command: its feed, or what is left of a delay
/// (ms) with a period of `period_s`.
fn info_feed(r: &Running, period_s: f64) -> f64 {
    match r.progress {
        Progress::Delay { left } => left as f64 * period_s * 1000.0,
        _ => r.cmd.info_feed,
    }
}

#[cfg(test)]
mod tests {
    use super::super::test_group;

    #[test]
    fn the_published_key_holds_exactly_while_the_info_stays_the_same() {
        // A line of 10 UU along X at 10 UU/s with 100 ms ramps (T-curve): accelerating
        // for 0.1 s, at speed until its deceleration starts at 1.0 s (10 UU = 10 UU/s x
        // (T - 0.1 s), T = 1.1 s), decelerating to 1.1 s. Published every 1 ms tick, the
        // info changes (and must be published) when the line starts, at 0.1 s (phase
        // 0 -> 1), at 1.0 s (1 -> 2) and when it ends; on every other tick the key must
        // be found to hold without being built.
        let mut g = test_group();
        let mut target = g.ctx().from;
        target[0] = 10.0;
        let cmd = g.ctx().line(target).expect("line");
        g.enqueue(cmd).expect("queued");
        let mut published = None;
        let (mut changes, mut phases) = (Vec::new(), Vec::new());
        for tick in 1..=1300 {
            g.tick(0.001);
            let holds = g.published_key_holds();
            let changed = g.info_changed();
            let info = g.info();
            assert_eq!(
                changed,
                published.as_ref() != Some(&info),
                "tick {tick}: published again exactly when the info changed"
            );
            if holds {
                assert_eq!(g.publishing.key.key, g.info_key(), "tick {tick}");
            }
            if changed {
                changes.push(tick);
                phases.push((info.cmd.nType, info.cmd.nMotionPhase));
                published = Some(info);
            }
        }
        // The first tick starts the line (the first publication) in its acceleration
        // (phase 11), then cruise (13) 100 ticks later, deceleration (12) 900 after,
        // the period that ends it (21) 100 after, and the next, with nothing running
        // (the vendor's library reads type 0, phase 0 then).
        assert_eq!(changes, [1, 101, 1001, 1101, 1102]);
        let line = crate::engine::command::ctype::LINE;
        assert_eq!(
            phases,
            [(line, 11), (line, 13), (line, 12), (line, 21), (0, 0)]
        );
    }
}
