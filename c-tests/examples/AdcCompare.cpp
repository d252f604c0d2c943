// AdcCompare.cpp: examples manual §38 (ADCComp.cpp): ADC channel 0's comparator, set to
// 2.0 V and ADC_COMP_LEVEL (any crossing), calls the user routine each time the input
// -- DAC channel 0's output, wired to ADC channel 0 -- crosses 2.0 V.
//
// The program steps DAC 0 through a waveform, one value per tick (1 ms), and counts the
// crossings it produced itself: a sample at or above 2.0 V after one below (or the
// reverse) is one crossing. nISRCount must equal that count. Then ADC_COMP_RISE and
// ADC_COMP_FALL count only upward and only downward crossings.
#include "MotionSys.h"

static volatile int nISRCount = 0;

// Step 1-2: declare and define the ADC routine.
void MCC_CALLBACK ADC_ISR_Function(ADCINT *pstINTSource)
{
    if (pstINTSource->COMP0)   // the compare condition holds
        nISRCount++;
}

// Steps DAC 0 through n values of a triangle wave 0..3.9 V (0.3 V steps) and returns the
// crossings of dfComp: [up, down].
static void RunWave(int nSamples, float fComp, int anCross[2])
{
    anCross[0] = anCross[1] = 0;
    float fPrev = 0.0f;
    CHECK_EQ(MCC_SetDACOutput(0.0f, 0, CARD_INDEX), NO_ERR);
    MCC_TimeDelay(1);
    for (int i = 1; i <= nSamples; i++)
    {
        int k = i % 26;                                  // 0..13 up, 13..0 down
        float f = 0.3f * (float)(k <= 13 ? k : 26 - k);
        CHECK_EQ(MCC_SetDACOutput(f, 0, CARD_INDEX), NO_ERR);
        MCC_TimeDelay(1);
        if (fPrev < fComp && f >= fComp) anCross[0]++;
        if (fPrev >= fComp && f < fComp) anCross[1]++;
        fPrev = f;
    }
}

int main()
{
    if (InitSys8() != NO_ERR)
        return check_done("AdcCompare");

    // Step 3: connect the routine.
    CHECK_EQ(MCC_SetADCRoutine(ADC_ISR_Function, CARD_INDEX), NO_ERR);
    // Step 4: bipolar differential input (-5..5 V).
    CHECK_EQ(MCC_SetADCConvType(ADC_TYPE_BIP_DIFF, 0, CARD_INDEX), NO_ERR);
    // Compare value 2.0 V.
    CHECK_EQ(MCC_SetADCCompValue(2.0f, 0, CARD_INDEX), NO_ERR);
    float fComp = 0;
    CHECK_EQ(MCC_GetADCCompValue(&fComp, 0, CARD_INDEX), NO_ERR);
    CHECK_NEAR(fComp, 2.0, 0);
    // Any crossing.
    CHECK_EQ(MCC_SetADCCompType(ADC_COMP_LEVEL, 0, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_EnableADCCompTrigger(0, CARD_INDEX), NO_ERR);
    // Channel 0 converts; start converting.
    CHECK_EQ(MCC_EnableADCConvChannel(0, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_StartADCConv(CARD_INDEX), NO_ERR);

    int anCross[2];
    RunWave(130, 2.0f, anCross);   // 5 periods
    printf("  LEVEL: %d crossings produced (%d up, %d down), %d interrupts\n",
           anCross[0] + anCross[1], anCross[0], anCross[1], nISRCount);
    CHECK_EQ(anCross[0], 5);
    CHECK_EQ(anCross[1], 5);
    CHECK_EQ(nISRCount, anCross[0] + anCross[1]);

    nISRCount = 0;
    CHECK_EQ(MCC_SetADCCompType(ADC_COMP_RISE, 0, CARD_INDEX), NO_ERR);
    RunWave(52, 2.0f, anCross);
    printf("  RISE: %d up-crossings, %d interrupts\n", anCross[0], nISRCount);
    CHECK_EQ(nISRCount, anCross[0]);

    nISRCount = 0;
    CHECK_EQ(MCC_SetADCCompType(ADC_COMP_FALL, 0, CARD_INDEX), NO_ERR);
    RunWave(52, 2.0f, anCross);
    printf("  FALL: %d down-crossings, %d interrupts\n", anCross[1], nISRCount);
    CHECK_EQ(nISRCount, anCross[1]);

    // Trigger off: no interrupt.
    nISRCount = 0;
    CHECK_EQ(MCC_DisableADCCompTrigger(0, CARD_INDEX), NO_ERR);
    RunWave(52, 2.0f, anCross);
    CHECK_EQ(nISRCount, 0);

    CHECK_EQ(MCC_SetADCCompType(3, 0, CARD_INDEX), PARAMETER_ERR);
    CHECK_EQ(MCC_SetADCCompValue(NAN, 0, CARD_INDEX), PARAMETER_ERR);
    CHECK_EQ(MCC_SetADCCompMask(4, CARD_INDEX), PARAMETER_ERR);
    CHECK_EQ(MCC_SetADCRoutine(ADC_ISR_Function, 1), PARAMETER_ERR);
    Close();
    return check_done("AdcCompare");
}
