//! Cruise ticks: the ticks of a quiet virtual run in which every group only moves along
//! (or stands idle), run without the checks of a full tick that cannot come true.
//!
//! Under a virtual clock with nothing between ticks ([`Shared::quiet_between_ticks`]) the
//! engine thread keeps the machine's and the groups' locks from one tick to the next, so
//! only the ticks change the groups and the channels. When every group is certain, for
//! some ticks ahead, to cruise in the middle of one command or to stand idle
//! ([`GroupState::quiet_ticks_ahead`]), and the machine has nothing to do that such a
//! tick would need (no card armed, no safety check, no homing, no trace), those ticks
//! are cruise ticks: [`Shared::tick`] with the steps it would find nothing to do for left
//! out (each group's period, its channels commanded, the channels' steps deferred, the
//! status or the motion part published, the peripherals): one definition of a tick, one
//! plan of which steps run. What the other threads may change at any time (a lock wanted, a
//! routine registered, a limit check, a view asked for, the end of the run) is asked
//! before every tick, as the full tick asks it.
//!
//! A group cruises only while the info it last published holds (its key, see
//! `group/status.rs`), so that a cruise tick that publishes stores the motion part
//! without looking at the info: after a command starts or ends, or its phase changes,
//! the group waits for the next full tick that publishes (at most [`PUBLISH_EVERY`]
//! ticks under a quiet virtual clock).
//!
//! `MCCL_CRUISE=0` turns cruise ticks off (every tick full), to compare.

use super::homing::HOME_BUSY;
use super::shared::Shared;
use super::tick::{Held, PUBLISH_EVERY};
use mccl_core::engine::tick as card_tick;
use std::sync::atomic::Ordering;

/// The most ticks one plan covers: the plan (which copies each group's line,
/// `GroupState::prepare_cruise`) costs about one operation a group a tick at this length.
const PLAN_TICKS: u32 = 256;

/// After a plan that found no cruise tick ahead, the quiet ticks that pass before the next
/// plan: a group that cannot cruise (starting, blending, ramping its rate, checking its
/// position) stays so for some ticks, and a plan asks every group.
const REPLAN_AFTER: u32 = 8;

/// Whether cruise ticks are on for engines started from now on: `MCCL_CRUISE` unset or
/// anything but `0`.
pub(super) fn enabled_by_env() -> bool {
    std::env::var("MCCL_CRUISE").map_or(true, |v| v.trim() != "0")
}

impl Shared {
    /// At the end of a quiet tick, before it is counted: whether the next tick is a cruise
    /// tick. It must be inside the run and not its last (which publishes everything), with
    /// no homing, no limit check and no view to copy; the groups and the machine are
    /// planned for when the last plan ran out (see [`Shared::plan_cruise`]).
    pub(super) fn cruise_next(&self, held: &mut Option<Held<'_>>) -> bool {
        let Some(h) = held.as_mut() else {
            return false;
        };
        if !self.cruise.cruise_enabled || !self.clock.next_is_inside_run() {
            return false;
        }
        if self.home.home_status.load(Ordering::Acquire) == HOME_BUSY
            || self.outputs.limit_check.load(Ordering::Relaxed) >= 0
        {
            return false;
        }
        let next = self.clock.ticks().wrapping_add(1);
        if self.publishes_everything(next) && self.view.may_be_due() {
            return false;
        }
        if h.state.cruise_left() == 0 {
            if h.replan_in > 0 {
                h.replan_in -= 1;
                return false;
            }
            let ahead = self.plan_cruise(h);
            h.state.plan_cruise(ahead);
            if h.state.cruise_left() == 0 {
                h.replan_in = REPLAN_AFTER;
            }
        }
        h.state.cruise_left() > 0
    }

    /// Whether virtual tick `n` (not the last of its run) publishes every snapshot, as
    /// [`Shared::tick`] decides it.
    #[inline]
    pub(super) fn publishes_everything(&self, n: u64) -> bool {
        self.routines.live_snapshots.load(Ordering::Relaxed) || n % PUBLISH_EVERY == 0
    }

    /// How many ticks from the next are cruise ticks for the groups and the machine (0:
    /// the next is not): what only the program changes (under the locks `held` holds) or
    /// the ticks themselves. Every card idle (nothing armed), no safety check reading the
    /// channels, no trace, every group quiet ahead.
    fn plan_cruise(&self, held: &mut Held<'_>) -> u32 {
        if self.tracer.tracing {
            return 0;
        }
        let h = &mut *held;
        card_tick::cruise_ahead(
            &h.machine,
            &mut h.groups,
            &mut h.state,
            self.clock.period_s(),
            self.limit_check(),
            PLAN_TICKS,
        )
    }

    /// How many ticks of this engine were cruise ticks (for tests and benchmarks).
    pub fn cruise_ticks(&self) -> u64 {
        self.cruise.cruise_ticks.load(Ordering::Relaxed)
    }
}
