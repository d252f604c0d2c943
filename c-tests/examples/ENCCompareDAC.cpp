// ENCCompareDAC.cpp: examples manual §36 (an encoder compare triggers the DAC's preset
// voltage). Compare value 5000 on channel 0; DAC channel 0 in trigger mode with source
// DAC_TRIG_ENC0 and preset 3.5 V. Before X reaches 5000 counts the DAC reads 0 V; after,
// 3.5 V (read back through ADC 0, which the virtual card wires to DAC 0).
#include "MotionSys.h"

#define CHANNEL_INDEX 0
#define DAC_CHANNEL_INDEX 0
#define TRIGOUT_VOLTAGE 3.5f

int main()
{
    if (InitSys8() != NO_ERR)
        return check_done("ENCCompareDAC");
    MCC_SetFeedSpeed(10, g_nGroupIndex);
    // Step 1-2: the compare value and its trigger.
    CHECK_EQ(MCC_SetENCCompValue(5000, CHANNEL_INDEX, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_EnableENCCompTrigger(CHANNEL_INDEX, CARD_INDEX), NO_ERR);
    // Step 3: the voltage the trigger outputs (-10 V..10 V), its source, trigger mode on.
    CHECK_EQ(MCC_SetDACTriggerOutput(TRIGOUT_VOLTAGE, DAC_CHANNEL_INDEX, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_SetDACTriggerSource(DAC_TRIG_ENC0, DAC_CHANNEL_INDEX, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_EnableDACTriggerMode(DAC_CHANNEL_INDEX, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_StartDACConv(CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_EnableADCConvChannel(0, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_StartADCConv(CARD_INDEX), NO_ERR);

    MCC_Line(5, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex);   // 2500 counts: not yet
    WaitStop(g_nGroupIndex);
    MCC_TimeDelay(5);
    float fIn = -1;
    CHECK_EQ(MCC_GetADCInput(&fIn, 0, CARD_INDEX), NO_ERR);
    printf("At 2500 counts the DAC reads %.3f V\n", fIn);
    CHECK(fIn > -0.01f && fIn < 0.01f);
    MCC_Line(12, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex);  // 6000 counts: past 5000
    WaitStop(g_nGroupIndex);
    MCC_TimeDelay(5);
    CHECK_EQ(MCC_GetADCInput(&fIn, 0, CARD_INDEX), NO_ERR);
    printf("After 5000 counts the DAC reads %.3f V\n", fIn);
    CHECK(fIn > 3.49f && fIn < 3.51f);
    Close();
    return check_done("ENCCompareDAC");
}
