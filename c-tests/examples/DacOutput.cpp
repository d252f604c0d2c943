// DacOutput.cpp: examples manual §35 (DACOutput.cpp): a channel whose axis does not use
// V-command mode can output any voltage -10..10 V: MCC_StartDACConv, MCC_SetDACOutput,
// MCC_StopDACConv.
//
// The output is read back through the ADC: on the virtual card ADC channel n reads DAC
// channel n of the same card (the wiring of examples manual §38). Conversion runs from
// MCC_InitSystem on; MCC_StopDACConv holds every output at 0 V until MCC_StartDACConv
// (the set voltages are kept). Channel 7 is configured as a V-command axis here
// (wCommandMode = OCM_VOLTAGE): DAC calls on it return VOLTAGE_COMMAND_CHANNEL_ERR
// (user manual §2.11).
#include "MotionSys.h"

static float ReadADC(WORD wChannel)
{
    MCC_TimeDelay(1);   // one conversion (one tick)
    float f = NAN;
    CHECK_EQ(MCC_GetADCInput(&f, wChannel, CARD_INDEX), NO_ERR);
    return f;
}

int main()
{
    CHECK_EQ(MCC_SetSysMaxSpeed(EX_MAX_SPEED), NO_ERR);
    SetMacParams();
    SYS_MAC_PARAM stAxisParam;
    CHECK_EQ(MCC_GetMacParam(&stAxisParam, 7, CARD_INDEX), NO_ERR);
    stAxisParam.wCommandMode = OCM_VOLTAGE;
    CHECK_EQ(MCC_SetMacParam(&stAxisParam, 7, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_CloseAllGroups(), NO_ERR);
    g_nGroupIndex = MCC_CreateGroup(0, 1, 2, 3, 4, 5, 6, -1, CARD_INDEX);
    if (StartSystem() != NO_ERR)
        return check_done("DacOutput");

    // The ADC reads -5..5 V (bipolar) by default; 0..10 V would be ADC_TYPE_UNI_DIFF.
    for (WORD ch = 0; ch < 2; ch++)
        CHECK_EQ(MCC_EnableADCConvChannel(ch, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_SetADCConvType(ADC_TYPE_UNI_DIFF, 1, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_StartADCConv(CARD_INDEX), NO_ERR);

    // Start D/A conversion, output voltages.
    CHECK_EQ(MCC_StartDACConv(CARD_INDEX), NO_ERR);
    const float afVolt[] = { 0.0f, 1.5f, -2.25f, 4.75f, -4.0f };
    for (size_t i = 0; i < sizeof(afVolt) / sizeof(afVolt[0]); i++)
    {
        CHECK_EQ(MCC_SetDACOutput(afVolt[i], 0, CARD_INDEX), NO_ERR);
        float f = ReadADC(0);
        printf("  DAC 0 = %+.2f V -> ADC 0 reads %+.2f V\n", afVolt[i], f);
        CHECK_NEAR(f, afVolt[i], 1e-6);
    }
    CHECK_EQ(MCC_SetDACOutput(8.5f, 1, CARD_INDEX), NO_ERR);
    CHECK_NEAR(ReadADC(1), 8.5, 1e-6);
    CHECK_EQ(MCC_SetDACOutput(10.0f, 1, CARD_INDEX), NO_ERR);    // the range's ends
    CHECK_EQ(MCC_SetDACOutput(-10.0f, 1, CARD_INDEX), NO_ERR);
    CHECK_NEAR(ReadADC(1), 0.0, 1e-6);                           // unipolar ADC: 0 V
    CHECK_EQ(MCC_SetDACOutput(8.5f, 1, CARD_INDEX), NO_ERR);

    // Outside -10..10 V, or the V-command channel: refused, the output stays.
    CHECK_EQ(MCC_SetDACOutput(10.5f, 0, CARD_INDEX), PARAMETER_ERR);
    CHECK_EQ(MCC_SetDACOutput(-10.01f, 0, CARD_INDEX), PARAMETER_ERR);
    CHECK_EQ(MCC_SetDACOutput(NAN, 0, CARD_INDEX), PARAMETER_ERR);
    CHECK_EQ(MCC_SetDACOutput(1.0f, 8, CARD_INDEX), PARAMETER_ERR);
    CHECK_EQ(MCC_SetDACOutput(1.0f, 0, 1), PARAMETER_ERR);
    CHECK_EQ(MCC_SetDACOutput(1.0f, 7, CARD_INDEX), VOLTAGE_COMMAND_CHANNEL_ERR);
    CHECK_NEAR(ReadADC(0), -4.0, 1e-6);

    // Stop: 0 V on every output; start again: the set voltages come back.
    CHECK_EQ(MCC_StopDACConv(CARD_INDEX), NO_ERR);
    CHECK_NEAR(ReadADC(0), 0.0, 1e-6);
    CHECK_NEAR(ReadADC(1), 0.0, 1e-6);
    CHECK_EQ(MCC_StartDACConv(CARD_INDEX), NO_ERR);
    CHECK_NEAR(ReadADC(0), -4.0, 1e-6);
    CHECK_NEAR(ReadADC(1), 8.5, 1e-6);
    CHECK_EQ(MCC_StopDACConv(CARD_INDEX), NO_ERR);

    Close();
    return check_done("DacOutput");
}
