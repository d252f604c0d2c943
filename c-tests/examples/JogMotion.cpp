// JogMotion.cpp: examples manual §13 (jog): MCC_JogPulse (pulses, at most 2048),
// MCC_JogSpace (UU at a PtP-style speed ratio), MCC_JogConti (the work zone's extent of
// the mechanism parameters). cAxis is the axis number (0 = X), as the manual passes it
// (0..7; anything else is GROUP_PARAMETER_ERR, as the vendor's library answers).
// MCC_JogPulse needs the group at rest; MCC_JogSpace and MCC_JogConti queue behind what
// runs, as motion commands do (the vendor's library, scenario jog_while_moving).
//
// This program gives the axes a work zone of -20..+20 UU (dfLowLimit/dfHighLimit) so that
// MCC_JogConti ends soon. A jog runs as the vendor's library runs one: a point-to-point
// move of the axis, ramped with the group's acc/dec times (300 ms), the status GMS_STOP
// four periods after its last. Expected numbers (500 pulses/UU; max safe speed 50 UU/s):
//   MCC_JogPulse(100, 0): X + 100 pulses = +0.2 UU                  -> X = 0.2
//   MCC_JogSpace(-1, 10, 0): X - 1 UU at 10 % = 5 UU/s: too short to reach 5 UU/s (that
//     takes 5 x 0.6/2 = 1.5 UU), so the ramps keep their 300 ms: 600 ms -> X = -0.8
//   MCC_JogConti(1, 10, 0): X travels the high limit's 20 UU from where it stands, to
//     19.2, at 5 UU/s: 300 + ceil(4000 - 300) + 300 = 4300 ms
//   MCC_JogConti(-1, 100, 0): X travels 20 UU back, to -0.8, at 50 UU/s: 300 + 100 +
//     300 = 700 ms
//   MCC_JogConti(1, 10, 1) on Y (20 UU at 5 UU/s), stopped with MCC_AbortMotionEx(100)
//     after 1 s at 0.15 x 5 + 0.7 x 5 = 4.25: the vendor's library reads a timed
//     abort's time of a point-to-point move as ms (1 ms here), so Y stops after
//     v² x 0.001/(2 x 5) = 0.0025 UU more: 4.2525, read as 4.252 (2126 whole pulses).
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
    // 1 UU is too short to reach 5 UU/s with 300 ms ramps (they need 2 x 0.75 UU): the
    // ramps keep their times and the peak drops: 600 ms (a PtP's one more period).
    CheckEndsIn(g_nGroupIndex, 600 + 1, "JogSpace -1 UU at 5 UU/s");
    WaitStop(g_nGroupIndex);
    CheckPosXYZ(g_nGroupIndex, -0.8, 0, 0);
    CHECK_EQ(PulseX(g_nGroupIndex), -400);
    PrintPos(g_nGroupIndex, "After MCC_JogSpace(-1, 10, 0)");

    // Step 3: X up by the work zone's extent.
    nRet = MCC_JogConti(1, 10, 0, g_nGroupIndex);
    printf("MCC_JogConti(1, 10, 0): returned %d\n", nRet);
    CHECK(nRet >= 0);
    CHECK(MCC_GetMotionStatus(g_nGroupIndex) != GMS_STOP);
    // MCC_JogPulse needs the group at rest: while this jog runs it is refused.
    CHECK_EQ(MCC_JogPulse(10, 1, g_nGroupIndex), COMMAND_NOTFINISHED_ERR);
    CheckEndsIn(g_nGroupIndex, 4300 + 1, "JogConti +20 UU at 5 UU/s");
    WaitStop(g_nGroupIndex);
    CheckPosXYZ(g_nGroupIndex, 19.2, 0, 0);
    CHECK_EQ(PulseX(g_nGroupIndex), 9600);
    PrintPos(g_nGroupIndex, "After MCC_JogConti(1, 10, 0)");

    // The other way at 100 %.
    CHECK(MCC_JogConti(-1, 100, 0, g_nGroupIndex) >= 0);
    CheckEndsIn(g_nGroupIndex, 700 + 1, "JogConti -20 UU at 50 UU/s");
    WaitStop(g_nGroupIndex);
    CheckPosXYZ(g_nGroupIndex, -0.8, 0, 0);

    // MCC_AbortMotionEx stops a continuous jog (user manual §2.6.2 III C).
    CHECK(MCC_JogConti(1, 10, 1, g_nGroupIndex) >= 0);   // Y up 20 UU at 5 UU/s: 4.3 s
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
    CHECK_NEAR(p1[0], -0.8, POS_TOL);
    if (SteppedClock())   // 1 s: 5 x 0.3/2 + 5 x 0.7 = 4.25; the 1 ms stop: + 0.0025
        CHECK_NEAR(p1[1], 4.252, POS_TOL);

    // Bad input.
    CHECK_EQ(MCC_JogPulse(2049, 0, g_nGroupIndex), PARAMETER_ERR);    // at most 2048 pulses
    CHECK_EQ(MCC_JogPulse(-2049, 0, g_nGroupIndex), PARAMETER_ERR);
    CHECK_EQ(MCC_JogPulse(10, 8, g_nGroupIndex), GROUP_PARAMETER_ERR);   // axes are 0..7
    CHECK_EQ(MCC_JogPulse(10, -1, g_nGroupIndex), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCC_JogPulse(10, 0, BAD_GROUP), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCC_JogSpace(NAN, 10, 0, g_nGroupIndex), PARAMETER_ERR);
    CHECK_EQ(MCC_JogSpace(1, NAN, 0, g_nGroupIndex), PARAMETER_ERR);
    CHECK_EQ(MCC_JogSpace(1, 10, 8, g_nGroupIndex), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCC_JogSpace(1, 10, 0, BAD_GROUP), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCC_JogConti(1, NAN, 0, g_nGroupIndex), PARAMETER_ERR);
    CHECK_EQ(MCC_JogConti(1, 10, 8, g_nGroupIndex), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCC_JogConti(1, 10, 0, BAD_GROUP), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCC_GetMotionStatus(g_nGroupIndex), GMS_STOP);
    CHECK_NEAR(p2[0], -0.8, POS_TOL);
    GetPos(g_nGroupIndex, p2);
    CHECK(p1[0] == p2[0] && p1[1] == p2[1]);

    Close();
    CHECK_EQ(MCC_JogPulse(10, 0, 0), INITIAL_MOTION_ERR);
    return check_done("JogMotion");
}
