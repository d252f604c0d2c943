//! The safety checks of a tick over the shared state: the machine's limits, emergency and tracking checked against every group.

use super::Shared;
use crate::config::AXES;
use crate::engine::group::GroupState;
use crate::engine::safety::*;
use crate::machine::Machine;
use std::sync::atomic::Ordering;

impl Shared {
    /// Turns the hardware limit switch check on in `mode` (see [`limit_check_mode`]) or,
    /// with `None`, off.
    pub fn set_limit_check(&self, mode: Option<i32>) {
        self.outputs
            .limit_check
            .store(mode.unwrap_or(-1), Ordering::Release);
    }

    /// Whether [`Shared::safety`] may read the channels this tick: a check of every moving
    /// group is on, or a group has checks of its own (`group_checks`: some group's
    /// [`GroupState::has_safety_checks`], which the tick gathers as it ticks them).
    pub(in crate::engine) fn safety_reads_channels(
        &self,
        machine: &Machine,
        group_checks: bool,
    ) -> bool {
        group_checks || global_checks(self.outputs.limit_check.load(Ordering::Relaxed), machine)
    }

    /// The checks that need the machine: emergency stop (0xF102), hardware limit
    /// switches (0xF701 + axis in the `_GEN_ERR` modes), tracking error (0xF801 + axis),
    /// pulse speed and acceleration limits (0xF203, 0xF204). A check that trips stops the
    /// group at once (its queue is dropped). With no check to make
    /// ([`Shared::safety_reads_channels`] false) it does nothing, and the tick does not
    /// call it.
    pub(in crate::engine) fn safety(
        &self,
        machine: &Machine,
        groups: &mut [GroupState],
        full: bool,
        dt: f64,
    ) {
        let limit_mode = self.outputs.limit_check.load(Ordering::Relaxed);
        // Checks every moving group needs; otherwise only groups with checks of their own
        // (tracking error, in-position) are looked at again.
        let global = global_checks(limit_mode, machine);
        for g in groups.iter_mut() {
            if !global && !g.has_safety_checks() {
                continue;
            }
            if (!g.busy() && !g.has_safety_checks()) || g.homing() != 0 {
                // Homing watches its own limit switches and emergency stop.
                continue;
            }
            if g.inpos_waiting() {
                let mask = g.inpos_mask_waiting();
                let errs: [Option<f64>; AXES] = std::array::from_fn(|i| {
                    let (card, ch) = g.axes()[i].channel?;
                    let chan = machine.channel(card, ch)?;
                    let f = g.axes()[i].factor.abs();
                    (mask & (1 << i) != 0 && f > 0.0).then(|| chan.error_count() as f64 / f)
                });
                g.check_inpos(&errs, dt);
                self.publish_or_status(g, full);
            }
            if let Some(code) = check(g, machine, limit_mode) {
                g.stop_for(code.record);
                self.publish_or_status(g, full);
            }
        }
    }
}

/// Whether a check of every moving group is on: the hardware limit switches (`mode`
/// from [`Shared::set_limit_check`], −1 off), an emergency stop, a pulse limit.
fn global_checks(limit_mode: i32, machine: &Machine) -> bool {
    limit_mode >= 0 || machine.any_emergency() || machine.pulse_limits_set()
}
