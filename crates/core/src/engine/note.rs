//! What a group notes for the trace's events file as it happens.

/// Something a group did that the events file records, noted where it happens (only while
/// tracing: `GroupState::note` is a check of an `Option` otherwise) and written with the
/// virtual time of the tick that writes the group's row.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Note {
    /// A command started running (blended commands start while another runs).
    Start {
        /// Command index.
        index: i32,
        /// `COMMAND_INFO.nType`.
        ctype: i32,
    },
    /// A command ended: it reached its end (`done`) or was cut short (`stopped`).
    End {
        /// Command index.
        index: i32,
        /// `COMMAND_INFO.nType`.
        ctype: i32,
        /// Whether it was cut short (abort, a safety stop).
        stopped: bool,
    },
    /// `MCC_HoldMotion`.
    Hold {
        /// Hold at the end of the running command.
        block_end: bool,
    },
    /// `MCC_ContiMotion`.
    Continue,
    /// `MCC_AbortMotion(Ex)`.
    Abort {
        /// Deceleration time, s.
        dec_s: f64,
        /// Abort at the end of the running command.
        block_end: bool,
    },
    /// An error record was set.
    ErrorSet(i32),
    /// The error record was cleared (`MCC_ClearError`); the code it held.
    ErrorCleared(i32),
    /// An in-position check began for these axes.
    InPosBegin(u32),
    /// The in-position check found every axis in position.
    InPosDone(u32),
    /// The in-position check ran out of time (`error`: whether it records 0xF501).
    InPosFail {
        /// Axes checked.
        mask: u32,
        /// Whether the failure records an error (`BLOCK` modes).
        error: bool,
    },
}
