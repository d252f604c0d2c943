/* filters_c.c: the cycle routine, acc/dec after interpolation and reverse interpolation
 * from C99 through the vendor's prototypes and callback types (docs/compatibility.md,
 * "Filters, reverse interpolation, cycle routine"). Runs on the fast and the stepped
 * clock: 1 ms periods, virtual time runs only in MCC_TimeDelay (n ms = n periods). */
#include <string.h>
#include "MCCL.h"
#include "MCCL_Fun.h"
#include "check.h"

static int cycles = 0;
static int interp_calls = 0;

static void MCC_CALLBACK on_cycle(void)
{
    cycles++;
}

/* Forward for calls 1..99, then back (the decision applies to the next period). */
static int MCC_CALLBACK steer(int nGroup, int nCommandIndex, int nTimeIndex, void *pvBuffer)
{
    (void)nCommandIndex;
    (void)nTimeIndex;
    CHECK_EQ(nGroup, 0);
    CHECK(pvBuffer == NULL);
    interp_calls++;
    return interp_calls < 100 ? 1 : -1;
}

static double cur_x(void)
{
    double p[8];
    CHECK_EQ(MCC_GetCurPos(&p[0], &p[1], &p[2], &p[3], &p[4], &p[5], &p[6], &p[7], 0), NO_ERR);
    return p[0];
}

int main(void)
{
    SYS_CARD_CONFIG card[1];
    double x60;
    memset(card, 0, sizeof card);
    card[0].wCardType = IMP_III_8_AXIS_PCI_CARD;
    CHECK_EQ(MCC_SetCycleInterruptRoutine(on_cycle), INITIAL_MOTION_ERR);
    CHECK_EQ(MCC_InitSystem(1, card, 1), NO_ERR);

    /* One call per period. */
    CHECK_EQ(MCC_SetCycleInterruptRoutine(on_cycle), NO_ERR);
    MCC_TimeDelay(50);
    CHECK_EQ(cycles, 50);
    CHECK_EQ(MCC_SetCycleInterruptRoutine(NULL), NO_ERR);

    /* Acc/dec after interpolation over 100 periods: X 0 -> 1 at 10 UU/s is 100 periods
     * of interpolation at full speed; the output at period 50 is the trapezoidal mean of
     * x(j) = j/100, j = 0..50: (12.25 + 0.25) / 100 = 0.125, read in whole pulses toward
     * 0 (trunc(62.5) = 62 of 500 per UU: 0.124); it arrives at period 200. */
    MCC_SetFeedSpeed(10, 0);
    CHECK_EQ(MCC_SetAccTime(100, 0), NO_ERR);
    CHECK_EQ(MCC_EnableAccDecAfterIPO(0), NO_ERR);
    CHECK_EQ(MCC_Line(1, 0, 0, 0, 0, 0, 0, 0, 0, IMP_AXIS_ALL), 0);
    MCC_TimeDelay(50);
    CHECK_NEAR(cur_x(), 0.124, 1e-9);
    MCC_TimeDelay(149);
    CHECK_EQ(MCC_GetMotionStatus(0), GMS_RUNNING);
    MCC_TimeDelay(1);
    CHECK_EQ(MCC_GetMotionStatus(0), GMS_STOP);
    CHECK(cur_x() == 1.0);
    CHECK_EQ(MCC_DisableAccDecAfterIPO(0), NO_ERR);
    CHECK_EQ(MCC_EnableMovingAverage(0), NO_ERR);
    CHECK_EQ(MCC_DisableMovingAverage(0), NO_ERR);

    /* Reverse: periods 1..100 forward, then back: at period 100 + m the group stands
     * where it stood at period 100 - m (period 140: period 60). */
    CHECK_EQ(MCC_SetReverseInterpRoutine(steer, 0), NO_ERR);
    CHECK_EQ(MCC_EnableReverseInterp(1, 0), NO_ERR);
    CHECK_EQ(MCC_Line(0, 0, 0, 0, 0, 0, 0, 0, 0, IMP_AXIS_ALL), 1);
    MCC_TimeDelay(60);
    x60 = cur_x();
    MCC_TimeDelay(60);
    MCC_TimeDelay(20);
    CHECK(cur_x() == x60);
    CHECK_EQ(MCC_EnableReverseInterp(0, 0), NO_ERR);
    CHECK_EQ(MCC_CloseSystem(), NO_ERR);
    return check_done("filters_c");
}
