// Helical.cpp: examples manual §11 (helical motion with the circle in the X-Y plane):
// MCC_HelicalXY_Z(5, 5, 2, 360) from the current position.
//
// Conventions (docs/decisions.md, "Motion conventions"): the third argument is the
// pitch (Z travel per full turn), Z moves pitch x theta / 360 in total, theta > 0 is
// counter-clockwise seen from +Z.
//   Start (10, 5, 0): radius 5 about (5, 5), angle 0.
//   MCC_HelicalXY_Z(5, 5, 2, 360): one CCW turn, Z + 2 -> ends at (10, 5, 2).
//     Path length counts X, Y and Z: sqrt((2 pi 5)^2 + 2^2) = 31.4795 UU;
//     at F = 10: 3.14795 + 0.3 s = 3447.9 ms.
//     At every instant Z = 2 x (angle turned) / 360 deg.
//   MCC_HelicalXY_Z(5, 5, 2, -180): half a turn clockwise, Z - 1 -> ends at (0, 5, 1).
// Command types (user manual §2.6.5): 5 = counter-clockwise helix, 4 = clockwise helix.
#include "MotionSys.h"

#define PI 3.14159265358979323846

int main()
{
    if (InitSys8() != NO_ERR)
        return check_done("Helical");

    CHECK_EQ(MCC_SetAbsolute(g_nGroupIndex), NO_ERR);
    MCC_SetFeedSpeed(10, g_nGroupIndex);
    CHECK(MCC_Line(10, 5, 0, 0, 0, 0, 0, 0, g_nGroupIndex) >= 0);
    WaitStop(g_nGroupIndex);
    CheckPosXYZ(g_nGroupIndex, 10, 5, 0);

    // The manual's call.
    int nRet = MCC_HelicalXY_Z(5, 5,   // centre of the circle in X-Y
                               2,      // Z travel per turn
                               360,    // angle
                               g_nGroupIndex);
    printf("MCC_HelicalXY_Z(5, 5, 2, 360) from (10, 5, 0): returned %d\n", nRet);
    CHECK(nRet >= 0);
    CHECK(MCC_GetMotionStatus(g_nGroupIndex) != GMS_STOP);
    if (SteppedClock())
    {
        // Samples every 500 ms: on the cylinder, CCW, Z proportional to the angle. The
        // last sample (3 s: 1.5 + 10 x 2.7 = 28.5 of 31.48 UU) is still short of a turn.
        double p[8], dfPrevAngle = 0;
        for (int i = 1; i <= 6; i++)
        {
            MCC_TimeDelay(500);
            GetPos(g_nGroupIndex, p);
            double dfAngle = atan2(p[1] - 5, p[0] - 5);
            if (dfAngle < -1e-12) dfAngle += 2 * PI;
            printf("  t = %4d ms: X = %.3f, Y = %.3f, Z = %.3f, angle %.1f deg\n",
                   i * 500, p[0], p[1], p[2], dfAngle * 180 / PI);
            CHECK_NEAR(hypot(p[0] - 5, p[1] - 5), 5.0, 1e-9);
            CHECK(dfAngle > dfPrevAngle);                       // counter-clockwise
            CHECK_NEAR(p[2], 2 * dfAngle / (2 * PI), 1e-9);     // Z = pitch x theta / 360
            dfPrevAngle = dfAngle;
            if (i == 2)
            {
                COMMAND_INFO stInfo;
                CHECK_EQ(MCC_GetCurCommand(&stInfo, g_nGroupIndex), NO_ERR);
                CHECK_EQ(stInfo.nType, 5);
                CHECK(stInfo.dfFeedSpeed == 10.0);
                CHECK_NEAR(stInfo.dfPos[2], 2, POS_TOL);
                // 1000 ms: 1.5 + 10 x 0.7 = 8.5 UU along a 31.4795 UU helix.
                CHECK_NEAR(dfAngle, 2 * PI * 8.5 / sqrt(pow(10 * PI, 2) + 4), 0.005);
            }
        }
        CheckEndsIn(g_nGroupIndex, 1000 * sqrt(pow(10 * PI, 2) + 4) / 10 + 300 - 3000, "helix 360 deg");
    }
    WaitStop(g_nGroupIndex);
    PrintPos(g_nGroupIndex, "After the helix");
    CheckPosXYZ(g_nGroupIndex, 10, 5, 2);

    // Half a turn clockwise, Z back by 1.
    CHECK(MCC_HelicalXY_Z(5, 5, 2, -180, g_nGroupIndex) >= 0);
    if (SteppedClock())
    {
        MCC_TimeDelay(800);
        double p[8];
        GetPos(g_nGroupIndex, p);
        CHECK(p[1] < 5);                                   // clockwise from angle 0 goes down
        CHECK_NEAR(hypot(p[0] - 5, p[1] - 5), 5.0, 1e-9);
        double dfTurned = -atan2(p[1] - 5, p[0] - 5);      // radians turned clockwise
        CHECK_NEAR(p[2], 2 - 2 * dfTurned / (2 * PI), 1e-9);
        COMMAND_INFO stInfo;
        CHECK_EQ(MCC_GetCurCommand(&stInfo, g_nGroupIndex), NO_ERR);
        CHECK_EQ(stInfo.nType, 4);
    }
    WaitStop(g_nGroupIndex);
    PrintPos(g_nGroupIndex, "After the half turn back");
    CheckPosXYZ(g_nGroupIndex, 0, 5, 1);

    // Bad input.
    CHECK_EQ(MCC_HelicalXY_Z(NAN, 5, 2, 360, g_nGroupIndex), PARAMETER_ERR);
    CHECK_EQ(MCC_HelicalXY_Z(5, 5, INFINITY, 360, g_nGroupIndex), PARAMETER_ERR);
    CHECK_EQ(MCC_HelicalXY_Z(5, 5, 2, NAN, g_nGroupIndex), PARAMETER_ERR);
    CHECK_EQ(MCC_HelicalXY_Z(0, 5, 2, 360, g_nGroupIndex), PARAMETER_ERR);   // centre = current point
    CHECK_EQ(MCC_HelicalXY_Z(5, 5, 2, 360, BAD_GROUP), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCC_GetMotionStatus(g_nGroupIndex), GMS_STOP);
    CheckPosXYZ(g_nGroupIndex, 0, 5, 1);

    Close();
    return check_done("Helical");
}
