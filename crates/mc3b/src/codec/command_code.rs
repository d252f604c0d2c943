//! The command letters of §6.

/// The command letters of §6 (every command of the MC3B).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum CommandCode {
    /// `I`: initialize (§6.1).
    Initialize,
    /// `A`: set acceleration (§6.2).
    Acceleration,
    /// `D`: set deceleration (§6.3).
    Deceleration,
    /// `V`: set maximum velocity (§6.4).
    Velocity,
    /// `L`: set limit switch masks (§6.5).
    Limits,
    /// `F`: full/half stepping (§6.6).
    HalfStep,
    /// `R`: run (§6.7).
    Run,
    /// `M`: move (§6.8).
    Move,
    /// `H`: home (§6.9).
    Home,
    /// `G`: rate-based motion (§6.10).
    RateMove,
    /// `S`: stop (§6.11).
    Stop,
    /// `Y`: synchronous move (§6.12).
    SyncMove,
    /// `Q`: query motor status (§6.13).
    QueryStatus,
    /// `B`: query limit inputs (§6.14).
    QueryLimits,
    /// `C`: holding current usage (§6.15).
    HoldingCurrent,
    /// `K`: current limits (§6.16).
    CurrentLimits,
    /// `N`: limit switch debounce count (§6.17).
    Debounce,
    /// `P`: query product ID (§6.18).
    ProductId,
}

impl CommandCode {
    /// All command codes, in the order of §6.
    pub const ALL: [CommandCode; 18] = [
        CommandCode::Initialize,
        CommandCode::Acceleration,
        CommandCode::Deceleration,
        CommandCode::Velocity,
        CommandCode::Limits,
        CommandCode::HalfStep,
        CommandCode::Run,
        CommandCode::Move,
        CommandCode::Home,
        CommandCode::RateMove,
        CommandCode::Stop,
        CommandCode::SyncMove,
        CommandCode::QueryStatus,
        CommandCode::QueryLimits,
        CommandCode::HoldingCurrent,
        CommandCode::CurrentLimits,
        CommandCode::Debounce,
        CommandCode::ProductId,
    ];

    /// The ASCII letter of this command on the wire.
    pub fn letter(self) -> u8 {
        match self {
            CommandCode::Initialize => b'I',
            CommandCode::Acceleration => b'A',
            CommandCode::Deceleration => b'D',
            CommandCode::Velocity => b'V',
            CommandCode::Limits => b'L',
            CommandCode::HalfStep => b'F',
            CommandCode::Run => b'R',
            CommandCode::Move => b'M',
            CommandCode::Home => b'H',
            CommandCode::RateMove => b'G',
            CommandCode::Stop => b'S',
            CommandCode::SyncMove => b'Y',
            CommandCode::QueryStatus => b'Q',
            CommandCode::QueryLimits => b'B',
            CommandCode::HoldingCurrent => b'C',
            CommandCode::CurrentLimits => b'K',
            CommandCode::Debounce => b'N',
            CommandCode::ProductId => b'P',
        }
    }

    /// The command for an ASCII letter (case-sensitive: the guide only uses
    /// capitals), or `None`.
    pub fn from_letter(b: u8) -> Option<CommandCode> {
        CommandCode::ALL.iter().copied().find(|c| c.letter() == b)
    }

    /// Accepted parameter counts `(min, max)` for this command.
    pub fn param_counts(self) -> (usize, usize) {
        match self {
            CommandCode::Initialize | CommandCode::QueryLimits | CommandCode::ProductId => (0, 0),
            CommandCode::Stop | CommandCode::QueryStatus | CommandCode::Debounce => (1, 1),
            CommandCode::Acceleration
            | CommandCode::Deceleration
            | CommandCode::HalfStep
            | CommandCode::Run
            | CommandCode::Home
            | CommandCode::HoldingCurrent => (2, 2),
            CommandCode::Velocity => (2, 3),
            CommandCode::Move | CommandCode::CurrentLimits => (3, 3),
            CommandCode::RateMove => (4, 4),
            CommandCode::Limits => (5, 5),
            CommandCode::SyncMove => (6, 7),
        }
    }

    /// Whether the device answers this command with a bare `<id><letter>`
    /// acknowledgement (all but the three queries).
    pub fn is_acknowledged(self) -> bool {
        !matches!(
            self,
            CommandCode::QueryStatus | CommandCode::QueryLimits | CommandCode::ProductId
        )
    }
}
