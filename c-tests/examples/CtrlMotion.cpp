// CtrlMotion.cpp: examples manual §16 (hold, continue, abort): MCC_HoldMotion pauses the
// running command (ramping down), MCC_ContiMotion resumes the same command, and
// MCC_AbortMotionEx(t) ramps down within t ms and empties the queue, whatever the state.
// Without a running command MCC_HoldMotion gives HOLD_ILLEGAL_ERR (-11); without a
// successful hold MCC_ContiMotion gives CONTI_ILLEGAL_ERR (-12).
//
// Expected numbers (F = 10 UU/s, Ta = Td = 300 ms; moves are long so that acting on them
// 1 s in is no race on the fast clock):
//   Line X 0 -> 100 (10.3 s). 1 s in it has covered 10 x 0.3/2 + 10 x 0.7 = 8.5 UU; held,
//   it ramps down over Td and covers 10 x 0.3/2 = 1.5 more: stands at X = 10.0
//   (stepped clock). Conti: the same line ends at X = 100.
//   Lines to 200, 300, 0 queued, MCC_AbortMotionEx(200) 1 s into the first: it covers
//   10 x 0.2/2 = 1 UU while stopping: X = 100 + 8.5 + 1 = 109.5 (stepped clock); the two
//   other lines are dropped (MCC_GetCommandCount = 0), GMS_STOP.
#include "MotionSys.h"

int main()
{
    if (InitSys8() != NO_ERR)
        return check_done("CtrlMotion");
    int nRet;
    double p1[8], p2[8];

    // Nothing runs: hold and continue are illegal; abort is harmless.
    CHECK_EQ(MCC_HoldMotion(g_nGroupIndex), HOLD_ILLEGAL_ERR);
    CHECK_EQ(MCC_ContiMotion(g_nGroupIndex), CONTI_ILLEGAL_ERR);
    CHECK_EQ(MCC_AbortMotionEx(100, g_nGroupIndex), NO_ERR);
    CHECK_EQ(MCC_GetMotionStatus(g_nGroupIndex), GMS_STOP);

    CHECK_EQ(MCC_SetAbsolute(g_nGroupIndex), NO_ERR);
    MCC_SetFeedSpeed(10, g_nGroupIndex);

    // Hold and continue.
    CHECK(MCC_Line(100, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex) >= 0);
    MCC_TimeDelay(1000);
    CHECK_EQ(MCC_ContiMotion(g_nGroupIndex), CONTI_ILLEGAL_ERR);   // running, not held
    nRet = MCC_HoldMotion(g_nGroupIndex);
    CHECK_EQ(nRet, NO_ERR);
    CHECK_EQ(MCC_GetMotionStatus(g_nGroupIndex), GMS_HOLD);
    MCC_TimeDelay(300 + TOL_MS);
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
    CHECK_EQ(MCC_ContiMotion(g_nGroupIndex), CONTI_ILLEGAL_ERR); // no longer held
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
    MCC_TimeDelay(200 + TOL_MS);
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
    CHECK_EQ(MCC_HoldMotion(g_nGroupIndex), HOLD_ILLEGAL_ERR);

    // New commands start from where the abort left the axes.
    CHECK(MCC_Line(p1[0] + 5, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex) >= 0);
    WaitStop(g_nGroupIndex);
    CheckPosXYZ(g_nGroupIndex, p1[0] + 5, 0, 0);

    // Abort while held: stays where it was held, queue dropped.
    CHECK(MCC_Line(0, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex) >= 0);
    CHECK(MCC_Line(50, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex) >= 0);
    MCC_TimeDelay(1000);
    CHECK_EQ(MCC_HoldMotion(g_nGroupIndex), NO_ERR);
    MCC_TimeDelay(300 + TOL_MS);
    GetPos(g_nGroupIndex, p1);
    CHECK_EQ(MCC_AbortMotionEx(100, g_nGroupIndex), NO_ERR);
    MCC_TimeDelay(TOL_MS);
    CHECK_EQ(MCC_GetMotionStatus(g_nGroupIndex), GMS_STOP);
    CHECK_EQ(MCC_GetCommandCount(&nCount, g_nGroupIndex), NO_ERR);
    CHECK_EQ(nCount, 0);
    GetPos(g_nGroupIndex, p2);
    CHECK(p1[0] == p2[0]);
    CHECK_EQ(MCC_ContiMotion(g_nGroupIndex), CONTI_ILLEGAL_ERR);

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
