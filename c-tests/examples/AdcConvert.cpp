// AdcConvert.cpp: examples manual §37 (ADCInput.cpp): ADC channel 0 converts
// continuously, bipolar (-5..5 V), and the program reads the input voltage.
//
// The input: DAC channel 0, which the virtual card wires to ADC channel 0 (as the
// examples manual's §38 does). In ADC_MODE_FREE (the default) every enabled channel
// converts once per tick (1 ms here) after MCC_StartADCConv; an input outside the
// conversion type's range reads as the range's end (user manual §2.12.1: bipolar
// -5..5 V, unipolar 0..10 V). Then a single conversion (user manual §2.12.3).
#include "MotionSys.h"

int main()
{
    if (InitSys8() != NO_ERR)
        return check_done("AdcConvert");
    float fInput = NAN;

    // Step 1: bipolar differential input (-5..5 V).
    CHECK_EQ(MCC_SetADCConvType(ADC_TYPE_BIP_DIFF, 0, CARD_INDEX), NO_ERR);
    WORD wType = 9;
    CHECK_EQ(MCC_GetADCConvType(&wType, 0, CARD_INDEX), NO_ERR);
    CHECK_EQ(wType, ADC_TYPE_BIP_DIFF);
    // Step 2: channel 0 converts.
    CHECK_EQ(MCC_EnableADCConvChannel(0, CARD_INDEX), NO_ERR);
    // Step 3: start converting.
    CHECK_EQ(MCC_StartADCConv(CARD_INDEX), NO_ERR);
    WORD wStatus = 9;
    CHECK_EQ(MCC_GetADCWorkStatus(&wStatus, CARD_INDEX), NO_ERR);
    CHECK_EQ(wStatus, 1);

    const float afDAC[] = { 1.0f, -2.5f, 4.999f, 6.0f, -7.5f, 0.0f };
    const float afExpect[] = { 1.0f, -2.5f, 4.999f, 5.0f, -5.0f, 0.0f };
    for (int i = 0; i < 6; i++)
    {
        CHECK_EQ(MCC_SetDACOutput(afDAC[i], 0, CARD_INDEX), NO_ERR);
        MCC_TimeDelay(1);
        CHECK_EQ(MCC_GetADCInput(&fInput, 0, CARD_INDEX), NO_ERR);
        printf("  DAC 0 %+.3f V -> ADC 0 %+.3f V (bipolar)\n", afDAC[i], fInput);
        CHECK_NEAR(fInput, afExpect[i], 1e-6);
    }

    // Unipolar: 0..10 V.
    CHECK_EQ(MCC_SetADCConvType(ADC_TYPE_UNI_DIFF, 0, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_SetDACOutput(7.25f, 0, CARD_INDEX), NO_ERR);
    MCC_TimeDelay(1);
    CHECK_EQ(MCC_GetADCInput(&fInput, 0, CARD_INDEX), NO_ERR);
    CHECK_NEAR(fInput, 7.25, 1e-6);
    CHECK_EQ(MCC_SetDACOutput(-1.0f, 0, CARD_INDEX), NO_ERR);
    MCC_TimeDelay(1);
    CHECK_EQ(MCC_GetADCInput(&fInput, 0, CARD_INDEX), NO_ERR);
    CHECK_NEAR(fInput, 0.0, 1e-6);

    // Stopped: the last value stays.
    CHECK_EQ(MCC_StopADCConv(CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_SetDACOutput(3.0f, 0, CARD_INDEX), NO_ERR);
    MCC_TimeDelay(5);
    CHECK_EQ(MCC_GetADCInput(&fInput, 0, CARD_INDEX), NO_ERR);
    CHECK_NEAR(fInput, 0.0, 1e-6);

    // Single conversion of channel 2 (DAC 2): converted once per MCC_StartADCConv.
    CHECK_EQ(MCC_SetADCSingleChannel(2, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_SetADCConvMode(ADC_MODE_SINGLE, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_SetDACOutput(-3.5f, 2, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_StartADCConv(CARD_INDEX), NO_ERR);
    do
        CHECK_EQ(MCC_GetADCWorkStatus(&wStatus, CARD_INDEX), NO_ERR);
    while (wStatus != 0);
    CHECK_EQ(MCC_GetADCInput(&fInput, 2, CARD_INDEX), NO_ERR);
    CHECK_NEAR(fInput, -3.5, 1e-6);
    CHECK_EQ(MCC_SetDACOutput(2.0f, 2, CARD_INDEX), NO_ERR);
    MCC_TimeDelay(10);
    CHECK_EQ(MCC_GetADCInput(&fInput, 2, CARD_INDEX), NO_ERR);
    CHECK_NEAR(fInput, -3.5, 1e-6);   // no conversion without MCC_StartADCConv
    CHECK_EQ(MCC_StartADCConv(CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_GetADCInput(&fInput, 2, CARD_INDEX), NO_ERR);
    CHECK_NEAR(fInput, 2.0, 1e-6);

    CHECK_EQ(MCC_SetADCConvType(4, 0, CARD_INDEX), PARAMETER_ERR);
    CHECK_EQ(MCC_SetADCConvMode(2, CARD_INDEX), PARAMETER_ERR);
    CHECK_EQ(MCC_GetADCInput(NULL, 0, CARD_INDEX), PARAMETER_ERR);
    CHECK_EQ(MCC_GetADCInput(&fInput, 8, CARD_INDEX), PARAMETER_ERR);
    Close();
    return check_done("AdcConvert");
}
