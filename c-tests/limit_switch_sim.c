/* limit_switch_sim.c: a limit switch worked through MCCL_Sim.h during a move:
 * the group stops, records 0xF701 (X), refuses to move until MCC_ClearError, then moves
 * back. C99. */
#include <string.h>
#include "MCCL.h"
#include "MCCL_Fun.h"
#include "MCCL_Sim.h"
#include "check.h"

int main(void)
{
    SYS_MAC_PARAM m;
    SYS_CARD_CONFIG card[1];
    double x[8], x2[8];
    memset(card, 0, sizeof card);
    card[0].wCardType = IMP_III_8_AXIS_PCI_CARD;
    CHECK_EQ(MCC_GetMacParam(&m, 0, 0), NO_ERR);
    m.wOverTravelUpSensorMode = SL_NORMAL_OPEN;
    CHECK_EQ(MCC_SetMacParam(&m, 0, 0), NO_ERR);
    CHECK_EQ(MCC_InitSystem(1, card, 1), NO_ERR);
    CHECK_EQ(MCC_EnableLimitSwitchCheck(HLP_BIDIR_GEN_ERR), NO_ERR);
    MCC_SetFeedSpeed(10.0, 0);
    CHECK(MCC_Line(10, 0, 0, 0, 0, 0, 0, 0, 0, IMP_AXIS_ALL) >= 0);
    MCC_TimeDelay(300);
    /* The + limit switch closes. */
    CHECK_EQ(MCCL_SimSetSensor(0, 0, MCCL_SIM_LIMIT_PLUS, 1), NO_ERR);
    MCC_TimeDelay(5);
    CHECK_EQ(MCC_GetMotionStatus(0), GMS_STOP);
    CHECK_EQ(MCC_GetErrorCode(0), 0xF701);
    MCC_GetCurPos(&x[0], &x[1], &x[2], &x[3], &x[4], &x[5], &x[6], &x[7], 0);
    CHECK(x[0] > 0.0 && x[0] < 10.0);
    /* Refused until cleared: with an error record every motion command answers
     * RUN_TIME_ERR, as the vendor's library answers. */
    CHECK_EQ(MCC_Line(0, 0, 0, 0, 0, 0, 0, 0, 0, IMP_AXIS_ALL), RUN_TIME_ERR);
    MCC_TimeDelay(200);
    MCC_GetCurPos(&x2[0], &x2[1], &x2[2], &x2[3], &x2[4], &x2[5], &x2[6], &x2[7], 0);
    CHECK(x2[0] == x[0]);
    CHECK_EQ(MCC_ClearError(0), NO_ERR);
    CHECK(MCC_Line(0, 0, 0, 0, 0, 0, 0, 0, 0, IMP_AXIS_ALL) >= 0);
    while (MCC_GetMotionStatus(0) != GMS_STOP)
        MCC_TimeDelay(1);
    MCC_GetCurPos(&x2[0], &x2[1], &x2[2], &x2[3], &x2[4], &x2[5], &x2[6], &x2[7], 0);
    CHECK(x2[0] == 0.0);   /* moved back, away from the pressed switch */
    CHECK_EQ(MCC_GetErrorCode(0), 0);
    CHECK_EQ(MCCL_SimSetSensor(0, 9, MCCL_SIM_LIMIT_PLUS, 1), PARAMETER_ERR);
    CHECK_EQ(MCC_CloseSystem(), NO_ERR);
    CHECK_EQ(MCCL_SimSetSensor(0, 0, MCCL_SIM_LIMIT_PLUS, 1), INITIAL_MOTION_ERR);
    return check_done("limit_switch_sim");
}
