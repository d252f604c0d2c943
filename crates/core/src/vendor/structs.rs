//! Struct layouts of MCCL.h (docs/vendor-interface.md), field order and sizes exactly as the
//! vendor's (DWORD is 32-bit, default alignment, no packing).
#![allow(missing_docs)]

use super::{BYTE, DWORD, WORD};

/// Information about the motion command being executed (`MCC_GetCurCommand`), 104 bytes.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct COMMAND_INFO {
    pub nType: i32,
    pub nCommandIndex: i32,
    pub dfFeedSpeed: f64,
    pub dfPos: [f64; 8],
    pub dfAcctime: f64,
    pub dfDectime: f64,
    pub nMotionPhase: i32,
    pub nCommandIndex_LD: i32,
}

/// Mechanism parameters of one channel (§2.4.1), 72 bytes.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct SYS_MAC_PARAM {
    pub wPosToEncoderDir: WORD,
    pub wRPM: WORD,
    pub dwPPR: DWORD,
    pub dfPitch: f64,
    pub dfGearRatio: f64,
    pub dfHighLimit: f64,
    pub dfLowLimit: f64,
    pub dfHighLimitOffset: f64,
    pub dfLowLimitOffset: f64,
    pub wPulseMode: WORD,
    pub wPulseWidth: WORD,
    pub wCommandMode: WORD,
    pub wPaddle: WORD,
    pub wOverTravelUpSensorMode: WORD,
    pub wOverTravelDownSensorMode: WORD,
}

/// Extended mechanism parameters (later header generations), 72 bytes.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct SYS_MAC_PARAM_EX {
    pub wPosToEncoderDir: WORD,
    pub wPulseMode: WORD,
    pub wPulseWidth: WORD,
    pub wCommandMode: WORD,
    pub dwRPM: DWORD,
    pub dwPPR: DWORD,
    pub dfPitch: f64,
    pub dfGearRatio: f64,
    pub dfHighLimit: f64,
    pub dfLowLimit: f64,
    pub dfHighLimitOffset: f64,
    pub dfLowLimitOffset: f64,
    pub wOverTravelUpSensorMode: WORD,
    pub wOverTravelDownSensorMode: WORD,
}

/// Encoder parameters of one channel (§2.4.2), 16 bytes.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct SYS_ENCODER_CONFIG {
    pub wType: WORD,
    pub wAInverse: WORD,
    pub wBInverse: WORD,
    pub wCInverse: WORD,
    pub wABSwap: WORD,
    pub wInputRate: WORD,
    pub wPaddle: [WORD; 2],
}

/// Older name of [`SYS_ENCODER_CONFIG`].
pub type ENCODER_CONFIG = SYS_ENCODER_CONFIG;

/// Pulse output configuration, 8 bytes.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct SYS_PULSE_CONFIG {
    pub wType: WORD,
    pub wAInverse: WORD,
    pub wBInverse: WORD,
    pub wABSwap: WORD,
}

/// Older name of [`SYS_PULSE_CONFIG`].
pub type PULSE_CONFIG = SYS_PULSE_CONFIG;

/// Go-home parameters of one channel (§2.4.3), 56 bytes.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct SYS_HOME_CONFIG {
    pub wMode: WORD,
    pub wDirection: WORD,
    pub wSensorMode: WORD,
    pub wPaddel0: WORD,
    pub nIndexCount: i32,
    pub nPaddel1: i32,
    pub dfAccTime: f64,
    pub dfDecTime: f64,
    pub dfHighSpeed: f64,
    pub dfLowSpeed: f64,
    pub dfOffset: f64,
}

/// Extended go-home parameters, 88 bytes.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct SYS_HOME_CONFIG_EX {
    pub wMode: WORD,
    pub wDirection: WORD,
    pub wSensorMode: WORD,
    pub wPaddel0: WORD,
    pub nIndexCount: i32,
    pub nPaddel1: i32,
    pub dfAccTime: f64,
    pub dfDecTime: f64,
    pub dfHighSpeed: f64,
    pub dfLowSpeed: f64,
    pub dfOffset: f64,
    pub dfStableTime: f64,
    pub dfCheckTime: f64,
    pub dfEscapeTime: f64,
    pub wStaticError: WORD,
    pub wTolerance: WORD,
}

/// Backlash/gap compensation tables of one channel (§2.7.5), 2056 bytes.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SYS_COMP_PARAM {
    pub dwInterval: DWORD,
    pub wHome_No: WORD,
    pub wPaddle: WORD,
    pub nForwardTable: [i32; 256],
    pub nBackwardTable: [i32; 256],
}

/// Hardware description of one card, 8 bytes.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct SYS_CARD_CONFIG {
    pub wCardType: WORD,
    pub wCardAddress: WORD,
    pub wIRQ_No: WORD,
    pub wPaddle: WORD,
}

/// Old home configuration, 16 bytes.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct HOME_CONFIG {
    pub wType: WORD,
    pub wApproachDir: WORD,
    pub wLeaveDir: WORD,
    pub wSensorMode: WORD,
    pub dfOffset: f64,
}

/// Old combined machine parameters, 104 bytes.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct SYS_MACH_PARAM {
    pub wPosToEncoderDir: WORD,
    pub wRPM: WORD,
    pub dwPPR: DWORD,
    pub dfPitch: f64,
    pub dfGearRatio: f64,
    pub dfHighLimit: f64,
    pub dfLowLimit: f64,
    pub dfHighLimitOffset: f64,
    pub dfLowLimitOffset: f64,
    pub wPulseMode: WORD,
    pub wPulseWidth: WORD,
    pub wCommandMode: WORD,
    pub wPaddle: WORD,
    pub stHome: HOME_CONFIG,
    pub stEncoder: ENCODER_CONFIG,
    pub wOverTravelUpSensorMode: WORD,
    pub wOverTravelDownSensorMode: WORD,
}

/// One group's mapping, 36 bytes.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct SYS_GROUP_INFO {
    pub nCardIndex: i32,
    pub nChannel: [i32; 8],
}

/// All groups' mappings, 3840 bytes.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SYS_GROUP_CONFIG {
    pub nGroupUsed: [i32; 96],
    pub stGroupInfo: [SYS_GROUP_INFO; 96],
}

// ---- ISR argument structs (every field a BYTE) ----

/// Local I/O interrupt causes, 24 bytes.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct LIOINT {
    pub OTP0: BYTE,
    pub OTP1: BYTE,
    pub OTP2: BYTE,
    pub OTP3: BYTE,
    pub OTP4: BYTE,
    pub OTP5: BYTE,
    pub OTP6: BYTE,
    pub OTP7: BYTE,
    pub OTN0: BYTE,
    pub OTN1: BYTE,
    pub OTN2: BYTE,
    pub OTN3: BYTE,
    pub OTN4: BYTE,
    pub OTN5: BYTE,
    pub OTN6: BYTE,
    pub OTN7: BYTE,
    pub HOME0: BYTE,
    pub HOME1: BYTE,
    pub HOME2: BYTE,
    pub HOME3: BYTE,
    pub HOME4: BYTE,
    pub HOME5: BYTE,
    pub HOME6: BYTE,
    pub HOME7: BYTE,
}

/// Encoder interrupt causes, 16 bytes.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ENCINT {
    pub INDEX0: BYTE,
    pub INDEX1: BYTE,
    pub INDEX2: BYTE,
    pub INDEX3: BYTE,
    pub INDEX4: BYTE,
    pub INDEX5: BYTE,
    pub INDEX6: BYTE,
    pub INDEX7: BYTE,
    pub COMP0: BYTE,
    pub COMP1: BYTE,
    pub COMP2: BYTE,
    pub COMP3: BYTE,
    pub COMP4: BYTE,
    pub COMP5: BYTE,
    pub COMP6: BYTE,
    pub COMP7: BYTE,
}

/// Position-control-loop interrupt causes, 16 bytes.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct PCLINT {
    pub OVP0: BYTE,
    pub OVP1: BYTE,
    pub OVP2: BYTE,
    pub OVP3: BYTE,
    pub OVP4: BYTE,
    pub OVP5: BYTE,
    pub OVP6: BYTE,
    pub OVP7: BYTE,
    pub OVN0: BYTE,
    pub OVN1: BYTE,
    pub OVN2: BYTE,
    pub OVN3: BYTE,
    pub OVN4: BYTE,
    pub OVN5: BYTE,
    pub OVN6: BYTE,
    pub OVN7: BYTE,
}

/// ADC interrupt causes, 10 bytes.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ADCINT {
    pub COMP0: BYTE,
    pub COMP1: BYTE,
    pub COMP2: BYTE,
    pub COMP3: BYTE,
    pub COMP4: BYTE,
    pub COMP5: BYTE,
    pub COMP6: BYTE,
    pub COMP7: BYTE,
    pub CONV: BYTE,
    pub TAG: BYTE,
}

/// Remote I/O interrupt causes, 8 bytes.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct RIOINT {
    pub RDI0: BYTE,
    pub RDI1: BYTE,
    pub RDI2: BYTE,
    pub RDI3: BYTE,
    pub RDI4: BYTE,
    pub RDI5: BYTE,
    pub RDI6: BYTE,
    pub RDI7: BYTE,
}

/// Timer interrupt cause, 1 byte.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct TMRINT {
    pub TIMER: BYTE,
}

/// Handshake interrupt cause, 1 byte.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct HSKINT {
    pub HANDSHAKE: BYTE,
}
