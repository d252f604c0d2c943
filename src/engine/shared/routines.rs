//! The per-period routines on the shared state: whether any may run, and calling them.

use super::Shared;
use crate::engine::cycle::*;

impl Shared {
    /// Whether any routine (interrupt, cycle or INTERP) may run after a tick.
    pub fn routines_any(&self) -> bool {
        self.routines.isr.any() || self.routines.cycle.any()
    }

    /// Calls the routines of the module documentation. Call with no lock held.
    pub(in crate::engine) fn call_cycle_routines(&self) {
        if self.routines.cycle.reverse_armed() {
            for n in 0..self.group_count() {
                if self.clock.stopped() {
                    return;
                }
                let due = self.nth_group(n).and_then(|mut g| g.take_reverse_call());
                if let Some((f, group, cmd, time)) = due {
                    // SAFETY: the group stored `f` from a non-null `INTERP`.
                    let r = unsafe { call_interp(f, group, cmd, time) };
                    if let Some(mut g) = self.nth_group(n) {
                        g.set_reverse_decision(r);
                    }
                }
            }
        }
        if !self.clock.stopped() {
            self.routines.cycle.call_cycle();
        }
    }
}
