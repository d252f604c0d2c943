// OverrideSpeed.cpp: examples manual §18 (speed override): MCC_OverrideSpeed /
// MCC_OverrideSpeedEx set the speed as a percentage of the set feed speed, for the running
// command and every later one; MCC_GetOverrideRate reads it back.
//
// Expected numbers (MCC_SetFeedSpeed(20); a long line X 0 -> 300 so that changing its
// speed 1 s in is no race on the fast clock):
//   MCC_OverrideSpeedEx(150, 1): "20 x 150 % = 30 UU/s", immediately; rate 150
//   MCC_OverrideSpeed(50): 20 x 50 % = 10 UU/s; rate 50
//   MCC_OverrideSpeedEx(200, 0): rate 200 from the next command on: the running line
//     keeps 10 UU/s, the next line (back to 0) cruises at 20 x 200 % = 40 UU/s
// Speeds are read 500 ms or more after each change, when the speed change (which this
// program assumes takes no longer than the 300 ms acceleration time) is over.
#include "MotionSys.h"

int main()
{
    if (InitSys8() != NO_ERR)
        return check_done("OverrideSpeed");
    double dfRate;

    CHECK_EQ(MCC_SetAbsolute(g_nGroupIndex), NO_ERR);
    CHECK(MCC_GetOverrideRate(g_nGroupIndex) == 100.0);   // no override to begin with

    // Step 1: 20 UU/s.
    MCC_SetFeedSpeed(20, g_nGroupIndex);
    CHECK_EQ(MCC_ResetCommandIndex(g_nGroupIndex), NO_ERR);
    CHECK_EQ(MCC_Line(300, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex), 0);
    MCC_TimeDelay(1000);
    CHECK_NEAR(MCC_GetCurFeedSpeed(g_nGroupIndex), 20, 1e-6);

    // Step 2: 150 % at once.
    MCC_OverrideSpeedEx(150, 1, g_nGroupIndex);
    // Step 3: the rate reads 150.
    dfRate = MCC_GetOverrideRate(g_nGroupIndex);
    CHECK(dfRate == 150.0);
    MCC_TimeDelay(500);
    printf("Override 150 %%: path speed %.3f UU/s\n", MCC_GetCurFeedSpeed(g_nGroupIndex));
    CHECK_NEAR(MCC_GetCurFeedSpeed(g_nGroupIndex), 30, 1e-6);
    CHECK(MCC_GetFeedSpeed(g_nGroupIndex) == 20.0);      // the set feed speed is unchanged

    // 50 %.
    MCC_OverrideSpeed(50, g_nGroupIndex);
    CHECK(MCC_GetOverrideRate(g_nGroupIndex) == 50.0);
    MCC_TimeDelay(1000);
    printf("Override 50 %%: path speed %.3f UU/s\n", MCC_GetCurFeedSpeed(g_nGroupIndex));
    CHECK_NEAR(MCC_GetCurFeedSpeed(g_nGroupIndex), 10, 1e-6);

    // 200 %, from the next command on.
    CHECK_EQ(MCC_Line(0, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex), 1);
    MCC_OverrideSpeedEx(200, 0, g_nGroupIndex);
    CHECK(MCC_GetOverrideRate(g_nGroupIndex) == 200.0);
    MCC_TimeDelay(500);
    COMMAND_INFO stInfo;
    CHECK_EQ(MCC_GetCurCommand(&stInfo, g_nGroupIndex), NO_ERR);
    CHECK_EQ(stInfo.nCommandIndex, 0);
    CHECK_NEAR(MCC_GetCurFeedSpeed(g_nGroupIndex), 10, 1e-6);   // still the old rate
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
    CHECK(MCC_GetOverrideRate(g_nGroupIndex) == 200.0);
    MCC_OverrideSpeed(100, g_nGroupIndex);
    CHECK(MCC_GetOverrideRate(g_nGroupIndex) == 100.0);
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
    CHECK(MCC_GetOverrideRate(g_nGroupIndex) == 100.0);
    MCC_OverrideSpeed(-10, g_nGroupIndex);
    CHECK(MCC_GetOverrideRate(g_nGroupIndex) == 100.0);
    MCC_OverrideSpeedEx(INFINITY, 1, g_nGroupIndex);
    CHECK(MCC_GetOverrideRate(g_nGroupIndex) == 100.0);
    MCC_OverrideSpeed(150, BAD_GROUP);
    CHECK(MCC_GetOverrideRate(g_nGroupIndex) == 100.0);
    CheckPosXYZ(g_nGroupIndex, 0, 0, 0);

    Close();
    return check_done("OverrideSpeed");
}
