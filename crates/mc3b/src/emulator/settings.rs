//! The settings of one motor, as `I` (§6.1) leaves them and the commands change them.

/// Settings of one motor (§6.1 defaults).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MotorSettings {
    /// Steps/s.
    pub max_velocity: u32,
    /// Steps/s².
    pub acceleration: u32,
    /// Steps/s².
    pub deceleration: u32,
    /// mA.
    pub running_current: u32,
    /// mA.
    pub holding_current: u32,
    /// Apply the holding current when idle.
    pub use_holding_current: bool,
    /// Half stepping.
    pub half_steps: bool,
    /// `[and0, xor0, and1, xor1]` home masks.
    pub limit_masks: [u8; 4],
    /// Direction modifier of the last `V` command.
    pub direction_modifier: bool,
}

impl Default for MotorSettings {
    fn default() -> Self {
        MotorSettings {
            max_velocity: 1000,
            acceleration: 5000,
            deceleration: 5000,
            running_current: 2000,
            holding_current: 500,
            use_holding_current: false,
            half_steps: true,
            limit_masks: [0; 4],
            direction_modifier: false,
        }
    }
}
