// DelayMotion.cpp: examples manual §17 (forced delay): after the first line the next
// command waits MCC_DelayMotion(3000) = 3000 ms; meanwhile the status is GMS_DELAYING.
//
// Expected numbers (F = 20 UU/s, Ta = Td = 300 ms):
//   MCC_Line(10, 10): L = 10 sqrt(2) = 14.1421: 0.7071 + 0.3 = 1007.1 ms
//   MCC_DelayMotion(3000): 1007.1 .. 4007.1 ms GMS_DELAYING, axes stand at (10, 10);
//     the running command is a delay (type 6) whose dfFeedSpeed is the remaining time
//     (ms): 2990 ms, 10 ms into the delay (stepped clock)
//   MCC_Line(20, 20): 4007.1 .. 5014.2 ms; total 5014.2 ms.
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
    const double dfLine = 1000 * 10 * sqrt(2.0) / 20 + 300;   // 1007.1 ms

    // Step 2: the first line.  Step 3: the delay.  Then the next line.
    CHECK_EQ(MCC_ResetCommandIndex(g_nGroupIndex), NO_ERR);
    CHECK_EQ(MCC_Line(10, 10, 0, 0, 0, 0, 0, 0, g_nGroupIndex), 0);
    CHECK_EQ(MCC_DelayMotion(3000, g_nGroupIndex), 1);
    CHECK_EQ(MCC_Line(20, 20, 0, 0, 0, 0, 0, 0, g_nGroupIndex), 2);

    if (SteppedClock())
    {
        // Line until 1007.1 ms.
        MCC_TimeDelay((DWORD)dfLine - TOL_MS);
        CHECK_EQ(MCC_GetMotionStatus(g_nGroupIndex), GMS_RUNNING);
        MCC_TimeDelay(10);   // now about 1015 ms: 8 ms into the delay (+- a tick)
        CHECK_EQ(MCC_GetMotionStatus(g_nGroupIndex), GMS_DELAYING);
        COMMAND_INFO stInfo;
        CHECK_EQ(MCC_GetCurCommand(&stInfo, g_nGroupIndex), NO_ERR);
        printf("  [stepped clock] during the delay: command type %d, index %d, %.0f ms left\n",
               stInfo.nType, stInfo.nCommandIndex, stInfo.dfFeedSpeed);
        CHECK_EQ(stInfo.nType, 6);
        CHECK_EQ(stInfo.nCommandIndex, 1);
        CHECK_NEAR(stInfo.dfFeedSpeed, 3000 - (floor(dfLine) - TOL_MS + 10 + 1 - dfLine), 2 * TOL_MS + 1);
        CheckPosXYZ(g_nGroupIndex, 10, 10, 0);
        // Still delaying shortly before 4007.1 ms, the line runs shortly after.
        MCC_TimeDelay(3000 - 10 - 2 * TOL_MS - 2);
        CHECK_EQ(MCC_GetMotionStatus(g_nGroupIndex), GMS_DELAYING);
        CheckPosXYZ(g_nGroupIndex, 10, 10, 0);
        MCC_TimeDelay(4 * TOL_MS + 2);
        CHECK_EQ(MCC_GetMotionStatus(g_nGroupIndex), GMS_RUNNING);
        double p[8];
        GetPos(g_nGroupIndex, p);
        CHECK(p[0] > 10 && p[0] < 20);
        // The second line ends 1007.1 ms after the delay, at 5014.2 ms. Now is about
        // 4012 ms (+- the ticks of the status polls), so bracket a little wider.
        MCC_TimeDelay(1003 - 2 * TOL_MS - 3);
        CHECK_EQ(MCC_GetMotionStatus(g_nGroupIndex), GMS_RUNNING);
        MCC_TimeDelay(4 * TOL_MS + 6);
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
