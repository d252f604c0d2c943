// SetBlend.cpp: examples manual §20 (motion blending): with MCC_EnableBlend the first
// command goes from its cruise speed straight into the next command's cruise speed
// without stopping; MCC_CheckBlend returns 0 when blending is on, 1 when it is off.
//
// As the vendor's library blends (docs/decisions.md): the next command starts when the
// previous one starts to decelerate, both ramps of the overlap are S ramps (the cubic
// smoothstep), and the two velocity profiles add. Expected numbers (Ta = Td = 300 ms,
// periods of 1 ms; GMS_STOP three periods after the last):
//   off: Line (10,0) then (10,10) at 10 UU/s: 1300 periods, the first's end period,
//        1300 more: 2601 ms; the path passes exactly through the corner (10, 0),
//        reached at 1300 ms
//   on:  Line (0,10) then (0,0) from (10,10) at 10 UU/s: the second starts at 1.0 s:
//        1.0 + 1.3 = 2300 ms. Half-way through the overlap (1150 ms) the first still has
//        V Td x (the integral of 1 - smoothstep over [1/2, 1]: 1/2 - 13/32 = 3/32) =
//        10 x 0.3 x 0.09375 = 0.28125 UU to go and the second has covered as much: the
//        axes are at (0.28125, 9.71875), inside the corner (0, 10); read in whole pulses
//        toward 0: (0.28, 9.718).
//   on, different speeds: (10,0) at 10 UU/s, then (10,10) at 20 UU/s:
//        1.0 + (10/20 + 0.3) = 1800 ms (off it would be 1300 + 1 + 800 = 2101 ms).
#include "MotionSys.h"

int main()
{
    if (InitSys8() != NO_ERR)
        return check_done("SetBlend");
    double p[8];

    CHECK_EQ(MCC_SetAbsolute(g_nGroupIndex), NO_ERR);
    MCC_SetFeedSpeed(10, g_nGroupIndex);

    // Blending off.
    CHECK(MCC_DisableBlend(g_nGroupIndex) >= 0);   // a queued command (user manual §2.3 H)
    MCC_TimeDelay(10);
    CHECK_EQ(MCC_CheckBlend(g_nGroupIndex), 1);
    CHECK_EQ(MCC_GetMotionStatus(g_nGroupIndex), GMS_STOP);
    CHECK(MCC_Line(10, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex) >= 0);
    CHECK(MCC_Line(10, 10, 0, 0, 0, 0, 0, 0, g_nGroupIndex) >= 0);
    if (SteppedClock())
    {
        MCC_TimeDelay(1300 + TOL_MS);
        GetPos(g_nGroupIndex, p);
        printf("  [stepped clock] blending off, 1.3 s: X = %.3f, Y = %.3f\n", p[0], p[1]);
        CHECK_NEAR(p[0], 10, POS_TOL);      // went all the way to the corner
        CHECK(p[1] >= 0 && p[1] < 0.01);
        CheckEndsIn(g_nGroupIndex, 2601 - 1300 - TOL_MS, "two lines, blending off");
    }
    else
    {
        // Any clock: without blending the path never cuts the corner: X reaches 10 before
        // Y leaves 0.
        while (MCC_GetMotionStatus(g_nGroupIndex) != GMS_STOP)
        {
            GetPos(g_nGroupIndex, p);
            CHECK(p[1] == 0.0 || fabs(p[0] - 10) <= POS_TOL);
            MCC_TimeDelay(1);
        }
    }
    WaitStop(g_nGroupIndex);
    CheckPosXYZ(g_nGroupIndex, 10, 10, 0);

    // Blending on.
    CHECK(MCC_EnableBlend(g_nGroupIndex) >= 0);
    MCC_TimeDelay(10);
    CHECK_EQ(MCC_CheckBlend(g_nGroupIndex), 0);
    CHECK(MCC_Line(0, 10, 0, 0, 0, 0, 0, 0, g_nGroupIndex) >= 0);
    CHECK(MCC_Line(0, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex) >= 0);
    if (SteppedClock())
    {
        MCC_TimeDelay(1150);
        GetPos(g_nGroupIndex, p);
        printf("  [stepped clock] blending on, 1.15 s: X = %.3f, Y = %.3f\n", p[0], p[1]);
        CHECK_NEAR(p[0], 0.28, POS_TOL);
        CHECK_NEAR(p[1], 9.718, POS_TOL);
        CheckEndsIn(g_nGroupIndex, 2300 - 1150, "two lines, blending on");
    }
    else
    {
        // Any clock: the corner (0, 10) is cut: at some moment X > 0 while Y < 10.
        bool bCut = false;
        while (MCC_GetMotionStatus(g_nGroupIndex) != GMS_STOP)
        {
            GetPos(g_nGroupIndex, p);
            if (p[0] > 1e-6 && p[1] < 10 - 1e-6) bCut = true;
            MCC_TimeDelay(1);
        }
        CHECK(bCut);
    }
    WaitStop(g_nGroupIndex);
    CheckPosXYZ(g_nGroupIndex, 0, 0, 0);

    // Blending on, different feed speeds.
    CHECK(MCC_Line(10, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex) >= 0);
    MCC_SetFeedSpeed(20, g_nGroupIndex);
    CHECK(MCC_Line(10, 10, 0, 0, 0, 0, 0, 0, g_nGroupIndex) >= 0);
    CheckEndsIn(g_nGroupIndex, 1800, "10 UU at 10 then 10 UU at 20, blended");
    WaitStop(g_nGroupIndex);
    CheckPosXYZ(g_nGroupIndex, 10, 10, 0);

    // Off again.
    CHECK(MCC_DisableBlend(g_nGroupIndex) >= 0);
    MCC_TimeDelay(10);
    CHECK_EQ(MCC_CheckBlend(g_nGroupIndex), 1);

    // Bad input.
    CHECK_EQ(MCC_EnableBlend(BAD_GROUP), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCC_DisableBlend(BAD_GROUP), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCC_CheckBlend(BAD_GROUP), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCC_CheckBlend(7), GROUP_PARAMETER_ERR);   // not created
    CHECK_EQ(MCC_CheckBlend(g_nGroupIndex), 1);

    Close();
    CHECK_EQ(MCC_CheckBlend(0), INITIAL_MOTION_ERR);
    return check_done("SetBlend");
}
