//! Error records: why a group stopped running commands, read with `MCC_GetErrorCode` and
//! cleared with `MCC_ClearError` (docs/vendor-interface.md, "Error records"). Every
//! record the library sets is a variant here; the vendor's codes keep their values, the
//! library's own (0xF103, 0xF1FF, 0xF901, 0xF902) are outside the vendor's table.

/// One error record. Axis numbers are 0..=7 (X..B).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ErrorRecord {
    /// The emergency-stop input (0xF102).
    EmergencyStop,
    /// The watchdog reset the card (0xF103, the library's own).
    WatchdogReset,
    /// A bad arc or circle command (0xF104).
    BadArc,
    /// The forward kinematics of a kinematic group failed (0xF105).
    ForwardKinematics,
    /// The inverse kinematics of a kinematic group failed: the Cartesian point is
    /// unreachable (0xF106).
    InverseKinematics,
    /// More pulses in a period than the pulse-speed limit (0xF203).
    PulseSpeed,
    /// A pulse-rate change over the pulse-acceleration limit (0xF204).
    PulseAcc,
    /// Software over-travel of an axis (0xF301 + axis).
    OverTravel(u8),
    /// The in-position check failed (0xF501).
    InPosition,
    /// A hardware limit switch of an axis (0xF701 + axis).
    Limit(u8),
    /// The tracking error of an axis over its limit (0xF801 + axis).
    Tracking(u8),
    /// An MC3B did not answer in time (0xF901, the library's own).
    Mc3bLink,
    /// An MC3B refused a command or answered what does not fit (0xF902, the library's own).
    Mc3bDevice,
    /// A custom motion's interpolation callback returned FALSE (0xF107, as the vendor's
    /// library records it).
    CustomInterpolation,
    /// A custom motion's callback gave an unusable total distance or offset (0xF10A,
    /// the library's own).
    CustomMotion,
    /// The library caught a panic of its own and stopped the group (0xF1FF, the
    /// library's own; the vendor's test programs report unknown codes as "Run Time Error").
    Internal,
}

impl ErrorRecord {
    /// The value `MCC_GetErrorCode` returns.
    pub const fn code(self) -> i32 {
        match self {
            ErrorRecord::EmergencyStop => 0xF102,
            ErrorRecord::WatchdogReset => 0xF103,
            ErrorRecord::BadArc => 0xF104,
            ErrorRecord::ForwardKinematics => 0xF105,
            ErrorRecord::InverseKinematics => 0xF106,
            ErrorRecord::PulseSpeed => 0xF203,
            ErrorRecord::PulseAcc => 0xF204,
            ErrorRecord::OverTravel(axis) => 0xF301 + axis as i32,
            ErrorRecord::InPosition => 0xF501,
            ErrorRecord::Limit(axis) => 0xF701 + axis as i32,
            ErrorRecord::Tracking(axis) => 0xF801 + axis as i32,
            ErrorRecord::Mc3bLink => 0xF901,
            ErrorRecord::Mc3bDevice => 0xF902,
            ErrorRecord::CustomInterpolation => 0xF107,
            ErrorRecord::CustomMotion => 0xF10A,
            ErrorRecord::Internal => 0xF1FF,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::ErrorRecord::*;

    #[test]
    fn codes_are_the_documented_values() {
        assert_eq!(EmergencyStop.code(), 0xF102);
        assert_eq!(ForwardKinematics.code(), 0xF105);
        assert_eq!(InverseKinematics.code(), 0xF106);
        assert_eq!(CustomInterpolation.code(), 0xF107);
        assert_eq!(OverTravel(0).code(), 0xF301);
        assert_eq!(OverTravel(7).code(), 0xF308);
        assert_eq!(Limit(2).code(), 0xF703);
        assert_eq!(Tracking(7).code(), 0xF808);
        assert_eq!(Internal.code(), 0xF1FF);
    }
}
