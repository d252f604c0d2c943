// InPosCheck.cpp: examples manual §14 (in-position confirmation), written the way the
// manual writes it. Run with MCCL_SIM=c-tests/sim/lag_x.toml: X's motor lags 50 ms, so
// after a move at 10 UU/s it trails by 0.5 UU and closes in as e^(-t/50 ms).
//
//   Tolerance 0.5 UU (the manual's values), max check 1000 ms: in position at once,
//   MCC_GetInPosStatus gives 0xFF for X, no error.
//   Tolerance 0.001 UU with a 100 ms max check: 0.5 x e^(-2) = 0.068 UU left at 100 ms:
//   not in position, MCC_GetErrorCode = 0xF501 (IPM_ONETIME_BLOCK), the next command is
//   dropped; MCC_ClearError; in IPM_ONETIME_UNBLOCK the queue goes on without a record.
#include "MotionSys.h"

int main()
{
    if (InitSys8() != NO_ERR)
        return check_done("InPosCheck");
    MCC_SetFeedSpeed(10, g_nGroupIndex);
    MCC_SetAccTime(0, g_nGroupIndex);
    MCC_SetDecTime(0, g_nGroupIndex);

    // Step 1: the longest check time, ms.
    CHECK_EQ(MCC_SetInPosMaxCheckTime(1000, g_nGroupIndex), NO_ERR);
    // Step 2: the mode.
    CHECK_EQ(MCC_SetInPosMode(IPM_ONETIME_BLOCK, g_nGroupIndex), NO_ERR);
    // Step 3: the tolerance per axis, UU.
    CHECK_EQ(MCC_SetInPosToleranceEx(0.5, 0.5, 1000, 1000, 1000, 1000, 1000, 1000, g_nGroupIndex), NO_ERR);
    // Step 4: on (a queued command: it returns its index).
    CHECK(MCC_EnableInPos(g_nGroupIndex) >= 0);

    MCC_Line(5, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex);
    WaitStop(g_nGroupIndex);
    // Step 5: the in-position status of every axis; 0xFF (255) when in position.
    BYTE byInPos0, byInPos1, byInPos2, byInPos3, byInPos4, byInPos5, byInPos6, byInPos7;
    CHECK_EQ(MCC_GetInPosStatus(&byInPos0, &byInPos1, &byInPos2, &byInPos3, &byInPos4,
                                &byInPos5, &byInPos6, &byInPos7, g_nGroupIndex), NO_ERR);
    printf("Tolerance 0.5 UU: in-position status X 0x%X, Y 0x%X\n", byInPos0, byInPos1);
    CHECK_EQ(byInPos0, 0xFF);
    CHECK_EQ(byInPos1, 0xFF);
    // Step 6: the error code.
    int nErrCode = MCC_GetErrorCode(g_nGroupIndex);
    CHECK_EQ(nErrCode, 0);

    // A tolerance the lagging motor cannot meet within 100 ms.
    CHECK_EQ(MCC_SetInPosToleranceEx(0.001, 0.5, 1000, 1000, 1000, 1000, 1000, 1000, g_nGroupIndex), NO_ERR);
    CHECK_EQ(MCC_SetInPosMaxCheckTime(100, g_nGroupIndex), NO_ERR);
    MCC_Line(10, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex);
    MCC_Line(0, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex);
    WaitStop(g_nGroupIndex);
    nErrCode = MCC_GetErrorCode(g_nGroupIndex);
    printf("Tolerance 0.001 UU, 100 ms: error 0x%X\n", nErrCode);
    CHECK_EQ(nErrCode, 0xF501);
    CheckPosXYZ(g_nGroupIndex, 10, 0, 0);   // the line back to 0 was dropped
    CHECK_EQ(MCC_ClearError(g_nGroupIndex), NO_ERR);

    CHECK_EQ(MCC_SetInPosMode(IPM_ONETIME_UNBLOCK, g_nGroupIndex), NO_ERR);
    MCC_Line(15, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex);
    MCC_Line(0, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex);
    WaitStop(g_nGroupIndex);
    CHECK_EQ(MCC_GetErrorCode(g_nGroupIndex), 0);
    CheckPosXYZ(g_nGroupIndex, 0, 0, 0);
    printf("IPM_ONETIME_UNBLOCK: no error, the queue went on to X = 0\n");

    CHECK_EQ(MCC_SetInPosMode(9, g_nGroupIndex), PARAMETER_ERR);
    // A negative tolerance counts by its size, as the vendor's library keeps it (whole
    // pulses, |trunc(x x 500)|: -1 UU is 500 pulses, read back as 1 UU).
    CHECK_EQ(MCC_SetInPosToleranceEx(-1, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex), NO_ERR);
    double t[8];
    CHECK_EQ(MCC_GetInPosToleranceEx(&t[0], &t[1], &t[2], &t[3], &t[4], &t[5], &t[6], &t[7], g_nGroupIndex), NO_ERR);
    CHECK_NEAR(t[0], 1.0, 1e-12);
    CHECK(MCC_EnableInPos(BAD_GROUP) == GROUP_PARAMETER_ERR);
    Close();
    return check_done("InPosCheck");
}
