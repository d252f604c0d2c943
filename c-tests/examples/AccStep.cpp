// AccStep.cpp: examples manual §8 (acceleration and deceleration times): the default is
// 300 ms for general and point-to-point motion; MCC_SetAccTime/MCC_SetDecTime and
// MCC_SetPtPAccTime/MCC_SetPtPDecTime change them; "acc time = required speed / required
// acceleration".
//
// Expected durations (MotionSys.h: na + nc + nd periods of 1 ms, nc = ceil(L/F/T - na/2
// - nd/2); the status reads GMS_STOP three periods after the last, a PtP's four):
//   line 10 UU at 20 UU/s, defaults 300/300 ms:            300 + 200 + 300 = 800 ms
//   same with acceleration 200 UU/s^2 -> Ta = 20/200 = 100 ms, Td = 300 ms:
//                                                           100 + 300 + 300 = 700 ms
//   a 1 UU line at 20 UU/s with Ta = Td = 300 ms cannot reach 20 UU/s (that takes
//   20 x 0.6/2 = 6 UU): the vendor's library keeps the ramp times and lowers the peak to
//   V = 2L/(Ta+Td) = 3.33 UU/s: 300 + 300 = 600 ms
//   PtP X 10 UU at 20 % (10 UU/s): the PtP acc/dec times are kept per axis but a PtP
//   ramps with the group's acc/dec times (the vendor's library, scenario
//   ptp_axis_times), 300/300 ms:                            300 + 700 + 300 = 1300 ms
//   PtP X back, per-axis times X acc 200 / dec 400 ms: the same 1300 ms
#include "MotionSys.h"

int main()
{
    if (InitSys8() != NO_ERR)
        return check_done("AccStep");

    // Defaults: 300 ms everywhere.
    CHECK(MCC_GetAccTime(g_nGroupIndex) == 300.0);
    CHECK(MCC_GetDecTime(g_nGroupIndex) == 300.0);
    double a[8], d[8];
    CHECK_EQ(MCC_GetPtPAccTime(&a[0], &a[1], &a[2], &a[3], &a[4], &a[5], &a[6], &a[7], g_nGroupIndex), NO_ERR);
    CHECK_EQ(MCC_GetPtPDecTime(&d[0], &d[1], &d[2], &d[3], &d[4], &d[5], &d[6], &d[7], g_nGroupIndex), NO_ERR);
    for (int i = 0; i < 8; i++)
    {
        CHECK(a[i] == 300.0);
        CHECK(d[i] == 300.0);
    }

    CHECK_EQ(MCC_SetAbsolute(g_nGroupIndex), NO_ERR);
    MCC_SetFeedSpeed(20, g_nGroupIndex);
    CHECK(MCC_Line(10, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex) >= 0);
    CheckEndsIn(g_nGroupIndex, 800, "10 UU at 20 UU/s, 300/300 ms");
    WaitStop(g_nGroupIndex);
    CheckPosXYZ(g_nGroupIndex, 10, 0, 0);

    // The manual's formula: acceleration time = required speed / required acceleration.
    double dfSpeed = 20, dfAcc = 200;              // UU/s, UU/s^2
    double dfTime = dfSpeed / dfAcc * 1000;        // 100 ms
    CHECK_EQ(MCC_SetAccTime(dfTime, g_nGroupIndex), NO_ERR);
    CHECK(MCC_GetAccTime(g_nGroupIndex) == 100.0);
    CHECK(MCC_GetDecTime(g_nGroupIndex) == 300.0);
    CHECK(MCC_Line(0, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex) >= 0);
    CheckEndsIn(g_nGroupIndex, 700, "10 UU at 20 UU/s, 100/300 ms");
    WaitStop(g_nGroupIndex);
    CheckPosXYZ(g_nGroupIndex, 0, 0, 0);

    // A move too short to reach the feed speed keeps the ramp times (the peak is lower).
    CHECK_EQ(MCC_SetAccTime(300, g_nGroupIndex), NO_ERR);
    CHECK_EQ(MCC_SetDecTime(300, g_nGroupIndex), NO_ERR);
    CHECK(MCC_Line(0, 1, 0, 0, 0, 0, 0, 0, g_nGroupIndex) >= 0);
    CheckEndsIn(g_nGroupIndex, 600, "1 UU at 20 UU/s (short of the feed)");
    WaitStop(g_nGroupIndex);
    CheckPosXYZ(g_nGroupIndex, 0, 1, 0);

    // Point-to-point: its own times, kept (the PtP ramps with the group's 300/300 ms).
    CHECK_EQ(MCC_SetPtPAccTime(100, 100, 100, 100, 100, 100, 100, 100, g_nGroupIndex), NO_ERR);
    CHECK_EQ(MCC_SetPtPDecTime(100, 100, 100, 100, 100, 100, 100, 100, g_nGroupIndex), NO_ERR);
    CHECK_EQ(MCC_GetPtPAccTime(&a[0], &a[1], &a[2], &a[3], &a[4], &a[5], &a[6], &a[7], g_nGroupIndex), NO_ERR);
    for (int i = 0; i < 8; i++)
        CHECK(a[i] == 100.0);
    CHECK(MCC_GetAccTime(g_nGroupIndex) == 300.0);   // general motion unchanged
    MCC_SetPtPSpeed(20, g_nGroupIndex);               // 20 % of 50 UU/s = 10 UU/s
    CHECK(MCC_PtP(10, 1, 0, 0, 0, 0, 0, 0, g_nGroupIndex) >= 0);
    CheckEndsIn(g_nGroupIndex, 1300 + 1, "PtP X 10 UU at 10 UU/s, the group's 300/300 ms");
    WaitStop(g_nGroupIndex);
    CheckPosXYZ(g_nGroupIndex, 10, 1, 0);

    // Per-axis times: X 200/400 ms, the others 100 ms.
    CHECK_EQ(MCC_SetPtPAccTime(200, 100, 100, 100, 100, 100, 100, 100, g_nGroupIndex), NO_ERR);
    CHECK_EQ(MCC_SetPtPDecTime(400, 100, 100, 100, 100, 100, 100, 100, g_nGroupIndex), NO_ERR);
    CHECK_EQ(MCC_GetPtPDecTime(&d[0], &d[1], &d[2], &d[3], &d[4], &d[5], &d[6], &d[7], g_nGroupIndex), NO_ERR);
    CHECK(d[0] == 400.0 && d[1] == 100.0 && d[7] == 100.0);
    CHECK(MCC_PtP(0, 1, 0, 0, 0, 0, 0, 0, g_nGroupIndex) >= 0);
    CheckEndsIn(g_nGroupIndex, 1300 + 1, "PtP X 10 UU at 10 UU/s, X's 200/400 ms kept");
    WaitStop(g_nGroupIndex);
    CheckPosXYZ(g_nGroupIndex, 0, 1, 0);

    // Bad input changes nothing.
    CHECK_EQ(MCC_SetAccTime(NAN, g_nGroupIndex), PARAMETER_ERR);
    CHECK_EQ(MCC_SetAccTime(-1, g_nGroupIndex), PARAMETER_ERR);
    CHECK_EQ(MCC_SetDecTime(INFINITY, g_nGroupIndex), PARAMETER_ERR);
    CHECK_EQ(MCC_SetAccTime(100, BAD_GROUP), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCC_SetDecTime(100, BAD_GROUP), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCC_SetPtPAccTime(100, NAN, 100, 100, 100, 100, 100, 100, g_nGroupIndex), PARAMETER_ERR);
    CHECK_EQ(MCC_SetPtPDecTime(100, 100, 100, 100, 100, 100, 100, -5, g_nGroupIndex), PARAMETER_ERR);
    CHECK_EQ(MCC_SetPtPAccTime(100, 100, 100, 100, 100, 100, 100, 100, BAD_GROUP), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCC_GetPtPAccTime(NULL, &a[1], &a[2], &a[3], &a[4], &a[5], &a[6], &a[7], g_nGroupIndex), PARAMETER_ERR);
    CHECK_EQ(MCC_GetPtPDecTime(&d[0], &d[1], &d[2], &d[3], &d[4], &d[5], &d[6], &d[7], BAD_GROUP), GROUP_PARAMETER_ERR);
    CHECK(MCC_GetAccTime(g_nGroupIndex) == 300.0);
    CHECK(MCC_GetDecTime(g_nGroupIndex) == 300.0);
    CHECK_EQ(MCC_GetPtPAccTime(&a[0], &a[1], &a[2], &a[3], &a[4], &a[5], &a[6], &a[7], g_nGroupIndex), NO_ERR);
    CHECK(a[0] == 200.0 && a[1] == 100.0);

    Close();
    return check_done("AccStep");
}
