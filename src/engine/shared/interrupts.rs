//! Interrupts on the shared state: raising a cause, the card peripherals' tick that collects the causes, a watchdog's reset of its card.

use super::Shared;
use crate::engine::isr::*;
use std::sync::atomic::Ordering;

impl Shared {
    /// Raises an interrupt cause on `card`; it is delivered at the end of the current
    /// tick (or of the next one when raised between ticks). Unknown cards are ignored.
    pub fn raise(&self, card: usize, i: Interrupt) {
        if let Some(p) = self.periph.get(card) {
            p.lock().raise(i);
        }
    }

    /// Runs every card's peripherals for one tick of `dt_ns` and takes the causes raised
    /// since the last delivery into `out` (cleared first). A watchdog that expired resets
    /// its card here (its groups abort and record [`ERR_WATCHDOG_RESET`], servo-on and
    /// position-ready go off). Returns whether every card was idle (nothing ran, no group
    /// was touched).
    #[inline]
    pub fn tick_peripherals(
        &self,
        dt_ns: u64,
        out: &mut Collected,
        groups: &mut [crate::engine::group::GroupState],
    ) -> bool {
        out.clear();
        // The idle cards' tick, counted for all of them at once; it runs when a card is
        // next locked (see `PeriphCells`).
        let counted = self.periph.count_idle_tick();
        let mut idle = true;
        for (card, p) in self.periph.cells().iter().enumerate() {
            if counted >> card & 1 == 0 {
                idle = false;
                self.tick_busy_card(card, p, dt_ns, out, groups);
            }
        }
        idle
    }

    /// [`Shared::tick_peripherals`] of a card that is not idle: its tick under its lock.
    #[inline(never)]
    fn tick_busy_card(
        &self,
        card: usize,
        p: &crate::card::PeriphCell,
        dt_ns: u64,
        out: &mut Collected,
        groups: &mut [crate::engine::group::GroupState],
    ) {
        let (reset, pending) = {
            let mut p = p.lock();
            let reset = p.tick(dt_ns);
            let pending = p.take_pending();
            (reset, pending)
        };
        if reset {
            self.reset_card(card, groups);
        }
        if let Some(pending) = pending {
            out.push(card, pending);
        }
    }

    /// The card-level part of a watchdog reset (the peripherals reset themselves).
    fn reset_card(&self, card: usize, groups: &mut [crate::engine::group::GroupState]) {
        self.outputs.servo_on[card].store(0, Ordering::Release);
        self.outputs.pos_ready[card].store(false, std::sync::atomic::Ordering::Release);
        for g in groups.iter_mut() {
            if g.def().card.0 == card {
                g.abort_within_period();
                g.set_error(ERR_WATCHDOG_RESET);
            }
            self.publish(g);
        }
    }
}
