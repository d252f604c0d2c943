/* initsys_c99.c: the InitSys flow of examples manual §2-4 as a C99 program (no C++
 * default arguments: every card and group index is passed explicitly). */
#include <stdio.h>
#include <string.h>
#include "MCCL.h"
#include "MCCL_Fun.h"
#include "check.h"

#define CARD_INDEX 0
#define INTERPOLATION_TIME 2

int main(void)
{
    SYS_MAC_PARAM stAxisParam;
    SYS_ENCODER_CONFIG stENCConfig;
    SYS_CARD_CONFIG stCardConfig[MAX_CARD_NUM];
    WORD wChannel;
    int nGroup, nRet;

    CHECK_EQ(MCC_SetSysMaxSpeed(100.0), NO_ERR);

    memset(&stAxisParam, 0, sizeof(stAxisParam));
    stAxisParam.dwPPR = 500;
    stAxisParam.wRPM = 3000;
    stAxisParam.dfPitch = 1.0;
    stAxisParam.dfGearRatio = 1.0;
    stAxisParam.dfHighLimit = 50000.0;
    stAxisParam.dfLowLimit = -50000.0;
    stAxisParam.wPulseMode = DDA_FMT_PD;
    stAxisParam.wPulseWidth = 100;   /* the vendor's library refuses a pulse width of 0 */
    stAxisParam.wCommandMode = OCM_PULSE;
    stAxisParam.wOverTravelUpSensorMode = SL_UNUSED;
    stAxisParam.wOverTravelDownSensorMode = SL_UNUSED;
    for (wChannel = 0; wChannel < MAX_AXIS_NUM; wChannel++)
        CHECK_EQ(MCC_SetMacParam(&stAxisParam, wChannel, CARD_INDEX), NO_ERR);

    memset(&stENCConfig, 0, sizeof(stENCConfig));
    stENCConfig.wType = ENC_TYPE_AB;
    stENCConfig.wInputRate = 4;
    for (wChannel = 0; wChannel < MAX_AXIS_NUM; wChannel++)
        CHECK_EQ(MCC_SetEncoderConfig(&stENCConfig, wChannel, CARD_INDEX), NO_ERR);

    /* User manual Fig. 2.4.4: two groups on one card. */
    CHECK_EQ(MCC_CloseAllGroups(), NO_ERR);
    nGroup = MCC_CreateGroup(0, 1, 2, -1, -1, -1, -1, -1, CARD_INDEX);
    CHECK_EQ(nGroup, 0);
    CHECK_EQ(MCC_CreateGroupEx(3, 4, 5, -1, -1, -1, -1, -1, CARD_INDEX, 50), 1);
    CHECK_EQ(MCC_GetCmdQueueSize(1), 50);
    /* A group on a card that InitSystem will not have is refused at init. */
    CHECK_EQ(MCC_CreateGroup(0, -1, -1, -1, -1, -1, -1, -1, 1), 2);

    memset(stCardConfig, 0, sizeof(stCardConfig));
    stCardConfig[CARD_INDEX].wCardType = IMP_III_8_AXIS_PCI_CARD;
    CHECK_EQ(MCC_InitSystem(INTERPOLATION_TIME, stCardConfig, 1), GROUP_PARAMETER_ERR);
    CHECK_EQ(MCC_CloseGroup(2), NO_ERR);
    CHECK_EQ(MCC_InitSystem(INTERPOLATION_TIME, stCardConfig, 0), PARAMETER_ERR);
    /* A NULL card table is taken as IMP-III cards, as the vendor's library takes it; a
     * close forgets the group table, so the groups are made again. */
    CHECK_EQ(MCC_InitSystem(INTERPOLATION_TIME, NULL, 1), NO_ERR);
    CHECK_EQ(MCC_GetMotionStatus(1), GMS_STOP);
    CHECK_EQ(MCC_CloseSystem(), NO_ERR);
    CHECK_EQ(MCC_CreateGroup(0, 1, 2, -1, -1, -1, -1, -1, CARD_INDEX), 0);
    CHECK_EQ(MCC_CreateGroupEx(3, 4, 5, -1, -1, -1, -1, -1, CARD_INDEX, 50), 1);

    nRet = MCC_InitSystem(INTERPOLATION_TIME, stCardConfig, 1);
    CHECK_EQ(nRet, NO_ERR);
    CHECK_EQ(MCC_GetMotionStatus(0), GMS_STOP);
    CHECK_EQ(MCC_GetMotionStatus(1), GMS_STOP);
    CHECK_EQ(MCC_GetMotionStatus(2), GROUP_PARAMETER_ERR);

    while (MCC_GetMotionStatus(nGroup) != GMS_STOP)
        MCC_TimeDelay(1);
    CHECK_EQ(MCC_CloseSystem(), NO_ERR);
    return check_done("initsys_c99");
}
