//! The go-home modes as data (user manual §2.8.1): each mode is a list of [`Step`]s, and
//! the Case 2/3 recovery is one more.

/// Which speed a step runs at.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Speed {
    /// `dfHighSpeed`.
    High,
    /// `dfLowSpeed`.
    Low,
}

/// The event that ends a step.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Until {
    /// The home sensor turns active during the step.
    EnterHome,
    /// The home sensor turns inactive during the step (after being active in it).
    LeaveHome,
    /// The limit switch in the direction of motion is active.
    Limit,
    /// The limit switch in the configured direction is no longer active.
    LeaveLimit,
    /// The `nIndexCount`th index pulse (from 0) since the step began.
    Index,
    /// Back at the position of the index pulse found before.
    ReturnToIndex,
}

/// How a step ends when its event comes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Then {
    /// Decelerate to a stop over `dfDecTime`.
    Decel,
    /// Stop at once (the manual's "emergency stop").
    Halt,
    /// Go on into the next step without stopping.
    Continue,
}

/// One step of a go-home mode (§2.8.1).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Step {
    /// In the configured direction (`wDirection`), else the reverse.
    pub forward: bool,
    /// Speed.
    pub speed: Speed,
    /// What ends it.
    pub until: Until,
    /// How it ends.
    pub then: Then,
    /// The phase (1 or 2) it belongs to.
    pub phase: u8,
}

const fn st(forward: bool, speed: Speed, until: Until, then: Then, phase: u8) -> Step {
    Step {
        forward,
        speed,
        until,
        then,
        phase,
    }
}

use Speed::{High as H, Low as L};
use Then::{Continue, Decel, Halt};
use Until::{EnterHome, Index, LeaveHome, LeaveLimit, Limit, ReturnToIndex};

const F: bool = true;
const R: bool = false;

/// The steps of go-home mode `mode` (3..16) in Case 1, phases 1 and 2 (§2.8.1).
pub fn program(mode: u16) -> &'static [Step] {
    const M3: &[Step] = &[st(F, H, EnterHome, Decel, 1)];
    const M4: &[Step] = &[
        st(F, H, EnterHome, Decel, 1),
        st(R, H, LeaveHome, Decel, 1),
        st(F, L, EnterHome, Halt, 1),
    ];
    const M5: &[Step] = &[st(F, H, EnterHome, Continue, 1), st(F, L, Index, Halt, 2)];
    const M6: &[Step] = &[st(F, H, EnterHome, Continue, 1), st(F, H, Index, Decel, 2)];
    const M7: &[Step] = &[
        st(F, H, EnterHome, Decel, 1),
        st(R, L, LeaveHome, Continue, 1),
        st(R, L, Index, Halt, 2),
    ];
    const M8: &[Step] = &[
        st(F, H, EnterHome, Decel, 1),
        st(R, H, LeaveHome, Continue, 1),
        st(R, H, Index, Decel, 2),
    ];
    const M9: &[Step] = &[st(F, H, Limit, Halt, 1)];
    const M10: &[Step] = &[st(F, H, Limit, Halt, 1), st(R, L, Index, Halt, 2)];
    const M11: &[Step] = &[st(F, H, Limit, Halt, 1), st(R, H, Index, Decel, 2)];
    const M12: &[Step] = &[st(F, H, EnterHome, Decel, 1), st(R, L, LeaveHome, Halt, 1)];
    const M13: &[Step] = &[
        st(F, H, EnterHome, Continue, 1),
        st(F, H, Index, Decel, 2),
        st(R, L, ReturnToIndex, Halt, 2),
    ];
    const M14: &[Step] = &[
        st(F, H, EnterHome, Decel, 1),
        st(R, H, LeaveHome, Continue, 1),
        st(R, H, Index, Decel, 2),
        st(F, L, ReturnToIndex, Halt, 2),
    ];
    const M15: &[Step] = &[
        st(F, H, Limit, Halt, 1),
        st(R, H, Index, Decel, 2),
        st(F, L, ReturnToIndex, Halt, 2),
    ];
    const M16: &[Step] = &[st(F, H, Limit, Decel, 1), st(R, L, LeaveLimit, Halt, 1)];
    match mode {
        3 => M3,
        4 => M4,
        5 => M5,
        6 => M6,
        7 => M7,
        8 => M8,
        9 => M9,
        10 => M10,
        11 => M11,
        12 => M12,
        13 => M13,
        14 => M14,
        15 => M15,
        16 => M16,
        _ => &[],
    }
}

/// Whether mode `mode` searches the home sensor (and so handles Case 2 and 3).
pub fn uses_home_sensor(mode: u16) -> bool {
    program(mode).iter().any(|s| s.until == EnterHome)
}

/// The Case 2/3 recovery steps (§2.8.1 a, b); then the mode starts again.
pub(super) const RECOVER: [Step; 2] = [st(F, H, Limit, Halt, 1), st(R, H, LeaveHome, Decel, 1)];
