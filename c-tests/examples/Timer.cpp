// Timer.cpp: examples manual §31 (the manual's TimerTrigger.cpp): the card's 32-bit timer
// calls a user routine each time its count reaches the set value, and starts again.
//
// Units (docs/compatibility.md, "Timer unit"): MCC_SetTimer counts system clocks of
// 10 ns, as the user manual (EN and ZH §2.13) says; the examples manual's text says 1 µs
// for the same call. So the manual's MCC_SetTimer(1000) is 10 µs here, and a 1 ms timer
// is MCC_SetTimer(100000).
// The virtual card runs in ticks of the interpolation time (1 ms here): a timer whose
// period ends in a tick calls the routine once after that tick, TIMER = how many times
// the period ended in the tick (saturated at 255).
//
// Expected numbers (INTERPOLATION_TIME 1 ms, MCC_TimeDelay(n) = n ticks):
//   1 ms timer, 1000 ms          -> 1000 calls, TIMER = 1 each
//   trigger off, 100 ms          -> no call
//   25 ms timer (restarts), 100 ms -> 4 calls
//   10 µs timer (the manual's 1000), 10 ms -> 10 calls, TIMER = 100 each
//   timer off, 100 ms            -> no call
// The manual declares the routine `void _stdcall f(TMRINT*)`; MCC_CALLBACK is that
// calling convention on Windows and empty elsewhere.
#include "MotionSys.h"

static volatile int nISRCount = 0;
static volatile int nTimerSum = 0;
static volatile int nLastTimer = 0;

// Step 1-2: declare and define the routine.
void MCC_CALLBACK Timer_ISR_Function(TMRINT *pstINTSource)
{
    // Not 0: the timer ended (TIMER times in this tick).
    if (pstINTSource->TIMER)
    {
        nISRCount++;
        nTimerSum += pstINTSource->TIMER;
        nLastTimer = pstINTSource->TIMER;
    }
}

int main()
{
    if (InitSys8() != NO_ERR)
        return check_done("Timer");

    // Step 3: connect the routine.
    CHECK_EQ(MCC_SetTMRRoutine(Timer_ISR_Function, CARD_INDEX), NO_ERR);
    // Step 4: the timer's length: 100000 x 10 ns = 1 ms.
    CHECK_EQ(MCC_SetTimer(100000, CARD_INDEX), NO_ERR);
    // Step 5: start timing.
    CHECK_EQ(MCC_EnableTimer(CARD_INDEX), NO_ERR);
    // Step 6: the end of each period calls the routine.
    CHECK_EQ(MCC_EnableTimerTrigger(CARD_INDEX), NO_ERR);

    MCC_TimeDelay(1000);
    printf("  1 ms timer, 1000 ms: %d calls, TIMER = %d\n", nISRCount, nLastTimer);
    CHECK_EQ(nISRCount, 1000);
    CHECK_EQ(nTimerSum, 1000);

    CHECK_EQ(MCC_DisableTimerTrigger(CARD_INDEX), NO_ERR);
    MCC_TimeDelay(100);
    CHECK_EQ(nISRCount, 1000);

    CHECK_EQ(MCC_EnableTimerTrigger(CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_SetTimer(2500000, CARD_INDEX), NO_ERR);   // 25 ms
    MCC_TimeDelay(100);
    printf("  25 ms timer, 100 ms: %d calls\n", nISRCount - 1000);
    CHECK_EQ(nISRCount, 1004);

    CHECK_EQ(MCC_SetTimer(1000, CARD_INDEX), NO_ERR);      // the manual's value: 10 us
    nTimerSum = 0;
    MCC_TimeDelay(10);
    printf("  10 us timer, 10 ms: %d calls, TIMER = %d per call\n", nISRCount - 1004, nLastTimer);
    CHECK_EQ(nISRCount, 1014);
    CHECK_EQ(nLastTimer, 100);
    CHECK_EQ(nTimerSum, 1000);

    CHECK_EQ(MCC_DisableTimer(CARD_INDEX), NO_ERR);
    MCC_TimeDelay(100);
    CHECK_EQ(nISRCount, 1014);

    // Bad arguments change nothing.
    CHECK_EQ(MCC_SetTimer(0, CARD_INDEX), PARAMETER_ERR);
    CHECK_EQ(MCC_EnableTimer(1), PARAMETER_ERR);   // only card 0 was started
    CHECK_EQ(MCC_SetTMRRoutine(Timer_ISR_Function, MAX_CARD_NUM), PARAMETER_ERR);

    Close();
    return check_done("Timer");
}
