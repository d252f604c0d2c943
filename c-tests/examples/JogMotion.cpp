// JogMotion.cpp: examples manual §13 (jog): MCC_JogPulse (pulses, at most 2048),
// MCC_JogSpace (UU at a PtP-style speed ratio), MCC_JogConti (to the work-zone boundary
// of the mechanism parameters). All three need the group at GMS_STOP. cAxis is the axis
// number (0 = X), as the manual passes it.
//
// This program gives the axes a work zone of -20..+20 UU (dfLowLimit/dfHighLimit) so that
// MCC_JogConti ends soon. Expected numbers (500 pulses/UU; max safe speed 50 UU/s; PtP
// acc/dec 300 ms):
//   MCC_JogPulse(100, 0): X + 100 pulses = +0.2 UU                  -> X = 0.2
//   MCC_JogSpace(-1, 10, 0): X - 1 UU at 10 % = 5 UU/s: 0.2 + 0.3 s -> X = -0.8
//   MCC_JogConti(1, 10, 0): X to +20 at 5 UU/s: 20.8/5 + 0.3 = 4.46 s
//   MCC_JogConti(-1, 100, 0): X to -20 at 50 UU/s: 40/50 + 0.3 = 1.1 s
//   MCC_JogConti(1, 10, 1) on Y, stopped with MCC_AbortMotionEx(100) after 1 s:
//     Y stops between 0 and 20 within 100 ms (+ one period); the group is at GMS_STOP.
#include <math.h>
#include "MotionSys.h"

static long PulseX(int g)
{
    long l[8];
    CHECK_EQ(MCC_GetPulsePos(&l[0], &l[1], &l[2], &l[3], &l[4], &l[5], &l[6], &l[7], (WORD)g), NO_ERR);
    return l[0];
}

int main()
{
    if (InitSys8(20.0, -20.0) != NO_ERR)
        return check_done("JogMotion");
    int nRet;

    // Step 1: X + 100 pulses.
    nRet = MCC_JogPulse(100, 0, g_nGroupIndex);
    printf("MCC_JogPulse(100, 0): returned %d\n", nRet);
    CHECK(nRet >= 0);
    WaitStop(g_nGroupIndex);
    CHECK_EQ(PulseX(g_nGroupIndex), 100);
    CheckPosXYZ(g_nGroupIndex, 0.2, 0, 0);
    PrintPos(g_nGroupIndex, "After MCC_JogPulse(100, 0)");

    nRet = MCC_JogPulse(-50, 0, g_nGroupIndex);   // back 50 pulses
    CHECK(nRet >= 0);
    WaitStop(g_nGroupIndex);
    CHECK_EQ(PulseX(g_nGroupIndex), 50);
    nRet = MCC_JogPulse(50, 0, g_nGroupIndex);
    CHECK(nRet >= 0);
    WaitStop(g_nGroupIndex);
    CHECK_EQ(PulseX(g_nGroupIndex), 100);

    // Step 2: X - 1 UU at 10 % of the maximum safe speed.
    nRet = MCC_JogSpace(-1, 10, 0, g_nGroupIndex);
    printf("MCC_JogSpace(-1, 10, 0): returned %d\n", nRet);
    CHECK(nRet >= 0);
    // 1 UU is too short to reach 5 UU/s with 300 ms ramps (they need 2 x 0.75 UU), so the
    // peak drops and the acceleration 5/0.3 UU/s^2 stays: 2 sqrt(1 x 0.3 / 5) = 489.9 ms.
    CheckEndsIn(g_nGroupIndex, 2000 * sqrt(0.3 / 5), "JogSpace -1 UU at 5 UU/s");
    WaitStop(g_nGroupIndex);
    CheckPosXYZ(g_nGroupIndex, -0.8, 0, 0);
    CHECK_EQ(PulseX(g_nGroupIndex), -400);
    PrintPos(g_nGroupIndex, "After MCC_JogSpace(-1, 10, 0)");

    // Step 3: X to the upper boundary of the work zone.
    nRet = MCC_JogConti(1, 10, 0, g_nGroupIndex);
    printf("MCC_JogConti(1, 10, 0): returned %d\n", nRet);
    CHECK(nRet >= 0);
    CHECK(MCC_GetMotionStatus(g_nGroupIndex) != GMS_STOP);
    // A jog needs GMS_STOP: while this one runs, other jogs are refused.
    CHECK(MCC_JogPulse(10, 1, g_nGroupIndex) < 0);
    CHECK(MCC_JogSpace(1, 10, 1, g_nGroupIndex) < 0);
    CHECK(MCC_JogConti(1, 10, 1, g_nGroupIndex) < 0);
    CheckEndsIn(g_nGroupIndex, 1000 * 20.8 / 5 + 300, "JogConti to +20 at 5 UU/s");
    WaitStop(g_nGroupIndex);
    CheckPosXYZ(g_nGroupIndex, 20, 0, 0);
    CHECK_EQ(PulseX(g_nGroupIndex), 10000);
    PrintPos(g_nGroupIndex, "After MCC_JogConti(1, 10, 0)");

    // At the boundary, the other way at 100 %.
    CHECK(MCC_JogConti(-1, 100, 0, g_nGroupIndex) >= 0);
    CheckEndsIn(g_nGroupIndex, 1100, "JogConti to -20 at 50 UU/s");
    WaitStop(g_nGroupIndex);
    CheckPosXYZ(g_nGroupIndex, -20, 0, 0);

    // MCC_AbortMotionEx stops a continuous jog (user manual §2.6.2 III C).
    CHECK(MCC_JogConti(1, 10, 1, g_nGroupIndex) >= 0);   // Y up at 5 UU/s: 4.3 s to +20
    MCC_TimeDelay(1000);
    CHECK_EQ(MCC_AbortMotionEx(100, g_nGroupIndex), NO_ERR);
    MCC_TimeDelay(100 + TOL_MS);
    CHECK_EQ(MCC_GetMotionStatus(g_nGroupIndex), GMS_STOP);
    double p1[8], p2[8];
    GetPos(g_nGroupIndex, p1);
    MCC_TimeDelay(100);
    GetPos(g_nGroupIndex, p2);
    printf("Continuous jog of Y aborted at Y = %.3f\n", p1[1]);
    CHECK(p1[1] > 0 && p1[1] < 20);
    CHECK(p1[1] == p2[1]);
    CHECK_NEAR(p1[0], -20, POS_TOL);
    if (SteppedClock())   // 1 s: 5 x 0.3/2 + 5 x 0.7 = 4.25; 100 ms ramp: + 5 x 0.1/2 = 4.5
        CHECK_NEAR(p1[1], 4.5, 0.03);

    // Bad input.
    CHECK_EQ(MCC_JogPulse(2049, 0, g_nGroupIndex), PARAMETER_ERR);    // at most 2048 pulses
    CHECK_EQ(MCC_JogPulse(-2049, 0, g_nGroupIndex), PARAMETER_ERR);
    CHECK_EQ(MCC_JogPulse(10, 8, g_nGroupIndex), PARAMETER_ERR);      // axes are 0..7
    CHECK_EQ(MCC_JogPulse(10, -1, g_nGroupIndex), PARAMETER_ERR);
    CHECK_EQ(MCC_JogPulse(10, 0, BAD_GROUP), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCC_JogSpace(NAN, 10, 0, g_nGroupIndex), PARAMETER_ERR);
    CHECK_EQ(MCC_JogSpace(1, NAN, 0, g_nGroupIndex), PARAMETER_ERR);
    CHECK_EQ(MCC_JogSpace(1, 10, 8, g_nGroupIndex), PARAMETER_ERR);
    CHECK_EQ(MCC_JogSpace(1, 10, 0, BAD_GROUP), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCC_JogConti(1, NAN, 0, g_nGroupIndex), PARAMETER_ERR);
    CHECK_EQ(MCC_JogConti(1, 10, 8, g_nGroupIndex), PARAMETER_ERR);
    CHECK_EQ(MCC_JogConti(1, 10, 0, BAD_GROUP), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCC_GetMotionStatus(g_nGroupIndex), GMS_STOP);
    CHECK_NEAR(p2[0], -20, POS_TOL);
    GetPos(g_nGroupIndex, p2);
    CHECK(p1[0] == p2[0] && p1[1] == p2[1]);

    Close();
    CHECK_EQ(MCC_JogPulse(10, 0, 0), INITIAL_MOTION_ERR);
    return check_done("JogMotion");
}
