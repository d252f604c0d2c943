// ENCCompareContinue.cpp: examples manual §26-28 (several encoder compare values trigger
// local outputs and the interrupt routine). X's compare values are 10000, 20000, ...,
// 50000; X and Y run 60 UU, i.e. 30000 counts at 500 counts/UU, so 10000, 20000 and
// 30000 fire (three routine calls, COMP0 each time) and two stay in the stock. Each turns
// Y's servo-on output (SERVO_POINT) off for 0.5 s (trigger value 1 = Servo-Off), then back
// on, and lights Y's LED for the same 0.5 s (the LED trigger-out of the A header). Then §27: channels 0 and 1 compared together within a tolerance of 100 counts; the
// pair fires only when both reach their values.
#include "MotionSys.h"
#include "MCCL_Sim.h"

#define SERVO_POINT 1

static volatile int ENC_ISR = 0, SERVO_OFF_SEEN = 0, LED_ON_SEEN = 0, COMP1_SEEN = 0;

void _stdcall ENC_ISR_Function(ENCINT *pstINTSource)
{
    if (pstINTSource->COMP0)
    {
        ENC_ISR++;
        int nServo = 1;
        MCCL_SimGetOutput(CARD_INDEX, SERVO_POINT, MCCL_SIM_OUT_SERVO, &nServo);
        if (nServo == 0)
            SERVO_OFF_SEEN++;   // the trigger-out acted in the same tick
        WORD wLed = 0;
        MCC_GetLedLightStatus(SERVO_POINT, &wLed, CARD_INDEX);
        if (wLed == 1)
            LED_ON_SEEN++;
    }
    if (pstINTSource->COMP1)
        COMP1_SEEN++;
}

int main()
{
    if (InitSys8() != NO_ERR)
        return check_done("ENCCompareContinue");
    MCC_SetFeedSpeed(20, g_nGroupIndex);
    CHECK_EQ(MCC_SetServoOn(SERVO_POINT, CARD_INDEX), NO_ERR);

    // Step 1: compare channel 0 alone.
    CHECK_EQ(MCC_Enable3DCompareChannel(0x1 << ENC_COMP_CH0, CARD_INDEX), NO_ERR);
    // Step 2: the values (or MCC_SetENCCompValueTab(10000, 50000, 10000, ENC_COMP_CH0)).
    for (long v = 10000; v <= 50000; v += 10000)
        CHECK_EQ(MCC_SetENCCompValue(v, ENC_COMP_CH0, CARD_INDEX), NO_ERR);
    // Step 3.1: the local output it drives.
    CHECK_EQ(MCC_SetLIOTrigOutEnable(1, SERVO_POINT, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_SetLIOTrigOutValue(1, SERVO_POINT, CARD_INDEX), NO_ERR);   // 1: Servo-Off
    CHECK_EQ(MCC_SetLIOTrigOutSource(IO_TRIG_ENC0, SERVO_POINT, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_SetLIOTrigOutPeriod(500000000, CARD_INDEX), NO_ERR);       // 0.5 s in ns
    // Y's LED lights on the same compares, for the same period.
    CHECK_EQ(MCC_SetLedTrigOutEnable(1, SERVO_POINT, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_SetLedTrigOutValue(1, SERVO_POINT, CARD_INDEX), NO_ERR);   // 1: lit
    CHECK_EQ(MCC_SetLedTrigOutSource(LED_TRIG_ENC0, SERVO_POINT, CARD_INDEX), NO_ERR);
    // Step 3.2: the routine.
    CHECK_EQ(MCC_SetENCRoutine(ENC_ISR_Function, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_EnableENCCompTrigger(ENC_COMP_CH0, CARD_INDEX), NO_ERR);
    WORD wCount = 0;
    CHECK_EQ(MCC_GetLIOCompStockCount(&wCount, CARD_INDEX), NO_ERR);
    CHECK_EQ(wCount, 5);

    MCC_Line(60, 60, 0, 0, 0, 0, 0, 0, g_nGroupIndex);
    WaitStop(g_nGroupIndex);
    MCC_TimeDelay(600);
    int nServo = 0;
    CHECK_EQ(MCCL_SimGetOutput(CARD_INDEX, SERVO_POINT, MCCL_SIM_OUT_SERVO, &nServo), NO_ERR);
    printf("30000 counts: routine %d time(s), Y servo off at each: %d, back on after: %d\n",
           ENC_ISR, SERVO_OFF_SEEN, nServo);
    CHECK_EQ(ENC_ISR, 3);          // 10000, 20000, 30000 reached
    CHECK_EQ(SERVO_OFF_SEEN, 3);
    CHECK_EQ(nServo, 1);
    WORD wLed = 9;
    CHECK_EQ(MCC_GetLedLightStatus(SERVO_POINT, &wLed, CARD_INDEX), NO_ERR);
    printf("  Y's LED lit at each: %d, dark after: %d\n", LED_ON_SEEN, wLed == 0);
    CHECK_EQ(LED_ON_SEEN, 3);
    CHECK_EQ(wLed, 0);
    CHECK_EQ(MCC_SetLedTrigOutEnable(1, 8, CARD_INDEX), PARAMETER_ERR);
    CHECK_EQ(MCC_SetLedTrigOutValue(2, SERVO_POINT, CARD_INDEX), PARAMETER_ERR);
    CHECK_EQ(MCC_SetLedTrigOutSource(0x100, SERVO_POINT, CARD_INDEX), PARAMETER_ERR);
    // Step 4: two values still waiting; erase them.
    CHECK_EQ(MCC_GetLIOCompStockCount(&wCount, CARD_INDEX), NO_ERR);
    CHECK_EQ(wCount, 2);
    CHECK_EQ(MCC_EraseLIOCompValue(CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_GetLIOCompStockCount(&wCount, CARD_INDEX), NO_ERR);
    CHECK_EQ(wCount, 0);

    // §27: channels 0 and 1 together, tolerance 100 counts. Y's value is reached only
    // when Y moves too: X alone to 40 UU (20000 counts) fires nothing.
    ENC_ISR = 0;
    CHECK_EQ(MCC_Enable3DCompareChannel(0x1 << ENC_COMP_CH0 | 0x1 << ENC_COMP_CH1, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_Set3DCompareTolerance(100, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_SetENCCompValue(40000, ENC_COMP_CH0, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_SetENCCompValue(40000, ENC_COMP_CH1, CARD_INDEX), NO_ERR);
    CHECK_EQ(MCC_EnableENCCompTrigger(ENC_COMP_CH1, CARD_INDEX), NO_ERR);
    MCC_Line(80, 60, 0, 0, 0, 0, 0, 0, g_nGroupIndex);   // X to 40000 counts, Y stays at 30000
    WaitStop(g_nGroupIndex);
    CHECK_EQ(ENC_ISR, 0);
    MCC_Line(80, 80, 0, 0, 0, 0, 0, 0, g_nGroupIndex);   // now Y reaches 40000 too
    WaitStop(g_nGroupIndex);
    printf("3-D compare: fired once both reached 40000: COMP0 %d, COMP1 %d\n", ENC_ISR, COMP1_SEEN);
    CHECK_EQ(ENC_ISR, 1);
    CHECK_EQ(COMP1_SEEN, 1);
    CHECK_EQ(MCC_SetLIOTrigOutEnable(2, SERVO_POINT, CARD_INDEX), PARAMETER_ERR);
    CHECK_EQ(MCC_SetLIOTrigOutSource(0x100, SERVO_POINT, CARD_INDEX), PARAMETER_ERR);
    Close();
    return check_done("ENCCompareContinue");
}
