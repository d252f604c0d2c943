// MotionSys.h: the start-up the examples manual repeats in every motion sample program
// (§2-§4, as in InitSys.cpp), plus small helpers the motion examples share.
//
// The machine every example assumes (all 8 channels alike):
//   dwPPR 500, wRPM 3000, dfPitch 1, dfGearRatio 1, limits +-50000 UU (out of the way)
//   => 500 pulses per UU; maximum safe (PtP 100 %) speed = 3000/60 x 1/1 = 50 UU/s
//   MCC_SetSysMaxSpeed(100): feed speeds above 100 UU/s are clamped to 100
//   interpolation time 1 ms, so MCC_TimeDelay(1) is exactly one tick of virtual time
//   acc/dec time 300 ms, type 'S' (a cubic smoothstep speed ramp), feed 1 UU/s: the
//   defaults the vendor's library reads right after init
//
// Expected times follow the vendor's library (docs/decisions.md): a move runs on the
// grid of periods, na = ceil(Ta/T) and nd = ceil(Td/T) periods of ramps and nc =
// ceil(L/F/T - na/2 - nd/2) at the speed V = L/((na+nd)/2 T + nc T) (at most F); a move
// too short to reach F (L < F (Ta+Td)/2) keeps its ramps and peaks at V = 2L/(Ta+Td).
// With 1 ms periods an unblended move that reaches F so lasts L/F + (Ta+Td)/2 rounded up
// to a whole ms, a short one Ta + Td. The period after its last is its end period
// (phase 21), the next runs nothing, and the status reads GMS_STOP in the third
// (STOP_AFTER_END_MS); a point-to-point move shows one period more.
// Positions read whole pulses toward 0 (500 per UU here: 0.002 UU).
//
// Virtual-time assertions. With MCCL_CLOCK=fast the engine runs ahead on its own while
// a group is busy, so what a program sees in the middle of a move depends on thread
// scheduling: under `fast` the examples assert only end positions and things that hold
// at any moment (status, "on the path", ratios). With MCCL_CLOCK=stepped virtual time
// only advances while the program waits (MCC_TimeDelay(ms) runs exactly ms ticks of
// 1 ms, a status poll of a busy group may run one more), so the examples additionally
// check when moves end (CheckEndsIn) and where the axes are at given instants.
#ifndef MCCL_EXAMPLES_MOTIONSYS_H
#define MCCL_EXAMPLES_MOTIONSYS_H
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <math.h>
#include "MCCL.h"
#include "MCCL_Fun.h"
#include "check.h"

#define CARD_INDEX          0
#define INTERPOLATION_TIME  1       // ms
#define EX_PPR              500     // pulses per motor turn
#define EX_RPM              3000
#define EX_LIMIT            50000.0
#define EX_MAX_SPEED        100.0   // MCC_SetSysMaxSpeed
#define EX_PTP_MAX_SPEED    50.0    // (wRPM / 60) x dfPitch / dfGearRatio, UU/s
#define TOL_MS              (INTERPOLATION_TIME + 1)   // one period + 1 ms
#define STOP_AFTER_END_MS   (3 * INTERPOLATION_TIME)   // GMS_STOP three periods after a move's last
#define POS_TOL             1e-9    // end positions, UU
#define BAD_GROUP           100     // >= MAX_GROUP_NUM (96): never a group

static int g_nGroupIndex = -1;

// True when virtual time only runs while the program waits (MCCL_CLOCK=stepped).
static inline bool SteppedClock()
{
    const char *s = getenv("MCCL_CLOCK");
    return s && (strcasecmp(s, "stepped") == 0 || strcasecmp(s, "step") == 0);
}

// Examples manual §2: mechanism parameters for the 8 channels of the card.
static inline void SetMacParams(double dfHighLimit = EX_LIMIT, double dfLowLimit = -EX_LIMIT)
{
    SYS_MAC_PARAM stAxisParam;
    memset(&stAxisParam, 0, sizeof(SYS_MAC_PARAM));
    stAxisParam.wPosToEncoderDir          = 0;
    stAxisParam.dwPPR                     = EX_PPR;
    stAxisParam.wRPM                      = EX_RPM;
    stAxisParam.dfPitch                   = 1.0;
    stAxisParam.dfGearRatio               = 1.0;
    stAxisParam.dfHighLimit               = dfHighLimit;
    stAxisParam.dfLowLimit                = dfLowLimit;
    stAxisParam.wPulseMode                = DDA_FMT_PD;
    stAxisParam.wPulseWidth               = 100;
    stAxisParam.wCommandMode              = OCM_PULSE;
    stAxisParam.wOverTravelUpSensorMode   = SL_UNUSED;
    stAxisParam.wOverTravelDownSensorMode = SL_UNUSED;
    for (WORD wChannel = 0; wChannel < MAX_AXIS_NUM; wChannel++)
        CHECK_EQ(MCC_SetMacParam(&stAxisParam, wChannel, CARD_INDEX), NO_ERR);

    SYS_ENCODER_CONFIG stENCConfig;
    memset(&stENCConfig, 0, sizeof(SYS_ENCODER_CONFIG));
    stENCConfig.wType      = ENC_TYPE_AB;
    stENCConfig.wInputRate = 4;
    for (WORD wChannel = 0; wChannel < MAX_AXIS_NUM; wChannel++)
        CHECK_EQ(MCC_SetEncoderConfig(&stENCConfig, wChannel, CARD_INDEX), NO_ERR);
}

// Examples manual §4: start the library on one IMP card. The groups are created by the
// caller before this (they cannot change while the card runs).
static inline int StartSystem()
{
    SYS_CARD_CONFIG stCardConfig[MAX_CARD_NUM];
    memset(stCardConfig, 0, sizeof(stCardConfig));
    stCardConfig[CARD_INDEX].wCardType = IMP_III_8_AXIS_PCI_CARD;
    int nRet = MCC_InitSystem(INTERPOLATION_TIME, stCardConfig, 1);
    CHECK_EQ(nRet, NO_ERR);
    if (nRet != NO_ERR)
        printf("MCC_InitSystem failed: %d\n", nRet);
    return nRet;
}

// The whole InitSys.cpp sequence with one group X..B on channels 0..7 (group 0).
static inline int InitSys8(double dfHighLimit = EX_LIMIT, double dfLowLimit = -EX_LIMIT)
{
    CHECK_EQ(MCC_SetSysMaxSpeed(EX_MAX_SPEED), NO_ERR);
    SetMacParams(dfHighLimit, dfLowLimit);
    CHECK_EQ(MCC_CloseAllGroups(), NO_ERR);
    g_nGroupIndex = MCC_CreateGroup(0, 1, 2, 3, 4, 5, 6, 7, CARD_INDEX);
    CHECK_EQ(g_nGroupIndex, 0);
    return StartSystem();
}

// The manual's way to wait for the end of all queued commands, with a guard so that a
// broken engine fails the test instead of hanging it (1e7 ms of virtual time).
static inline void WaitStop(int nGroup)
{
    long n = 0;
    while (MCC_GetMotionStatus((WORD)nGroup) != GMS_STOP && n < 10000000L)
    {
        MCC_TimeDelay(1);
        n++;
    }
    CHECK_EQ(MCC_GetMotionStatus((WORD)nGroup), GMS_STOP);
}

// Stepped clock only (no-op otherwise): the group queued its motion "now" and its last
// motion period is expected to end dfMs of virtual time later, so GMS_STOP reads
// STOP_AFTER_END_MS after that. Checks that it is still busy at dfMs + STOP_AFTER_END_MS
// - TOL_MS and stopped by dfMs + STOP_AFTER_END_MS + TOL_MS (+1 ms for the status poll's
// own tick).
static inline void CheckEndsIn(int nGroup, double dfMs, const char *what)
{
    if (!SteppedClock())
        return;
    dfMs += STOP_AFTER_END_MS;
    long lBefore = (long)floor(dfMs) - TOL_MS;
    if (lBefore > 0)
        MCC_TimeDelay((DWORD)lBefore);
    int nBusy = MCC_GetMotionStatus((WORD)nGroup);
    MCC_TimeDelay(2 * TOL_MS + 1);
    int nDone = MCC_GetMotionStatus((WORD)nGroup);
    printf("  [stepped clock] %s: busy at %ld ms: %s, stopped by %ld ms: %s (expected end %.1f ms)\n",
           what, lBefore, nBusy != GMS_STOP ? "yes" : "NO", lBefore + 2 * TOL_MS + 2,
           nDone == GMS_STOP ? "yes" : "NO", dfMs);
    CHECK(nBusy != GMS_STOP);
    CHECK_EQ(nDone, GMS_STOP);
}

// Current position of the 8 axes of a group (UU).
static inline void GetPos(int nGroup, double p[8])
{
    for (int i = 0; i < 8; i++) p[i] = NAN;
    CHECK_EQ(MCC_GetCurPos(&p[0], &p[1], &p[2], &p[3], &p[4], &p[5], &p[6], &p[7], (WORD)nGroup), NO_ERR);
}

// Checks the X/Y/Z (and optionally all 8) end positions of a group.
static inline void CheckPosXYZ(int nGroup, double x, double y, double z)
{
    double p[8];
    GetPos(nGroup, p);
    CHECK_NEAR(p[0], x, POS_TOL);
    CHECK_NEAR(p[1], y, POS_TOL);
    CHECK_NEAR(p[2], z, POS_TOL);
}

static inline void CheckPos8(int nGroup, const double e[8])
{
    double p[8];
    GetPos(nGroup, p);
    for (int i = 0; i < 8; i++)
        CHECK_NEAR(p[i], e[i], POS_TOL);
}

// Prints where X/Y/Z are, in plain words.
static inline void PrintPos(int nGroup, const char *when)
{
    double p[8];
    GetPos(nGroup, p);
    printf("  %s: X = %.3f, Y = %.3f, Z = %.3f\n", when, p[0], p[1], p[2]);
}

// Pulse position the card reports for an axis at dfUU (GearRatio 1, Pitch 1, PPR 500):
// whole pulses toward 0, a count within 1e-7 of a whole one being that one (as the
// vendor's library counts).
static inline long PulsesOf(double dfUU)
{
    double p = dfUU * 1.0 / 1.0 * EX_PPR;
    double r = round(p);
    return fabs(p - r) <= 1e-7 ? (long)r : (long)trunc(p);
}

static inline void Close()
{
    CHECK_EQ(MCC_CloseSystem(), NO_ERR);
}
#endif
