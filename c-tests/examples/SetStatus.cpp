// SetStatus.cpp: examples manual §5 (system state): coordinate type, acc/dec curve types
// of general and point-to-point motion, servo-on and position-ready outputs.
//
// What is asserted and why:
// - MCC_SetAbsolute / MCC_SetIncrease change how MCC_Line reads its arguments: in
//   incremental mode two MCC_Line(5, ...) end at X = 10; back in absolute mode
//   MCC_Line(2, ...) ends at X = 2.
// - MCC_GetCoordType: 1 after MCC_SetAbsolute, 0 after MCC_SetIncrease (the values vendor
//   client programs test for; the manuals do not print them).
// - MCC_GetAccType / MCC_GetDecType return 0 for 'T' and 1 for 'S' (as the vendor's
//   library answers; MCC_GetPtPAccType / MCC_GetPtPDecType likewise per axis).
// - 'T' acceleration with 'S' deceleration: a 10 UU line at 20 UU/s still lasts
//   300 + ceil(500 - 300) + 300 = 800 periods of 1 ms (both shapes cover F*T/2 while
//   ramping).
// The manual passes seven letters and the group to MCC_SetPtPAccType; the prototype has
// eight axes, so eight letters are written here.
#include "MotionSys.h"

int main()
{
    if (InitSys8() != NO_ERR)
        return check_done("SetStatus");

    // Absolute coordinates.
    CHECK_EQ(MCC_SetAbsolute(g_nGroupIndex), NO_ERR);
    CHECK_EQ(MCC_GetCoordType(g_nGroupIndex), 1);

    // 'T' acceleration, 'S' deceleration for line/arc/circle/helix.
    CHECK_EQ(MCC_SetAccType('T', g_nGroupIndex), NO_ERR);
    CHECK_EQ(MCC_GetAccType(g_nGroupIndex), 0);
    CHECK_EQ(MCC_SetDecType('S', g_nGroupIndex), NO_ERR);
    CHECK_EQ(MCC_GetDecType(g_nGroupIndex), 1);

    // 'T' acceleration and 'S' deceleration for every axis of point-to-point motion.
    CHECK_EQ(MCC_SetPtPAccType('T', 'T', 'T', 'T', 'T', 'T', 'T', 'T', g_nGroupIndex), NO_ERR);
    CHECK_EQ(MCC_SetPtPDecType('S', 'S', 'S', 'S', 'S', 'S', 'S', 'S', g_nGroupIndex), NO_ERR);
    char c[8], d[8];
    memset(c, 0, sizeof(c));
    memset(d, 0, sizeof(d));
    CHECK_EQ(MCC_GetPtPAccType(&c[0], &c[1], &c[2], &c[3], &c[4], &c[5], &c[6], &c[7], g_nGroupIndex), NO_ERR);
    CHECK_EQ(MCC_GetPtPDecType(&d[0], &d[1], &d[2], &d[3], &d[4], &d[5], &d[6], &d[7], g_nGroupIndex), NO_ERR);
    for (int i = 0; i < 8; i++)
    {
        CHECK_EQ(c[i], 0);
        CHECK_EQ(d[i], 1);
    }

    // Servo on for channel 0, position-ready output on.
    CHECK_EQ(MCC_SetServoOn(0, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_EnablePosReady(CARD_INDEX), NO_ERR);

    // The curve types do not change the duration: na = nd = 300, nc = ceil(10/20/0.001 -
    // 300) = 200 periods at 20 UU/s: 800 ms.
    MCC_SetFeedSpeed(20, g_nGroupIndex);
    CHECK(MCC_Line(10, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex) >= 0);
    CheckEndsIn(g_nGroupIndex, 800, "T/S line of 10 UU at 20 UU/s");
    WaitStop(g_nGroupIndex);
    CheckPosXYZ(g_nGroupIndex, 10, 0, 0);

    // 'S' acceleration too: same 800 ms.
    CHECK_EQ(MCC_SetAccType('S', g_nGroupIndex), NO_ERR);
    CHECK_EQ(MCC_GetAccType(g_nGroupIndex), 1);
    CHECK(MCC_Line(0, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex) >= 0);
    CheckEndsIn(g_nGroupIndex, 800, "S/S line of 10 UU at 20 UU/s");
    WaitStop(g_nGroupIndex);
    CheckPosXYZ(g_nGroupIndex, 0, 0, 0);

    // Incremental coordinates: each MCC_Line gives a displacement.
    CHECK_EQ(MCC_SetIncrease(g_nGroupIndex), NO_ERR);
    CHECK_EQ(MCC_GetCoordType(g_nGroupIndex), 0);
    CHECK(MCC_Line(5, 0, 1, 0, 0, 0, 0, 0, g_nGroupIndex) >= 0);
    CHECK(MCC_Line(5, 0, 1, 0, 0, 0, 0, 0, g_nGroupIndex) >= 0);
    WaitStop(g_nGroupIndex);
    CheckPosXYZ(g_nGroupIndex, 10, 0, 2);
    printf("Incremental: two MCC_Line(5, 0, 1) end at (10, 0, 2)\n");

    // Absolute again: MCC_Line(2, ...) goes to X = 2.
    CHECK_EQ(MCC_SetAbsolute(g_nGroupIndex), NO_ERR);
    CHECK_EQ(MCC_GetCoordType(g_nGroupIndex), 1);
    CHECK(MCC_Line(2, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex) >= 0);
    WaitStop(g_nGroupIndex);
    CheckPosXYZ(g_nGroupIndex, 2, 0, 0);
    printf("Absolute: MCC_Line(2, 0, 0) ends at (2, 0, 0)\n");

    // Bad input changes nothing.
    CHECK_EQ(MCC_SetAccType('X', g_nGroupIndex), PARAMETER_ERR);
    CHECK_EQ(MCC_GetAccType(g_nGroupIndex), 1);
    CHECK_EQ(MCC_SetDecType(0, g_nGroupIndex), PARAMETER_ERR);
    CHECK_EQ(MCC_GetDecType(g_nGroupIndex), 1);
    CHECK_EQ(MCC_SetPtPAccType('T', 'T', 'Q', 'T', 'T', 'T', 'T', 'T', g_nGroupIndex), PARAMETER_ERR);
    CHECK_EQ(MCC_SetAbsolute(BAD_GROUP), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCC_SetIncrease(BAD_GROUP), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCC_GetCoordType(BAD_GROUP), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCC_SetAccType('T', BAD_GROUP), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCC_SetDecType('T', BAD_GROUP), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCC_SetPtPAccType('T', 'T', 'T', 'T', 'T', 'T', 'T', 'T', BAD_GROUP), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCC_GetPtPAccType(NULL, &c[1], &c[2], &c[3], &c[4], &c[5], &c[6], &c[7], g_nGroupIndex), PARAMETER_ERR);
    CHECK_EQ(MCC_SetServoOn(MAX_AXIS_NUM, CARD_INDEX), PARAMETER_ERR);   // channel 8
    CHECK_EQ(MCC_SetServoOn(0, MAX_CARD_NUM), PARAMETER_ERR);            // card 12
    CHECK_EQ(MCC_EnablePosReady(MAX_CARD_NUM), PARAMETER_ERR);
    CHECK_EQ(MCC_GetCoordType(g_nGroupIndex), 1);

    CHECK_EQ(MCC_DisablePosReady(CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_SetServoOff(0, CARD_INDEX), NO_ERR);
    Close();
    CHECK_EQ(MCC_SetServoOn(0, CARD_INDEX), INITIAL_MOTION_ERR);
    return check_done("SetStatus");
}
