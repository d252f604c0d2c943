// OverrideSpeed.cpp: examples manual §18 (speed override): MCC_OverrideSpeed /
// MCC_OverrideSpeedEx set the speed as a percentage of the set feed speed, for the running
// command and every later one; MCC_GetOverrideRate reads it back as a fraction (1.5 for
// 150 %) from the period after it was set, as the vendor's library reads it.
//
// Expected numbers (MCC_SetFeedSpeed(20); a long line X 0 -> 300 so that changing its
// speed 1 s in is no race on the fast clock):
//   MCC_OverrideSpeedEx(150, 1): "20 x 150 % = 30 UU/s" from the next period; rate 1.5
//   MCC_OverrideSpeed(50): 20 x 50 % = 10 UU/s; rate 0.5
//   MCC_OverrideSpeedEx(200, 0): rate 2 from the next command on: the running line
//     keeps 10 UU/s, the next line (back to 0) cruises at 20 x 200 % = 40 UU/s (300 UU:
//     300 + ceil(7500 - 300) + 300 periods at exactly 40)
// An override plans the rest of the running line again from its speed, with the acc and
// dec times and whole periods at the new speed, which so falls short of F' by less than a
// period's worth of the distance left d (F'² T/d: 30² x 0.001/280 = 0.0032 at 150 %,
// 10² x 0.001/260 = 0.0004 at 50 %). Speeds are read 500 ms or more after each change,
// when the ramp (300 ms) is over.
#include "MotionSys.h"

int main()
{
    if (InitSys8() != NO_ERR)
        return check_done("OverrideSpeed");
    double dfRate;

    CHECK_EQ(MCC_SetAbsolute(g_nGroupIndex), NO_ERR);
    CHECK(MCC_GetOverrideRate(g_nGroupIndex) == 1.0);   // no override to begin with

    // Step 1: 20 UU/s.
    MCC_SetFeedSpeed(20, g_nGroupIndex);
    CHECK_EQ(MCC_ResetCommandIndex(g_nGroupIndex), NO_ERR);
    CHECK_EQ(MCC_Line(300, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex), 0);
    MCC_TimeDelay(1000);
    CHECK_NEAR(MCC_GetCurFeedSpeed(g_nGroupIndex), 20, 1e-6);

    // Step 2: 150 % at once.
    MCC_OverrideSpeedEx(150, 1, g_nGroupIndex);
    // Step 3: the rate reads 1.5 from the next period.
    MCC_TimeDelay(1);
    dfRate = MCC_GetOverrideRate(g_nGroupIndex);
    CHECK(dfRate == 1.5);
    MCC_TimeDelay(500);
    printf("Override 150 %%: path speed %.3f UU/s\n", MCC_GetCurFeedSpeed(g_nGroupIndex));
    CHECK(MCC_GetCurFeedSpeed(g_nGroupIndex) <= 30 + 1e-9);
    CHECK_NEAR(MCC_GetCurFeedSpeed(g_nGroupIndex), 30, 0.0032);
    CHECK(MCC_GetFeedSpeed(g_nGroupIndex) == 20.0);      // the set feed speed is unchanged

    // 50 %.
    MCC_OverrideSpeed(50, g_nGroupIndex);
    MCC_TimeDelay(1000);
    CHECK(MCC_GetOverrideRate(g_nGroupIndex) == 0.5);
    printf("Override 50 %%: path speed %.3f UU/s\n", MCC_GetCurFeedSpeed(g_nGroupIndex));
    CHECK(MCC_GetCurFeedSpeed(g_nGroupIndex) <= 10 + 1e-9);
    CHECK_NEAR(MCC_GetCurFeedSpeed(g_nGroupIndex), 10, 0.0004);
    double dfSpeed50 = MCC_GetCurFeedSpeed(g_nGroupIndex);

    // 200 %, from the next command on.
    CHECK_EQ(MCC_Line(0, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex), 1);
    MCC_OverrideSpeedEx(200, 0, g_nGroupIndex);
    MCC_TimeDelay(500);
    CHECK(MCC_GetOverrideRate(g_nGroupIndex) == 2.0);
    COMMAND_INFO stInfo;
    CHECK_EQ(MCC_GetCurCommand(&stInfo, g_nGroupIndex), NO_ERR);
    CHECK_EQ(stInfo.nCommandIndex, 0);
    CHECK(MCC_GetCurFeedSpeed(g_nGroupIndex) == dfSpeed50);   // still the old rate
    long n = 0;
    while (MCC_GetCurCommand(&stInfo, g_nGroupIndex) == NO_ERR && stInfo.nCommandIndex == 0 && n++ < 1000000)
        MCC_TimeDelay(1);
    CHECK_EQ(stInfo.nCommandIndex, 1);
    double p[8];
    GetPos(g_nGroupIndex, p);
    if (SteppedClock())   // the fast clock may already have moved on
        CHECK_NEAR(p[0], 300, 2.0);   // the first line was done (or, blended, decelerating)
    MCC_TimeDelay(1000);
    printf("Next command at 200 %%: path speed %.3f UU/s\n", MCC_GetCurFeedSpeed(g_nGroupIndex));
    CHECK_NEAR(MCC_GetCurFeedSpeed(g_nGroupIndex), 40, 1e-6);
    WaitStop(g_nGroupIndex);
    CheckPosXYZ(g_nGroupIndex, 0, 0, 0);

    // The override stays for later commands until changed.
    CHECK(MCC_GetOverrideRate(g_nGroupIndex) == 2.0);
    MCC_OverrideSpeed(100, g_nGroupIndex);
    MCC_TimeDelay(1);
    CHECK(MCC_GetOverrideRate(g_nGroupIndex) == 1.0);
    if (SteppedClock())
    {
        // Back at 100 %: 10 UU at 20 UU/s: 800 ms.
        CHECK(MCC_Line(10, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex) >= 0);
        CheckEndsIn(g_nGroupIndex, 800, "10 UU at 20 UU/s, override 100 %");
        WaitStop(g_nGroupIndex);
        CHECK(MCC_Line(0, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex) >= 0);
        WaitStop(g_nGroupIndex);
    }

    // Bad input leaves the rate alone.
    MCC_OverrideSpeed(NAN, g_nGroupIndex);
    MCC_OverrideSpeed(-10, g_nGroupIndex);
    MCC_OverrideSpeedEx(INFINITY, 1, g_nGroupIndex);
    MCC_OverrideSpeed(150, BAD_GROUP);
    MCC_TimeDelay(1);
    CHECK(MCC_GetOverrideRate(g_nGroupIndex) == 1.0);
    CheckPosXYZ(g_nGroupIndex, 0, 0, 0);

    Close();
    return check_done("OverrideSpeed");
}
