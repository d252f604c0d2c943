// GeneralMotion.cpp: examples manual §10 (line, arc and circle: "general motion"),
// written the way the manual writes it, printing each command and where the axes are
// after it.
//
//   MCC_SetAbsolute(); MCC_SetFeedSpeed(10);
//   MCC_Line(10, 10, ...)       (0,0)   -> (10,10)   straight, L = 10*sqrt(2) = 14.1421
//   MCC_ArcXY(10, 20, 20, 20)   (10,10) -> (20,20)   through the reference point (10,20):
//                               circle centre (15,15), radius sqrt(50) = 7.0711; the start
//                               (225 deg), reference (135 deg) and end (45 deg) go clockwise,
//                               half a circle, L = pi*sqrt(50) = 22.2144
//   MCC_CircleXY(25, 20, CIR_CW) (20,20) -> (20,20)  full circle about (25,20), r = 5,
//                               L = 10*pi = 31.4159; clockwise from the left point = upwards
//
// The manual writes MCC_Line(10, 10, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex): nine numbers and
// the group, which would pass 0 as wGroupIndex and g_nGroupIndex (0) as dwAxisMask (no
// axis). Eight positions and the group are written here, as the prototype means. Its
// MCC_ArcXY(10, 20, 20, g_nGroupIndex) lost one number in the PDF; the figure's arc ends
// at (20, 20), where the circle about (25, 20) starts.
//
// Durations (each command alone, F = 10 UU/s, Ta = Td = 300 ms, 1 ms periods: 300 +
// ceil(L/F/T - 300) + 300 periods, so L/F + 0.3 s rounded up to a whole ms, at a speed V
// = L/(0.3 s + nc T) a little under F):
//   line 1715 ms (V = 9.9944), arc 2522 ms (V = 9.9975), circle 3442 ms (V = 9.9987);
//   GMS_STOP reads three periods after each (MotionSys.h).
// Positions read whole pulses toward 0 (500 per UU): the points sampled on the arcs are
// within sqrt(2)/500 UU of their circle.
#include "MotionSys.h"

#define PI 3.14159265358979323846

int main()
{
    int nRet;
    if (InitSys8() != NO_ERR)
        return check_done("GeneralMotion");

    printf("GeneralMotion: examples manual section 10 on the virtual card (group %d)\n", g_nGroupIndex);
    PrintPos(g_nGroupIndex, "At start");
    CheckPosXYZ(g_nGroupIndex, 0, 0, 0);

    // Step 1: absolute coordinates and the feed speed.
    CHECK_EQ(MCC_SetAbsolute(g_nGroupIndex), NO_ERR);
    MCC_SetFeedSpeed(10, g_nGroupIndex);
    CHECK(MCC_GetFeedSpeed(g_nGroupIndex) == 10.0);
    printf("MCC_SetAbsolute, MCC_SetFeedSpeed(10): feed speed %.3f UU/s\n", MCC_GetFeedSpeed(g_nGroupIndex));
    CHECK_EQ(MCC_ResetCommandIndex(g_nGroupIndex), NO_ERR);

    // Step 2: a straight line to (10, 10).
    nRet = MCC_Line(10, 10, 0, 0, 0, 0, 0, 0, g_nGroupIndex);
    printf("MCC_Line(10, 10, 0, ...): returned command index %d\n", nRet);
    CHECK_EQ(nRet, 0);                                    // first command after the reset
    CHECK(MCC_GetMotionStatus(g_nGroupIndex) != GMS_STOP); // queued: no longer stopped
    CheckEndsIn(g_nGroupIndex, 1715, "line");
    WaitStop(g_nGroupIndex);
    PrintPos(g_nGroupIndex, "After the line");
    CheckPosXYZ(g_nGroupIndex, 10, 10, 0);

    // Step 3: an arc through the reference point (10, 20) to (20, 20). First a bad one:
    // start (10,10), reference (15,15) and end (20,20) lie on one line. The vendor's
    // library queues it (its index) and finds the fault when it starts: user manual
    // §2.6.3 VI, the error is recorded (0xF104), the group stops, its queue is dropped
    // and every motion command is refused (RUN_TIME_ERR) until MCC_ClearError.
    nRet = MCC_ArcXY(15, 15, 20, 20, g_nGroupIndex);
    printf("MCC_ArcXY(15, 15, 20, 20) with three points on one line: returned %d\n", nRet);
    CHECK_EQ(nRet, 1);
    MCC_TimeDelay(1);
    printf("MCC_GetErrorCode: 0x%X (bad arc); MCC_ClearError\n", MCC_GetErrorCode(g_nGroupIndex));
    CHECK_EQ(MCC_GetErrorCode(g_nGroupIndex), 0xF104);
    CHECK_EQ(MCC_ArcXY(10, 20, 20, 20, g_nGroupIndex), RUN_TIME_ERR);
    CHECK_EQ(MCC_ClearError(g_nGroupIndex), NO_ERR);
    CHECK_EQ(MCC_GetErrorCode(g_nGroupIndex), 0);
    CheckPosXYZ(g_nGroupIndex, 10, 10, 0);   // the bad arc did not move
    nRet = MCC_ArcXY(10, 20, 20, 20, g_nGroupIndex);
    printf("MCC_ArcXY(10, 20, 20, 20): returned command index %d\n", nRet);
    CHECK_EQ(nRet, 2);   // the refused call took no index
    if (SteppedClock())
    {
        // Sample the arc: every point is on the circle about (15,15), on the clockwise
        // side through (10,20) (y >= x), and at 1300 ms the arc length covered is
        // 0.15 V (acceleration) + V x 1.0 = 11.497 UU = 11.497/sqrt(50) rad past 225 deg.
        double p[8];
        for (int i = 0; i < 4; i++)
        {
            MCC_TimeDelay(i == 0 ? 1300 : 300);
            GetPos(g_nGroupIndex, p);
            CHECK_NEAR(hypot(p[0] - 15, p[1] - 15), sqrt(50.0), 0.003);
            CHECK(p[1] - p[0] >= -0.003);
            if (i == 0)
            {
                double dfAngle = 225.0 * PI / 180 - 11.497 / sqrt(50.0);
                CHECK_NEAR(p[0], 15 + sqrt(50.0) * cos(dfAngle), 0.03);
                CHECK_NEAR(p[1], 15 + sqrt(50.0) * sin(dfAngle), 0.03);
                COMMAND_INFO stInfo;
                CHECK_EQ(MCC_GetCurCommand(&stInfo, g_nGroupIndex), NO_ERR);
                // An arc through a point reads type 3 whichever way it turns, as the
                // vendor's library reports it (scenario arc_xy_cw; user manual §2.6.5
                // has 2 for a clockwise one).
                CHECK_EQ(stInfo.nType, 3);
                CHECK_EQ(stInfo.nCommandIndex, 2);
                CHECK(stInfo.dfFeedSpeed == 10.0);
                CHECK_NEAR(stInfo.dfPos[0], 20, POS_TOL);
                CHECK_NEAR(stInfo.dfPos[1], 20, POS_TOL);
            }
            printf("  during the arc: X = %.3f, Y = %.3f (distance to (15,15) = %.3f)\n",
                   p[0], p[1], hypot(p[0] - 15, p[1] - 15));
        }
    }
    WaitStop(g_nGroupIndex);
    PrintPos(g_nGroupIndex, "After the arc");
    CheckPosXYZ(g_nGroupIndex, 20, 20, 0);

    // Step 4: a full clockwise circle about (25, 20) (CIR_CW; any other direction byte
    // is counter-clockwise, as the vendor's library takes it).
    nRet = MCC_CircleXY(25, NAN, CIR_CW, g_nGroupIndex);
    CHECK_EQ(nRet, PARAMETER_ERR);
    CHECK_EQ(MCC_GetErrorCode(g_nGroupIndex), 0);        // argument errors record nothing
    // Centre on the start point: no circle; it fails when it starts (0xF104), as a bad
    // arc does.
    nRet = MCC_CircleXY(20, 20, CIR_CW, g_nGroupIndex);
    CHECK_EQ(nRet, 3);
    MCC_TimeDelay(1);
    CHECK_EQ(MCC_GetErrorCode(g_nGroupIndex), 0xF104);
    CHECK_EQ(MCC_ClearError(g_nGroupIndex), NO_ERR);
    CheckPosXYZ(g_nGroupIndex, 20, 20, 0);
    nRet = MCC_CircleXY(25, 20, CIR_CW, g_nGroupIndex);
    printf("MCC_CircleXY(25, 20, CIR_CW): returned command index %d\n", nRet);
    CHECK_EQ(nRet, 4);
    if (SteppedClock())
    {
        // 800 ms in: 0.15 V + 0.5 V = 6.499 UU = 1.2998 rad clockwise from the left
        // point (180 deg): clockwise from there goes up, so Y > 20.
        MCC_TimeDelay(800);
        double p[8];
        GetPos(g_nGroupIndex, p);
        printf("  during the circle: X = %.3f, Y = %.3f\n", p[0], p[1]);
        CHECK_NEAR(hypot(p[0] - 25, p[1] - 20), 5.0, 0.003);
        CHECK(p[1] > 20);
        CHECK_NEAR(p[0], 25 + 5 * cos(PI - 1.2998), 0.03);
        CHECK_NEAR(p[1], 20 + 5 * sin(PI - 1.2998), 0.03);
        CheckEndsIn(g_nGroupIndex, 3442 - 800, "circle");
    }
    WaitStop(g_nGroupIndex);
    PrintPos(g_nGroupIndex, "After the circle");
    CheckPosXYZ(g_nGroupIndex, 20, 20, 0);

    // The pulse position follows: 20 UU x 500 pulses/UU = 10000 pulses.
    long lX, lY, lZ, lU, lV, lW, lA, lB;
    CHECK_EQ(MCC_GetPulsePos(&lX, &lY, &lZ, &lU, &lV, &lW, &lA, &lB, g_nGroupIndex), NO_ERR);
    printf("Pulse position: X = %ld, Y = %ld, Z = %ld\n", lX, lY, lZ);
    CHECK_EQ(lX, 10000);
    CHECK_EQ(lY, 10000);
    CHECK_EQ(lZ, 0);

    // The three commands queued at once run one after the other (manual §10: the queue).
    printf("Queue all three again from (0,0): line, arc, circle\n");
    CHECK(MCC_Line(0, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex) >= 0);
    WaitStop(g_nGroupIndex);
    CHECK_EQ(MCC_ResetCommandIndex(g_nGroupIndex), NO_ERR);
    CHECK_EQ(MCC_Line(10, 10, 0, 0, 0, 0, 0, 0, g_nGroupIndex), 0);
    CHECK_EQ(MCC_ArcXY(10, 20, 20, 20, g_nGroupIndex), 1);
    CHECK_EQ(MCC_CircleXY(25, 20, CIR_CW, g_nGroupIndex), 2);
    int nCount = -1;
    CHECK_EQ(MCC_GetCommandCount(&nCount, g_nGroupIndex), NO_ERR);
    CHECK(nCount >= 2 && nCount <= 3);   // 3 queued, or 2 once the line has started
    // One after the other, each with its end period: 1715 + 1 + 2522 + 1 + 3442 ms.
    CheckEndsIn(g_nGroupIndex, 1715 + 1 + 2522 + 1 + 3442, "line + arc + circle");
    WaitStop(g_nGroupIndex);
    PrintPos(g_nGroupIndex, "After line, arc and circle");
    CheckPosXYZ(g_nGroupIndex, 20, 20, 0);

    // Bad input: nothing is queued, nothing moves.
    CHECK_EQ(MCC_Line(NAN, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex), PARAMETER_ERR);
    CHECK_EQ(MCC_Line(0, INFINITY, 0, 0, 0, 0, 0, 0, g_nGroupIndex), PARAMETER_ERR);
    CHECK_EQ(MCC_Line(1, 1, 0, 0, 0, 0, 0, 0, BAD_GROUP), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCC_Line(1, 1, 0, 0, 0, 0, 0, 0, 1), GROUP_PARAMETER_ERR);   // group 1 not created
    CHECK_EQ(MCC_ArcXY(NAN, 20, 20, 20, g_nGroupIndex), PARAMETER_ERR);
    CHECK_EQ(MCC_ArcXY(10, 20, 20, 20, BAD_GROUP), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCC_CircleXY(25, NAN, CIR_CW, g_nGroupIndex), PARAMETER_ERR);
    CHECK_EQ(MCC_CircleXY(25, 20, CIR_CW, BAD_GROUP), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCC_SetAbsolute(BAD_GROUP), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCC_GetCurPos(NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, g_nGroupIndex), PARAMETER_ERR);
    CHECK_EQ(MCC_GetMotionStatus(g_nGroupIndex), GMS_STOP);
    CheckPosXYZ(g_nGroupIndex, 20, 20, 0);

    Close();
    // After MCC_CloseSystem motion functions need a running system again.
    CHECK_EQ(MCC_Line(1, 1, 0, 0, 0, 0, 0, 0, 0), INITIAL_MOTION_ERR);
    return check_done("GeneralMotion");
}
