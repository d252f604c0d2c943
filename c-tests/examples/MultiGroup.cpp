// MultiGroup.cpp: examples manual §24 (several groups): MCC_CloseAllGroups before the
// first MCC_CreateGroup, then four groups of two axes on channels (0,1), (2,3), (4,5),
// (6,7) of card 0. Each group has its own queue, so their commands run at the same time
// and independently.
//
// Expected numbers (Ta = Td = 300 ms, all commands queued at the same moment; periods of
// 1 ms; GMS_STOP three periods after a line's last, four after a PtP's):
//   group 0: Line (10, 0) at 10 UU/s:        300 + 700 + 300 = 1300 ms, STOP at 1303
//   group 1: Line (0, 20) at 20 UU/s:        300 + 700 + 300 = 1300 ms, STOP at 1303
//   group 2: Line (-5, -5) at 5 UU/s:        300 + ceil(1414.2 - 300) + 300 = 1715 ms at
//                                            V = 7.0711/1.415 = 4.9972 UU/s
//   group 3: PtP (10, 20) at 20 % = 10 UU/s, on the group's ramps: Y 2300 ms, STOP at 2304
//   Holding group 2 does not stop the others: it stops from V over floor(300 V/5) + 1 =
//   300 periods and reads GMS_HOLD three periods later (GMS_RUNNING until then).
//   Each group numbers its commands from 0.
//   Group g's X is channel 2g: group 1 at (0, 20) reports pulses (0, 10000).
#include "MotionSys.h"

int g_nGroupIndex0 = -1;
int g_nGroupIndex1 = -1;
int g_nGroupIndex2 = -1;
int g_nGroupIndex3 = -1;

int main()
{
    CHECK_EQ(MCC_SetSysMaxSpeed(EX_MAX_SPEED), NO_ERR);
    SetMacParams();

    MCC_CloseAllGroups();
    g_nGroupIndex0 = MCC_CreateGroup(0, 1, -1, -1, -1, -1, -1, -1, CARD_INDEX);
    g_nGroupIndex1 = MCC_CreateGroup(2, 3, -1, -1, -1, -1, -1, -1, CARD_INDEX);
    g_nGroupIndex2 = MCC_CreateGroup(4, 5, -1, -1, -1, -1, -1, -1, CARD_INDEX);
    g_nGroupIndex3 = MCC_CreateGroup(6, 7, -1, -1, -1, -1, -1, -1, CARD_INDEX);
    CHECK_EQ(g_nGroupIndex0, 0);
    CHECK_EQ(g_nGroupIndex1, 1);
    CHECK_EQ(g_nGroupIndex2, 2);
    CHECK_EQ(g_nGroupIndex3, 3);
    if (StartSystem() != NO_ERR)
        return check_done("MultiGroup");
    const int g[4] = {g_nGroupIndex0, g_nGroupIndex1, g_nGroupIndex2, g_nGroupIndex3};
    g_nGroupIndex = g_nGroupIndex0;

    for (int i = 0; i < 4; i++)
    {
        CHECK_EQ(MCC_SetAbsolute((WORD)g[i]), NO_ERR);
        CHECK_EQ(MCC_ResetCommandIndex((WORD)g[i]), NO_ERR);
        CHECK_EQ(MCC_GetMotionStatus((WORD)g[i]), GMS_STOP);
    }
    MCC_SetFeedSpeed(10, g_nGroupIndex0);
    MCC_SetFeedSpeed(20, g_nGroupIndex1);
    MCC_SetFeedSpeed(5, g_nGroupIndex2);
    MCC_SetPtPSpeed(20, g_nGroupIndex3);
    CHECK(MCC_GetFeedSpeed(g_nGroupIndex0) == 10.0 && MCC_GetFeedSpeed(g_nGroupIndex1) == 20.0);

    // Every group's first command is its index 0.
    CHECK_EQ(MCC_Line(10, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex0), 0);
    CHECK_EQ(MCC_Line(0, 20, 0, 0, 0, 0, 0, 0, g_nGroupIndex1), 0);
    CHECK_EQ(MCC_Line(-5, -5, 0, 0, 0, 0, 0, 0, g_nGroupIndex2), 0);
    CHECK_EQ(MCC_PtP(10, 20, 0, 0, 0, 0, 0, 0, g_nGroupIndex3), 0);
    for (int i = 0; i < 4; i++)
        CHECK(MCC_GetMotionStatus((WORD)g[i]) != GMS_STOP);

    if (SteppedClock())
    {
        // 1303 ms: groups 0 and 1 read STOP, 2 and 3 still move. (Each status poll of a
        // busy group may run one tick, so the brackets leave room for them.)
        MCC_TimeDelay(1303 - TOL_MS - 2);
        CHECK(MCC_GetMotionStatus((WORD)g[0]) != GMS_STOP);
        CHECK(MCC_GetMotionStatus((WORD)g[1]) != GMS_STOP);
        MCC_TimeDelay(2 * TOL_MS + 2);   // about 1305..1307 ms
        CHECK_EQ(MCC_GetMotionStatus((WORD)g[0]), GMS_STOP);
        CHECK_EQ(MCC_GetMotionStatus((WORD)g[1]), GMS_STOP);
        CHECK_EQ(MCC_GetMotionStatus((WORD)g[2]), GMS_RUNNING);
        CHECK_EQ(MCC_GetMotionStatus((WORD)g[3]), GMS_RUNNING);
        // Hold group 2 at ~1.31 s (GMS_HOLD from ~1.613 s); group 3 goes on, STOP at
        // 2304 ms.
        CHECK_EQ(MCC_HoldMotion((WORD)g[2]), NO_ERR);
        MCC_TimeDelay(2300 - 1310 - TOL_MS);
        CHECK_EQ(MCC_GetMotionStatus((WORD)g[2]), GMS_HOLD);
        CHECK(MCC_GetMotionStatus((WORD)g[3]) != GMS_STOP);
        MCC_TimeDelay(2 * TOL_MS + 10);
        CHECK_EQ(MCC_GetMotionStatus((WORD)g[3]), GMS_STOP);
        CHECK_EQ(MCC_GetMotionStatus((WORD)g[2]), GMS_HOLD);
        CHECK_EQ(MCC_ContiMotion((WORD)g[2]), NO_ERR);
    }
    else
    {
        // Any clock: holding group 2 leaves group 3 alone. (Its 1.7 s line, held 0.5 s
        // in, once it runs: a hold with nothing running yet changes nothing, as in the
        // vendor's library. It ramps down and reads GMS_HOLD; a poll on the fast clock
        // may run it out.)
        MCC_TimeDelay(500);
        CHECK_EQ(MCC_HoldMotion((WORD)g[2]), NO_ERR);
        int nStatus = MCC_GetMotionStatus((WORD)g[2]);
        CHECK(nStatus == GMS_RUNNING || nStatus == GMS_HOLD);
        WaitStop(g[3]);   // 2.3 s: long past group 2's ramp
        CHECK_EQ(MCC_GetMotionStatus((WORD)g[2]), GMS_HOLD);
        CHECK_EQ(MCC_ContiMotion((WORD)g[2]), NO_ERR);
    }
    for (int i = 0; i < 4; i++)
        WaitStop(g[i]);

    CheckPosXYZ(g_nGroupIndex0, 10, 0, 0);
    CheckPosXYZ(g_nGroupIndex1, 0, 20, 0);
    CheckPosXYZ(g_nGroupIndex2, -5, -5, 0);
    CheckPosXYZ(g_nGroupIndex3, 10, 20, 0);
    for (int i = 0; i < 4; i++)
    {
        char what[64];
        snprintf(what, sizeof(what), "Group %d (channels %d, %d)", g[i], 2 * i, 2 * i + 1);
        PrintPos(g[i], what);
    }
    long l[8];
    CHECK_EQ(MCC_GetPulsePos(&l[0], &l[1], &l[2], &l[3], &l[4], &l[5], &l[6], &l[7], (WORD)g[1]), NO_ERR);
    CHECK_EQ(l[0], 0);
    CHECK_EQ(l[1], 10000);
    CHECK_EQ(MCC_GetPulsePos(&l[0], &l[1], &l[2], &l[3], &l[4], &l[5], &l[6], &l[7], (WORD)g[2]), NO_ERR);
    CHECK_EQ(l[0], -2500);
    CHECK_EQ(l[1], -2500);

    // The next command of each group is its index 1.
    CHECK_EQ(MCC_Line(0, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex1), 1);
    CHECK_EQ(MCC_GetMotionStatus(g_nGroupIndex0), GMS_STOP);
    WaitStop(g_nGroupIndex1);
    CheckPosXYZ(g_nGroupIndex1, 0, 0, 0);
    CheckPosXYZ(g_nGroupIndex0, 10, 0, 0);

    // Bad input: only groups 0..3 exist.
    CHECK_EQ(MCC_Line(1, 1, 0, 0, 0, 0, 0, 0, 4), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCC_GetMotionStatus(4), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCC_HoldMotion(4), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCC_PtP(1, 1, 0, 0, 0, 0, 0, 0, BAD_GROUP), GROUP_PARAMETER_ERR);
    // A channel belongs to one group only (channels 0 and 1 are group 0's).
    CHECK_EQ(MCC_CreateGroup(0, 1, -1, -1, -1, -1, -1, -1, CARD_INDEX), PARAMETER_ERR);

    Close();
    return check_done("MultiGroup");
}
