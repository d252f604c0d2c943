// MotionFinished.cpp: examples manual §7 (motion status): GMS_RUNNING while a command
// runs, GMS_STOP when the queue is empty, GMS_DELAYING during MCC_DelayMotion, GMS_HOLD
// after MCC_HoldMotion, GMS_RUNNING again after MCC_ContiMotion.
//
// Expected numbers (F = 20 UU/s for the first line, Ta = Td = 300 ms, 1 ms periods):
//   MCC_Line(20, 20): L = 20 sqrt(2) = 28.2843: 300 + ceil(1414.2 - 300) + 300 = 1715
//   periods, GMS_STOP three periods later
//   MCC_DelayMotion(10000): GMS_DELAYING for 10 s
//   MCC_Line(50, 50) at F = 1: L = 30 sqrt(2) = 42.4264: 300 + 42127 + 300 periods at
//   V = 42.4264/42.427 = 0.99999 UU/s (slow, so that holding it 1 s in is not a race on
//   the fast clock). Held 1 s in, it ramps down from v0 = V over n = floor(300 x V/1) + 1
//   = 300 periods, covering v0² x 0.3/2 and stands still: V x 0.3/2 + V x 0.7 + V² x
//   0.3/2 = 1.0 UU along the path, X = Y = 20 + 1/sqrt(2) = 20.707 (stepped clock); the
//   status reads GMS_HOLD three periods after the ramp (the vendor's library shows the
//   hold in the period after, and HOLD two periods later), GMS_RUNNING until then.
//   ContiMotion finishes the same command: the axes end at (50, 50).
// The manual writes MCC_Line(20, 20, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex) (nine numbers,
// so the group would land in dwAxisMask); eight positions and the group are used here.
#include "MotionSys.h"

int main()
{
    int nRet;
    // Step 1
    int nStatus;

    if (InitSys8() != NO_ERR)
        return check_done("MotionFinished");

    // Nothing queued yet.
    nStatus = MCC_GetMotionStatus(g_nGroupIndex);
    CHECK_EQ(nStatus, GMS_STOP);

    // Step 2: servo on.
    CHECK_EQ(MCC_SetServoOn(0, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_SetServoOn(1, CARD_INDEX), NO_ERR);

    // Step 3: a line.
    CHECK_EQ(MCC_SetAbsolute(g_nGroupIndex), NO_ERR);
    MCC_SetFeedSpeed(20, g_nGroupIndex);
    nRet = MCC_Line(20, 20, 0, 0, 0, 0, 0, 0, g_nGroupIndex);
    CHECK(nRet >= 0);
    nStatus = MCC_GetMotionStatus(g_nGroupIndex);
    CHECK_EQ(nStatus, GMS_RUNNING);     // queued: running, not stopped
    CheckEndsIn(g_nGroupIndex, 1715, "MCC_Line(20, 20)");

    // Step 4: wait for GMS_STOP, reading the status while the line runs.
    int nSawRunning = 0, nSawOther = 0;
    while ((nStatus = MCC_GetMotionStatus(g_nGroupIndex)) != GMS_STOP)
    {
        if (nStatus == GMS_RUNNING) nSawRunning++; else nSawOther++;
        MCC_TimeDelay(1);
    }
    CHECK_EQ(nSawOther, 0);             // only GMS_RUNNING until GMS_STOP
    CheckPosXYZ(g_nGroupIndex, 20, 20, 0);
    printf("Line to (20, 20) finished: status GMS_STOP\n");

    // Step 5: delay 10000 ms: GMS_DELAYING.
    nRet = MCC_DelayMotion(10000, g_nGroupIndex);
    CHECK(nRet >= 0);
    CHECK(MCC_GetMotionStatus(g_nGroupIndex) != GMS_STOP);
    MCC_TimeDelay(10);
    nStatus = MCC_GetMotionStatus(g_nGroupIndex);
    printf("During MCC_DelayMotion(10000): status %d (GMS_DELAYING = %d)\n", nStatus, GMS_DELAYING);
    CHECK_EQ(nStatus, GMS_DELAYING);
    CheckPosXYZ(g_nGroupIndex, 20, 20, 0);   // the delay does not move anything

    // Step 6: the next line waits for the delay.
    MCC_SetFeedSpeed(1, g_nGroupIndex);
    nRet = MCC_Line(50, 50, 0, 0, 0, 0, 0, 0, g_nGroupIndex);
    CHECK(nRet >= 0);
    CHECK_EQ(MCC_GetMotionStatus(g_nGroupIndex), GMS_DELAYING);
    if (SteppedClock())
    {
        // 10 ms (+1 poll tick) + 9980 ms: still delaying; +25 ms more: the line runs.
        MCC_TimeDelay(10000 - 10 - 1 - 2 * TOL_MS);
        CHECK_EQ(MCC_GetMotionStatus(g_nGroupIndex), GMS_DELAYING);
        MCC_TimeDelay(4 * TOL_MS + 2);
        CHECK_EQ(MCC_GetMotionStatus(g_nGroupIndex), GMS_RUNNING);
    }
    long n = 0;
    while (MCC_GetMotionStatus(g_nGroupIndex) == GMS_DELAYING && n++ < 100000)
        MCC_TimeDelay(1);
    CHECK_EQ(MCC_GetMotionStatus(g_nGroupIndex), GMS_RUNNING);
    MCC_TimeDelay(1000);

    // Step 7: hold: the axes ramp down (GMS_RUNNING) and stop between (20,20) and
    // (50,50): GMS_HOLD. (On the fast clock a poll may run the ramp out first.)
    nRet = MCC_HoldMotion(g_nGroupIndex);
    CHECK_EQ(nRet, NO_ERR);
    nStatus = MCC_GetMotionStatus(g_nGroupIndex);
    if (SteppedClock())
        CHECK_EQ(nStatus, GMS_RUNNING);
    else
        CHECK(nStatus == GMS_RUNNING || nStatus == GMS_HOLD);
    MCC_TimeDelay(500);                       // past the 300 ms ramp down and 3 periods
    CHECK_EQ(MCC_GetMotionStatus(g_nGroupIndex), GMS_HOLD);
    double p1[8], p2[8];
    GetPos(g_nGroupIndex, p1);
    MCC_TimeDelay(500);
    GetPos(g_nGroupIndex, p2);
    printf("Held at X = %.3f, Y = %.3f: status GMS_HOLD\n", p1[0], p1[1]);
    CHECK(p1[0] > 20 && p1[0] < 50);
    CHECK_NEAR(p1[0], p1[1], 1e-9);
    CHECK(p1[0] == p2[0] && p1[1] == p2[1]);   // standing still
    if (SteppedClock())
        CHECK_NEAR(p1[0], 20 + 1.0 / sqrt(2.0), 0.03);
    CHECK_EQ(MCC_GetMotionStatus(g_nGroupIndex), GMS_HOLD);

    // Step 8: continue: GMS_RUNNING, then the line finishes at (50, 50).
    nRet = MCC_ContiMotion(g_nGroupIndex);
    CHECK_EQ(nRet, NO_ERR);
    CHECK_EQ(MCC_GetMotionStatus(g_nGroupIndex), GMS_RUNNING);
    WaitStop(g_nGroupIndex);
    CheckPosXYZ(g_nGroupIndex, 50, 50, 0);
    printf("Continued: line to (50, 50) finished\n");

    // Bad input.
    CHECK_EQ(MCC_GetMotionStatus(BAD_GROUP), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCC_GetMotionStatus(5), GROUP_PARAMETER_ERR);         // not created
    CHECK_EQ(MCC_DelayMotion(100, BAD_GROUP), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCC_HoldMotion(BAD_GROUP), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCC_ContiMotion(BAD_GROUP), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCC_SetServoOn(MAX_AXIS_NUM, CARD_INDEX), PARAMETER_ERR);
    CHECK_EQ(MCC_GetMotionStatus(g_nGroupIndex), GMS_STOP);

    Close();
    CHECK_EQ(MCC_GetMotionStatus(g_nGroupIndex), INITIAL_MOTION_ERR);
    return check_done("MotionFinished");
}
