//! The device's error numbers of §6.19.

/// Device error numbers of §6.19 (sent as `<id>E<e>`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ErrorCode {
    /// `E0`: command character not recognized.
    InvalidCommand,
    /// `E1`: the command must be sent while the motor is idle.
    MotorRunning,
    /// `E2`: wrong number of parameters.
    WrongParameterCount,
    /// `E3`: parameter out of range.
    OutOfRange,
}

impl ErrorCode {
    /// Number used on the wire.
    pub fn number(self) -> u32 {
        match self {
            ErrorCode::InvalidCommand => 0,
            ErrorCode::MotorRunning => 1,
            ErrorCode::WrongParameterCount => 2,
            ErrorCode::OutOfRange => 3,
        }
    }

    /// What the error means, in the words of §6.19.
    pub fn meaning(self) -> &'static str {
        match self {
            ErrorCode::InvalidCommand => "invalid command: command character not recognized",
            ErrorCode::MotorRunning => "motor running: command must be sent when motor is idle",
            ErrorCode::WrongParameterCount => {
                "wrong number of parameters: the exact number of expected parameters must be \
                 supplied with a command"
            }
            ErrorCode::OutOfRange => "parameter out of range",
        }
    }

    /// Error code for a wire number, or `None`.
    pub fn from_number(n: u32) -> Option<ErrorCode> {
        match n {
            0 => Some(ErrorCode::InvalidCommand),
            1 => Some(ErrorCode::MotorRunning),
            2 => Some(ErrorCode::WrongParameterCount),
            3 => Some(ErrorCode::OutOfRange),
            _ => None,
        }
    }
}
