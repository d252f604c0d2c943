// CtrlMotion.cpp: examples manual §16 (hold, continue, abort): MCC_HoldMotion pauses the
// running command (ramping down), MCC_ContiMotion resumes the same command, and
// MCC_AbortMotionEx(t) ramps down within t ms and empties the queue, whatever the state.
// With nothing to hold or continue, MCC_HoldMotion and MCC_ContiMotion change nothing and
// answer NO_ERR, as the vendor's library answers (the manual lists HOLD_ILLEGAL_ERR and
// CONTI_ILLEGAL_ERR; the vendor's library does not return them).
//
// Expected numbers (F = 10 UU/s, Ta = Td = 300 ms; moves are long so that acting on them
// 1 s in is no race on the fast clock), as the vendor's library stops: from the speed v0
// of the last period over n = floor(Td v0/F/T) + 1 periods, covering v0² Td/(2F):
//   Line X 0 -> 100: 300 + 9700 + 300 periods at V = 10. 1 s in it has covered
//   10 x 0.3/2 + 10 x 0.7 = 8.5 UU; held, it covers 100 x 0.3/20 = 1.5 more in 300 (or
//   301: v0 = F puts n on the edge of its rounding) periods and stands at X = 10.0
//   (stepped clock); the period after shows the hold, GMS_HOLD reads two periods later,
//   GMS_RUNNING until then. Conti: the same line ends at X = 100.
//   Lines to 200, 300, 0 queued, MCC_AbortMotionEx(200) 1 s into the first: it covers
//   100 x 0.2/20 = 1 UU in 200 (or 201) periods: X = 100 + 8.5 + 1 = 109.5 (stepped
//   clock); the two other lines are dropped (MCC_GetCommandCount = 0); the end shows as
//   a hold for three periods and GMS_STOP reads in the fourth.
#include "MotionSys.h"

int main()
{
    if (InitSys8() != NO_ERR)
        return check_done("CtrlMotion");
    int nRet;
    double p1[8], p2[8];

    // Nothing runs: hold, continue and abort are harmless.
    CHECK_EQ(MCC_HoldMotion(g_nGroupIndex), NO_ERR);
    CHECK_EQ(MCC_ContiMotion(g_nGroupIndex), NO_ERR);
    CHECK_EQ(MCC_AbortMotionEx(100, g_nGroupIndex), NO_ERR);
    CHECK_EQ(MCC_GetMotionStatus(g_nGroupIndex), GMS_STOP);

    CHECK_EQ(MCC_SetAbsolute(g_nGroupIndex), NO_ERR);
    MCC_SetFeedSpeed(10, g_nGroupIndex);

    // Hold and continue.
    CHECK(MCC_Line(100, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex) >= 0);
    MCC_TimeDelay(1000);
    CHECK_EQ(MCC_ContiMotion(g_nGroupIndex), NO_ERR);   // running, not held: nothing
    nRet = MCC_HoldMotion(g_nGroupIndex);
    CHECK_EQ(nRet, NO_ERR);
    int nStatus = MCC_GetMotionStatus(g_nGroupIndex);
    if (SteppedClock())
        CHECK_EQ(nStatus, GMS_RUNNING);                           // ramping down
    else
        CHECK(nStatus == GMS_RUNNING || nStatus == GMS_HOLD);   // a poll may run it out
    MCC_TimeDelay(301 + 3 + TOL_MS);
    CHECK_EQ(MCC_GetMotionStatus(g_nGroupIndex), GMS_HOLD);
    GetPos(g_nGroupIndex, p1);
    MCC_TimeDelay(1000);
    GetPos(g_nGroupIndex, p2);
    printf("Held at X = %.3f (status %d = GMS_HOLD)\n", p1[0], MCC_GetMotionStatus(g_nGroupIndex));
    CHECK(p1[0] > 0 && p1[0] < 100);
    CHECK(p1[0] == p2[0]);                                       // standing still
    if (SteppedClock())
        CHECK_NEAR(p1[0], 10.0, 0.03);
    nRet = MCC_ContiMotion(g_nGroupIndex);
    CHECK_EQ(nRet, NO_ERR);
    CHECK_EQ(MCC_GetMotionStatus(g_nGroupIndex), GMS_RUNNING);
    CHECK_EQ(MCC_ContiMotion(g_nGroupIndex), NO_ERR);   // no longer held: nothing
    WaitStop(g_nGroupIndex);
    CheckPosXYZ(g_nGroupIndex, 100, 0, 0);
    printf("Continued: X = 100\n");

    // Abort while running: stops within the given time and drops the queue.
    CHECK(MCC_Line(200, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex) >= 0);
    CHECK(MCC_Line(300, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex) >= 0);
    CHECK(MCC_Line(0, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex) >= 0);
    MCC_TimeDelay(1000);
    int nCount = -1;
    CHECK_EQ(MCC_GetCommandCount(&nCount, g_nGroupIndex), NO_ERR);
    CHECK_EQ(nCount, 2);
    nRet = MCC_AbortMotionEx(200, g_nGroupIndex);
    CHECK_EQ(nRet, NO_ERR);
    MCC_TimeDelay(201 + 4 + TOL_MS);
    CHECK_EQ(MCC_GetMotionStatus(g_nGroupIndex), GMS_STOP);
    CHECK_EQ(MCC_GetCommandCount(&nCount, g_nGroupIndex), NO_ERR);
    CHECK_EQ(nCount, 0);
    GetPos(g_nGroupIndex, p1);
    MCC_TimeDelay(1000);
    GetPos(g_nGroupIndex, p2);
    printf("Aborted at X = %.3f, queue empty\n", p1[0]);
    CHECK(p1[0] > 100 && p1[0] < 200);
    CHECK(p1[0] == p2[0]);
    if (SteppedClock())
        CHECK_NEAR(p1[0], 109.5, 0.03);
    CHECK_EQ(MCC_HoldMotion(g_nGroupIndex), NO_ERR);   // nothing to hold

    // New commands start from where the abort left the axes.
    CHECK(MCC_Line(p1[0] + 5, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex) >= 0);
    WaitStop(g_nGroupIndex);
    CheckPosXYZ(g_nGroupIndex, p1[0] + 5, 0, 0);

    // Abort while held: stays where it was held, queue dropped.
    CHECK(MCC_Line(0, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex) >= 0);
    CHECK(MCC_Line(50, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex) >= 0);
    MCC_TimeDelay(1000);
    CHECK_EQ(MCC_HoldMotion(g_nGroupIndex), NO_ERR);
    MCC_TimeDelay(301 + 3 + TOL_MS);
    CHECK_EQ(MCC_GetMotionStatus(g_nGroupIndex), GMS_HOLD);
    GetPos(g_nGroupIndex, p1);
    CHECK_EQ(MCC_AbortMotionEx(100, g_nGroupIndex), NO_ERR);
    MCC_TimeDelay(TOL_MS);
    CHECK_EQ(MCC_GetMotionStatus(g_nGroupIndex), GMS_STOP);
    CHECK_EQ(MCC_GetCommandCount(&nCount, g_nGroupIndex), NO_ERR);
    CHECK_EQ(nCount, 0);
    GetPos(g_nGroupIndex, p2);
    CHECK(p1[0] == p2[0]);
    CHECK_EQ(MCC_ContiMotion(g_nGroupIndex), NO_ERR);   // nothing held any more
    MCC_TimeDelay(10);
    CHECK_EQ(MCC_GetMotionStatus(g_nGroupIndex), GMS_STOP);

    // Bad input.
    CHECK_EQ(MCC_HoldMotion(BAD_GROUP), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCC_ContiMotion(BAD_GROUP), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCC_AbortMotionEx(100, BAD_GROUP), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCC_AbortMotionEx(NAN, g_nGroupIndex), PARAMETER_ERR);
    CHECK_EQ(MCC_AbortMotionEx(-1, g_nGroupIndex), PARAMETER_ERR);

    Close();
    CHECK_EQ(MCC_HoldMotion(0), INITIAL_MOTION_ERR);
    return check_done("CtrlMotion");
}
