// PtPMotion.cpp: examples manual §12 (point-to-point motion): every axis moves with its
// own speed; the axes start together and need not arrive together (unlike a line).
//
// Expected numbers: MCC_SetPtPSpeed(20) -> 20 % of (3000/60) x 1/1 = 10 UU/s per axis,
// ramped with the group's acc/dec times, 300 ms (as the vendor's library runs a PtP),
// whole periods of 1 ms; GMS_STOP reads four periods after the last axis arrives:
//   MCC_PtP(10, 20): X 10 UU: 1.0 + 0.3 = 1.3 s; Y 20 UU: 2.0 + 0.3 = 2.3 s.
//     At 1.3 s X has arrived (10) while Y is at 10 x 1.3 - 1.5 = 11.5 and still moving.
//   MCC_SyncPtP(0, 0) from (10, 20): all axes end together, paced by the slowest (Y):
//     2.3 s; X is still moving at 1.3 s.
//   MCC_PtPX(5): X alone, 5 UU: 0.5 + 0.3 = 0.8 s.
//   MCC_PtP(7, 7, 7, ..., IMP_AXIS_Y): only Y moves (axes outside the mask stay).
#include "MotionSys.h"

int main()
{
    if (InitSys8() != NO_ERR)
        return check_done("PtPMotion");

    // Step 1: absolute coordinates, feed speed (the manual sets it too).
    CHECK_EQ(MCC_SetAbsolute(g_nGroupIndex), NO_ERR);
    MCC_SetFeedSpeed(20, g_nGroupIndex);

    // Step 2: 20 % of the maximum safe speed.
    MCC_SetPtPSpeed(20, g_nGroupIndex);
    CHECK(MCC_GetPtPSpeed(g_nGroupIndex) == 20.0);

    // Step 3: to (10, 20).
    int nRet = MCC_PtP(10, 20, 0, 0, 0, 0, 0, 0, g_nGroupIndex);
    printf("MCC_PtP(10, 20): returned %d\n", nRet);
    CHECK(nRet >= 0);
    CHECK(MCC_GetMotionStatus(g_nGroupIndex) != GMS_STOP);
    double p[8];
    if (SteppedClock())
    {
        MCC_TimeDelay(1300 - TOL_MS);
        GetPos(g_nGroupIndex, p);
        CHECK(p[0] < 10);                                  // X not there yet
        MCC_TimeDelay(2 * TOL_MS + 1);
        GetPos(g_nGroupIndex, p);
        printf("  at 1.3 s: X = %.3f (arrived), Y = %.3f (still moving)\n", p[0], p[1]);
        CHECK_NEAR(p[0], 10, POS_TOL);                     // X arrived
        CHECK_NEAR(p[1], 10 * (1.3 + (2 * TOL_MS + 1) / 1000.0) - 1.5, 0.03);
        CHECK_EQ(MCC_GetMotionStatus(g_nGroupIndex), GMS_RUNNING);
        CheckEndsIn(g_nGroupIndex, 2300 + 1 - 1300 - TOL_MS - 1, "PtP Y 20 UU at 10 UU/s");
    }
    else
    {
        // On any clock: X never passes 10, and X arrives no later than Y.
        int nStatus;
        while ((nStatus = MCC_GetMotionStatus(g_nGroupIndex)) != GMS_STOP)
        {
            GetPos(g_nGroupIndex, p);
            CHECK(p[0] <= 10 + POS_TOL && p[1] <= 20 + POS_TOL);
            CHECK(p[1] >= p[0] - POS_TOL);   // same speed, Y's target further: Y >= X
            MCC_TimeDelay(1);
        }
    }
    WaitStop(g_nGroupIndex);
    PrintPos(g_nGroupIndex, "After MCC_PtP(10, 20)");
    CheckPosXYZ(g_nGroupIndex, 10, 20, 0);

    // Synchronised PtP back to the origin: together, paced by Y.
    CHECK(MCC_SyncPtP(0, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex) >= 0);
    if (SteppedClock())
    {
        MCC_TimeDelay(1300 + 2 * TOL_MS);
        GetPos(g_nGroupIndex, p);
        CHECK(p[0] > 0);                                   // X still moving
        CHECK_NEAR(p[0] * 2, p[1], 1e-6);                  // both on one straight line
        CheckEndsIn(g_nGroupIndex, 2300 + 1 - 1300 - 2 * TOL_MS, "SyncPtP paced by Y");
    }
    WaitStop(g_nGroupIndex);
    CheckPosXYZ(g_nGroupIndex, 0, 0, 0);

    // One axis: MCC_PtPX.
    CHECK(MCC_PtPX(5, g_nGroupIndex) >= 0);
    CheckEndsIn(g_nGroupIndex, 800 + 1, "PtPX 5 UU");
    WaitStop(g_nGroupIndex);
    CheckPosXYZ(g_nGroupIndex, 5, 0, 0);

    // Axis mask: only Y.
    CHECK(MCC_PtP(7, 7, 7, 7, 7, 7, 7, 7, g_nGroupIndex, IMP_AXIS_Y) >= 0);
    WaitStop(g_nGroupIndex);
    double e[8] = {5, 7, 0, 0, 0, 0, 0, 0};
    CheckPos8(g_nGroupIndex, e);

    // Bad input.
    CHECK_EQ(MCC_PtP(NAN, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex), PARAMETER_ERR);
    CHECK_EQ(MCC_PtP(0, 0, 0, 0, 0, 0, 0, -INFINITY, g_nGroupIndex), PARAMETER_ERR);
    CHECK_EQ(MCC_PtP(0, 0, 0, 0, 0, 0, 0, 0, BAD_GROUP), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCC_SyncPtP(NAN, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex), PARAMETER_ERR);
    CHECK_EQ(MCC_SyncPtP(0, 0, 0, 0, 0, 0, 0, 0, BAD_GROUP), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCC_PtPX(NAN, g_nGroupIndex), PARAMETER_ERR);
    CHECK_EQ(MCC_PtPX(1, BAD_GROUP), GROUP_PARAMETER_ERR);
    MCC_SetPtPSpeed(NAN, g_nGroupIndex);
    CHECK(MCC_GetPtPSpeed(g_nGroupIndex) == 20.0);
    CHECK_EQ(MCC_GetMotionStatus(g_nGroupIndex), GMS_STOP);
    CheckPos8(g_nGroupIndex, e);

    Close();
    return check_done("PtPMotion");
}
