//! The MC3B's limit (home) masks of a motor, from its wiring.

/// The home (limit) masks of one motor as §6.5 sends them: AND and XOR for direction 0,
/// then for direction 1. All 0: no limit switch.
pub type LimitMasks = [u32; 4];

/// The masks of a motor whose direction-0 and direction-1 limit switches are the MC3B
/// inputs `bits` (0..5, -1 none), each active at the level in `high` (`true`: +5 V).
pub fn limit_masks(bits: [i8; 2], high: [Option<bool>; 2]) -> LimitMasks {
    let pair = |bit: i8, level: Option<bool>| match (u8::try_from(bit), level) {
        (Ok(b @ 0..=5), Some(l)) => {
            crate::mc3b::mcl::limit_masks(i32::from(b), l).unwrap_or((0, 0))
        }
        _ => (0, 0),
    };
    let (a0, x0) = pair(bits[0], high[0]);
    let (a1, x1) = pair(bits[1], high[1]);
    [a0, x0, a1, x1]
}

/// The limit masks of the motor on a channel: its configured `mc3b_limit_bits` (+, −),
/// each active at the level of the program's wiring setting (`SL_NORMAL_OPEN`: +5 V,
/// `SL_NORMAL_CLOSE`: 0 V, `SL_UNUSED`: no switch). Direction 0 counts steps up, so the +
/// switch is direction 0's unless the channel's output is reversed (`wPosToEncoderDir`).
pub fn motor_limits(
    ch: &crate::sim::config::ChannelSim,
    mac: &crate::vendor::SYS_MAC_PARAM,
) -> LimitMasks {
    use crate::vendor::consts as c;
    let Some([plus, minus]) = ch.mc3b_limit_bits else {
        return [0; 4];
    };
    let level = |mode: u16| match mode {
        c::SL_NORMAL_OPEN => Some(true),
        c::SL_NORMAL_CLOSE => Some(false),
        _ => None,
    };
    let (up, down) = (
        level(mac.wOverTravelUpSensorMode),
        level(mac.wOverTravelDownSensorMode),
    );
    if mac.wPosToEncoderDir != 0 {
        limit_masks([minus, plus], [down, up])
    } else {
        limit_masks([plus, minus], [up, down])
    }
}

#[cfg(test)]
mod tests;
