// ErrorStatus.cpp: examples manual §21 (reading and clearing the error state). After an
// error the group runs no motion until MCC_ClearError. The error here is the emergency
// stop, pressed through MCCL_Sim.h: it stops every group of the card and records 0xF102.
#include "MotionSys.h"
#include "MCCL_Sim.h"

// The messages of the vendor's test program for the error codes (docs/vendor-interface.md,
// "Error records").
static const char *ErrorText(int nCode)
{
    if (nCode == 0) return "No error";
    if (nCode == 0xF101) return "System not initialized yet";
    if (nCode == 0xF102) return "Emergency stop";
    if (nCode == 0xF104) return "Invalid parameters of arc command";
    if (nCode >= 0xF301 && nCode <= 0xF308) return "Axis exceeds position limit";
    if (nCode >= 0xF701 && nCode <= 0xF708) return "Hardware limit hit";
    if (nCode >= 0xF801 && nCode <= 0xF808) return "Tracking error";
    return "Run Time Error";
}

int main()
{
    if (InitSys8() != NO_ERR)
        return check_done("ErrorStatus");
    MCC_SetFeedSpeed(10, g_nGroupIndex);
    CHECK_EQ(MCC_GetErrorCode(g_nGroupIndex), 0);

    MCC_Line(10, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex);
    MCC_TimeDelay(500);
    CHECK_EQ(MCCL_SimSetEmergencyStop(CARD_INDEX, 1), NO_ERR);
    MCC_TimeDelay(10);
    double p1[8], p2[8];
    GetPos(g_nGroupIndex, p1);

    // The manual's pattern: check the error code, report it, clear it.
    int nCode = MCC_GetErrorCode(g_nGroupIndex);
    if (nCode)
    {
        printf("An error occurs and stops all motion commands! 0x%X: %s\n", nCode, ErrorText(nCode));
        CHECK_EQ(nCode, 0xF102);
        CHECK_EQ(MCC_GetMotionStatus(g_nGroupIndex), GMS_STOP);
        WORD wEmg = 0;
        CHECK_EQ(MCC_GetEmgcStopStatus(&wEmg, CARD_INDEX), NO_ERR);
        CHECK_EQ(wEmg, 1);

        // While the error stands, nothing moves.
        MCC_Line(20, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex);
        MCC_TimeDelay(200);
        GetPos(g_nGroupIndex, p2);
        CHECK(p1[0] == p2[0] && p1[0] > 0 && p1[0] < 10);

        CHECK_EQ(MCCL_SimSetEmergencyStop(CARD_INDEX, 0), NO_ERR);
        CHECK_EQ(MCC_ClearError(g_nGroupIndex), NO_ERR);
    }
    CHECK_EQ(MCC_GetErrorCode(g_nGroupIndex), 0);
    MCC_Line(20, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex);
    WaitStop(g_nGroupIndex);
    CheckPosXYZ(g_nGroupIndex, 20, 0, 0);
    printf("After MCC_ClearError the group moves again: X = 20\n");

    CHECK_EQ(MCC_GetErrorCode(BAD_GROUP), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCC_ClearError(BAD_GROUP), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCCL_SimSetEmergencyStop(CARD_INDEX, 2), PARAMETER_ERR);
    CHECK_EQ(MCCL_SimSetEmergencyStop(1, 1), PARAMETER_ERR);   // only one card
    Close();
    CHECK_EQ(MCC_GetErrorCode(0), INITIAL_MOTION_ERR);
    return check_done("ErrorStatus");
}
