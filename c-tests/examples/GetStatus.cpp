// GetStatus.cpp: examples manual §6 (reading speeds, positions and command information):
// MCC_GetCurFeedSpeed, MCC_GetSpeed, MCC_GetCurPos, MCC_GetPulsePos, MCC_GetCurCommand,
// MCC_GetCommandCount.
//
// Three lines are queued at F = 20 UU/s (Ta = Td = 300 ms), each followed by its end
// period (one period of 1 ms) before the next starts:
//   A: (0,0) -> (600,800)   L = 1000: 50.3 s; direction (0.6, 0.8): X at 12, Y at 16 UU/s
//   B: (600,800) -> (0,800) L = 600:  30.3 s
//   C: (0,800) -> (0,0)     L = 800:  40.3 s
// One second into A (acceleration over after 0.3 s):
//   path speed 20 (MCC_GetCurFeedSpeed), axis speeds 12 and 16 (MCC_GetSpeed),
//   the running command is A (type 1 = line, index 0, feed 20, target (600,800)),
//   two commands wait (MCC_GetCommandCount does not count the running one),
//   the point is on the segment (0.8 X == 0.6 Y); on the stepped clock it has covered
//   F x Ta / 2 = 20 x 0.3 / 2 = 3 UU while accelerating, then 20 x 0.7 = 14 UU: 17 UU,
//   i.e. X = 10.2, Y = 13.6.
// Pulse positions: UU x GearRatio / Pitch x PPR = UU x 500 in whole pulses toward 0, and
// MCC_GetCurPos reads them back (pulses / 500), as the vendor's library does, e.g. after
// MCC_Line(1.2345, -2.5, 0.0007): 617 (1.234 UU), -1250, 0.
#include "MotionSys.h"

int main()
{
    if (InitSys8() != NO_ERR)
        return check_done("GetStatus");

    // Step 1: the manual's variables.
    double dfCurPosX, dfCurPosY, dfCurPosZ, dfCurPosU, dfCurPosV, dfCurPosW, dfCurPosA, dfCurPosB, dfCurSpeed;
    double dfCurSpeedX, dfCurSpeedY, dfCurSpeedZ, dfCurSpeedU, dfCurSpeedV, dfCurSpeedW, dfCurSpeedA, dfCurSpeedB;
    long lCurPulseX, lCurPulseY, lCurPulseZ, lCurPulseU, lCurPulseV, lCurPulseW, lCurPulseA, lCurPulseB;
    int nCount = -1;

    // At rest at the origin.
    CHECK(MCC_GetCurFeedSpeed(g_nGroupIndex) == 0.0);
    CHECK_EQ(MCC_GetSpeed(&dfCurSpeedX, &dfCurSpeedY, &dfCurSpeedZ, &dfCurSpeedU, &dfCurSpeedV, &dfCurSpeedW,
                          &dfCurSpeedA, &dfCurSpeedB, g_nGroupIndex), NO_ERR);
    CHECK(dfCurSpeedX == 0.0 && dfCurSpeedY == 0.0 && dfCurSpeedB == 0.0);
    CHECK_EQ(MCC_GetPulsePos(&lCurPulseX, &lCurPulseY, &lCurPulseZ, &lCurPulseU, &lCurPulseV, &lCurPulseW,
                             &lCurPulseA, &lCurPulseB, g_nGroupIndex), NO_ERR);
    CHECK(lCurPulseX == 0 && lCurPulseY == 0 && lCurPulseZ == 0 && lCurPulseB == 0);
    CHECK_EQ(MCC_GetCommandCount(&nCount, g_nGroupIndex), NO_ERR);
    CHECK_EQ(nCount, 0);

    CHECK_EQ(MCC_SetAbsolute(g_nGroupIndex), NO_ERR);
    MCC_SetFeedSpeed(20, g_nGroupIndex);
    CHECK(MCC_GetFeedSpeed(g_nGroupIndex) == 20.0);
    CHECK_EQ(MCC_ResetCommandIndex(g_nGroupIndex), NO_ERR);
    CHECK_EQ(MCC_Line(600, 800, 0, 0, 0, 0, 0, 0, g_nGroupIndex), 0);
    CHECK_EQ(MCC_Line(0, 800, 0, 0, 0, 0, 0, 0, g_nGroupIndex), 1);
    CHECK_EQ(MCC_Line(0, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex), 2);

    MCC_TimeDelay(1000);

    // Step 2: the path speed.
    dfCurSpeed = MCC_GetCurFeedSpeed(g_nGroupIndex);
    // Step 3: the axis speeds.
    CHECK_EQ(MCC_GetSpeed(&dfCurSpeedX, &dfCurSpeedY, &dfCurSpeedZ, &dfCurSpeedU, &dfCurSpeedV, &dfCurSpeedW,
                          &dfCurSpeedA, &dfCurSpeedB, g_nGroupIndex), NO_ERR);
    // Step 4: the position (UU).
    CHECK_EQ(MCC_GetCurPos(&dfCurPosX, &dfCurPosY, &dfCurPosZ, &dfCurPosU, &dfCurPosV, &dfCurPosW,
                           &dfCurPosA, &dfCurPosB, g_nGroupIndex), NO_ERR);
    printf("1 s into line A: path speed %.3f, X speed %.3f, Y speed %.3f, X = %.3f, Y = %.3f\n",
           dfCurSpeed, dfCurSpeedX, dfCurSpeedY, dfCurPosX, dfCurPosY);
    CHECK_NEAR(dfCurSpeed, 20, 1e-6);
    CHECK_NEAR(dfCurSpeedX, 12, 1e-6);
    CHECK_NEAR(dfCurSpeedY, 16, 1e-6);
    CHECK(dfCurSpeedZ == 0.0 && dfCurSpeedU == 0.0);
    CHECK(dfCurPosX > 0 && dfCurPosX < 600);
    CHECK_NEAR(0.8 * dfCurPosX, 0.6 * dfCurPosY, 1e-9);   // on the segment
    CHECK(dfCurPosZ == 0.0 && dfCurPosU == 0.0 && dfCurPosB == 0.0);
    if (SteppedClock())
    {
        CHECK_NEAR(dfCurPosX, 17 * 0.6, 0.03);
        CHECK_NEAR(dfCurPosY, 17 * 0.8, 0.03);
    }
    (void)dfCurPosV; (void)dfCurPosW; (void)dfCurPosA;
    (void)dfCurSpeedV; (void)dfCurSpeedW; (void)dfCurSpeedA; (void)dfCurSpeedB;

    // Step 5 comes at rest below; now the command information.
    COMMAND_INFO stInfo;
    memset(&stInfo, 0, sizeof(stInfo));
    CHECK_EQ(MCC_GetCurCommand(&stInfo, g_nGroupIndex), NO_ERR);
    printf("Current command: type %d, index %d, feed %.3f, target (%.3f, %.3f)\n",
           stInfo.nType, stInfo.nCommandIndex, stInfo.dfFeedSpeed, stInfo.dfPos[0], stInfo.dfPos[1]);
    CHECK_EQ(stInfo.nType, 1);            // linear motion (user manual §2.6.5)
    CHECK_EQ(stInfo.nCommandIndex, 0);
    CHECK(stInfo.dfFeedSpeed == 20.0);
    CHECK_NEAR(stInfo.dfPos[0], 600, POS_TOL);
    CHECK_NEAR(stInfo.dfPos[1], 800, POS_TOL);
    CHECK_NEAR(stInfo.dfPos[2], 0, POS_TOL);
    CHECK_EQ(MCC_GetCommandCount(&nCount, g_nGroupIndex), NO_ERR);
    CHECK_EQ(nCount, 2);                  // B and C wait; A runs

    // On the stepped clock: A's last period ends at 50.3 s, B runs from 50.302 s to
    // 80.601 s, C from 80.603 s to 120.902 s.
    if (SteppedClock())
    {
        MCC_TimeDelay(50300);                 // now 1000 ms + 50300 ms: 1 s into B
        CHECK_EQ(MCC_GetCurCommand(&stInfo, g_nGroupIndex), NO_ERR);
        CHECK_EQ(stInfo.nCommandIndex, 1);
        CHECK_NEAR(stInfo.dfPos[0], 0, POS_TOL);
        CHECK_NEAR(stInfo.dfPos[1], 800, POS_TOL);
        CHECK_EQ(MCC_GetCommandCount(&nCount, g_nGroupIndex), NO_ERR);
        CHECK_EQ(nCount, 1);
    }
    WaitStop(g_nGroupIndex);
    CheckPosXYZ(g_nGroupIndex, 0, 0, 0);
    CHECK_EQ(MCC_GetCommandCount(&nCount, g_nGroupIndex), NO_ERR);
    CHECK_EQ(nCount, 0);
    CHECK(MCC_GetCurFeedSpeed(g_nGroupIndex) == 0.0);

    // Step 5: pulse positions = UU x 500 in whole pulses toward 0.
    CHECK(MCC_Line(1.2345, -2.5, 0.0007, 3, 0, 0, 0, -0.0031, g_nGroupIndex) >= 0);
    WaitStop(g_nGroupIndex);
    CHECK_EQ(MCC_GetCurPos(&dfCurPosX, &dfCurPosY, &dfCurPosZ, &dfCurPosU, &dfCurPosV, &dfCurPosW,
                           &dfCurPosA, &dfCurPosB, g_nGroupIndex), NO_ERR);
    CHECK_EQ(MCC_GetPulsePos(&lCurPulseX, &lCurPulseY, &lCurPulseZ, &lCurPulseU, &lCurPulseV, &lCurPulseW,
                             &lCurPulseA, &lCurPulseB, g_nGroupIndex), NO_ERR);
    printf("At (%.4f, %.4f, %.4f, U %.4f, B %.4f): pulses %ld, %ld, %ld, U %ld, B %ld\n",
           dfCurPosX, dfCurPosY, dfCurPosZ, dfCurPosU, dfCurPosB,
           lCurPulseX, lCurPulseY, lCurPulseZ, lCurPulseU, lCurPulseB);
    CHECK_NEAR(dfCurPosX, 1.234, POS_TOL);    // 617 pulses / 500
    CHECK_NEAR(dfCurPosB, -0.002, POS_TOL);   // -1 pulse / 500
    CHECK_EQ(lCurPulseX, 617);                // 617.25 toward 0
    CHECK_EQ(lCurPulseY, -1250);
    CHECK_EQ(lCurPulseZ, 0);                  // 0.35 toward 0
    CHECK_EQ(lCurPulseU, 1500);
    CHECK_EQ(lCurPulseV, 0);
    CHECK_EQ(lCurPulseB, -1);                 // -1.55 toward 0

    // Bad input.
    CHECK_EQ(MCC_GetCurPos(&dfCurPosX, &dfCurPosY, &dfCurPosZ, &dfCurPosU, &dfCurPosV, &dfCurPosW,
                           &dfCurPosA, &dfCurPosB, BAD_GROUP), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCC_GetCurPos(NULL, &dfCurPosY, &dfCurPosZ, &dfCurPosU, &dfCurPosV, &dfCurPosW,
                           &dfCurPosA, &dfCurPosB, g_nGroupIndex), PARAMETER_ERR);
    CHECK_EQ(MCC_GetPulsePos(&lCurPulseX, &lCurPulseY, &lCurPulseZ, &lCurPulseU, &lCurPulseV, &lCurPulseW,
                             &lCurPulseA, &lCurPulseB, BAD_GROUP), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCC_GetPulsePos(&lCurPulseX, NULL, &lCurPulseZ, &lCurPulseU, &lCurPulseV, &lCurPulseW,
                             &lCurPulseA, &lCurPulseB, g_nGroupIndex), PARAMETER_ERR);
    CHECK_EQ(MCC_GetSpeed(&dfCurSpeedX, &dfCurSpeedY, &dfCurSpeedZ, &dfCurSpeedU, &dfCurSpeedV, &dfCurSpeedW,
                          &dfCurSpeedA, &dfCurSpeedB, BAD_GROUP), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCC_GetCurCommand(NULL, g_nGroupIndex), PARAMETER_ERR);
    CHECK_EQ(MCC_GetCurCommand(&stInfo, BAD_GROUP), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCC_GetCommandCount(NULL, g_nGroupIndex), PARAMETER_ERR);
    CHECK_EQ(MCC_GetCommandCount(&nCount, BAD_GROUP), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCC_ResetCommandIndex(BAD_GROUP), GROUP_PARAMETER_ERR);

    Close();
    return check_done("GetStatus");
}
