//! The card's DAC through the C entry points: its output, stop and trigger modes, and the
//! channels that carry a voltage command. On the stepped clock: 1 ms ticks,
//! `MCC_TimeDelay(n)` runs exactly n ticks.

mod common;

use common::periph::{periph, with_periph};
use common::{fresh, init_ms};
use MCCLPCI_IMP::ffi::dac::*;
use MCCLPCI_IMP::ffi::system::*;
use MCCLPCI_IMP::vendor::consts::*;
use MCCLPCI_IMP::vendor::*;

#[test]
fn dac_output_stop_trigger_and_voltage_channels() {
    let _g = fresh();
    let mut m = SYS_MAC_PARAM::default();
    // SAFETY: valid pointers.
    unsafe {
        assert_eq!(MCC_GetMacParam(&mut m, 2, 0), NO_ERR);
        m.wCommandMode = OCM_VOLTAGE;
        assert_eq!(MCC_SetMacParam(&mut m, 2, 0), NO_ERR);
    }
    assert_eq!(init_ms(1, 1), NO_ERR);
    assert_eq!(MCC_SetDACOutput(1.0, 2, 0), VOLTAGE_COMMAND_CHANNEL_ERR);
    assert_eq!(
        MCC_SetDACTriggerOutput(1.0, 2, 0),
        VOLTAGE_COMMAND_CHANNEL_ERR
    );
    assert_eq!(
        MCC_SetDACTriggerSource(1, 2, 0),
        VOLTAGE_COMMAND_CHANNEL_ERR
    );
    assert_eq!(MCC_EnableDACTriggerMode(2, 0), VOLTAGE_COMMAND_CHANNEL_ERR);
    assert_eq!(MCC_DisableDACTriggerMode(2, 0), VOLTAGE_COMMAND_CHANNEL_ERR);
    assert_eq!(periph(0).dac().value(2), 0.0);

    assert_eq!(MCC_SetDACOutput(-2.5, 1, 0), NO_ERR);
    assert_eq!(periph(0).dac().output(1), -2.5);
    assert_eq!(MCC_StopDACConv(0), NO_ERR);
    assert_eq!(periph(0).dac().output(1), 0.0);
    assert_eq!(MCC_StartDACConv(0), NO_ERR);
    assert_eq!(periph(0).dac().output(1), -2.5);

    assert_eq!(MCC_SetDACTriggerOutput(2.0, 0, 0), NO_ERR);
    assert_eq!(
        MCC_SetDACTriggerSource(DAC_TRIG_ENC0 | DAC_TRIG_ENC5, 0, 0),
        NO_ERR
    );
    assert_eq!(MCC_EnableDACTriggerMode(0, 0), NO_ERR);
    with_periph(0, |p| p.dac_trigger(1));
    assert_eq!(periph(0).dac().output(0), 0.0, "not a source");
    with_periph(0, |p| p.dac_trigger(5));
    assert_eq!(periph(0).dac().output(0), 2.0);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}
