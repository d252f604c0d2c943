// Helical.cpp: examples manual §11 (helical motion with the circle in the X-Y plane):
// MCC_HelicalXY_Z(5, 5, 2, 360) from the current position.
//
// Conventions, as the vendor's library moves a helix (docs/decisions.md): the third
// argument is the pitch (Z travel per full turn), Z moves pitch x |theta| / 360 in total
// (the rise follows the pitch's sign whichever way it turns), theta > 0 is
// counter-clockwise seen from +Z; the path's length, which the feed runs along, is the
// arc in the X-Y plane.
//   Start (10, 5, 0): radius 5 about (5, 5), angle 0.
//   MCC_HelicalXY_Z(5, 5, 2, 360): one CCW turn, Z + 2 -> ends at (10, 5, 2).
//     Length 2 pi 5 = 31.4159 UU; at F = 10 with 300 ms ramps: 300 + ceil(3141.59 -
//     300) + 300 = 3442 periods of 1 ms at V = 31.4159/3.142 = 9.9987 UU/s.
//     At every instant Z = 2 x (angle turned) / 360 deg.
//   MCC_HelicalXY_Z(5, 5, 2, -180): half a turn clockwise, Z + 1 -> ends at (0, 5, 3);
//     length 15.708 UU: 300 + 1271 + 300 = 1871 periods at V = 9.9987 UU/s.
// Positions read whole pulses toward 0 (500 per UU): samples are within 0.003 UU of the
// cylinder and of the height their angle gives.
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
        // last sample (3 s: 0.15 V + 2.7 V = 28.5 of 31.42 UU) is still short of a turn.
        double p[8], dfPrevAngle = 0;
        for (int i = 1; i <= 6; i++)
        {
            MCC_TimeDelay(500);
            GetPos(g_nGroupIndex, p);
            double dfAngle = atan2(p[1] - 5, p[0] - 5);
            if (dfAngle < -1e-12) dfAngle += 2 * PI;
            printf("  t = %4d ms: X = %.3f, Y = %.3f, Z = %.3f, angle %.1f deg\n",
                   i * 500, p[0], p[1], p[2], dfAngle * 180 / PI);
            CHECK_NEAR(hypot(p[0] - 5, p[1] - 5), 5.0, 0.003);
            CHECK(dfAngle > dfPrevAngle);                       // counter-clockwise
            CHECK_NEAR(p[2], 2 * dfAngle / (2 * PI), 0.003);    // Z = pitch x theta / 360
            dfPrevAngle = dfAngle;
            if (i == 2)
            {
                COMMAND_INFO stInfo;
                CHECK_EQ(MCC_GetCurCommand(&stInfo, g_nGroupIndex), NO_ERR);
                CHECK_EQ(stInfo.nType, 5);
                CHECK(stInfo.dfFeedSpeed == 10.0);
                CHECK_NEAR(stInfo.dfPos[2], 2, POS_TOL);
                // 1000 ms: 0.15 V + 0.7 V = 8.499 UU along the 31.4159 UU arc.
                CHECK_NEAR(dfAngle, 0.85 * (10 * PI / 3.142) / 5, 0.005);
            }
        }
        CheckEndsIn(g_nGroupIndex, 3442 - 3000, "helix 360 deg");
    }
    WaitStop(g_nGroupIndex);
    PrintPos(g_nGroupIndex, "After the helix");
    CheckPosXYZ(g_nGroupIndex, 10, 5, 2);

    // Half a turn clockwise: the pitch is positive, so Z rises by 1.
    CHECK(MCC_HelicalXY_Z(5, 5, 2, -180, g_nGroupIndex) >= 0);
    if (SteppedClock())
    {
        MCC_TimeDelay(800);
        double p[8];
        GetPos(g_nGroupIndex, p);
        CHECK(p[1] < 5);                                   // clockwise from angle 0 goes down
        CHECK_NEAR(hypot(p[0] - 5, p[1] - 5), 5.0, 0.003);
        double dfTurned = -atan2(p[1] - 5, p[0] - 5);      // radians turned clockwise
        CHECK_NEAR(p[2], 2 + 2 * dfTurned / (2 * PI), 0.003);
        CHECK_NEAR(dfTurned, 0.65 * (5 * PI / 1.571) / 5, 0.005);   // 800 ms: 0.15 V + 0.5 V
        COMMAND_INFO stInfo;
        CHECK_EQ(MCC_GetCurCommand(&stInfo, g_nGroupIndex), NO_ERR);
        CHECK_EQ(stInfo.nType, 4);
    }
    WaitStop(g_nGroupIndex);
    PrintPos(g_nGroupIndex, "After the half turn back");
    CheckPosXYZ(g_nGroupIndex, 0, 5, 3);

    // Bad input.
    CHECK_EQ(MCC_HelicalXY_Z(NAN, 5, 2, 360, g_nGroupIndex), PARAMETER_ERR);
    CHECK_EQ(MCC_HelicalXY_Z(5, 5, INFINITY, 360, g_nGroupIndex), PARAMETER_ERR);
    CHECK_EQ(MCC_HelicalXY_Z(5, 5, 2, NAN, g_nGroupIndex), PARAMETER_ERR);
    CHECK_EQ(MCC_HelicalXY_Z(5, 5, 2, 360, BAD_GROUP), GROUP_PARAMETER_ERR);
    // Centre = current point: no circle; queued (index 3), it fails when it starts with
    // error record 0xF104 and the group stops where it stands.
    CHECK_EQ(MCC_HelicalXY_Z(0, 5, 2, 360, g_nGroupIndex), 3);
    MCC_TimeDelay(1);
    CHECK_EQ(MCC_GetErrorCode(g_nGroupIndex), 0xF104);
    WaitStop(g_nGroupIndex);
    CHECK_EQ(MCC_ClearError(g_nGroupIndex), NO_ERR);
    CheckPosXYZ(g_nGroupIndex, 0, 5, 3);

    Close();
    return check_done("Helical");
}
