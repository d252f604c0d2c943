//! The go home of one card as the engine runs it ([`Shared::start_homing`] and the rest):
//! which groups it takes over, the MC3B's own homing, aborting and cancelling it, its
//! tick with the machine locked, and what a tick of it does to the groups.

use super::Shared;
use crate::config::AXES;
use crate::engine::group::GroupState;
use crate::engine::homing;
use crate::error::{McclError, McclResult};
use crate::machine::Machine;
use std::sync::atomic::Ordering;

impl Shared {
    /// `MCC_Home`: starts homing the channels of `card` whose order is 0..7 (255 skips
    /// one) with the go-home parameters `cfgs`. `COMMAND_NOTFINISHED_ERR` while a homing
    /// runs or a group driving one of the channels is busy, `COMMAND_NOTACCEPTED_ERR` in
    /// dry run (nothing moves, so no sensor can be found). Nothing changes on an error.
    pub fn start_homing(
        &self,
        card: usize,
        orders: [i32; AXES],
        cfgs: &[crate::vendor::SYS_HOME_CONFIG; AXES],
    ) -> McclResult<()> {
        if self.outputs.dry_run.load(Ordering::Acquire) {
            return Err(McclError::NotAccepted);
        }
        if self.home.home_status.load(Ordering::Acquire) == homing::HOME_BUSY {
            return Err(McclError::NotFinished);
        }
        if self.home.mc3b_cards.load(Ordering::Acquire) & (1 << card) != 0 {
            return self.start_mc3b_homing(card, orders, cfgs);
        }
        let machine = self.lock_machine();
        let chans = machine.cards().get(card).ok_or(McclError::Parameter)?;
        let mut slot = self.home.homing.lock();
        if slot.is_some() {
            return Err(McclError::NotFinished);
        }
        let h = homing::Homing::new(card, orders, cfgs, chans);
        let chan_mask = h.channel_mask();
        let axes_of = |g: &GroupState| {
            (0..AXES).fold(0u32, |m, i| match g.axes()[i].channel {
                Some((c, ch)) if c == card && chan_mask & (1 << ch) != 0 => m | 1 << i,
                _ => m,
            })
        };
        // Every group driving a homed channel must be idle; mark them, undo on failure.
        let mut marked: Vec<usize> = Vec::new();
        let mut groups = self.lock_groups();
        for n in 0..groups.len() {
            let g = &mut groups[n];
            let mask = axes_of(g);
            if mask == 0 {
                continue;
            }
            if let Err(e) = g.begin_homing(mask) {
                for &m in &marked {
                    let g = &mut groups[m];
                    g.end_homing();
                    self.publish(g);
                }
                return Err(e);
            }
            self.publish(g);
            marked.push(n);
        }
        drop(groups);
        if chan_mask == 0 {
            self.home
                .home_status
                .store(homing::HOME_DONE, Ordering::Release);
        } else {
            *slot = Some(h);
            self.home
                .home_status
                .store(homing::HOME_BUSY, Ordering::Release);
        }
        Ok(())
    }

    /// `MCC_Home` on a card whose channels 0..2 are an MC3B: the device's own homing
    /// (`H`: seek the limit switch at the maximum velocity, back off and approach it at
    /// 10 steps/s), which is modes 9 and 16 of the manual; then phase 3 (`dfOffset`) as a
    /// move. `COMMAND_NOTACCEPTED_ERR` for another mode (the MC3B has no home sensor and
    /// no index input), a channel above 2, a channel no group drives, or a motor with no
    /// limit switch in the search direction (`mc3b_limit_bits`: it would seek for ever).
    fn start_mc3b_homing(
        &self,
        card: usize,
        orders: [i32; AXES],
        cfgs: &[crate::vendor::SYS_HOME_CONFIG; AXES],
    ) -> McclResult<()> {
        let homed: Vec<usize> = (0..AXES)
            .filter(|&c| orders[c] != homing::ORDER_SKIP)
            .collect();
        if homed.is_empty() {
            self.home
                .home_status
                .store(homing::HOME_DONE, Ordering::Release);
            return Ok(());
        }
        for g in self.lock_groups().iter_mut() {
            if g.def().card.0 != card || !g.is_external() {
                continue;
            }
            g.begin_external_home(&orders, cfgs)?;
            self.publish(g);
            self.home
                .mc3b_home_card
                .store(i32::try_from(card).unwrap_or(-1), Ordering::Release);
            self.home
                .home_status
                .store(homing::HOME_BUSY, Ordering::Release);
            return Ok(());
        }
        Err(McclError::NotAccepted)
    }

    /// `MCC_AbortGoHome`: the homing channels decelerate to a stop and the homing ends
    /// without completing. `HOME_COMMAND_NOTCALLED_ERR` when no homing was started (or
    /// the last one was aborted); `NO_ERR` after one completed.
    pub fn abort_homing(&self) -> McclResult<()> {
        if let Ok(card) = usize::try_from(self.home.mc3b_home_card.load(Ordering::Acquire)) {
            self.for_each_group(|g| {
                if g.def().card.0 == card {
                    g.abort_external_home();
                }
            });
            return Ok(());
        }
        match self.home.homing.lock().as_mut() {
            Some(h) => {
                h.abort();
                Ok(())
            }
            None if self.home.home_status.load(Ordering::Acquire) == homing::HOME_DONE => Ok(()),
            None => Err(McclError::HomeNotCalled),
        }
    }

    /// Drops a homing in progress (`MCC_ResetMotion`, `MCC_UpdateParam`): the channels
    /// stop where they are.
    pub(in crate::engine) fn cancel_homing(&self) {
        let mc3b = self.home.mc3b_home_card.swap(-1, Ordering::AcqRel) >= 0;
        if self.home.homing.lock().take().is_some() || mc3b {
            self.home
                .home_status
                .store(homing::HOME_NONE, Ordering::Release);
        }
    }

    /// `MCC_ResetMotion`: a go home in progress stops, and the status reads 0 as the
    /// vendor's library answers after a reset ([`homing::HOME_AFTER_RESET`]).
    pub(in crate::engine) fn reset_homing(&self) {
        self.cancel_homing();
        self.home
            .home_status
            .store(homing::HOME_AFTER_RESET, Ordering::Release);
    }

    /// One tick of the homing in progress (with the machine locked).
    pub(in crate::engine) fn tick_homing(
        &self,
        machine: &mut Machine,
        dt: f64,
    ) -> Option<homing::HomeTick> {
        // No lock on the tick's path while nothing is homed.
        if self.home.home_status.load(Ordering::Acquire) != homing::HOME_BUSY {
            return None;
        }
        let mut slot = self.home.homing.lock();
        let h = slot.as_mut()?;
        let card = h.card();
        let emergency = machine.emergency(card);
        let chans = machine.cards_mut().get_mut(card)?;
        let out = h.tick(chans, emergency, dt);
        if let Some(status) = out.finished {
            *slot = None;
            self.home.home_status.store(status, Ordering::Release);
        }
        Some(out)
    }
}
