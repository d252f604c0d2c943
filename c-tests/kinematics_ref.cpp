// kinematics_ref.cpp: a C++ robot program written for the vendor's header, whose
// kinematics callbacks take the posture the way that header declares it, as a C++
// reference (`DWORD& dwPosture`), and are registered without a cast. In C the header
// declares a pointer instead (the same ABI: a reference is passed as its address); this
// program checks that the C++ form compiles against the generated headers and that the
// posture travels through the reference both ways at run time.
//
// The robot: a "gear" robot whose joints are twice its Cartesian coordinates
// (joint = 2 x Cartesian on every axis), so that joints and Cartesian positions differ
// and each can be checked: PPR 1000, pitch 1, gear 1 => 1000 pulses per joint unit.
//
// What it checks:
//   1. the callbacks convert to FWDKINEFUN / INVKINEFUN as written (compile time), and
//      are registered before the card starts, as the vendor's library takes them;
//   2. MCC_Line_V6 to X = 1 with posture 1: the inverse kinematics gets posture 1 on its
//      first call (the command's posture, read through the reference), writes 0x101 back
//      through the reference, and every later call of the move gets 0x101 (the library
//      passes the DWORD the callback wrote);
//   3. the move ends with the X joint at 2 (2000 pulses), Y and Z at 0.
#include "MCCL.h"
#include "MCCL_Fun.h"
#include "check.h"
#include <string.h>

namespace {

int g_nInvCalls = 0;
DWORD g_dwFirstPosture = 0xFFFF;
bool g_bLaterPosturesKept = true;

// The callbacks as a program written for the vendor's header declares them.
BOOL _stdcall ForwardKinematics(int nGroup, int nSynAxisNum, const double* pdfFrom, double* pdfTo,
                                DWORD& dwPosture, void* pvExtension)
{
    (void)nGroup;
    (void)dwPosture;
    (void)pvExtension;
    for (int i = 0; i < nSynAxisNum; i++)
        pdfTo[i] = pdfFrom[i] / 2.0;
    return 1;
}

BOOL _stdcall InverseKinematics(int nGroup, int nSynAxisNum, const double* pdfFrom,
                                const double* pdfPrevResult, double* pdfTo, DWORD& dwPosture,
                                void* pvExtension)
{
    (void)nGroup;
    (void)pdfPrevResult;
    (void)pvExtension;
    for (int i = 0; i < nSynAxisNum; i++)
        pdfTo[i] = pdfFrom[i] * 2.0;
    if (pdfFrom[0] != 0.0) // the move has begun
    {
        if (g_nInvCalls == 0)
            g_dwFirstPosture = dwPosture;
        else if (dwPosture != 0x101)
            g_bLaterPosturesKept = false;
        g_nInvCalls++;
        dwPosture = 0x101; // the configuration the kinematics chose, reported back
    }
    return 1;
}

} // namespace

int main()
{
    // 1. Registered as written: no cast, the header's types are the vendor's.
    FWDKINEFUN pfnFwd = ForwardKinematics;
    INVKINEFUN pfnInv = InverseKinematics;

    SYS_MAC_PARAM stAxis;
    memset(&stAxis, 0, sizeof(stAxis));
    stAxis.dwPPR = 1000;
    stAxis.wRPM = 3000;
    stAxis.dfPitch = 1.0;
    stAxis.dfGearRatio = 1.0;
    stAxis.dfHighLimit = 50000;
    stAxis.dfLowLimit = -50000;
    stAxis.wPulseMode = DDA_FMT_PD;
    stAxis.wPulseWidth = 100;
    stAxis.wCommandMode = OCM_PULSE;
    stAxis.wOverTravelUpSensorMode = SL_UNUSED;
    stAxis.wOverTravelDownSensorMode = SL_UNUSED;
    for (WORD ch = 0; ch < 8; ch++)
        CHECK_EQ(MCC_SetMacParam(&stAxis, ch), NO_ERR);
    CHECK_EQ(MCC_CloseAllGroups(), NO_ERR);
    CHECK_EQ(MCC_CreateGroup(0, 1, 2, 3, 4, 5, 6, 7, 0), 0);
    CHECK_EQ(MCC_SetKinematicTrans(pfnFwd, pfnInv), NO_ERR); // size, init, group defaulted
    SYS_CARD_CONFIG stCard[MAX_CARD_NUM];
    memset(stCard, 0, sizeof(stCard));
    stCard[0].wCardType = IMP_III_8_AXIS_PCI_CARD;
    CHECK_EQ(MCC_InitSystem(1, stCard, 1), NO_ERR);

    // 2. A line with posture 1.
    MCC_SetFeedSpeed(10);
    CHECK(MCC_Line_V6(1, 0, 0, 0, 0, 0, 0, 0, 1) >= 0);
    long n = 0;
    while (MCC_GetMotionStatus() != GMS_STOP && n++ < 1000000L)
        MCC_TimeDelay(1);
    CHECK_EQ(MCC_GetMotionStatus(), GMS_STOP);
    printf("inverse kinematics: %d calls during the move, first posture %lu\n", g_nInvCalls,
           (unsigned long)g_dwFirstPosture);
    CHECK(g_nInvCalls > 10);
    CHECK_EQ(g_dwFirstPosture, 1);
    CHECK(g_bLaterPosturesKept);

    // 3. The joints are twice the Cartesian end (1, 0, 0).
    long p[8];
    CHECK_EQ(MCC_GetPulsePos(&p[0], &p[1], &p[2], &p[3], &p[4], &p[5], &p[6], &p[7]), NO_ERR);
    CHECK_EQ(p[0], 2000);
    CHECK_EQ(p[1], 0);
    CHECK_EQ(p[2], 0);

    CHECK_EQ(MCC_CloseSystem(), NO_ERR);
    return check_done("kinematics_ref");
}
