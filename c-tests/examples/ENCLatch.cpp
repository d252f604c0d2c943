// ENCLatch.cpp: examples manual §29 (encoder count latch and the index interrupt). The
// latch source is channel 0's index pulse (ENC_TRIG_INDEX0), type ENC_TRIG_LAST; the
// index interrupt reads the latch in the routine. Index pulses fall every dwPPR = 500
// counts (one per motor turn, phase 0), so a line to 3 UU (1500 counts) passes the index
// at 500, 1000 and 1500: three routine calls, latched 500, 1000, 1500.
#include "MotionSys.h"

#define CHANNEL_INDEX 0

static volatile int ENC_ISR = 0;
static long lLatch[8];

void _stdcall ENC_ISR_Function(ENCINT *pstINTSource)
{
    if (pstINTSource->INDEX0)
    {
        long lLatchValue = 0;
        MCC_GetENCLatchValue(&lLatchValue, CHANNEL_INDEX, CARD_INDEX);
        if (ENC_ISR < 8)
            lLatch[ENC_ISR] = lLatchValue;
        ENC_ISR++;
    }
}

int main()
{
    if (InitSys8() != NO_ERR)
        return check_done("ENCLatch");
    MCC_SetFeedSpeed(1, g_nGroupIndex);   // 500 counts/s: one index per second, one per tick at most
    // Step 3: register the routine.
    CHECK_EQ(MCC_SetENCRoutine(ENC_ISR_Function, CARD_INDEX), NO_ERR);
    // Step 4: latch mode.
    CHECK_EQ(MCC_SetENCLatchType(ENC_TRIG_LAST, CHANNEL_INDEX, CARD_INDEX), NO_ERR);
    // Step 5: latch source: channel 0's index.
    CHECK_EQ(MCC_SetENCLatchSource(ENC_TRIG_INDEX0, CHANNEL_INDEX, CARD_INDEX), NO_ERR);
    // Step 6: the index interrupt.
    CHECK_EQ(MCC_EnableENCIndexTrigger(CHANNEL_INDEX, CARD_INDEX), NO_ERR);
    MCC_Line(3, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex);
    WaitStop(g_nGroupIndex);
    printf("Index routine calls: %d, latched %ld %ld %ld\n", ENC_ISR, lLatch[0], lLatch[1], lLatch[2]);
    CHECK_EQ(ENC_ISR, 3);
    CHECK_EQ(lLatch[0], 500);
    CHECK_EQ(lLatch[1], 1000);
    CHECK_EQ(lLatch[2], 1500);
    WORD wStatus = 0;
    CHECK_EQ(MCC_GetENCIndexStatus(&wStatus, CHANNEL_INDEX, CARD_INDEX), NO_ERR);
    CHECK_EQ(wStatus, 1);
    CHECK_EQ(MCC_GetENCIndexStatus(&wStatus, CHANNEL_INDEX, CARD_INDEX), NO_ERR);
    CHECK_EQ(wStatus, 0);   // the read cleared it

    // ENC_TRIG_FIRST keeps the first one.
    CHECK_EQ(MCC_SetENCLatchType(ENC_TRIG_FIRST, CHANNEL_INDEX, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_DisableENCIndexTrigger(CHANNEL_INDEX, CARD_INDEX), NO_ERR);
    // Back down from 1500, which is itself an index position: leaving it downward passes
    // that index first, then 1000, 500 and 0; FIRST keeps 1500.
    MCC_Line(0, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex);
    WaitStop(g_nGroupIndex);
    long lLatchValue = 0;
    CHECK_EQ(MCC_GetENCLatchValue(&lLatchValue, CHANNEL_INDEX, CARD_INDEX), NO_ERR);
    CHECK_EQ(lLatchValue, 1500);
    CHECK_EQ(ENC_ISR, 3);   // index trigger off
    CHECK_EQ(MCC_SetENCLatchType(2, CHANNEL_INDEX, CARD_INDEX), PARAMETER_ERR);
    CHECK_EQ(MCC_SetENCLatchSource(0x2000000, CHANNEL_INDEX, CARD_INDEX), PARAMETER_ERR);
    // A latch on the timer is not simulated (docs/compatibility.md, "Encoder latch
    // sources"): refused, and the latch keeps its value.
    CHECK_EQ(MCC_SetENCLatchSource(ENC_TRIG_TMR, CHANNEL_INDEX, CARD_INDEX), PARAMETER_ERR);
    CHECK_EQ(MCC_GetENCLatchValue(&lLatchValue, CHANNEL_INDEX, CARD_INDEX), NO_ERR);
    CHECK_EQ(lLatchValue, 1500);
    Close();
    return check_done("ENCLatch");
}
