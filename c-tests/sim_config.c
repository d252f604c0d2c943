/* sim_config.c: the simulated machine read from MCCL_SIM. With "bad" the
 * configuration is malformed and MCC_InitSystem must refuse to start; with "good" it
 * must honour the file: + limit switch of X at 3 UU, home sensor of Y over [-1, 1],
 * a 20 ms lag on Z (following error = speed x lag). */
#include <stdio.h>
#include <string.h>
#include "MCCL.h"
#include "MCCL_Fun.h"
#include "MCCL_Sim.h"
#include "check.h"

int main(int argc, char **argv)
{
    SYS_MAC_PARAM m;
    SYS_CARD_CONFIG card[1];
    WORD w = 9;
    double x[8];
    int e[8];
    memset(card, 0, sizeof card);
    card[0].wCardType = IMP_III_8_AXIS_PCI_CARD;
    if (argc > 1 && strcmp(argv[1], "bad") == 0) {
        CHECK_EQ(MCC_InitSystem(1, card, 1), INITIAL_MOTION_ERR);
        CHECK_EQ(MCC_GetMotionStatus(0), INITIAL_MOTION_ERR);   /* nothing started */
        return check_done("sim_config bad");
    }
    CHECK_EQ(MCC_GetMacParam(&m, 0, 0), NO_ERR);
    m.wOverTravelUpSensorMode = SL_NORMAL_OPEN;
    CHECK_EQ(MCC_SetMacParam(&m, 0, 0), NO_ERR);
    CHECK_EQ(MCC_InitSystem(1, card, 1), NO_ERR);
    /* Y starts inside its home sensor region. */
    CHECK_EQ(MCC_GetHomeSensorStatus(&w, 1, 0), NO_ERR);
    CHECK_EQ(w, 1);
    CHECK_EQ(MCC_EnableLimitSwitchCheck(HLP_UNIDIR), NO_ERR);
    MCC_SetFeedSpeed(10.0, 0);
    MCC_SetAccTime(0, 0);
    MCC_SetDecTime(0, 0);
    MCC_Line(10, 2, 10, 0, 0, 0, 0, 0, 0, IMP_AXIS_ALL);
    MCC_TimeDelay(150);
    /* Z is 10/sqrt(204) of the path speed... all three start together; at 150 ms the
     * following error of Z is about speed x 20 ms (minus the first e-folding). */
    CHECK_EQ(MCC_GetErrorCount(&e[0], &e[1], &e[2], &e[3], &e[4], &e[5], &e[6], &e[7], 0), NO_ERR);
    printf("following error at 150 ms: X %d, Z %d pulses\n", e[0], e[2]);
    CHECK(e[0] == 0);          /* X ideal */
    CHECK(e[2] > 20 && e[2] < 80);   /* Z at 10 x 10/sqrt(204) UU/s x 0.02 s x 500 ~ 70 */
    while (MCC_GetMotionStatus(0) != GMS_STOP)
        MCC_TimeDelay(1);
    MCC_GetCurPos(&x[0], &x[1], &x[2], &x[3], &x[4], &x[5], &x[6], &x[7], 0);
    printf("stopped by the + limit switch of X at %.3f\n", x[0]);
    CHECK(x[0] >= 3.0 && x[0] < 3.02);
    CHECK_EQ(MCC_GetLimitSwitchStatus(&w, 0, 0, 0), NO_ERR);
    CHECK_EQ(w, 1);
    /* The whole group stopped with X: Y = X x 2/10 ~ 0.6, still inside [-1, 1]. */
    CHECK(x[1] > 0.59 && x[1] < 0.61);
    CHECK_EQ(MCC_GetHomeSensorStatus(&w, 1, 0), NO_ERR);
    CHECK_EQ(w, 1);
    MCC_Line(0, 1.5, 0, 0, 0, 0, 0, 0, 0, IMP_AXIS_ALL);   /* Y out of the region */
    while (MCC_GetMotionStatus(0) != GMS_STOP)
        MCC_TimeDelay(1);
    CHECK_EQ(MCC_GetHomeSensorStatus(&w, 1, 0), NO_ERR);
    CHECK_EQ(w, 0);
    CHECK_EQ(MCC_CloseSystem(), NO_ERR);
    return check_done("sim_config good");
}
