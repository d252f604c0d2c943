//! Checks that compare a group's motion with the simulated machine after each tick
//! (user manual §2.4.1, §2.6.4, §2.7.3; examples manual §19): emergency stop, hardware
//! limit switches, tracking error, and pulse speed and acceleration limits.

use super::group::GroupState;
use crate::config::AXES;
use crate::error::{McclError, McclResult};
use crate::error_record::ErrorRecord;
use crate::machine::Machine;
use crate::vendor::consts as c;

/// Error record: emergency stop.
pub const ERR_EMERGENCY: i32 = ErrorRecord::EmergencyStop.code();
/// Error record: pulse speed over the limit.
pub const ERR_PULSE_SPEED: i32 = ErrorRecord::PulseSpeed.code();
/// Error record: pulse acceleration over the limit.
pub const ERR_PULSE_ACC: i32 = ErrorRecord::PulseAcc.code();
/// Error record: hardware limit switch, + axis.
pub const ERR_LIMIT: i32 = ErrorRecord::Limit(0).code();
/// Error record: tracking error, + axis.
pub const ERR_TRACKING: i32 = ErrorRecord::Tracking(0).code();
/// Error record: the library caught a panic of its own (a defect) and stopped the group
/// where it stood. Not in the vendor's table: its test programs report any unknown code
/// as "Run Time Error", which is what happened.
pub const ERR_INTERNAL: i32 = ErrorRecord::Internal.code();

/// A check that tripped: the group stops; `record` is its error record, if any.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Trip {
    /// The error record (`None`: the limit switch modes that only stop).
    pub record: Option<i32>,
}

/// Runs the checks for `g`; `limit_mode` is `MCC_EnableLimitSwitchCheck`'s mode or -1.
///
/// Limit switches (examples manual §19): moving toward an active switch always stops.
/// `HLP_BIDIR` (0) and `HLP_BIDIR_GEN_ERR` (2) also stop when either switch of a moving
/// axis becomes active, whatever its direction; `HLP_UNIDIR` (1) and
/// `HLP_UNIDIR_GEN_ERR` (3) only for the switch ahead. Modes 2 and 3 record
/// 0xF701 + axis (recover: `MCC_ClearError`, then move back out); modes 0 and 1 only stop
/// (recover: move back out).
pub fn check(g: &GroupState, m: &Machine, limit_mode: i32) -> Option<Trip> {
    let busy = g.busy();
    let vel = g.vel();
    for (i, ax) in g.axes().iter().enumerate() {
        let Some((card, ch)) = ax.channel else {
            continue;
        };
        let Some(chan) = m.channel(card, ch) else {
            continue;
        };
        if busy && m.emergency(card) {
            return Some(Trip {
                record: Some(ERR_EMERGENCY),
            });
        }
        if busy && limit_mode >= 0 {
            let (lv, prev) = (chan.levels(), chan.prev_levels());
            let v = vel[i];
            let mut hit = (lv.plus && v > 0.0) || (lv.minus && v < 0.0);
            if limit_mode == 0 || limit_mode == 2 {
                hit |= v != 0.0 && ((lv.plus && !prev.plus) || (lv.minus && !prev.minus));
            }
            if hit {
                let record = (limit_mode >= 2).then_some(ERR_LIMIT + i as i32);
                return Some(Trip { record });
            }
        }
        if let Some(limit) = g.checked_track_limit(i) {
            let f = ax.factor.abs();
            if f > 0.0 && (chan.error_count() as f64 / f).abs() > limit {
                return Some(Trip {
                    record: Some(ERR_TRACKING + i as i32),
                });
            }
        }
        if busy {
            let (d, dd) = chan.pulse_rate();
            if d.abs() > i64::from(chan.max_speed()) {
                return Some(Trip {
                    record: Some(ERR_PULSE_SPEED),
                });
            }
            if dd.abs() > i64::from(chan.max_acc()) {
                return Some(Trip {
                    record: Some(ERR_PULSE_ACC),
                });
            }
        }
    }
    None
}

/// A hardware limit switch check mode from `MCC_EnableLimitSwitchCheck`: `HLP_BIDIR`,
/// `HLP_UNIDIR`, `HLP_BIDIR_GEN_ERR` or `HLP_UNIDIR_GEN_ERR`; anything else is
/// `PARAMETER_ERR`.
pub fn limit_check_mode(mode: i32) -> McclResult<i32> {
    if !(c::HLP_BIDIR..=c::HLP_UNIDIR_GEN_ERR).contains(&mode) {
        return Err(McclError::Parameter);
    }
    Ok(mode)
}

/// Whether the safety checks read the channels this tick: a check of every moving group
/// is on (the limit switches, an emergency stop, a pulse limit), or a group has checks of its own (`group_checks`: some
/// group's [`GroupState::has_safety_checks`], which the tick gathers as it ticks them).
#[inline]
pub fn reads_channels(limit_mode: i32, machine: &Machine, group_checks: bool) -> bool {
    group_checks || global_checks(limit_mode, machine)
}

/// The checks that need the machine, over every group: emergency stop (0xF102), hardware
/// limit switches (0xF701 + axis in the `_GEN_ERR` modes of `limit_mode`, −1 off),
/// tracking error (0xF801 + axis), pulse speed and acceleration limits (0xF203, 0xF204),
/// and the in-position check of the command ending. A check that trips stops the group
/// at once (its queue is dropped); `changed` is called for each group a check changed.
/// With no check to make ([`reads_channels`] false) it does nothing, and the tick does
/// not call it.
pub fn check_groups(
    machine: &Machine,
    groups: &mut [GroupState],
    limit_mode: i32,
    dt: f64,
    mut changed: impl FnMut(&mut GroupState),
) {
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
            changed(g);
        }
        if let Some(code) = check(g, machine, limit_mode) {
            g.stop_for(code.record);
            changed(g);
        }
    }
}

/// Whether a check of every moving group is on: the hardware limit switches (`mode`, −1
/// off), an emergency stop, a pulse limit.
fn global_checks(limit_mode: i32, machine: &Machine) -> bool {
    limit_mode >= 0 || machine.any_emergency() || machine.pulse_limits_set()
}

#[cfg(test)]
mod mode_tests {
    use super::*;

    #[test]
    fn limit_check_modes_are_the_four_hlp_values() {
        // HLP_BIDIR 0, HLP_UNIDIR 1, HLP_BIDIR_GEN_ERR 2, HLP_UNIDIR_GEN_ERR 3.
        for m in 0..=3 {
            assert_eq!(limit_check_mode(m), Ok(m));
        }
        assert_eq!(limit_check_mode(4), Err(McclError::Parameter));
        assert_eq!(limit_check_mode(-1), Err(McclError::Parameter));
    }
}
