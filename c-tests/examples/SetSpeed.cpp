// SetSpeed.cpp: examples manual §9 (feed speed): MCC_SetFeedSpeed in UU/s for line, arc,
// circle and helix, not above MCC_SetSysMaxSpeed; MCC_SetPtPSpeed as a percentage of
// (wRPM / 60) x dfPitch / dfGearRatio.
//
// Expected numbers (Ta = Td = 300 ms, so every move below lasts L/F + 0.3 s, a whole
// number of 1 ms periods; GMS_STOP reads three periods after, a PtP's four):
//   MCC_SetFeedSpeed(20): MCC_GetFeedSpeed() = 20; line 10 UU: 800 ms
//   MCC_SetFeedSpeed(150) with MCC_SetSysMaxSpeed(100): the feed speed becomes 100
//     (user manual §2.6.2 E); line 100 UU: 1.0 + 0.3 = 1300 ms
//   MCC_SetPtPSpeed(50): 50 % of 3000/60 x 1/1 = 25 UU/s; PtP X 10 UU with the group's
//     300/300 ms ramps: 0.4 + 0.3 = 700 ms
//   a line that moves only U and V (no X/Y/Z): the feed speed applies to the axis going
//     furthest (U, 10 UU at 20 UU/s: 800 ms), V arrives with it (user manual §2.6.2 E)
//   a line with X/Y and U: only X/Y/Z count for the speed, U follows linearly
//     ((30,40) at F = 10: 5.3 s; U/X = 100/30 at every instant)
#include "MotionSys.h"

int main()
{
    if (InitSys8() != NO_ERR)
        return check_done("SetSpeed");
    CHECK(MCC_GetSysMaxSpeed() == EX_MAX_SPEED);
    CHECK_EQ(MCC_SetAbsolute(g_nGroupIndex), NO_ERR);

    MCC_SetFeedSpeed(20, g_nGroupIndex);
    CHECK(MCC_GetFeedSpeed(g_nGroupIndex) == 20.0);
    CHECK(MCC_Line(10, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex) >= 0);
    CheckEndsIn(g_nGroupIndex, 800, "10 UU at 20 UU/s");
    WaitStop(g_nGroupIndex);
    CheckPosXYZ(g_nGroupIndex, 10, 0, 0);

    // Above the system maximum: clamped to it.
    MCC_SetFeedSpeed(150, g_nGroupIndex);
    CHECK(MCC_GetFeedSpeed(g_nGroupIndex) == EX_MAX_SPEED);
    CHECK(MCC_Line(110, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex) >= 0);
    CheckEndsIn(g_nGroupIndex, 1300, "100 UU at 150 -> 100 UU/s");
    WaitStop(g_nGroupIndex);
    CheckPosXYZ(g_nGroupIndex, 110, 0, 0);

    // Point-to-point speed ratio.
    MCC_SetPtPSpeed(50, g_nGroupIndex);
    CHECK(MCC_GetPtPSpeed(g_nGroupIndex) == 50.0);
    CHECK(MCC_PtP(100, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex) >= 0);
    CheckEndsIn(g_nGroupIndex, 700 + 1, "PtP 10 UU at 50 % = 25 UU/s");
    WaitStop(g_nGroupIndex);
    CheckPosXYZ(g_nGroupIndex, 100, 0, 0);

    // Only U and V move: the feed speed is U's speed.
    MCC_SetFeedSpeed(20, g_nGroupIndex);
    CHECK(MCC_Line(100, 0, 0, 10, 5, 0, 0, 0, g_nGroupIndex) >= 0);
    CheckEndsIn(g_nGroupIndex, 800, "U 10 UU (V 5 UU) at 20 UU/s");
    WaitStop(g_nGroupIndex);
    double e1[8] = {100, 0, 0, 10, 5, 0, 0, 0};
    CheckPos8(g_nGroupIndex, e1);

    // X/Y define the speed; U follows linearly.
    CHECK(MCC_Line(0, 0, 0, 0, 5, 0, 0, 0, g_nGroupIndex) >= 0);
    WaitStop(g_nGroupIndex);
    MCC_SetFeedSpeed(10, g_nGroupIndex);
    CHECK(MCC_Line(30, 40, 0, 100, 5, 0, 0, 0, g_nGroupIndex) >= 0);
    double p[8];
    MCC_TimeDelay(2000);
    GetPos(g_nGroupIndex, p);
    printf("2 s into the line to (30, 40, U 100): X = %.3f, Y = %.3f, U = %.3f\n", p[0], p[1], p[3]);
    CHECK(p[0] > 0 && p[0] <= 30);   // (the fast clock may have finished it)
    CHECK_NEAR(p[3] * 30, p[0] * 100, 1e-6);
    CHECK_NEAR(p[1] * 30, p[0] * 40, 1e-6);
    CHECK_NEAR(p[4], 5, POS_TOL);
    if (SteppedClock())
    {
        // 2 s: 10 x 0.3 / 2 + 10 x 1.7 = 18.5 UU along the 50 UU path.
        CHECK_NEAR(p[0], 18.5 * 0.6, 0.03);
        CHECK_NEAR(p[3], 18.5 / 50 * 100, 0.06);
        CHECK_NEAR(MCC_GetCurFeedSpeed(g_nGroupIndex), 10, 1e-6);
        CheckEndsIn(g_nGroupIndex, 5300 - 2000, "(30, 40) at 10 UU/s, U along");
    }
    WaitStop(g_nGroupIndex);
    double e2[8] = {30, 40, 0, 100, 5, 0, 0, 0};
    CheckPos8(g_nGroupIndex, e2);

    // Bad input leaves the speeds alone; a negative feed counts by its size, as the
    // vendor's library takes it (-5 is 5 UU/s).
    MCC_SetFeedSpeed(NAN, g_nGroupIndex);
    CHECK(MCC_GetFeedSpeed(g_nGroupIndex) == 10.0);
    CHECK(MCC_SetFeedSpeed(-5, g_nGroupIndex) == 5.0);
    CHECK(MCC_GetFeedSpeed(g_nGroupIndex) == 5.0);
    MCC_SetFeedSpeed(20, BAD_GROUP);
    CHECK(MCC_GetFeedSpeed(g_nGroupIndex) == 5.0);
    MCC_SetPtPSpeed(NAN, g_nGroupIndex);
    CHECK(MCC_GetPtPSpeed(g_nGroupIndex) == 50.0);
    MCC_SetPtPSpeed(-1, g_nGroupIndex);
    CHECK(MCC_GetPtPSpeed(g_nGroupIndex) == 50.0);
    CHECK_EQ(MCC_PtP(NAN, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex), PARAMETER_ERR);
    CHECK_EQ(MCC_PtP(0, 0, 0, 0, 0, 0, 0, 0, BAD_GROUP), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCC_GetMotionStatus(g_nGroupIndex), GMS_STOP);
    CheckPos8(g_nGroupIndex, e2);

    Close();
    return check_done("SetSpeed");
}
