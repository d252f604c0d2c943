/* home_abort.c: MCC_AbortGoHome in the middle of phase 1, C99. Run with
 * MCCL_SIM=c-tests/sim/home_x.toml (X's home sensor on [-3, -2] UU).
 *
 * Mode 3, negative, 300 ms ramps, 10 UU/s: accelerating covers 1.5 UU in 300 ms, then
 * 0.01 UU a tick; at 320 ms X is at -1.7 UU, still searching the sensor. The abort
 * decelerates over dfDecTime (300 ms, 1.5 UU): X stops at -3.2 UU. Meanwhile the status
 * reads 0; then HOME_COMMAND_NOTCALLED_ERR (homing did not complete), the group is stopped
 * with no error record and its position is not zeroed. A new MCC_Home then completes. */
#include <string.h>
#include "MCCL.h"
#include "MCCL_Fun.h"
#include "MCCL_Sim.h"
#include "check.h"

static double motor_x(void)
{
    double p = 0;
    long long n = 0;
    CHECK_EQ(MCCL_SimGetMotor(0, 0, &p, &n), NO_ERR);
    return p;
}

int main(void)
{
    SYS_CARD_CONFIG card[1];
    SYS_HOME_CONFIG h;
    double x[8];
    int ms;
    memset(card, 0, sizeof card);
    card[0].wCardType = IMP_III_8_AXIS_PCI_CARD;
    memset(&h, 0, sizeof h);
    h.wMode = 3;
    h.wDirection = 1;
    h.wSensorMode = SL_NORMAL_OPEN;
    h.dfAccTime = 300;
    h.dfDecTime = 300;
    h.dfHighSpeed = 10;
    h.dfLowSpeed = 2;
    CHECK_EQ(MCC_SetHomeConfig(&h, 0, 0), NO_ERR);
    CHECK_EQ(MCC_InitSystem(1, card, 1), NO_ERR);
    /* Nothing started yet: the go-home status reads 1 (as the vendor's library reads it
     * right after init) and there is nothing to stop. */
    CHECK_EQ(MCC_GetGoHomeStatus(), 1);
    CHECK_EQ(MCC_AbortGoHome(), NO_ERR);

    CHECK_EQ(MCC_Home(0, 255, 255, 255, 255, 255, 255, 255, 0), NO_ERR);
    MCC_TimeDelay(320);
    CHECK_EQ(MCC_GetGoHomeStatus(), 0);
    CHECK_NEAR(motor_x(), -1.7, 1e-9);
    CHECK_EQ(MCC_AbortGoHome(), NO_ERR);
    MCC_TimeDelay(150);
    CHECK_EQ(MCC_GetGoHomeStatus(), 0);                     /* still decelerating */
    CHECK_EQ(MCC_GetMotionStatus(0), GMS_RUNNING);
    for (ms = 0; MCC_GetGoHomeStatus() == 0 && ms < 10000; ms++)
        MCC_TimeDelay(1);
    CHECK_EQ(MCC_GetGoHomeStatus(), HOME_COMMAND_NOTCALLED_ERR);
    CHECK_EQ(MCC_GetMotionStatus(0), GMS_STOP);
    CHECK_EQ(MCC_GetErrorCode(0), 0);
    CHECK_NEAR(motor_x(), -3.2, 1e-9);
    MCC_GetCurPos(&x[0], &x[1], &x[2], &x[3], &x[4], &x[5], &x[6], &x[7], 0);
    CHECK_NEAR(x[0], -3.2, 1e-9);                           /* not homed: not zeroed */
    CHECK_EQ(MCC_AbortGoHome(), HOME_COMMAND_NOTCALLED_ERR);

    /* Again, to the end. From -3.2 UU (inside the sensor: Case 2) the search would need
     * the limit switches, which are unused here: move above the sensor first, to +1 UU.
     * From there as in GoHome.cpp: 1.5 UU accelerating, the edge -2 UU reached at 10 UU/s,
     * 1.5 UU decelerating: the machine home is -3.5 UU. */
    CHECK(MCC_Line(1, 0, 0, 0, 0, 0, 0, 0, 0, IMP_AXIS_ALL) >= 0);
    while (MCC_GetMotionStatus(0) != GMS_STOP)
        MCC_TimeDelay(1);
    CHECK_EQ(MCC_Home(0, 255, 255, 255, 255, 255, 255, 255, 0), NO_ERR);
    for (ms = 0; MCC_GetGoHomeStatus() == 0 && ms < 100000; ms++)
        MCC_TimeDelay(1);
    CHECK_EQ(MCC_GetGoHomeStatus(), 1);
    CHECK_NEAR(motor_x(), -3.5, 1e-9);
    MCC_GetCurPos(&x[0], &x[1], &x[2], &x[3], &x[4], &x[5], &x[6], &x[7], 0);
    CHECK_EQ(x[0], 0.0);
    CHECK_EQ(MCC_CloseSystem(), NO_ERR);
    return check_done("home_abort");
}
