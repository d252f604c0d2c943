//! The older combined machine parameters (`SYS_MACH_PARAM`, 104 bytes: the mechanism
//! parameters, an old `HOME_CONFIG` and an `ENCODER_CONFIG` in one struct) as the three
//! configurations the library keeps: `MCC_SetMachParam` is `MCC_SetMacParam`,
//! `MCC_SetHomeConfig` and `MCC_SetEncoderConfig` in one call, with the same checks.
//!
//! The old `HOME_CONFIG` has a `wType` (the constants `HM_NORMAL` = 0,
//! `HM_SENSOR_ONLY` = 1, `HM_INDEX_ONLY` = 2, marked obsolete, and `HM_FIRST` = 3 ..
//! `HM_LAST`), an approach and a leave direction, the sensor mode and the offset. Read
//! here as: `wType` `HM_FIRST`..=`HM_LAST` (3..19) is the go-home mode of
//! `SYS_HOME_CONFIG.wMode` (the same numbers; `MCC_Home` runs 3..16); `HM_SENSOR_ONLY` is
//! mode 3 (search the home sensor only); `HM_NORMAL` is mode 5 (the home sensor at high
//! speed, then the index pulse at low speed in the same direction); `HM_INDEX_ONLY` has no
//! mode (every mode that counts index pulses first finds a sensor or switch) and is
//! refused. `wApproachDir` is `wDirection`; `wLeaveDir` must be 0 or 1 and is not kept:
//! every mode leaves a sensor against the approach direction, and reading the struct
//! back reports that. The home fields the old struct lacks (index count, ramps, speeds)
//! keep the channel's current values.

use super::{validate_encoder_config, validate_home_config, validate_mac_param};
use crate::error::{McclError, McclResult};
use crate::vendor::consts as c;
use crate::vendor::{
    HOME_CONFIG, SYS_ENCODER_CONFIG, SYS_HOME_CONFIG, SYS_MACH_PARAM, SYS_MAC_PARAM, WORD,
};

/// The go-home mode an old `HOME_CONFIG.wType` stands for (`PARAMETER_ERR` for none).
pub fn home_mode(w_type: WORD) -> McclResult<WORD> {
    match i32::from(w_type) {
        c::HM_NORMAL => Ok(5),
        c::HM_SENSOR_ONLY => Ok(3),
        c::HM_FIRST..=c::HM_LAST => Ok(w_type),
        _ => Err(McclError::Parameter),
    }
}

/// Splits `p` into the three configurations, each checked as its own setter checks it;
/// `home_now` supplies the home fields the old struct does not have. Nothing is returned
/// unless all three are valid.
pub fn split(
    p: &SYS_MACH_PARAM,
    home_now: &SYS_HOME_CONFIG,
) -> McclResult<(SYS_MAC_PARAM, SYS_HOME_CONFIG, SYS_ENCODER_CONFIG)> {
    let mac = SYS_MAC_PARAM {
        wPosToEncoderDir: p.wPosToEncoderDir,
        wRPM: p.wRPM,
        dwPPR: p.dwPPR,
        dfPitch: p.dfPitch,
        dfGearRatio: p.dfGearRatio,
        dfHighLimit: p.dfHighLimit,
        dfLowLimit: p.dfLowLimit,
        dfHighLimitOffset: p.dfHighLimitOffset,
        dfLowLimitOffset: p.dfLowLimitOffset,
        wPulseMode: p.wPulseMode,
        wPulseWidth: p.wPulseWidth,
        wCommandMode: p.wCommandMode,
        wPaddle: p.wPaddle,
        wOverTravelUpSensorMode: p.wOverTravelUpSensorMode,
        wOverTravelDownSensorMode: p.wOverTravelDownSensorMode,
    };
    validate_mac_param(&mac)?;
    let h = &p.stHome;
    if h.wLeaveDir > 1 {
        return Err(McclError::Parameter);
    }
    let home = SYS_HOME_CONFIG {
        wMode: home_mode(h.wType)?,
        wDirection: h.wApproachDir,
        wSensorMode: h.wSensorMode,
        dfOffset: h.dfOffset,
        ..*home_now
    };
    validate_home_config(&home, &mac)?;
    validate_encoder_config(&p.stEncoder)?;
    Ok((mac, home, p.stEncoder))
}

/// The old struct that the three configurations make (`MCC_GetMachParam`).
pub fn join(
    mac: &SYS_MAC_PARAM,
    home: &SYS_HOME_CONFIG,
    enc: &SYS_ENCODER_CONFIG,
) -> SYS_MACH_PARAM {
    SYS_MACH_PARAM {
        wPosToEncoderDir: mac.wPosToEncoderDir,
        wRPM: mac.wRPM,
        dwPPR: mac.dwPPR,
        dfPitch: mac.dfPitch,
        dfGearRatio: mac.dfGearRatio,
        dfHighLimit: mac.dfHighLimit,
        dfLowLimit: mac.dfLowLimit,
        dfHighLimitOffset: mac.dfHighLimitOffset,
        dfLowLimitOffset: mac.dfLowLimitOffset,
        wPulseMode: mac.wPulseMode,
        wPulseWidth: mac.wPulseWidth,
        wCommandMode: mac.wCommandMode,
        wPaddle: mac.wPaddle,
        stHome: HOME_CONFIG {
            wType: home.wMode,
            wApproachDir: home.wDirection,
            wLeaveDir: u16::from(home.wDirection == 0),
            wSensorMode: home.wSensorMode,
            dfOffset: home.dfOffset,
        },
        stEncoder: *enc,
        wOverTravelUpSensorMode: mac.wOverTravelUpSensorMode,
        wOverTravelDownSensorMode: mac.wOverTravelDownSensorMode,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::config::{default_encoder_config, default_home_config, default_mac_param};

    fn sample() -> SYS_MACH_PARAM {
        join(
            &default_mac_param(),
            &default_home_config(),
            &default_encoder_config(),
        )
    }

    #[test]
    fn split_and_join_round_trip_and_map_the_old_home_types() {
        let mut p = sample();
        p.dwPPR = 2000;
        p.dfPitch = 5.0;
        p.stHome.wType = c::HM_NORMAL as WORD;
        p.stHome.wApproachDir = 0;
        p.stHome.dfOffset = 1.5;
        p.stEncoder.wInputRate = 2;
        p.wOverTravelUpSensorMode = c::SL_NORMAL_CLOSE;
        let mut now = default_home_config();
        now.dfHighSpeed = 7.0;
        let (mac, home, enc) = split(&p, &now).unwrap();
        assert_eq!((mac.dwPPR, mac.dfPitch), (2000, 5.0));
        assert_eq!(mac.wOverTravelUpSensorMode, c::SL_NORMAL_CLOSE);
        assert_eq!((home.wMode, home.wDirection, home.dfOffset), (5, 0, 1.5));
        assert_eq!(home.dfHighSpeed, 7.0, "kept from the channel");
        assert_eq!(enc.wInputRate, 2);
        let back = join(&mac, &home, &enc);
        assert_eq!(back.stHome.wType, 5, "read back as the mode");
        assert_eq!(back.stHome.wLeaveDir, 1, "against the approach");
        assert_eq!(back.dwPPR, 2000);
        // HM_SENSOR_ONLY is mode 3; HM_FIRST..HM_LAST (3..19) pass as they are; the
        // rest is refused.
        assert_eq!(home_mode(1), Ok(3));
        assert_eq!(home_mode(16), Ok(16));
        assert_eq!(home_mode(19), Ok(19));
        for bad in [2, 20, 0xFFFF] {
            assert_eq!(home_mode(bad), Err(McclError::Parameter), "{bad}");
        }
    }

    #[test]
    fn each_part_is_checked_as_its_own_setter_checks_it() {
        let now = default_home_config();
        let mut p = sample();
        p.dwPPR = 0; // MCC_SetMacParam refuses it
        assert_eq!(split(&p, &now), Err(McclError::Parameter));
        let mut p = sample();
        p.stHome.wApproachDir = 2; // MCC_SetHomeConfig refuses it
        assert_eq!(split(&p, &now), Err(McclError::Parameter));
        let mut p = sample();
        p.stHome.wLeaveDir = 2;
        assert_eq!(split(&p, &now), Err(McclError::Parameter));
        let mut p = sample();
        p.stHome.dfOffset = f64::NAN;
        assert_eq!(split(&p, &now), Err(McclError::Parameter));
        let mut p = sample();
        p.stEncoder.wInputRate = 5; // MCC_SetEncoderConfig refuses it
        assert_eq!(split(&p, &now), Err(McclError::Parameter));
    }
}
