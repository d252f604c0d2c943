// PCLControl.cpp: examples manual §39 (closed-loop control failure). Run with
// MCCL_SIM=c-tests/sim/lag_x.toml: X's motor lags 50 ms, so at 10 UU/s it trails by
// 0.5 UU = 250 pulses. With the + threshold of the error counter at 100 pulses the PCL
// routine runs once with OVP0 set when the error crosses it; OVN0 never.
#include "MotionSys.h"

static volatile int PCL_ISR = 0, OVP0 = 0, OVN0 = 0;

void _stdcall PCL_ISR_Function(PCLINT *pstINTSource)
{
    PCL_ISR++;
    if (pstINTSource->OVP0) OVP0++;
    if (pstINTSource->OVN0) OVN0++;
}

int main()
{
    if (InitSys8() != NO_ERR)
        return check_done("PCLControl");
    MCC_SetFeedSpeed(10, g_nGroupIndex);
    CHECK_EQ(MCC_SetPCLRoutine(PCL_ISR_Function, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_SetErrorCountThreshold(0, 100, 100, CARD_INDEX), NO_ERR);
    MCC_Line(5, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex);
    MCC_TimeDelay(500);
    int e[8];
    CHECK_EQ(MCC_GetErrorCount(&e[0], &e[1], &e[2], &e[3], &e[4], &e[5], &e[6], &e[7], CARD_INDEX), NO_ERR);
    printf("Error counter of X while moving: %d pulses (threshold 100)\n", e[0]);
    CHECK(e[0] > 200 && e[0] < 260);
    WaitStop(g_nGroupIndex);
    MCC_TimeDelay(500);
    printf("PCL routine: %d call(s), OVP0 %d, OVN0 %d\n", PCL_ISR, OVP0, OVN0);
    CHECK_EQ(PCL_ISR, 1);
    CHECK_EQ(OVP0, 1);
    CHECK_EQ(OVN0, 0);
    CHECK_EQ(MCC_SetErrorCountThreshold(8, 1, 1, CARD_INDEX), PARAMETER_ERR);
    Close();
    return check_done("PCLControl");
}
