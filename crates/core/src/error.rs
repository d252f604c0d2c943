//! Errors of the core and their vendor return codes (docs/vendor-interface.md, "Return codes").

use crate::vendor::consts as c;

/// Why a call failed; each maps to one vendor return code.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum McclError {
    /// The system is not initialised (`INITIAL_MOTION_ERR`, -1).
    NotInitialized,
    /// The group's command queue is full (`COMMAND_BUFFER_FULL_ERR`, -2).
    BufferFull,
    /// The call is not accepted in the current state (`COMMAND_NOTACCEPTED_ERR`, -3).
    NotAccepted,
    /// Queued commands are still pending (`COMMAND_NOTFINISHED_ERR`, -4).
    NotFinished,
    /// A bad card, channel, axis, pointer, number or range (`PARAMETER_ERR`, -5).
    Parameter,
    /// A bad group index or group definition (`GROUP_PARAMETER_ERR`, -6).
    Group,
    /// A bad feed rate (`FEED_RATE_ERR`, -7).
    FeedRate,
    /// A DAC call on a channel that runs in voltage-command mode
    /// (`VOLTAGE_COMMAND_CHANNEL_ERR`, -9).
    VoltageChannel,
    /// No go home to act on: `MCC_Home` was not called, or its homing was aborted
    /// (`HOME_COMMAND_NOTCALLED_ERR`, -10).
    HomeNotCalled,
    /// Hold with nothing to hold (`HOLD_ILLEGAL_ERR`, -11).
    HoldIllegal,
    /// Continue when not held (`CONTI_ILLEGAL_ERR`, -12).
    ContiIllegal,
    /// Abort not allowed now (`ABORT_ILLEGAL_ERR`, -13).
    AbortIllegal,
    /// An abort is still decelerating (`ABORT_NOT_FINISH_ERR`, -15).
    AbortNotFinished,
    /// A failure inside the library (`RUN_TIME_ERR`, -14), e.g. a caught panic.
    RunTime,
}

impl McclError {
    /// The vendor return code.
    pub fn code(self) -> i32 {
        match self {
            McclError::NotInitialized => c::INITIAL_MOTION_ERR,
            McclError::BufferFull => c::COMMAND_BUFFER_FULL_ERR,
            McclError::NotAccepted => c::COMMAND_NOTACCEPTED_ERR,
            McclError::NotFinished => c::COMMAND_NOTFINISHED_ERR,
            McclError::Parameter => c::PARAMETER_ERR,
            McclError::Group => c::GROUP_PARAMETER_ERR,
            McclError::FeedRate => c::FEED_RATE_ERR,
            McclError::VoltageChannel => c::VOLTAGE_COMMAND_CHANNEL_ERR,
            McclError::HomeNotCalled => c::HOME_COMMAND_NOTCALLED_ERR,
            McclError::HoldIllegal => c::HOLD_ILLEGAL_ERR,
            McclError::ContiIllegal => c::CONTI_ILLEGAL_ERR,
            McclError::AbortIllegal => c::ABORT_ILLEGAL_ERR,
            McclError::AbortNotFinished => c::ABORT_NOT_FINISH_ERR,
            McclError::RunTime => c::RUN_TIME_ERR,
        }
    }
}

/// Result of a core operation.
pub type McclResult<T> = Result<T, McclError>;
