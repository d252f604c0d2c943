// Compensate.cpp: examples manual §22 (gear backlash and gap compensation) with the user
// manual's worked example (§2.7.5): interval 10000 pulses, home at point 4, forward table
// 22 20 15 11 0 10 12 15. Moving X forward 15000 pulses sends
// 15000 + 10 + 5000 / 10000 x 2 = 15011 pulses; the command position (MCC_GetCurPos) and
// MCC_GetPulsePos include the compensation, as the vendor's library counts them (30.022
// UU, 15011 pulses), the reference position (MCC_GetCurRefPos) does not (30 UU).
// Interval 0 turns compensation off.
#include "MotionSys.h"
#include "MCCL_Sim.h"

int main()
{
    if (InitSys8() != NO_ERR)
        return check_done("Compensate");
    MCC_SetFeedSpeed(50, g_nGroupIndex);

    SYS_COMP_PARAM stUserCompParam;
    memset(&stUserCompParam, 0, sizeof(stUserCompParam));
    stUserCompParam.dwInterval = 10000;
    stUserCompParam.wHome_No = 4;
    stUserCompParam.nForwardTable[0] = 22; // unit: pulse
    stUserCompParam.nForwardTable[1] = 20;
    stUserCompParam.nForwardTable[2] = 15;
    stUserCompParam.nForwardTable[3] = 11;
    stUserCompParam.nForwardTable[4] = 0;  // home position, set as 0
    stUserCompParam.nForwardTable[5] = 10;
    stUserCompParam.nForwardTable[6] = 12;
    stUserCompParam.nForwardTable[7] = 15;
    CHECK_EQ(MCC_SetCompParam(&stUserCompParam, 0, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_UpdateCompParam(), NO_ERR);

    // X forward 15000 pulses = 30 UU at 500 pulses/UU.
    MCC_Line(30, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex);
    WaitStop(g_nGroupIndex);
    double dfMotor;
    long long llSent;
    CHECK_EQ(MCCL_SimGetMotor(CARD_INDEX, 0, &dfMotor, &llSent), NO_ERR);
    long lX, lY, lZ, lU, lV, lW, lA, lB;
    MCC_GetPulsePos(&lX, &lY, &lZ, &lU, &lV, &lW, &lA, &lB, g_nGroupIndex);
    printf("X +15000 pulses with compensation: %lld pulses sent (command %ld)\n", llSent, lX);
    CHECK_EQ(llSent, 15011);
    CHECK_EQ(lX, 15011);
    CheckPosXYZ(g_nGroupIndex, 30.022, 0, 0);
    double r[8];
    CHECK_EQ(MCC_GetCurRefPos(&r[0], &r[1], &r[2], &r[3], &r[4], &r[5], &r[6], &r[7], g_nGroupIndex), NO_ERR);
    CHECK_NEAR(r[0], 30, POS_TOL);

    // Compensation off: dwInterval 0.
    stUserCompParam.dwInterval = 0;
    CHECK_EQ(MCC_SetCompParam(&stUserCompParam, 0, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_UpdateCompParam(), NO_ERR);
    MCC_Line(40, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex);
    WaitStop(g_nGroupIndex);
    CHECK_EQ(MCCL_SimGetMotor(CARD_INDEX, 0, &dfMotor, &llSent), NO_ERR);
    printf("Compensation off, X at 40 UU: %lld pulses sent\n", llSent);
    CHECK_EQ(llSent, 20000);

    CHECK_EQ(MCC_SetCompParam(NULL, 0, CARD_INDEX), PARAMETER_ERR);
    CHECK_EQ(MCC_SetCompParam(&stUserCompParam, 8, CARD_INDEX), PARAMETER_ERR);
    stUserCompParam.wHome_No = 256;
    CHECK_EQ(MCC_SetCompParam(&stUserCompParam, 0, CARD_INDEX), PARAMETER_ERR);
    Close();
    return check_done("Compensate");
}
