// InitSys.cpp: examples manual §2 (Group, mechanism and encoder parameters), §3
// (interpolation time) and §4 (starting and closing the library), written the way the
// manual writes it: parameters first, then MCC_InitSystem, then wait for GMS_STOP and
// MCC_CloseSystem. The CHECKs assert what the manuals say happens.
#include <stdio.h>
#include <string.h>
#include "MCCL.h"
#include "MCCL_Fun.h"
#include "check.h"

#define CARD_INDEX          0
#define INTERPOLATION_TIME  2   // 2 ms, the manual's suggested value

int g_nGroupIndex = -1;

// Examples manual §2: system maximum speed, mechanism and encoder parameters, group.
void SetSysParam(WORD wCardType)
{
    (void)wCardType;
    CHECK_EQ(MCC_SetSysMaxSpeed(100), NO_ERR);          // feed speed limit, UU/sec
    CHECK(MCC_GetSysMaxSpeed() == 100.0);

    SYS_MAC_PARAM stAxisParam;
    memset(&stAxisParam, 0, sizeof(SYS_MAC_PARAM));
    stAxisParam.wPosToEncoderDir          = 0;
    stAxisParam.dwPPR                     = 500;
    stAxisParam.wRPM                      = 3000;
    stAxisParam.dfPitch                   = 1.0;
    stAxisParam.dfGearRatio               = 1.0;
    stAxisParam.dfHighLimit               = 50000.0;
    stAxisParam.dfLowLimit                = -50000.0;
    stAxisParam.wPulseMode                = DDA_FMT_PD;
    stAxisParam.wPulseWidth               = 100;
    stAxisParam.wCommandMode              = OCM_PULSE;
    stAxisParam.wOverTravelUpSensorMode   = SL_UNUSED;
    stAxisParam.wOverTravelDownSensorMode = SL_UNUSED;

    for (WORD wChannel = 0; wChannel < MAX_AXIS_NUM; wChannel++)
        CHECK_EQ(MCC_SetMacParam(&stAxisParam, wChannel, CARD_INDEX), NO_ERR);

    SYS_MAC_PARAM stRead;
    memset(&stRead, 0xAB, sizeof(stRead));
    CHECK_EQ(MCC_GetMacParam(&stRead, 3, CARD_INDEX), NO_ERR);
    CHECK(stRead.dwPPR == 500 && stRead.wRPM == 3000 && stRead.dfHighLimit == 50000.0);

    SYS_ENCODER_CONFIG stENCConfig;
    memset(&stENCConfig, 0, sizeof(SYS_ENCODER_CONFIG));
    stENCConfig.wType      = ENC_TYPE_AB;
    stENCConfig.wAInverse  = 0;
    stENCConfig.wBInverse  = 0;
    stENCConfig.wCInverse  = 0;
    stENCConfig.wABSwap    = 0;
    stENCConfig.wInputRate = 4;   // x4

    for (WORD wChannel = 0; wChannel < MAX_AXIS_NUM; wChannel++)
        CHECK_EQ(MCC_SetEncoderConfig(&stENCConfig, wChannel), NO_ERR);   // default card 0

    // Group: X..B on channels 0..7 of this card (user manual Fig. 2.4.4 style).
    CHECK_EQ(MCC_CloseAllGroups(), NO_ERR);
    g_nGroupIndex = MCC_CreateGroup(0, 1, 2, 3, 4, 5, 6, 7, CARD_INDEX);
    CHECK_EQ(g_nGroupIndex, 0);                  // the first group is group 0
    CHECK_EQ(MCC_GetCmdQueueSize(g_nGroupIndex), MOTION_QUEUE_SIZE);   // 10000 (§2.3)
}

int main()
{
    int nRet;
    WORD wCardType = IMP_III_8_AXIS_PCI_CARD;

    // Before MCC_InitSystem nothing that needs the card works (docs/decisions.md, "Return values");
    // closing what is not open answers NO_ERR, as the vendor's library answers.
    CHECK_EQ(MCC_GetMotionStatus(0), INITIAL_MOTION_ERR);
    CHECK_EQ(MCC_CloseSystem(), NO_ERR);

    SetSysParam(wCardType);

    // Step 1: the card's hardware parameters.
    SYS_CARD_CONFIG stCardConfig[MAX_CARD_NUM];
    memset(stCardConfig, 0, sizeof(stCardConfig));
    stCardConfig[CARD_INDEX].wCardType = wCardType;

    // §3: the interpolation time must be 1..50 ms.
    CHECK_EQ(MCC_InitSystem(0, stCardConfig, 1), PARAMETER_ERR);
    CHECK_EQ(MCC_InitSystem(51, stCardConfig, 1), PARAMETER_ERR);

    // Step 2: start the motion control library.
    nRet = MCC_InitSystem(INTERPOLATION_TIME,   // interpolation time 2 ms
                          stCardConfig,         // hardware parameters
                          1);                   // one IMP card
    CHECK_EQ(nRet, NO_ERR);
    if (nRet == NO_ERR)
    {
        char strVersion[16];
        MCC_GetVersion(strVersion);
        printf("Initialize MCCL successfully (version %s): %d ms interpolation, 1 card, group %d\n",
               strVersion, INTERPOLATION_TIME, g_nGroupIndex);

        // Pulses per UU = dwPPR x dfGearRatio / dfPitch = 500 (examples manual §6).
        CHECK(MCC_GetConvFactor(0, CARD_INDEX) == 500.0);
        CHECK_EQ(MCC_GetMotionStatus(g_nGroupIndex), GMS_STOP);

        // Groups may change while the card runs (as the vendor's library lets them), but a
        // channel belongs to one group only: channel 0 is group 0's X (PARAMETER_ERR).
        CHECK_EQ(MCC_CreateGroup(0, -1, -1, -1, -1, -1, -1, -1, CARD_INDEX), PARAMETER_ERR);

        // §2.4.2: changed mechanism parameters take effect with MCC_UpdateParam.
        SYS_MAC_PARAM stAxisParam;
        MCC_GetMacParam(&stAxisParam, 0, CARD_INDEX);
        stAxisParam.dfGearRatio = 2.0;
        CHECK_EQ(MCC_SetMacParam(&stAxisParam, 0, CARD_INDEX), NO_ERR);
        CHECK(MCC_GetConvFactor(0, CARD_INDEX) == 500.0);
        CHECK_EQ(MCC_UpdateParam(), NO_ERR);
        CHECK(MCC_GetConvFactor(0, CARD_INDEX) == 1000.0);
        printf("After MCC_UpdateParam: channel 0 converts %.0f pulses per UU\n",
               MCC_GetConvFactor(0, CARD_INDEX));
    }

    // Step 3 (1): close after every motion command has finished.
    while ((nRet = MCC_GetMotionStatus(g_nGroupIndex)) != GMS_STOP)
    {
        MCC_TimeDelay(1);   // Sleep 1 ms, releasing the CPU
    }
    CHECK_EQ(MCC_CloseSystem(), NO_ERR);
    CHECK_EQ(MCC_GetMotionStatus(g_nGroupIndex), INITIAL_MOTION_ERR);
    printf("MCCL closed\n");

    return check_done("InitSys");
}
