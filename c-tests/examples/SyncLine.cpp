// SyncLine.cpp: examples manual §23 (continuous 8-axis motion).
//
// Part 1: one group of 8 axes. MCC_Line(10, 20, 30, 40, 50, 60, 70, 80) at F = 10: only
//   X/Y/Z set the speed (L = sqrt(10^2+20^2+30^2) = 37.4166: 300 + ceil(3741.66 - 300) +
//   300 = 4042 periods of 1 ms at V = 37.4166/3.742 = 9.9991, after the blend switch's
//   one period); U..B start and end with them, moving linearly (U = 4 X, ..., B = 8 X at
//   every instant; each read in whole pulses toward 0, so within (i+1)/500 UU of it).
// Part 2: the manual's fnSyncLine with three groups, X/Y/Z on channels 0-2, U/V/W on 3-5,
//   A/B on 6-7, each blending; the second and third group's speeds are scaled by their
//   distance over the first group's, so all three take the same time. The manual's
//   fnSyncLine uses each call's arguments as distances, i.e. incremental coordinates
//   (MCC_SetIncrease here). Calls: fnSyncLine(10,20,30, 40,50,60, 70,80, 10) and
//   fnSyncLine(40,50,60, 10,20,30, 70,80, 10):
//     segment 1: 37.4166/10 = 3.7417 s in every group (300 + 3442 + 300 periods),
//     segment 2: 87.7496/10 = 8.7750 s (300 + 8475 + 300 periods); blended (the next
//     starts when the previous decelerates, Ta = Td = 300 ms), after the blend switch's
//     period: 1 + 3742 + 9075 = 12818 periods for all three groups;
//     end: group 0 (50, 70, 90), group 1 (50, 70, 90) on channels 3-5, group 2
//     (140, 160) on channels 6-7.
//   During segment 1 the three groups have covered the same fraction of their segment
//   (within the whole-pulse readings: 0.002/10 + 0.002/40 = 0.00025).
// The manual's CreateGroup for the third group lists seven channels and its MCC_Line
// calls six positions; eight of each are written here.
#include "MotionSys.h"

int g_nGroupIndex0 = -1;
int g_nGroupIndex1 = -1;
int g_nGroupIndex2 = -1;

// Step 1/5: fnSyncLine, as the manual defines it.
void fnSyncLine(double x, double y, double z, double u, double v, double w, double a, double b, double dfXYZSpeed)
{
    double dfDistance0, dfDistance1, dfDistance2, dfUVWSpeed, dfABSpeed;
    dfDistance0 = x * x + y * y + z * z;
    if (dfDistance0 && dfXYZSpeed)
    {
        MCC_SetFeedSpeed(dfXYZSpeed, g_nGroupIndex0);
        // group 0 sends this command to the first three axes
        CHECK(MCC_Line(x, y, z, 0, 0, 0, 0, 0, g_nGroupIndex0) >= 0);
        // the speed the middle three axes need
        dfDistance1 = u * u + v * v + w * w;
        dfUVWSpeed = dfXYZSpeed * sqrt(dfDistance1 / dfDistance0);
        MCC_SetFeedSpeed(dfUVWSpeed, g_nGroupIndex1);
        CHECK(MCC_Line(u, v, w, 0, 0, 0, 0, 0, g_nGroupIndex1) >= 0);
        // the speed the last two axes need
        dfDistance2 = a * a + b * b;
        dfABSpeed = dfXYZSpeed * sqrt(dfDistance2 / dfDistance0);
        MCC_SetFeedSpeed(dfABSpeed, g_nGroupIndex2);
        CHECK(MCC_Line(a, b, 0, 0, 0, 0, 0, 0, g_nGroupIndex2) >= 0);
    }
}

static void PartOneGroup()
{
    if (InitSys8() != NO_ERR)
        return;
    CHECK_EQ(MCC_SetAbsolute(g_nGroupIndex), NO_ERR);
    CHECK(MCC_EnableBlend(g_nGroupIndex) >= 0);
    MCC_SetFeedSpeed(10, g_nGroupIndex);
    CHECK(MCC_Line(10, 20, 30, 40, 50, 60, 70, 80, g_nGroupIndex) >= 0);
    MCC_TimeDelay(2000);
    double p[8];
    GetPos(g_nGroupIndex, p);
    printf("One group, 2 s in: X = %.3f, U = %.3f, B = %.3f\n", p[0], p[3], p[7]);
    CHECK(p[0] > 0 && p[0] <= 10);
    for (int i = 1; i < 8; i++)
        CHECK_NEAR(p[i], p[0] * (i + 1), (i + 1) * 0.002);   // all 8 on one straight line
    if (SteppedClock())
    {
        // 2 s (the line's 1999th period): 0.15 V + 1.699 V = 18.49 of 37.4166 UU.
        CHECK_NEAR(p[0], 10 * 18.49 / sqrt(1400.0), 0.01);
        CheckEndsIn(g_nGroupIndex, 1 + 4042 - 2000, "8-axis line");
    }
    WaitStop(g_nGroupIndex);
    double e[8] = {10, 20, 30, 40, 50, 60, 70, 80};
    CheckPos8(g_nGroupIndex, e);
    Close();
}

static void PartThreeGroups()
{
    CHECK_EQ(MCC_SetSysMaxSpeed(EX_MAX_SPEED), NO_ERR);
    SetMacParams();

    // Step 2: three groups.
    CHECK_EQ(MCC_CloseAllGroups(), NO_ERR);
    g_nGroupIndex0 = MCC_CreateGroup(0, 1, 2, -1, -1, -1, -1, -1, CARD_INDEX);
    CHECK_EQ(g_nGroupIndex0, 0);
    g_nGroupIndex1 = MCC_CreateGroup(3, 4, 5, -1, -1, -1, -1, -1, CARD_INDEX);
    CHECK_EQ(g_nGroupIndex1, 1);
    g_nGroupIndex2 = MCC_CreateGroup(6, 7, -1, -1, -1, -1, -1, -1, CARD_INDEX);
    CHECK_EQ(g_nGroupIndex2, 2);
    if (g_nGroupIndex0 < 0 || g_nGroupIndex1 < 0 || g_nGroupIndex2 < 0)
    {
        printf("Groups create error !\n\n");
        return;
    }
    if (StartSystem() != NO_ERR)
        return;

    const int g[3] = {g_nGroupIndex0, g_nGroupIndex1, g_nGroupIndex2};
    for (int i = 0; i < 3; i++)
        CHECK_EQ(MCC_SetIncrease((WORD)g[i]), NO_ERR);

    // Step 3: blending in every group.
    CHECK(MCC_EnableBlend(g_nGroupIndex0) >= 0);
    CHECK(MCC_EnableBlend(g_nGroupIndex1) >= 0);
    CHECK(MCC_EnableBlend(g_nGroupIndex2) >= 0);

    // Step 4: the two synchronised moves.
    fnSyncLine(10, 20, 30, 40, 50, 60, 70, 80, 10);
    fnSyncLine(40, 50, 60, 10, 20, 30, 70, 80, 10);

    const double dfTotal = 1 + 3742 + 9075 + STOP_AFTER_END_MS;   // GMS_STOP in period 12821
    if (SteppedClock())
    {
        // 2 s in (segment 1): the same fraction everywhere.
        MCC_TimeDelay(2000);
        double p0[8], p1[8], p2[8];
        GetPos(g[0], p0);
        GetPos(g[1], p1);
        GetPos(g[2], p2);
        printf("  [stepped clock] 2 s in: X = %.3f, U = %.3f, A = %.3f\n", p0[0], p1[0], p2[0]);
        CHECK(p0[0] > 0 && p0[0] < 10);
        CHECK_NEAR(p1[0] / 40, p0[0] / 10, 0.00025);
        CHECK_NEAR(p2[0] / 70, p0[0] / 10, 0.00025);
        CHECK_NEAR(p2[1] / 80, p0[0] / 10, 0.00025);
        // All three still moving shortly before the end, all stopped shortly after (each
        // status poll of a busy group may run one tick: room for three).
        long lBefore = (long)floor(dfTotal) - 2000 - TOL_MS - 3;
        MCC_TimeDelay((DWORD)lBefore);
        for (int i = 0; i < 3; i++)
            CHECK(MCC_GetMotionStatus((WORD)g[i]) != GMS_STOP);
        MCC_TimeDelay(2 * TOL_MS + 6);
        for (int i = 0; i < 3; i++)
            CHECK_EQ(MCC_GetMotionStatus((WORD)g[i]), GMS_STOP);
    }
    for (int i = 0; i < 3; i++)
        WaitStop(g[i]);
    CheckPosXYZ(g[0], 50, 70, 90);
    CheckPosXYZ(g[1], 50, 70, 90);
    CheckPosXYZ(g[2], 140, 160, 0);
    long l[8];
    CHECK_EQ(MCC_GetPulsePos(&l[0], &l[1], &l[2], &l[3], &l[4], &l[5], &l[6], &l[7], (WORD)g[2]), NO_ERR);
    CHECK_EQ(l[0], 70000);   // group 2's X is channel 6: 140 UU x 500
    CHECK_EQ(l[1], 80000);
    printf("Three groups: X/Y/Z (50, 70, 90), U/V/W (50, 70, 90), A/B (140, 160)\n");

    // Bad input: group 3 does not exist.
    CHECK_EQ(MCC_Line(1, 1, 1, 0, 0, 0, 0, 0, 3), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCC_EnableBlend(3), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCC_Line(NAN, 1, 1, 0, 0, 0, 0, 0, (WORD)g[1]), PARAMETER_ERR);
    Close();
}

int main()
{
    PartOneGroup();
    // Groups cannot be created for channels the card does not have.
    CHECK_EQ(MCC_CloseAllGroups(), NO_ERR);
    CHECK(MCC_CreateGroup(8, -1, -1, -1, -1, -1, -1, -1, CARD_INDEX) < 0);
    PartThreeGroups();
    return check_done("SyncLine");
}
