/* isr_reentry.c: every interrupt routine type registered from C (LIO through
 * MCC_SetLIORoutineEx as well, ENC, PCL, ADC, TMR, RIO, HSK), and routines that call back
 * into the library while the engine delivers them: MCC_GetCurPos (timer routine, every
 * tick), MCC_AbortMotionEx (ADC routine, at a comparator crossing), MCC_CloseSystem (RIO
 * routine, on a remote input edge). Repeated for several init/close cycles; the last
 * cycle closes from the program. No deadlock, no crash, no leak (also run under
 * valgrind). Usage: isr_reentry [cycles=5] */
#define _POSIX_C_SOURCE 200809L
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "MCCL.h"
#include "MCCL_Fun.h"
#include "check.h"

static atomic_int nTicks, nAborts, nCloses, nClosedDone, nUnexpected;
static atomic_int nAbortRet = 99, nCloseRet = 99, nPosRet = 99;
static double dfLastX;

static void MCC_CALLBACK OnLIO(LIOINT *p) { (void)p; atomic_fetch_add(&nUnexpected, 1); }
static void MCC_CALLBACK OnENC(ENCINT *p) { (void)p; atomic_fetch_add(&nUnexpected, 1); }
static void MCC_CALLBACK OnPCL(PCLINT *p) { (void)p; atomic_fetch_add(&nUnexpected, 1); }
static void MCC_CALLBACK OnHSK(HSKINT *p) { (void)p; atomic_fetch_add(&nUnexpected, 1); }

static void MCC_CALLBACK OnTMR(TMRINT *p)
{
    double x[8];
    if (!p->TIMER)
        return;
    atomic_fetch_add(&nTicks, 1);
    atomic_store(&nPosRet, MCC_GetCurPos(&x[0], &x[1], &x[2], &x[3], &x[4], &x[5], &x[6], &x[7], 0));
    dfLastX = x[0];
}

static void MCC_CALLBACK OnADC(ADCINT *p)
{
    if (p->COMP0)
    {
        atomic_fetch_add(&nAborts, 1);
        atomic_store(&nAbortRet, MCC_AbortMotionEx(50.0, 0));
    }
}

static void MCC_CALLBACK OnRIO(RIOINT *p)
{
    if (p->RDI0)
    {
        atomic_fetch_add(&nCloses, 1);
        atomic_store(&nCloseRet, MCC_CloseSystem());
        atomic_store(&nClosedDone, 1);
    }
}

static int Start(void)
{
    SYS_CARD_CONFIG card[1];
    memset(card, 0, sizeof card);
    card[0].wCardType = IMP_III_8_AXIS_PCI_CARD;
    return MCC_InitSystem(1, card, 1);
}

static void Register(void)
{
    CHECK_EQ(MCC_SetLIORoutine(OnLIO, 0), NO_ERR);
    CHECK_EQ(MCC_SetLIORoutineEx(OnLIO, 0), NO_ERR);
    CHECK_EQ(MCC_SetENCRoutine(OnENC, 0), NO_ERR);
    CHECK_EQ(MCC_SetPCLRoutine(OnPCL, 0), NO_ERR);
    CHECK_EQ(MCC_SetADCRoutine(OnADC, 0), NO_ERR);
    CHECK_EQ(MCC_SetTMRRoutine(OnTMR, 0), NO_ERR);
    CHECK_EQ(MCC_SetRIORoutine(OnRIO, 0), NO_ERR);
    CHECK_EQ(MCC_SetHSKRoutine(OnHSK, 0), NO_ERR);
    /* NULL unregisters; a card not started is refused. */
    CHECK_EQ(MCC_SetHSKRoutine(NULL, 0), NO_ERR);
    CHECK_EQ(MCC_SetHSKRoutine(OnHSK, 0), NO_ERR);
    CHECK_EQ(MCC_SetTMRRoutine(OnTMR, 1), PARAMETER_ERR);
}

static void Cycle(int bCloseFromRoutine)
{
    atomic_store(&nTicks, 0);
    atomic_store(&nAborts, 0);
    atomic_store(&nCloses, 0);
    atomic_store(&nClosedDone, 0);
    CHECK_EQ(Start(), NO_ERR);
    Register();

    /* Timer every 1 ms; the routine reads the position each tick. */
    CHECK_EQ(MCC_SetTimer(100000, 0), NO_ERR);
    CHECK_EQ(MCC_EnableTimerTrigger(0), NO_ERR);
    CHECK_EQ(MCC_EnableTimer(0), NO_ERR);
    /* ADC 0 reads DAC 0; crossing 1 V aborts the motion from the routine. */
    CHECK_EQ(MCC_SetADCCompValue(1.0f, 0, 0), NO_ERR);
    CHECK_EQ(MCC_SetADCCompType(ADC_COMP_RISE, 0, 0), NO_ERR);
    CHECK_EQ(MCC_EnableADCCompTrigger(0, 0), NO_ERR);
    CHECK_EQ(MCC_EnableADCConvChannel(0, 0), NO_ERR);
    CHECK_EQ(MCC_StartADCConv(0), NO_ERR);
    /* RIO set 0, DI0 (loops back from port 0's output bit 0) closes the system. */
    CHECK_EQ(MCC_EnableRIOSetControl(RIO_SET0, 0), NO_ERR);
    CHECK_EQ(MCC_EnableRIOSlaveControl(RIO_SET0, 0, 0), NO_ERR);
    CHECK_EQ(MCC_SetRIOTriggerType(RIO_INT_RISE, RIO_SET0, RIO_DI0, 0), NO_ERR);
    CHECK_EQ(MCC_EnableRIOInputTrigger(RIO_SET0, RIO_DI0, 0), NO_ERR);

    MCC_SetFeedSpeed(10, 0);
    CHECK(MCC_Line(100, 0, 0, 0, 0, 0, 0, 0, 0, IMP_AXIS_ALL) >= 0);
    MCC_TimeDelay(200);
    CHECK_EQ(atomic_load(&nTicks), 200);
    CHECK_EQ(atomic_load(&nPosRet), NO_ERR);
    CHECK(dfLastX > 0.0);
    CHECK_EQ(MCC_GetMotionStatus(0), GMS_RUNNING);

    CHECK_EQ(MCC_SetDACOutput(2.0f, 0, 0), NO_ERR);
    MCC_TimeDelay(100);
    CHECK_EQ(atomic_load(&nAborts), 1);
    CHECK_EQ(atomic_load(&nAbortRet), NO_ERR);
    CHECK_EQ(MCC_GetMotionStatus(0), GMS_STOP);

    if (bCloseFromRoutine)
    {
        struct timespec ts = { 0, 1000000 };
        int n = 0;
        CHECK_EQ(MCC_SetRIOOutputValue(0x0001, RIO_SET0, RIO_PORT0, 0), NO_ERR);
        MCC_TimeDelay(1000);   /* returns when the routine stops the clock */
        while (!atomic_load(&nClosedDone) && n++ < 10000)
            nanosleep(&ts, NULL);
        CHECK_EQ(atomic_load(&nCloses), 1);
        CHECK_EQ(atomic_load(&nCloseRet), NO_ERR);
        CHECK_EQ(MCC_GetMotionStatus(0), INITIAL_MOTION_ERR);
        /* Closing what is closed answers NO_ERR, as the vendor's library answers. */
        CHECK_EQ(MCC_CloseSystem(), NO_ERR);
    }
    else
    {
        CHECK_EQ(MCC_CloseSystem(), NO_ERR);
    }
}

int main(int argc, char **argv)
{
    int nCycles = argc > 1 ? atoi(argv[1]) : 5;
    for (int i = 0; i < nCycles; i++)
        Cycle(1);
    Cycle(0);
    CHECK_EQ(atomic_load(&nUnexpected), 0);
    return check_done("isr_reentry");
}
