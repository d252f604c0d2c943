// LIOControl.cpp: examples manual §30 (local I/O signals and their interrupt routine).
// X's + limit switch sits at 2 UU (placed through MCCL_Sim.h). With the OTP0 input
// triggered on its rising edge, a line to 5 UU (limit check off) passes the switch once:
// the routine runs once with OTP0 set; with LIO_INT_FALL it runs when X comes back out.
#include "MotionSys.h"
#include "MCCL_Sim.h"

static volatile int LIO_ISR = 0, LIO_OTP0 = 0;

void _stdcall LIO_ISR_Function(LIOINT *pstINTSource)
{
    LIO_ISR++;
    if (pstINTSource->OTP0)
        LIO_OTP0++;
}

int main()
{
    if (InitSys8() != NO_ERR)
        return check_done("LIOControl");
    SYS_MAC_PARAM stAxisParam;
    MCC_GetMacParam(&stAxisParam, 0, CARD_INDEX);
    stAxisParam.wOverTravelUpSensorMode = SL_NORMAL_OPEN;
    CHECK_EQ(MCC_SetMacParam(&stAxisParam, 0, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_UpdateParam(), NO_ERR);
    MCC_SetFeedSpeed(10, g_nGroupIndex);
    CHECK_EQ(MCCL_SimPlaceSensor(CARD_INDEX, 0, MCCL_SIM_LIMIT_PLUS, 2.0, 0), NO_ERR);

    CHECK_EQ(MCC_SetLIORoutine(LIO_ISR_Function, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_SetLIOTriggerType(LIO_INT_RISE, LIO_LDI_OTP0, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_EnableLIOTrigger(LIO_LDI_OTP0, CARD_INDEX), NO_ERR);
    MCC_Line(5, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex);
    WaitStop(g_nGroupIndex);
    printf("Through the + switch at 2 UU: routine %d time(s), OTP0 %d\n", LIO_ISR, LIO_OTP0);
    CHECK_EQ(LIO_ISR, 1);
    CHECK_EQ(LIO_OTP0, 1);

    CHECK_EQ(MCC_SetLIOTriggerType(LIO_INT_FALL, LIO_LDI_OTP0, CARD_INDEX), NO_ERR);
    MCC_Line(0, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex);
    WaitStop(g_nGroupIndex);
    CHECK_EQ(LIO_ISR, 2);   // left the switch: a falling edge
    CHECK_EQ(MCC_DisableLIOTrigger(LIO_LDI_OTP0, CARD_INDEX), NO_ERR);
    MCC_Line(5, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex);
    WaitStop(g_nGroupIndex);
    CHECK_EQ(LIO_ISR, 2);   // disabled
    CHECK_EQ(MCC_SetLIOTriggerType(4, 0, CARD_INDEX), PARAMETER_ERR);
    CHECK_EQ(MCC_EnableLIOTrigger(24, CARD_INDEX), PARAMETER_ERR);
    Close();
    return check_done("LIOControl");
}
