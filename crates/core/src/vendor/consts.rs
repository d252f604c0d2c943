//! Constants of MCCL.h with the IMP-3 values (docs/vendor-interface.md, docs/decisions.md).
#![allow(missing_docs)]

use super::{DWORD, WORD};

// ---- 2.1 sizes ----
pub const MAX_CARD_NUM: i32 = 12;
pub const MAX_AXIS_NUM: i32 = 8;
pub const MAX_GROUP_NUM: i32 = MAX_CARD_NUM * MAX_AXIS_NUM;
pub const MOTION_QUEUE_SIZE: i32 = 10000;
pub const GROUP_VALID: i32 = 0;
pub const GROUP_INVALID: i32 = -1;
pub const AXIS_INVALID: i32 = -1;
pub const _YES_: i32 = 1;
pub const _NO_: i32 = 0;
pub const IPO_PERIOD_MIN: i32 = 1;
pub const IPO_PERIOD_MAX: i32 = 50;
pub const IPO_PERIOD_DEFAULT: i32 = 5;
pub const MAX_COMP_POINT: i32 = 256;

// ---- 2.2 modes and enums ----
pub const OCM_PULSE: WORD = 0;
pub const OCM_VOLTAGE: WORD = 1;
pub const OCM_SWCLOSELOOP: WORD = 2;

pub const SL_NORMAL_OPEN: WORD = 0;
pub const SL_NORMAL_CLOSE: WORD = 1;
pub const SL_UNUSED: WORD = 2;

pub const EPCIO_4_AXIS_ISA_CARD: WORD = 0;
pub const EPCIO_6_AXIS_ISA_CARD: WORD = 1;
pub const EPCIO_4_AXIS_PCI_CARD: WORD = 2;
pub const EPCIO_6_AXIS_PCI_CARD: WORD = 3;
pub const IMP_II_8_AXIS_PCI_CARD: WORD = 4;
pub const IMP_III_8_AXIS_PCI_CARD: WORD = 5;

pub const UNIT_MM: i32 = 1;
pub const UNIT_INCH: i32 = 2;

pub const HM_NORMAL: i32 = 0;
pub const HM_SENSOR_ONLY: i32 = 1;
pub const HM_INDEX_ONLY: i32 = 2;
pub const HM_FIRST: i32 = 3;
pub const HM_LAST: i32 = 19;

pub const HLP_BIDIR: i32 = 0;
pub const HLP_UNIDIR: i32 = 1;
pub const HLP_BIDIR_GEN_ERR: i32 = 2;
pub const HLP_UNIDIR_GEN_ERR: i32 = 3;

pub const CIR_CW: i32 = 0;
pub const CIR_CCW: i32 = 1;

pub const GMS_RUNNING: i32 = 0;
pub const GMS_STOP: i32 = 1;
pub const GMS_HOLD: i32 = 2;
pub const GMS_DELAYING: i32 = 3;
pub const GMS_BLOCKHOLD: i32 = 4;
pub const GMS_MPGING: i32 = 5;

pub const IPM_ONETIME_BLOCK: WORD = 0;
pub const IPM_ONETIME_UNBLOCK: WORD = 1;
pub const IPM_SETTLE_BLOCK: WORD = 2;
pub const IPM_SETTLE_UNBLOCK: WORD = 3;

pub const IMP_AXIS_X: DWORD = 0x01;
pub const IMP_AXIS_Y: DWORD = 0x02;
pub const IMP_AXIS_Z: DWORD = 0x04;
pub const IMP_AXIS_U: DWORD = 0x08;
pub const IMP_AXIS_V: DWORD = 0x10;
pub const IMP_AXIS_W: DWORD = 0x20;
pub const IMP_AXIS_A: DWORD = 0x40;
pub const IMP_AXIS_B: DWORD = 0x80;
pub const IMP_AXIS_ALL: DWORD = 0xFF;

// ---- 2.3 return codes ----
pub const NO_ERR: i32 = 0;
pub const INITIAL_MOTION_ERR: i32 = -1;
pub const COMMAND_BUFFER_FULL_ERR: i32 = -2;
pub const COMMAND_NOTACCEPTED_ERR: i32 = -3;
pub const COMMAND_NOTFINISHED_ERR: i32 = -4;
pub const PARAMETER_ERR: i32 = -5;
pub const GROUP_PARAMETER_ERR: i32 = -6;
pub const FEED_RATE_ERR: i32 = -7;
pub const BLEND_COMMAND_NOTCALLED_ERR: i32 = -8;
pub const VOLTAGE_COMMAND_CHANNEL_ERR: i32 = -9;
pub const HOME_COMMAND_NOTCALLED_ERR: i32 = -10;
pub const HOLD_ILLEGAL_ERR: i32 = -11;
pub const CONTI_ILLEGAL_ERR: i32 = -12;
pub const ABORT_ILLEGAL_ERR: i32 = -13;
pub const RUN_TIME_ERR: i32 = -14;
pub const ABORT_NOT_FINISH_ERR: i32 = -15;
pub const GROUP_RAN_OUT_ERR: i32 = -16;

// ---- 2.5 pulse/encoder formats and triggers ----
pub const DDA_FMT_NO: WORD = 0;
pub const DDA_FMT_PD: WORD = 1;
pub const DDA_FMT_CW: WORD = 2;
pub const DDA_FMT_AB: WORD = 3;
pub const PGE_FMT_NO: WORD = 0;
pub const PGE_FMT_PD: WORD = 1;
pub const PGE_FMT_CW: WORD = 2;
pub const PGE_FMT_AB: WORD = 3;

pub const ENC_TYPE_NO: WORD = 0;
pub const ENC_TYPE_PD: WORD = 1;
pub const ENC_TYPE_CW: WORD = 2;
pub const ENC_TYPE_AB: WORD = 3;
pub const ENC_FMT_NO: WORD = 0;
pub const ENC_FMT_PD: WORD = 1;
pub const ENC_FMT_CW: WORD = 2;
pub const ENC_FMT_AB: WORD = 3;

pub const ENC_RATE_X0: WORD = 0;
pub const ENC_RATE_X1: WORD = 1;
pub const ENC_RATE_X2: WORD = 2;
pub const ENC_RATE_X4: WORD = 3;

pub const ENC_TRIG_FIRST: WORD = 0;
pub const ENC_TRIG_LAST: WORD = 1;

pub const ENC_TRIG_NO: DWORD = 0;
pub const ENC_TRIG_INDEX0: DWORD = 0x01;
pub const ENC_TRIG_INDEX1: DWORD = 0x02;
pub const ENC_TRIG_INDEX2: DWORD = 0x04;
pub const ENC_TRIG_INDEX3: DWORD = 0x08;
pub const ENC_TRIG_INDEX4: DWORD = 0x10;
pub const ENC_TRIG_INDEX5: DWORD = 0x20;
pub const ENC_TRIG_INDEX6: DWORD = 0x40;
pub const ENC_TRIG_INDEX7: DWORD = 0x80;
pub const ENC_TRIG_OTP0: DWORD = 0x100;
pub const ENC_TRIG_OTP1: DWORD = 0x200;
pub const ENC_TRIG_OTP2: DWORD = 0x400;
pub const ENC_TRIG_OTP3: DWORD = 0x800;
pub const ENC_TRIG_OTP4: DWORD = 0x1000;
pub const ENC_TRIG_OTP5: DWORD = 0x2000;
pub const ENC_TRIG_OTP6: DWORD = 0x4000;
pub const ENC_TRIG_OTP7: DWORD = 0x8000;
pub const ENC_TRIG_OTN0: DWORD = 0x10000;
pub const ENC_TRIG_OTN1: DWORD = 0x20000;
pub const ENC_TRIG_OTN2: DWORD = 0x40000;
pub const ENC_TRIG_OTN3: DWORD = 0x80000;
pub const ENC_TRIG_OTN4: DWORD = 0x100000;
pub const ENC_TRIG_OTN5: DWORD = 0x200000;
pub const ENC_TRIG_OTN6: DWORD = 0x400000;
pub const ENC_TRIG_OTN7: DWORD = 0x800000;
pub const ENC_TRIG_TMR: DWORD = 0x01000000;

pub const LIO_INT_NO: WORD = 0;
pub const LIO_INT_RISE: WORD = 1;
pub const LIO_INT_FALL: WORD = 2;
pub const LIO_INT_LEVEL: WORD = 3;

pub const LIO_LDI_OTP0: WORD = 0;
pub const LIO_LDI_OTP1: WORD = 1;
pub const LIO_LDI_OTP2: WORD = 2;
pub const LIO_LDI_OTP3: WORD = 3;
pub const LIO_LDI_OTP4: WORD = 4;
pub const LIO_LDI_OTP5: WORD = 5;
pub const LIO_LDI_OTP6: WORD = 6;
pub const LIO_LDI_OTP7: WORD = 7;
pub const LIO_LDI_OTN0: WORD = 8;
pub const LIO_LDI_OTN1: WORD = 9;
pub const LIO_LDI_OTN2: WORD = 10;
pub const LIO_LDI_OTN3: WORD = 11;
pub const LIO_LDI_OTN4: WORD = 12;
pub const LIO_LDI_OTN5: WORD = 13;
pub const LIO_LDI_OTN6: WORD = 14;
pub const LIO_LDI_OTN7: WORD = 15;
pub const LIO_LDI_HOME0: WORD = 16;
pub const LIO_LDI_HOME1: WORD = 17;
pub const LIO_LDI_HOME2: WORD = 18;
pub const LIO_LDI_HOME3: WORD = 19;
pub const LIO_LDI_HOME4: WORD = 20;
pub const LIO_LDI_HOME5: WORD = 21;
pub const LIO_LDI_HOME6: WORD = 22;
pub const LIO_LDI_HOME7: WORD = 23;

pub const DAC_TRIG_ENC0: DWORD = 0x01;
pub const DAC_TRIG_ENC1: DWORD = 0x02;
pub const DAC_TRIG_ENC2: DWORD = 0x04;
pub const DAC_TRIG_ENC3: DWORD = 0x08;
pub const DAC_TRIG_ENC4: DWORD = 0x10;
pub const DAC_TRIG_ENC5: DWORD = 0x20;
pub const DAC_TRIG_ENC6: DWORD = 0x40;
pub const DAC_TRIG_ENC7: DWORD = 0x80;

pub const IO_TRIG_ENC0: DWORD = 0x01;
pub const IO_TRIG_ENC1: DWORD = 0x02;
pub const IO_TRIG_ENC2: DWORD = 0x04;
pub const IO_TRIG_ENC3: DWORD = 0x08;
pub const IO_TRIG_ENC4: DWORD = 0x10;
pub const IO_TRIG_ENC5: DWORD = 0x20;
pub const IO_TRIG_ENC6: DWORD = 0x40;
pub const IO_TRIG_ENC7: DWORD = 0x80;

pub const LED_TRIG_ENC0: DWORD = 0x01;
pub const LED_TRIG_ENC1: DWORD = 0x02;
pub const LED_TRIG_ENC2: DWORD = 0x04;
pub const LED_TRIG_ENC3: DWORD = 0x08;
pub const LED_TRIG_ENC4: DWORD = 0x10;
pub const LED_TRIG_ENC5: DWORD = 0x20;
pub const LED_TRIG_ENC6: DWORD = 0x40;
pub const LED_TRIG_ENC7: DWORD = 0x80;

pub const LIO_SOURCE_COMP0: WORD = 0x01;
pub const LIO_SOURCE_COMP1: WORD = 0x02;
pub const LIO_SOURCE_COMP2: WORD = 0x04;
pub const LIO_SOURCE_COMP3: WORD = 0x08;
pub const LIO_SOURCE_COMP4: WORD = 0x10;
pub const LIO_SOURCE_COMP5: WORD = 0x20;
pub const LIO_SOURCE_COMP6: WORD = 0x40;
pub const LIO_SOURCE_COMP7: WORD = 0x80;

/// `ENC_COMP_CH0..7`: used by the examples manual, defined nowhere public; 0..7
/// (docs/decisions.md, "Vendor interface").
pub const ENC_COMP_CH0: WORD = 0;
pub const ENC_COMP_CH1: WORD = 1;
pub const ENC_COMP_CH2: WORD = 2;
pub const ENC_COMP_CH3: WORD = 3;
pub const ENC_COMP_CH4: WORD = 4;
pub const ENC_COMP_CH5: WORD = 5;
pub const ENC_COMP_CH6: WORD = 6;
pub const ENC_COMP_CH7: WORD = 7;

// ---- 2.6 ADC (B/C values) ----
pub const ADC_COMP_RISE: WORD = 0;
pub const ADC_COMP_FALL: WORD = 1;
pub const ADC_COMP_LEVEL: WORD = 2;
pub const ADC_MASK_NO: WORD = 0;
pub const ADC_MASK_BIT1: WORD = 1;
pub const ADC_MASK_BIT2: WORD = 2;
pub const ADC_MASK_BIT3: WORD = 3;
pub const ADC_TYPE_BIP_DIFF: WORD = 0;
pub const ADC_TYPE_UNI_DIFF: WORD = 1;
pub const ADC_TYPE_BIP_SING: WORD = 2;
pub const ADC_TYPE_UNI_SING: WORD = 3;
pub const ADC_MODE_SINGLE: WORD = 0;
pub const ADC_MODE_FREE: WORD = 1;

// ---- 2.7 remote I/O ----
pub const RIO_SET0: WORD = 0;
pub const RIO_SET1: WORD = 1;
pub const RIO_SLAVE0: WORD = 0x0;
pub const RIO_SLAVE1: WORD = 0x1;
pub const RIO_SLAVE2: WORD = 0x2;
pub const RIO_SLAVE3: WORD = 0x3;
pub const RIO_SLAVE4: WORD = 0x4;
pub const RIO_SLAVE5: WORD = 0x5;
pub const RIO_SLAVE6: WORD = 0x6;
pub const RIO_SLAVE7: WORD = 0x7;
pub const RIO_SLAVE8: WORD = 0x8;
pub const RIO_SLAVE9: WORD = 0x9;
pub const RIO_SLAVE10: WORD = 0xA;
pub const RIO_SLAVE11: WORD = 0xB;
pub const RIO_SLAVE12: WORD = 0xC;
pub const RIO_SLAVE13: WORD = 0xD;
pub const RIO_SLAVE14: WORD = 0xE;
pub const RIO_SLAVE15: WORD = 0xF;
pub const RIO_SLAVE16: WORD = 0x10;
pub const RIO_SLAVE17: WORD = 0x11;
pub const RIO_SLAVE18: WORD = 0x12;
pub const RIO_SLAVE19: WORD = 0x13;
pub const RIO_SLAVE20: WORD = 0x14;
pub const RIO_SLAVE21: WORD = 0x15;
pub const RIO_SLAVE22: WORD = 0x16;
pub const RIO_SLAVE23: WORD = 0x17;
pub const RIO_SLAVE24: WORD = 0x18;
pub const RIO_SLAVE25: WORD = 0x19;
pub const RIO_SLAVE26: WORD = 0x1A;
pub const RIO_SLAVE27: WORD = 0x1B;
pub const RIO_SLAVE28: WORD = 0x1C;
pub const RIO_SLAVE29: WORD = 0x1D;
pub const RIO_SLAVE30: WORD = 0x1E;
pub const RIO_SLAVE31: WORD = 0x1F;
pub const RIO_PORT0: WORD = 0;
pub const RIO_PORT1: WORD = 1;
pub const RIO_PORT2: WORD = 2;
pub const RIO_PORT3: WORD = 3;
pub const RIO_DI0: WORD = 0;
pub const RIO_DI1: WORD = 1;
pub const RIO_DI2: WORD = 2;
pub const RIO_DI3: WORD = 3;
pub const RIO_DI4: WORD = 4;
pub const RIO_DI5: WORD = 5;
pub const RIO_DI6: WORD = 6;
pub const RIO_DI7: WORD = 7;
pub const RIO_INT_NO: WORD = 0;
pub const RIO_INT_RISE: WORD = 1;
pub const RIO_INT_FALL: WORD = 2;
pub const RIO_INT_LEVEL: WORD = 3;

// ---- IMCDefine.h extras that MCCL.h carries ----
pub const ADC_COMPARE_NO: WORD = 0;
pub const ADC_COMPARE_L2H: WORD = 1;
pub const ADC_COMPARE_H2L: WORD = 2;
pub const ADC_COMPARE_ANY: WORD = 3;
pub const DAC_SOURCE_SOFT: WORD = 0;
pub const DAC_SOURCE_PCL: WORD = 1;
