/* layout_check.h: sizes and field offsets of the vendor structs (docs/vendor-interface.md,
 * "Struct layouts"), checked from C and C++ against the values the vendor's (Windows)
 * layout gives. */
#include <stddef.h>
#include "MCCL.h"
#include "check.h"

#define SIZE(T, n) CHECK_EQ(sizeof(T), n)
#define OFF(T, f, n) CHECK_EQ(offsetof(T, f), n)

static int check_layouts(void)
{
    SIZE(COMMAND_INFO, 104);
    OFF(COMMAND_INFO, nCommandIndex, 4); OFF(COMMAND_INFO, dfFeedSpeed, 8);
    OFF(COMMAND_INFO, dfPos, 16); OFF(COMMAND_INFO, dfAcctime, 80);
    OFF(COMMAND_INFO, dfDectime, 88); OFF(COMMAND_INFO, nMotionPhase, 96);
    OFF(COMMAND_INFO, nCommandIndex_LD, 100);

    SIZE(SYS_MAC_PARAM, 72);
    OFF(SYS_MAC_PARAM, wRPM, 2); OFF(SYS_MAC_PARAM, dwPPR, 4); OFF(SYS_MAC_PARAM, dfPitch, 8);
    OFF(SYS_MAC_PARAM, dfGearRatio, 16); OFF(SYS_MAC_PARAM, dfHighLimit, 24);
    OFF(SYS_MAC_PARAM, dfLowLimit, 32); OFF(SYS_MAC_PARAM, dfHighLimitOffset, 40);
    OFF(SYS_MAC_PARAM, dfLowLimitOffset, 48); OFF(SYS_MAC_PARAM, wPulseMode, 56);
    OFF(SYS_MAC_PARAM, wPulseWidth, 58); OFF(SYS_MAC_PARAM, wCommandMode, 60);
    OFF(SYS_MAC_PARAM, wPaddle, 62); OFF(SYS_MAC_PARAM, wOverTravelUpSensorMode, 64);
    OFF(SYS_MAC_PARAM, wOverTravelDownSensorMode, 66);

    SIZE(SYS_MAC_PARAM_EX, 72);
    OFF(SYS_MAC_PARAM_EX, dwRPM, 8); OFF(SYS_MAC_PARAM_EX, dwPPR, 12);
    OFF(SYS_MAC_PARAM_EX, dfPitch, 16); OFF(SYS_MAC_PARAM_EX, wOverTravelUpSensorMode, 64);

    SIZE(SYS_ENCODER_CONFIG, 16);
    OFF(SYS_ENCODER_CONFIG, wInputRate, 10); OFF(SYS_ENCODER_CONFIG, wPaddle, 12);
    SIZE(ENCODER_CONFIG, 16);
    SIZE(SYS_PULSE_CONFIG, 8);

    SIZE(SYS_HOME_CONFIG, 56);
    OFF(SYS_HOME_CONFIG, nIndexCount, 8); OFF(SYS_HOME_CONFIG, nPaddel1, 12);
    OFF(SYS_HOME_CONFIG, dfAccTime, 16); OFF(SYS_HOME_CONFIG, dfDecTime, 24);
    OFF(SYS_HOME_CONFIG, dfHighSpeed, 32); OFF(SYS_HOME_CONFIG, dfLowSpeed, 40);
    OFF(SYS_HOME_CONFIG, dfOffset, 48);
    SIZE(SYS_HOME_CONFIG_EX, 88);
    OFF(SYS_HOME_CONFIG_EX, dfStableTime, 56); OFF(SYS_HOME_CONFIG_EX, wStaticError, 80);
    OFF(SYS_HOME_CONFIG_EX, wTolerance, 82);

    SIZE(SYS_COMP_PARAM, 2056);
    OFF(SYS_COMP_PARAM, wHome_No, 4); OFF(SYS_COMP_PARAM, nForwardTable, 8);
    OFF(SYS_COMP_PARAM, nBackwardTable, 1032);

    SIZE(SYS_CARD_CONFIG, 8);
    OFF(SYS_CARD_CONFIG, wIRQ_No, 4);
    SIZE(HOME_CONFIG, 16);
    OFF(HOME_CONFIG, wApproachDir, 2); OFF(HOME_CONFIG, wLeaveDir, 4);
    OFF(HOME_CONFIG, wSensorMode, 6); OFF(HOME_CONFIG, dfOffset, 8);
    SIZE(SYS_MACH_PARAM, 104);
    OFF(SYS_MACH_PARAM, dwPPR, 4); OFF(SYS_MACH_PARAM, dfPitch, 8);
    OFF(SYS_MACH_PARAM, dfLowLimitOffset, 48); OFF(SYS_MACH_PARAM, wPulseMode, 56);
    OFF(SYS_MACH_PARAM, wPaddle, 62);
    OFF(SYS_MACH_PARAM, stHome, 64); OFF(SYS_MACH_PARAM, stEncoder, 80);
    OFF(SYS_MACH_PARAM, wOverTravelUpSensorMode, 96);
    OFF(SYS_MACH_PARAM, wOverTravelDownSensorMode, 98);
    SIZE(SYS_GROUP_INFO, 36);
    SIZE(SYS_GROUP_CONFIG, 3840);
    OFF(SYS_GROUP_CONFIG, stGroupInfo, 384);

    SIZE(LIOINT, 24); OFF(LIOINT, OTN0, 8); OFF(LIOINT, HOME0, 16);
    SIZE(ENCINT, 16); OFF(ENCINT, COMP0, 8);
    SIZE(PCLINT, 16); OFF(PCLINT, OVN0, 8);
    SIZE(ADCINT, 10); OFF(ADCINT, CONV, 8); OFF(ADCINT, TAG, 9);
    SIZE(TMRINT, 1);
    SIZE(RIOINT, 8);
    SIZE(HSKINT, 1);

    /* Typedef widths (docs/decisions.md, "The C ABI and the headers"). */
    SIZE(WORD, 2); SIZE(DWORD, 4); SIZE(BYTE, 1); SIZE(BOOL, 4);
    return 0;
}
