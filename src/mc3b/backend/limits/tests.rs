//! Limit masks from input bits and wiring settings.

use super::*;

#[test]
fn limit_masks_from_bits_and_wiring() {
    use crate::vendor::consts as c;
    // Bit 2 active high (normally open) for direction 0, bit 5 active low for 1.
    assert_eq!(
        limit_masks([2, 5], [Some(true), Some(false)]),
        [4, 0, 32, 32]
    );
    assert_eq!(
        limit_masks([-1, 5], [Some(true), None]),
        [0; 4],
        "none, unused"
    );
    let mut mac = crate::config::default_mac_param();
    mac.wOverTravelUpSensorMode = c::SL_NORMAL_OPEN;
    mac.wOverTravelDownSensorMode = c::SL_NORMAL_CLOSE;
    let ch = crate::sim::config::ChannelSim {
        mc3b_limit_bits: Some([0, 1]),
        ..Default::default()
    };
    assert_eq!(motor_limits(&ch, &mac), [1, 0, 2, 2]);
    // A reversed output: the + switch limits direction 1.
    mac.wPosToEncoderDir = 1;
    assert_eq!(motor_limits(&ch, &mac), [2, 2, 1, 0]);
    assert_eq!(motor_limits(&Default::default(), &mac), [0; 4]);
}
