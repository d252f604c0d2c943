//! Go home on an MC3B: the device's own homing per order of channels, then the moves to
//! the working homes.

use crate::config::AXES;
use crate::engine::command::AxisMech;
use crate::engine::snapshot::round_pulses;
use crate::error::{McclError, McclResult};
use crate::mc3b::backend::{self, Job, Ramp, Speeds, MOTORS};
use std::collections::VecDeque;

/// A go home on the MC3B: its own homing (`H`) per order of channels, then the moves to
/// the working homes; the motors' positions read 0 at the end.
#[derive(Debug)]
pub(super) struct HomeRun {
    /// Jobs still to run, in order.
    pub(super) stages: VecDeque<Job>,
    /// The job running.
    pub(super) current: Option<u64>,
    /// The motors homed.
    pub(super) motors: [bool; MOTORS],
    /// `MCC_AbortGoHome` asked for a stop.
    pub(super) aborted: bool,
    /// How it ended (`HOME_DONE`, `HOME_NONE`), for the engine to take.
    pub(super) result: Option<i32>,
}

/// The jobs of `MCC_Home` with `orders` (per channel, 255 skips) and the go-home
/// parameters `cfgs` on this MC3B group: the device's homing (`H`) per order, then
/// one move of every motor by its `dfOffset` (phase 3); with the axes mask and the
/// motors homed. `COMMAND_NOTACCEPTED_ERR` for a mode other than 9 and 16 (the MC3B
/// has no home sensor or index input; its homing is their search of the limit
/// switch), a homed channel this group does not drive on the device, or a motor with
/// no limit switch in the search direction (it would seek for ever).
/// `motor` is the motor of each group axis, `limits` the switches per motor and
/// direction.
#[allow(clippy::type_complexity)]
pub(super) fn plan(
    motor: &[Option<usize>; AXES],
    limits: &[[bool; 2]; MOTORS],
    orders: &[i32; AXES],
    cfgs: &[crate::vendor::SYS_HOME_CONFIG; AXES],
    axes: &[AxisMech; AXES],
) -> McclResult<(u32, Vec<Job>, [bool; MOTORS])> {
    use crate::engine::homing::ORDER_SKIP;
    if orders[MOTORS..].iter().any(|&o| o != ORDER_SKIP) {
        return Err(McclError::NotAccepted);
    }
    // Per motor: order, direction, speeds, phase-3 steps.
    let mut plan: [Option<(i32, u32, Speeds, i64)>; MOTORS] = [None; MOTORS];
    let mut mask = 0u32;
    for m in 0..MOTORS {
        if orders[m] == ORDER_SKIP {
            continue;
        }
        let i = motor
            .iter()
            .position(|&mm| mm == Some(m))
            .ok_or(McclError::NotAccepted)?;
        let h = &cfgs[m];
        if h.wMode != 9 && h.wMode != 16 {
            return Err(McclError::NotAccepted);
        }
        let k = axes[i].factor;
        // Direction 0 counts steps up.
        let up = (h.wDirection == 0) == (k > 0.0);
        if !limits[m][usize::from(!up)] {
            return Err(McclError::NotAccepted);
        }
        let speeds = backend::speeds_for(
            h.dfHighSpeed * k.abs(),
            Ramp::Times {
                acc_s: h.dfAccTime / 1000.0,
                dec_s: h.dfDecTime / 1000.0,
            },
        );
        plan[m] = Some((
            orders[m],
            u32::from(!up),
            speeds,
            round_pulses(h.dfOffset * k),
        ));
        mask |= 1 << i;
    }
    let mut used: Vec<i32> = plan.iter().flatten().map(|p| p.0).collect();
    used.sort_unstable();
    used.dedup();
    let mut stages = Vec::new();
    for o in used {
        let pick = |m: usize| plan[m].filter(|p| p.0 == o);
        stages.push(Job::Home {
            dirs: std::array::from_fn(|m| pick(m).map(|p| p.1)),
            speeds: std::array::from_fn(|m| pick(m).map(|p| p.2)),
        });
    }
    let offsets: [i64; MOTORS] = std::array::from_fn(|m| plan[m].map_or(0, |p| p.3));
    if offsets.iter().any(|&n| n != 0) {
        stages.push(Job::Independent {
            steps: offsets,
            speeds: std::array::from_fn(|m| plan[m].map(|p| p.2)),
        });
    }
    Ok((mask, stages, plan.map(|p| p.is_some())))
}
