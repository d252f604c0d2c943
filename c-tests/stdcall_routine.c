/* stdcall_routine.c: a C99 program written as the manuals write them for Windows: an
 * interrupt routine declared `void _stdcall f(TMRINT *)`, which calls back into the
 * library, while MCC_Line moves the X axis. On 32-bit Windows every call in both
 * directions is stdcall (the callee removes its arguments): a mismatch on either side
 * would unbalance the stack on each of the 1300 calls of the routine and crash or
 * corrupt the run long before its end. Elsewhere `_stdcall` means nothing and the
 * program checks the same numbers.
 *
 * Expected (1 ms interpolation, 1 ms timer, F = 10 UU/s, acc and dec time 100 ms, a line
 * of 10 UU along X):
 *   the routine runs once per 1 ms period of the timer: 1300 calls in MCC_TimeDelay(1300);
 *   the line lasts L/F + (Ta + Td)/2 = 1 s + 0.1 s = 1100 ms (DECISIONS: both shapes
 *   cover F x Ta/2 while accelerating), so after 1300 ms the group is stopped at X = 10;
 *   X read in the routine never decreases, and its profile is symmetric (Ta = Td), so
 *   at 550 ms X is L/2 = 5, give or take one period's travel (F x 1 ms = 0.01 UU). */
#include <stdio.h>
#include <string.h>
#include "MCCL.h"
#include "MCCL_Fun.h"
#include "check.h"

#define CARD 0
#define GROUP 0

static volatile int nCalls = 0;
static volatile int nBackwards = 0;
static volatile int nFailedReads = 0;
static volatile double dfLastX = 0.0;
static volatile double dfXAt550 = -1.0;

static void _stdcall OnTimer(TMRINT *pstINTSource)
{
    double x, y, z, u, v, w, a, b;
    if (!pstINTSource->TIMER)
        return;
    nCalls++;
    if (MCC_GetCurPos(&x, &y, &z, &u, &v, &w, &a, &b, GROUP) != NO_ERR) {
        nFailedReads++;
        return;
    }
    if (x < dfLastX)
        nBackwards++;
    dfLastX = x;
    if (nCalls == 550)
        dfXAt550 = x;
}

int main(void)
{
    SYS_MAC_PARAM stAxis;
    SYS_CARD_CONFIG stCard[1];
    WORD ch;
    double x, y, z, u, v, w, a, b;

    memset(&stAxis, 0, sizeof(stAxis));
    stAxis.dwPPR = 500;
    stAxis.wRPM = 3000;
    stAxis.dfPitch = 1.0;
    stAxis.dfGearRatio = 1.0;
    stAxis.dfHighLimit = 50000.0;
    stAxis.dfLowLimit = -50000.0;
    stAxis.wPulseMode = DDA_FMT_PD;
    stAxis.wPulseWidth = 100; /* a pulse of no width is refused, as by the vendor's library */
    stAxis.wCommandMode = OCM_PULSE;
    stAxis.wOverTravelUpSensorMode = SL_UNUSED;
    stAxis.wOverTravelDownSensorMode = SL_UNUSED;
    CHECK_EQ(MCC_SetSysMaxSpeed(100.0), NO_ERR);
    for (ch = 0; ch < MAX_AXIS_NUM; ch++)
        CHECK_EQ(MCC_SetMacParam(&stAxis, ch, CARD), NO_ERR);
    CHECK_EQ(MCC_CloseAllGroups(), NO_ERR);
    CHECK_EQ(MCC_CreateGroup(0, 1, 2, -1, -1, -1, -1, -1, CARD), GROUP);
    memset(stCard, 0, sizeof(stCard));
    stCard[0].wCardType = IMP_III_8_AXIS_PCI_CARD;
    CHECK_EQ(MCC_InitSystem(1, stCard, 1), NO_ERR);

    CHECK_EQ(MCC_SetTMRRoutine(OnTimer, CARD), NO_ERR);
    CHECK_EQ(MCC_SetTimer(100000, CARD), NO_ERR); /* 100000 x 10 ns = 1 ms */
    CHECK_EQ(MCC_EnableTimer(CARD), NO_ERR);
    CHECK_EQ(MCC_EnableTimerTrigger(CARD), NO_ERR);

    CHECK_EQ(MCC_SetAccTime(100, GROUP), NO_ERR);
    CHECK_EQ(MCC_SetDecTime(100, GROUP), NO_ERR);
    MCC_SetFeedSpeed(10, GROUP);
    CHECK(MCC_Line(10, 0, 0, 0, 0, 0, 0, 0, GROUP, IMP_AXIS_ALL) >= 0);
    MCC_TimeDelay(1300);

    printf("  routine: %d calls, X at call 550 = %.6f, last X = %.6f\n", nCalls, dfXAt550,
           dfLastX);
    CHECK_EQ(nCalls, 1300);
    CHECK_EQ(nFailedReads, 0);
    CHECK_EQ(nBackwards, 0);
    CHECK_NEAR(dfXAt550, 5.0, 0.01);
    CHECK_EQ(MCC_GetMotionStatus(GROUP), GMS_STOP);
    CHECK_EQ(MCC_GetCurPos(&x, &y, &z, &u, &v, &w, &a, &b, GROUP), NO_ERR);
    CHECK_NEAR(x, 10.0, 1e-9);
    CHECK_NEAR(dfLastX, 10.0, 1e-9);
    CHECK_EQ(MCC_DisableTimerTrigger(CARD), NO_ERR);
    CHECK_EQ(MCC_CloseSystem(), NO_ERR);
    return check_done("stdcall_routine");
}
