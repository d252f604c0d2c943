//! A channel's home sensor and limit switches: where they are, forcing them, the levels
//! the card reads after the program's wiring setting, and the limit switch latches.

/// A sensor the program or a test can force through `MCCL_Sim.h`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Sensor {
    /// The home sensor.
    Home,
    /// The + limit switch.
    LimitPlus,
    /// The − limit switch.
    LimitMinus,
}

/// Sensor inputs of one channel after wiring, as the card sees them.
///
/// Aligned to 4 bytes so that the copies and comparisons a channel's step makes are one
/// 32-bit move each.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[repr(C, align(4))]
pub struct SensorLevels {
    /// Home sensor active.
    pub home: bool,
    /// + limit switch active.
    pub plus: bool,
    /// − limit switch active.
    pub minus: bool,
}
