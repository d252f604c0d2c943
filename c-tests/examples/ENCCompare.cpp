// ENCCompare.cpp: examples manual §25 (encoder count triggers an interrupt routine),
// written the way the manual writes it. X runs a line to 100 UU at 10 UU/s (5 counts per
// 1 ms tick at 500 counts/UU); the compare value 20000 fires the routine once, which
// aborts the motion with no deceleration and turns the compare trigger off. The routine
// runs after the tick in which the count reached 20000 and the abort acts at once, so X
// stops within one tick of counts past it: 20000 <= count <= 20005.
#include "MotionSys.h"

#define CHANNEL_INDEX 0

static volatile int ENC_ISR = 0;

// Step 1: declare the routine (the manual writes _stdcall; MCCL.h makes it mean nothing
// outside Windows).
void _stdcall ENC_ISR_Function(ENCINT *pstINTSource);

// Step 2: define it.
void _stdcall ENC_ISR_Function(ENCINT *pstINTSource)
{
    // Did channel 0's compare fire?
    if (pstINTSource->COMP0)
    {
        // Drop the running and every queued motion command.
        MCC_AbortMotionEx(0, g_nGroupIndex);
        ENC_ISR++;
        // Turn the compare trigger off.
        MCC_DisableENCCompTrigger(CHANNEL_INDEX);
    }
}

int main()
{
    if (InitSys8() != NO_ERR)
        return check_done("ENCCompare");
    MCC_SetFeedSpeed(10, g_nGroupIndex);

    // Step 3: register the routine.
    CHECK_EQ(MCC_SetENCRoutine(ENC_ISR_Function, CARD_INDEX), NO_ERR);
    // Step 4: compare value 20000 pulses.
    CHECK_EQ(MCC_SetENCCompValue(20000, CHANNEL_INDEX, CARD_INDEX), NO_ERR);
    WORD wCount = 0;
    CHECK_EQ(MCC_GetENCCompStockCount(&wCount, CHANNEL_INDEX, CARD_INDEX), NO_ERR);
    CHECK_EQ(wCount, 1);
    // Step 5: turn the compare trigger on.
    CHECK_EQ(MCC_EnableENCCompTrigger(CHANNEL_INDEX, CARD_INDEX), NO_ERR);
    // Step 6: the line; read the encoder.
    MCC_Line(100, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex);
    WaitStop(g_nGroupIndex);
    long lEncoderValue = 0;
    CHECK_EQ(MCC_GetENCValue(&lEncoderValue, CHANNEL_INDEX, CARD_INDEX), NO_ERR);
    printf("The routine ran %d time(s); X stopped at encoder count %ld (compare value 20000)\n",
           ENC_ISR, lEncoderValue);
    CHECK_EQ(ENC_ISR, 1);
    CHECK(lEncoderValue >= 20000 && lEncoderValue <= 20005);
    CHECK_EQ(MCC_GetENCCompStockCount(&wCount, CHANNEL_INDEX, CARD_INDEX), NO_ERR);
    CHECK_EQ(wCount, 0);

    // A stock of values fires one after the other (examples manual §26's table form).
    ENC_ISR = 0;
    CHECK_EQ(MCC_SetENCRoutine(NULL, CARD_INDEX), NO_ERR);   // NULL unregisters
    CHECK_EQ(MCC_SetENCCompValueTab(25000, 45000, 10000, CHANNEL_INDEX, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_GetENCCompStockCount(&wCount, CHANNEL_INDEX, CARD_INDEX), NO_ERR);
    CHECK_EQ(wCount, 3);
    long lComp = 0;
    CHECK_EQ(MCC_GetENCCompValue(&lComp, CHANNEL_INDEX, CARD_INDEX), NO_ERR);
    CHECK_EQ(lComp, 25000);
    CHECK_EQ(MCC_EnableENCCompTrigger(CHANNEL_INDEX, CARD_INDEX), NO_ERR);
    MCC_Line(80, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex);   // 40000 counts: passes 25000, 35000
    WaitStop(g_nGroupIndex);
    CHECK_EQ(MCC_GetENCCompStockCount(&wCount, CHANNEL_INDEX, CARD_INDEX), NO_ERR);
    CHECK_EQ(wCount, 1);
    CHECK_EQ(MCC_GetENCCompValue(&lComp, CHANNEL_INDEX, CARD_INDEX), NO_ERR);
    CHECK_EQ(lComp, 45000);
    CHECK_EQ(MCC_EraseENCCompValue(CHANNEL_INDEX, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_GetENCCompStockCount(&wCount, CHANNEL_INDEX, CARD_INDEX), NO_ERR);
    CHECK_EQ(wCount, 0);
    CHECK_EQ(ENC_ISR, 0);

    CHECK_EQ(MCC_SetENCCompValueTab(10, 0, 5, CHANNEL_INDEX, CARD_INDEX), PARAMETER_ERR);
    CHECK_EQ(MCC_SetENCCompValue(1, 8, CARD_INDEX), PARAMETER_ERR);
    CHECK_EQ(MCC_GetENCCompStockCount(NULL, 0, CARD_INDEX), PARAMETER_ERR);
    Close();
    return check_done("ENCCompare");
}
