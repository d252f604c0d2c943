// CheckOT.cpp: examples manual §19 (software over-travel check and hardware limit switch
// check), written the way the manual writes it. The limit switches are placed and worked
// through MCCL_Sim.h, the simulation extension.
//
//   Work zone +-10 UU (dfHighLimit/dfLowLimit), X over-travel check on: MCC_Line to X = 15
//   stops at or before 10 (never past: 10 UU/s = 0.01 UU per 1 ms tick, so within one
//   tick of it), MCC_GetErrorCode = 0xF301; MCC_ClearError, then X back to 0.
//   Y's + limit switch at 5 UU (normally open, read as SL_NORMAL_OPEN). For each mode of
//   MCC_EnableLimitSwitchCheck a line toward Y = 8 stops within a tick of 5; modes 0 and 1
//   only stop, modes 2 and 3 record 0xF702 (Y); recovery as the manual's a-d: modes 0/1
//   move back out, modes 2/3 MCC_ClearError first.
//   A switch that turns active behind a moving axis stops it in the BIDIR modes (0, 2),
//   not in the UNIDIR ones (1, 3).
#include "MotionSys.h"
#include "MCCL_Sim.h"

static void Go(double x, double y)
{
    MCC_Line(x, y, 0, 0, 0, 0, 0, 0, g_nGroupIndex);
    WaitStop(g_nGroupIndex);
}

int main()
{
    if (InitSys8(10.0, -10.0) != NO_ERR)
        return check_done("CheckOT");
    MCC_SetFeedSpeed(10, g_nGroupIndex);
    MCC_SetAccTime(0, g_nGroupIndex);
    MCC_SetDecTime(0, g_nGroupIndex);

    // Step 1: X over-travel check on.
    CHECK_EQ(MCC_SetOverTravelCheck(1, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex), NO_ERR);
    // Step 2: read it back.
    int OT0, OT1, OT2, OT3, OT4, OT5, OT6, OT7;
    CHECK_EQ(MCC_GetOverTravelCheck(&OT0, &OT1, &OT2, &OT3, &OT4, &OT5, &OT6, &OT7, g_nGroupIndex), NO_ERR);
    CHECK(OT0 == 1 && OT1 == 0 && OT7 == 0);

    Go(15, 0);
    double p[8];
    GetPos(g_nGroupIndex, p);
    printf("MCC_Line to X = 15 with the work zone at +-10: stopped at X = %.3f\n", p[0]);
    CHECK(p[0] <= 10.0 && p[0] > 10.0 - 0.0101);
    // Step 3: the error record.
    int nErrCode = MCC_GetErrorCode(g_nGroupIndex);
    printf("MCC_GetErrorCode: 0x%X\n", nErrCode);
    CHECK_EQ(nErrCode, 0xF301);
    // Step 4: clear it; then back the other way.
    CHECK_EQ(MCC_ClearError(g_nGroupIndex), NO_ERR);
    Go(0, 0);
    CheckPosXYZ(g_nGroupIndex, 0, 0, 0);
    CHECK_EQ(MCC_SetOverTravelCheck(0, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex), NO_ERR);

    // Hardware limit switches: Y's switches wired normally open.
    SYS_MAC_PARAM stAxisParam;
    MCC_GetMacParam(&stAxisParam, 1, CARD_INDEX);
    stAxisParam.wOverTravelUpSensorMode = SL_NORMAL_OPEN;
    stAxisParam.wOverTravelDownSensorMode = SL_NORMAL_OPEN;
    CHECK_EQ(MCC_SetMacParam(&stAxisParam, 1, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_UpdateParam(), NO_ERR);
    MCC_SetFeedSpeed(10, g_nGroupIndex);
    MCC_SetAccTime(0, g_nGroupIndex);
    MCC_SetDecTime(0, g_nGroupIndex);
    CHECK_EQ(MCCL_SimPlaceSensor(CARD_INDEX, 1, MCCL_SIM_LIMIT_PLUS, 5.0, 0), NO_ERR);

    for (int nMode = HLP_BIDIR; nMode <= HLP_UNIDIR_GEN_ERR; nMode++)
    {
        CHECK_EQ(MCC_EnableLimitSwitchCheck(nMode), NO_ERR);
        Go(0, 8);
        GetPos(g_nGroupIndex, p);
        WORD wStatus = 0;
        CHECK_EQ(MCC_GetLimitSwitchStatus(&wStatus, 0, 1, CARD_INDEX), NO_ERR);
        nErrCode = MCC_GetErrorCode(g_nGroupIndex);
        printf("MCC_EnableLimitSwitchCheck(%d): Y stopped at %.3f, + switch %d, error 0x%X\n",
               nMode, p[1], wStatus, nErrCode);
        CHECK(p[1] >= 5.0 && p[1] < 5.0 + 0.0101);
        CHECK_EQ(wStatus, 1);
        if (nMode >= HLP_BIDIR_GEN_ERR)
        {
            CHECK_EQ(nErrCode, 0xF702);
            CHECK_EQ(MCC_ClearError(g_nGroupIndex), NO_ERR);   // c, d: clear first
        }
        else
            CHECK_EQ(nErrCode, 0);                             // a, b: only stopped
        Go(0, 0);                                              // back out of the switch
        CheckPosXYZ(g_nGroupIndex, 0, 0, 0);
        CHECK_EQ(MCC_GetLimitSwitchStatus(&wStatus, 0, 1, CARD_INDEX), NO_ERR);
        CHECK_EQ(wStatus, 0);

        // The + switch turning active while Y moves the other way.
        MCC_Line(0, -5, 0, 0, 0, 0, 0, 0, g_nGroupIndex);
        MCC_TimeDelay(100);
        CHECK_EQ(MCCL_SimSetSensor(CARD_INDEX, 1, MCCL_SIM_LIMIT_PLUS, 1), NO_ERR);
        MCC_TimeDelay(10);
        CHECK_EQ(MCCL_SimSetSensor(CARD_INDEX, 1, MCCL_SIM_LIMIT_PLUS, MCCL_SIM_FOLLOW), NO_ERR);
        WaitStop(g_nGroupIndex);
        GetPos(g_nGroupIndex, p);
        bool bBidir = nMode == HLP_BIDIR || nMode == HLP_BIDIR_GEN_ERR;
        printf("  + switch pressed while Y moves to -5: Y ends at %.3f (%s)\n", p[1],
               bBidir ? "BIDIR stops" : "UNIDIR goes on");
        if (bBidir)
            CHECK(p[1] > -1.2 && p[1] < -0.9);   // stopped 100-110 ms in, at 10 UU/s
        else
            CHECK_NEAR(p[1], -5, POS_TOL);
        MCC_ClearError(g_nGroupIndex);
        Go(0, 0);
    }
    CHECK_EQ(MCC_EnableLimitSwitchCheck(4), PARAMETER_ERR);
    CHECK_EQ(MCC_DisableLimitSwitchCheck(), NO_ERR);
    CHECK_EQ(MCC_SetOverTravelCheck(0, 0, 0, 0, 0, 0, 0, 0, BAD_GROUP), GROUP_PARAMETER_ERR);
    WORD w;
    CHECK_EQ(MCC_GetLimitSwitchStatus(&w, 2, 1, CARD_INDEX), PARAMETER_ERR);
    CHECK_EQ(MCC_GetLimitSwitchStatus(NULL, 0, 1, CARD_INDEX), PARAMETER_ERR);
    Close();
    return check_done("CheckOT");
}
