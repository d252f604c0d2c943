// DelayMotion.cpp: examples manual §17 (forced delay): after the first line the next
// command waits MCC_DelayMotion(3000) = 3000 ms; meanwhile the status is GMS_DELAYING.
//
// Expected numbers (F = 20 UU/s, Ta = Td = 300 ms, periods of 1 ms, as the vendor's
// library runs them):
//   MCC_Line(10, 10): L = 10 sqrt(2) = 14.1421: 300 + ceil(707.1 - 300) + 300 = 1008
//     periods (1..1008), then its end period (1009)
//   MCC_DelayMotion(3000): periods 1010 .. 4009 GMS_DELAYING, axes stand at (10, 10);
//     the running command is a delay (type 8, the vendor's library's number; the manual
//     says 6) whose dfFeedSpeed is the time left after the period (ms): 3000 - k in its
//     k-th period
//   MCC_Line(20, 20): periods 4010 .. 5017 (a delay has no end period), its end period,
//     one period with nothing running, GMS_STOP in period 5020.
// The manual writes MCC_Line(10, 10, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex) (group in the
// axis-mask place); eight positions and the group are written here.
#include "MotionSys.h"

int main()
{
    // Step 1: interpolation time INTERPOLATION_TIME (MotionSys.h: 1 ms).
    if (InitSys8() != NO_ERR)
        return check_done("DelayMotion");

    CHECK_EQ(MCC_SetAbsolute(g_nGroupIndex), NO_ERR);
    MCC_SetFeedSpeed(20, g_nGroupIndex);

    // Step 2: the first line.  Step 3: the delay.  Then the next line.
    CHECK_EQ(MCC_ResetCommandIndex(g_nGroupIndex), NO_ERR);
    CHECK_EQ(MCC_Line(10, 10, 0, 0, 0, 0, 0, 0, g_nGroupIndex), 0);
    CHECK_EQ(MCC_DelayMotion(3000, g_nGroupIndex), 1);
    CHECK_EQ(MCC_Line(20, 20, 0, 0, 0, 0, 0, 0, g_nGroupIndex), 2);

    if (SteppedClock())
    {
        // The line's last period.
        MCC_TimeDelay(1008);
        CHECK_EQ(MCC_GetMotionStatus(g_nGroupIndex), GMS_RUNNING);
        MCC_TimeDelay(12);   // period 1020: the delay's 11th
        CHECK_EQ(MCC_GetMotionStatus(g_nGroupIndex), GMS_DELAYING);
        COMMAND_INFO stInfo;
        CHECK_EQ(MCC_GetCurCommand(&stInfo, g_nGroupIndex), NO_ERR);
        printf("  [stepped clock] during the delay: command type %d, index %d, %.0f ms left\n",
               stInfo.nType, stInfo.nCommandIndex, stInfo.dfFeedSpeed);
        CHECK_EQ(stInfo.nType, 8);
        CHECK_EQ(stInfo.nCommandIndex, 1);
        CHECK(stInfo.dfFeedSpeed == 3000 - 11);
        CheckPosXYZ(g_nGroupIndex, 10, 10, 0);
        // The delay's last period, then the line.
        MCC_TimeDelay(4009 - 1020);
        CHECK_EQ(MCC_GetMotionStatus(g_nGroupIndex), GMS_DELAYING);
        CheckPosXYZ(g_nGroupIndex, 10, 10, 0);
        MCC_TimeDelay(1);
        CHECK_EQ(MCC_GetMotionStatus(g_nGroupIndex), GMS_RUNNING);
        MCC_TimeDelay(300);
        double p[8];
        GetPos(g_nGroupIndex, p);
        CHECK(p[0] > 10 && p[0] < 20);
        // The second line's last period is 5017, GMS_STOP reads in 5020.
        MCC_TimeDelay(5019 - 4310);
        CHECK_EQ(MCC_GetMotionStatus(g_nGroupIndex), GMS_RUNNING);
        MCC_TimeDelay(1);
        CHECK_EQ(MCC_GetMotionStatus(g_nGroupIndex), GMS_STOP);
    }
    else
    {
        // Any clock: the status runs RUNNING -> DELAYING -> RUNNING -> STOP, and while
        // delaying the axes stand at (10, 10).
        int nPhase = 0, nStatus;
        while ((nStatus = MCC_GetMotionStatus(g_nGroupIndex)) != GMS_STOP)
        {
            if (nStatus == GMS_DELAYING)
            {
                double p[8];
                GetPos(g_nGroupIndex, p);
                CHECK_NEAR(p[0], 10, POS_TOL);
                CHECK_NEAR(p[1], 10, POS_TOL);
                if (nPhase == 0) nPhase = 1;
                CHECK(nPhase == 1);
            }
            else if (nStatus == GMS_RUNNING && nPhase == 1)
                nPhase = 2;
            else
                CHECK(nStatus == GMS_RUNNING);
            MCC_TimeDelay(1);
        }
        // The fast clock runs ahead of the program, so it may not see every phase; the
        // phases it sees come in order (checked above).
    }
    WaitStop(g_nGroupIndex);
    CheckPosXYZ(g_nGroupIndex, 20, 20, 0);

    // Bad input.
    CHECK_EQ(MCC_DelayMotion(100, BAD_GROUP), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCC_DelayMotion(100, 3), GROUP_PARAMETER_ERR);   // group 3 not created
    CHECK_EQ(MCC_GetMotionStatus(g_nGroupIndex), GMS_STOP);

    Close();
    CHECK_EQ(MCC_DelayMotion(100, 0), INITIAL_MOTION_ERR);
    return check_done("DelayMotion");
}
