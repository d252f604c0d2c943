// WatchDog.cpp: examples manual §32 (user manual §2.13.2): once enabled, the watchdog
// must be refreshed before its count reaches the compare value, or it resets the card.
//
// Units (docs/compatibility.md, "Watchdog"): the watchdog counts periods of the card's
// timer, whose period is 100 system clocks = 1 µs until MCC_SetTimer changes it. So the
// examples manual's MCC_SetWatchDogTimer(10000000) is 10 s (1 µs x 10000000), and the
// user manual's MCC_SetTimer(1000000) + MCC_SetWatchDogTimer(2000) is 10 ms x 2000
// = 20 s. The watchdog counts while the timer runs (user manual step 4: MCC_EnableTimer) and
// it is enabled (MCC_EnableWatchDogTimer, one of the functions §32 lists).
//
// What the reset does on the virtual card: the card's groups abort and record error
// 0xF103 (MCC_GetErrorCode), servo-on and position-ready go off, DAC outputs go to 0 V,
// remote I/O outputs to 0; the watchdog disables itself.
//
// Expected (1 ms ticks): refreshing every second for 30 s keeps the card alive; after
// the last refresh the reset comes exactly 10000 ms later: not at 9999 ms, at 10000 ms.
// The line X: 0 -> 500 at 10 UU/s (300 ms ramp) then has run 40 s: it stops at
// 10 x (40 - 0.3 / 2) = 398.5 UU.
#include "MotionSys.h"

int main()
{
    if (InitSys8() != NO_ERR)
        return check_done("WatchDog");

    // Outputs the reset must clear: servo on, position ready, DAC 1 at 3 V (read back
    // through ADC 1, wired to DAC 1), remote outputs.
    for (WORD ch = 0; ch < 3; ch++)
        CHECK_EQ(MCC_SetServoOn(ch, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_EnablePosReady(CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_SetDACOutput(3.0f, 1, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_EnableADCConvChannel(1, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_StartADCConv(CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_EnableARIOSlaveControl(RIO_SET0, RIO_SLAVE3, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_SetARIOOutputValue(0xA5A5, RIO_SET0, RIO_SLAVE3, CARD_INDEX), NO_ERR);
    MCC_SetFeedSpeed(10, g_nGroupIndex);
    CHECK_EQ(MCC_Line(500, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex), 0);

    // Step 1: compare value 1 us x 10000000 = 10 s.
    CHECK_EQ(MCC_SetWatchDogTimer(10000000, CARD_INDEX), NO_ERR);
    // Step 2: the reset signal lasts 10000 x 10 ns.
    CHECK_EQ(MCC_SetWatchDogResetPeriod(10000, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_EnableTimer(CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_EnableWatchDogTimer(CARD_INDEX), NO_ERR);

    // Step 3: refresh before the watchdog ends: every second for 30 s.
    for (int i = 0; i < 30; i++)
    {
        MCC_TimeDelay(1000);
        CHECK_EQ(MCC_RefreshWatchDogTimer(CARD_INDEX), NO_ERR);
    }
    CHECK_EQ(MCC_GetErrorCode(g_nGroupIndex), 0);
    CHECK_EQ(MCC_GetMotionStatus(g_nGroupIndex), GMS_RUNNING);
    float fIn = 0;
    CHECK_EQ(MCC_GetADCInput(&fIn, 1, CARD_INDEX), NO_ERR);
    CHECK_NEAR(fIn, 3.0, 1e-6);
    double p[8];
    GetPos(g_nGroupIndex, p);
    printf("  30 s with a refresh every second: no reset, X = %.1f\n", p[0]);
    CHECK_NEAR(p[0], 10 * (30 - 0.15), 1e-6);

    // No more refreshes: 9999 ms later the card still runs ...
    MCC_TimeDelay(9999);
    CHECK_EQ(MCC_GetErrorCode(g_nGroupIndex), 0);
    // ... at 10000 ms it is reset.
    MCC_TimeDelay(1);
    int nErr = MCC_GetErrorCode(g_nGroupIndex);
    printf("  10 s without a refresh: error code 0x%X, status %d\n", nErr, MCC_GetMotionStatus(g_nGroupIndex));
    CHECK_EQ(nErr, 0xF103);
    // The reset stops the group at once, as an abort at once: running for that period,
    // GMS_STOP the period after (as the vendor's library shows an abort).
    CHECK_EQ(MCC_GetMotionStatus(g_nGroupIndex), GMS_RUNNING);
    MCC_TimeDelay(1);
    CHECK_EQ(MCC_GetMotionStatus(g_nGroupIndex), GMS_STOP);
    GetPos(g_nGroupIndex, p);
    // 40 s of motion at 10 UU/s after a 300 ms ramp: 400 - 1.5 UU.
    CHECK_NEAR(p[0], 398.5, 1e-6);
    MCC_TimeDelay(100);
    CHECK_EQ(MCC_GetADCInput(&fIn, 1, CARD_INDEX), NO_ERR);
    CHECK_NEAR(fIn, 0.0, 1e-6);   // DAC 1 at 0 V
    WORD wOut = 0xFFFF;
    CHECK_EQ(MCC_GetARIOOutputValue(&wOut, RIO_SET0, RIO_SLAVE3, CARD_INDEX), NO_ERR);
    CHECK_EQ(wOut, 0);
    GetPos(g_nGroupIndex, p);
    CHECK_NEAR(p[0], 398.5, 1e-6);   // nothing moves until the error is cleared

    // The program clears the error and goes on.
    CHECK_EQ(MCC_ClearError(g_nGroupIndex), NO_ERR);
    CHECK_EQ(MCC_Line(0, 0, 0, 0, 0, 0, 0, 0, g_nGroupIndex), 1);
    WaitStop(g_nGroupIndex);
    CheckPosXYZ(g_nGroupIndex, 0, 0, 0);

    CHECK_EQ(MCC_SetWatchDogTimer(0, CARD_INDEX), PARAMETER_ERR);
    CHECK_EQ(MCC_RefreshWatchDogTimer(1), PARAMETER_ERR);
    Close();
    return check_done("WatchDog");
}
