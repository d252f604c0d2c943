//! What the program's calls set and read on the running card beside its groups: the
//! servo-on and position-ready outputs, the dry run, the pulse FIFO's depth, the routines
//! registered (and so whether snapshots are published every tick), and the card's parts
//! (clock, peripherals, observer's view) each behind its own methods.

use super::Shared;
use crate::card::PeriphCell;
use crate::clock::Clock;
use crate::engine::isr::Kind;
use crate::engine::view::ViewCell;
use std::sync::atomic::Ordering;

impl Shared {
    /// The tick clock.
    pub fn clock(&self) -> &Clock {
        &self.clock
    }

    /// Number of cards passed to `MCC_InitSystem`.
    pub fn cards(&self) -> usize {
        self.periph.cells().len()
    }

    /// The peripherals of card `card` (timer, watchdog, converters, remote I/O), if any.
    pub fn periph(&self, card: usize) -> Option<&PeriphCell> {
        self.periph.get(card)
    }

    /// The peripherals of every card, in card order.
    pub fn periphs(&self) -> &[PeriphCell] {
        self.periph.cells()
    }

    /// What an observer (the browser panel) sees beyond the snapshots.
    pub fn view(&self) -> &ViewCell {
        &self.view
    }

    /// Sets (`on`) or clears the servo-on output of the channels in `mask` of `card`
    /// (`MCC_SetServoOn`/`Off`); an unknown card is ignored.
    pub fn set_servo_on(&self, card: usize, mask: u32, on: bool) {
        if let Some(s) = self.outputs.servo_on.get(card) {
            if on {
                s.fetch_or(mask, Ordering::AcqRel);
            } else {
                s.fetch_and(!mask, Ordering::AcqRel);
            }
        }
    }

    /// The servo-on outputs of `card`, one bit a channel (0 for an unknown card).
    pub fn servo_on(&self, card: usize) -> u32 {
        self.outputs
            .servo_on
            .get(card)
            .map_or(0, |s| s.load(Ordering::Acquire))
    }

    /// Sets the position-ready output of `card` (`MCC_EnablePosReady`/`Disable`).
    pub fn set_pos_ready(&self, card: usize, on: bool) {
        if let Some(p) = self.outputs.pos_ready.get(card) {
            p.store(on, Ordering::Release);
        }
    }

    /// The position-ready output of `card` (false for an unknown card).
    pub fn pos_ready(&self, card: usize) -> bool {
        self.outputs
            .pos_ready
            .get(card)
            .is_some_and(|p| p.load(Ordering::Acquire))
    }

    /// Turns the dry run on or off (`MCC_EnableDryRun`/`Disable`): the plan runs, nothing
    /// is sent to the channels.
    pub fn set_dry_run(&self, on: bool) {
        self.outputs.dry_run.store(on, Ordering::Release);
    }

    /// Whether a dry run is in effect.
    pub fn dry_run(&self) -> bool {
        self.outputs.dry_run.load(Ordering::Acquire)
    }

    /// Sets the pulse FIFO depth reported while moving (`MCC_SetMaxPulseStockNum`).
    pub fn set_max_pulse_stock(&self, n: u32) {
        self.outputs.max_pulse_stock.store(n, Ordering::Relaxed);
    }

    /// The pulse FIFO depth reported while moving.
    pub fn max_pulse_stock(&self) -> u32 {
        self.outputs.max_pulse_stock.load(Ordering::Relaxed)
    }

    /// Registers the interrupt routine at address `f` (0 unregisters) of `kind` on `card`.
    /// Routines run between ticks and may read positions: while any is registered,
    /// snapshots are published every tick.
    pub fn set_interrupt_routine(&self, card: usize, kind: Kind, f: usize) {
        self.routines.isr.set(card, kind, f);
        self.publish_every_tick(false);
    }

    /// The interrupt routine of `kind` registered on `card` (its address, 0: none).
    pub fn interrupt_routine(&self, card: usize, kind: Kind) -> usize {
        self.routines.isr.get(card, kind)
    }

    /// Registers the cycle routine at address `f` (0 unregisters), publishing snapshots
    /// every tick while any routine is registered.
    pub fn set_cycle_routine(&self, f: usize) {
        self.routines.cycle.set_cycle(f);
        self.publish_every_tick(false);
    }

    /// Publishes every snapshot every tick (`on`), as while a routine is registered, or
    /// returns to what the routines registered ask (what every registration calls): for
    /// an observer that reads between the ticks of a virtual run, and for measuring what
    /// publishing costs.
    pub fn publish_every_tick(&self, on: bool) {
        self.routines
            .live_snapshots
            .store(on || self.routines_any(), Ordering::Relaxed);
    }

    /// Notes that a group has an INTERP routine from now on: the engine looks for its
    /// calls, and snapshots are published every tick.
    pub fn arm_reverse_routines(&self) {
        self.routines.cycle.arm_reverse();
        self.publish_every_tick(false);
    }
}
