/* What a program reads: every getter right after init, after MCC_ResetMotion and after
 * each setter; card tables; init and close sequences; bad arguments and the records they
 * leave; origins; compensation. */
#include "common.h"
#include <math.h>
#include <string.h>

STD_SETUP(std3, 10000, 1, 3)
STD_SETUP(std8, 10000, 1, 8)

static void state_after_init(int t)
{
    if (t == 0) {
        vd_dump_system();
        vd_dump_group(0);
    }
}

static void state_after_reset(int t)
{
    if (t == 0) {
        CI(MCC_SetIncrease, 0);
        vd_profile('T', 30, 40, 7);
        CD(MCC_SetPtPSpeed, 30, 0);
        CD(MCC_OverrideSpeed, 80, 0);
        CI(MCC_EnableBlend, 0);
        LINE(0, 0.3, 0.2, 0.1);
    }
    if (t == 20)
        CI(MCC_ResetMotion);
    if (t == 21) {
        vd_dump_system();
        vd_dump_group(0);
    }
    if (t == 30)
        LINE(0, 0.1, 0, 0);
}

static void state_reset_idle(int t)
{
    if (t == 0) {
        vd_profile('T', 30, 40, 7);
        LINE(0, 0.3, 0.2, 0.1);
    }
    if (t == 200) {
        CI(MCC_ResetMotion);
        vd_dump_group(0);
    }
}

/* Setter batteries: each value and the getters after it. */
static void setters_feed(int t)
{
    static const double v[] = {10, -1, 0, 1e-9, 1e6, 5};
    if (t < 6) {
        CD(MCC_SetFeedSpeed, v[t], 0);
        vd_note("GetFeedSpeed %.17g", V(MCC_GetFeedSpeed)(0));
        vd_note("GetCurFeedSpeed %.17g", V(MCC_GetCurFeedSpeed)(0));
    }
    if (t == 6)
        LINE(0, 0.2, 0, 0);
}

static void setters_ptp_speed(int t)
{
    static const double v[] = {50, 0, -5, 100, 100.5, 150, 1e-3, 20};
    if (t < 8) {
        CD(MCC_SetPtPSpeed, v[t], 0);
        vd_note("GetPtPSpeed %.17g", V(MCC_GetPtPSpeed)(0));
    }
    if (t == 8)
        PTP(0, 0.5, 0, 0);
}

static void setters_acc(int t)
{
    static const double v[] = {100, 0, -1, 1e5, 0.5, 3000, 1e9, 50};
    if (t < 8) {
        CI(MCC_SetAccTime, v[t], 0);
        CI(MCC_SetDecTime, v[7 - t], 0);
        vd_note("GetAccTime %.17g", V(MCC_GetAccTime)(0));
        vd_note("GetDecTime %.17g", V(MCC_GetDecTime)(0));
    }
    if (t == 8) {
        CD(MCC_SetFeedSpeed, 10, 0);
        LINE(0, 0.2, 0, 0);
    }
}

static void setters_type(int t)
{
    static const char v[] = {'T', 'S', 't', 's', 'X', 0, 1, 'S'};
    if (t < 8) {
        CI(MCC_SetAccType, v[t], 0);
        CI(MCC_SetDecType, v[7 - t], 0);
        vd_note("GetAccType %d", V(MCC_GetAccType)(0));
        vd_note("GetDecType %d", V(MCC_GetDecType)(0));
    }
}

static void setters_override(int t)
{
    static const double v[] = {100, 50, 0, -1, 5000, 1e-3, 99.999, 100};
    if (t < 8) {
        CD(MCC_OverrideSpeed, v[t], 0);
        vd_note("GetOverrideRate %.17g", V(MCC_GetOverrideRate)(0));
    }
    if (t > 0 && t < 9)
        vd_note("GetOverrideRate+1 %.17g", V(MCC_GetOverrideRate)(0));
}

static void setters_coord(int t)
{
    if (t == 0) {
        vd_note("GetCoordType %d", V(MCC_GetCoordType)(0));
        CI(MCC_SetIncrease, 0);
        vd_note("GetCoordType %d", V(MCC_GetCoordType)(0));
        CI(MCC_SetAbsolute, 0);
        vd_note("GetCoordType %d", V(MCC_GetCoordType)(0));
        CI(MCC_SetAbsolute, 7);
        CI(MCC_SetIncrease, 300);
        vd_note("GetCoordType %d", V(MCC_GetCoordType)(7));
    }
}

static void setters_sys(int t)
{
    static const double v[] = {100, 0, -1, 1e9, 1e-6, 50};
    if (t < 6) {
        CI(MCC_SetSysMaxSpeed, v[t]);
        vd_note("GetSysMaxSpeed %.17g", V(MCC_GetSysMaxSpeed)());
        vd_note("GetFeedSpeed %.17g", V(MCC_GetFeedSpeed)(0));
    }
    if (t == 6) {
        CD(MCC_SetFeedSpeed, 80, 0);
        vd_note("GetFeedSpeed %.17g", V(MCC_GetFeedSpeed)(0));
        LINE(0, 1, 0, 0);
    }
}

static void setters_pulse_limits(int t)
{
    if (t == 0) {
        CI(MCC_SetMaxPulseSpeed, 1, 2, 3, 4, 5, 6, 7, 8, 0);
        vd_dump_system();
        CI(MCC_SetMaxPulseSpeed, 0, -1, 1000000, 5000000, 100, 100, 100, 100, 0);
        vd_dump_system();
        CI(MCC_SetMaxPulseAcc, 0, -1, 1000000, 5000000, 100, 100, 100, 100, 0);
        vd_dump_system();
        CI(MCC_SetMaxPulseSpeed, 1000000, 1000000, 1000000, 1000000, 1000000, 1000000,
           1000000, 1000000, 7);
    }
}

static void setters_inpos(int t)
{
    if (t == 0) {
        CI(MCC_SetInPosToleranceEx, 0.1, 0.2, 0, -1, 1e6, 0, 0, 0, 0);
        CI(MCC_SetInPosMode, 1, 0);
        CI(MCC_SetInPosMaxCheckTime, 500, 0);
        CI(MCC_SetInPosSettleTime, 20, 0);
        CI(MCC_SetOverTravelCheck, 1, 0, 1, 0, 2, -1, 0, 0, 0);
        CI(MCC_SetTrackErrorLimit, 0.5, 'X', 0);
        CI(MCC_SetTrackErrorLimit, -0.5, 'Y', 0);
        CI(MCC_SetTrackErrorLimit, 0.5, 'Q', 0);
        vd_dump_group(0);
    }
}

static void setters_ptp_profile(int t)
{
    if (t == 0) {
        CI(MCC_SetPtPAccType, 'S', 'T', 'X', 's', 0, 'T', 'T', 'T', 0);
        CI(MCC_SetPtPAccTime, 0, -1, 50, 1e6, 100, 100, 100, 100, 0);
        CI(MCC_SetPtPDecTime, 10, 20, 30, 40, 50, 60, 70, 80, 0);
        vd_dump_group(0);
    }
}

static void setters_mac(int t)
{
    SYS_MAC_PARAM m;
    if (t == 0) {
        V(MCC_GetMacParam)(&m, 0, 0);
        m.wPulseWidth = 0;
        CI(MCC_SetMacParam, &m, 0, 0);
        V(MCC_GetMacParam)(&m, 0, 0);
        m.dwPPR = 0;
        CI(MCC_SetMacParam, &m, 0, 0);
        V(MCC_GetMacParam)(&m, 0, 0);
        m.dfPitch = 0;
        CI(MCC_SetMacParam, &m, 0, 0);
        V(MCC_GetMacParam)(&m, 0, 0);
        m.dfGearRatio = -1;
        CI(MCC_SetMacParam, &m, 0, 0);
        V(MCC_GetMacParam)(&m, 0, 0);
        m.wRPM = 0;
        CI(MCC_SetMacParam, &m, 0, 0);
        V(MCC_GetMacParam)(&m, 0, 0);
        m.dfHighLimit = -5;
        CI(MCC_SetMacParam, &m, 0, 0);
        V(MCC_GetMacParam)(&m, 0, 0);
        m.dwPPR = 20000;
        CI(MCC_SetMacParam, &m, 0, 0);
        CI(MCC_SetMacParam, &m, 8, 0);
        CI(MCC_SetMacParam, &m, 0, 1);
        vd_dump_system();
        CI(MCC_UpdateParam);
        vd_dump_system();
        vd_dump_group(0);
    }
    if (t == 1)
        LINE(0, 0.01, 0, 0);
}

/* Which software limits SetMacParam takes: each pair (high, low) from the defaults. */
static void setters_mac_limits(int t)
{
    static const double pairs[][2] = {{0, -50000}, {-5, -50000}, {5, -50000}, {50000, 0},
                                      {50000, 5},  {50000, -5},  {10, 20},    {20, 10},
                                      {0, 0},      {-10, -20},   {-20, -10}};
    SYS_MAC_PARAM m;
    if (t == 0) {
        for (size_t i = 0; i < sizeof pairs / sizeof pairs[0]; i++) {
            V(MCC_GetMacParam)(&m, 1, 0);
            m.dfHighLimit = pairs[i][0];
            m.dfLowLimit = pairs[i][1];
            CI(MCC_SetMacParam, &m, 1, 0);
        }
        V(MCC_GetMacParam)(&m, 1, 0);
        vd_note("limits %.17g %.17g", m.dfHighLimit, m.dfLowLimit);
        m.wOverTravelUpSensorMode = 3;
        CI(MCC_SetMacParam, &m, 1, 0);
        V(MCC_GetMacParam)(&m, 1, 0);
        m.wPulseMode = 9;
        CI(MCC_SetMacParam, &m, 1, 0);
        V(MCC_GetMacParam)(&m, 1, 0);
        m.wCommandMode = 9;
        CI(MCC_SetMacParam, &m, 1, 0);
        V(MCC_GetMacParam)(&m, 1, 0);
        m.wPaddle = 9;
        CI(MCC_SetMacParam, &m, 1, 0);
        V(MCC_GetMacParam)(&m, 1, 0);
        m.wPosToEncoderDir = 2;
        CI(MCC_SetMacParam, &m, 1, 0);
        V(MCC_GetMacParam)(&m, 1, 0);
        m.dfGearRatio = 0;
        CI(MCC_SetMacParam, &m, 1, 0);
    }
}

/* wPosToEncoderDir 2 on channel 0: which way its pulses count. */
static void mac_dir2(int t)
{
    SYS_MAC_PARAM m;
    if (t == 0) {
        V(MCC_GetMacParam)(&m, 0, 0);
        m.wPosToEncoderDir = 2;
        CI(MCC_SetMacParam, &m, 0, 0);
        CI(MCC_UpdateParam);
        vd_note("GetConvFactor %.17g", V(MCC_GetConvFactor)(0, 0));
    }
    if (t == 1) {
        vd_profile('T', 10, 10, 10);
        LINE(0, 0.01, 0.01, 0);
    }
}

/* In-group values the first battery left open: a negative tolerance, a check flag of 2. */
static void setters_inpos_group(int t)
{
    if (t == 0) {
        CI(MCC_SetInPosToleranceEx, -1, 1e6, 1e12, 0, 0, 0, 0, 0, 0);
        vd_dump_group(0);
        CI(MCC_SetInPosToleranceEx, NAN, 0, 0, 0, 0, 0, 0, 0, 0);
        CI(MCC_SetOverTravelCheck, 2, -1, 0, 0, 0, 0, 0, 0, 0);
        vd_dump_group(0);
        CI(MCC_SetTrackErrorLimit, -0.5, 1, 0);
        CI(MCC_SetTrackErrorLimit, 0.5, 1, 0);
        CI(MCC_SetTrackErrorLimit, 0.5, 7, 0);
        CI(MCC_SetTrackErrorLimit, 0.5, 8, 0);
        double d = -1;
        int r = V(MCC_GetTrackErrorLimit)(&d, 1, 0);
        vd_note("GetTrackErrorLimit %d %.17g", r, d);
        r = V(MCC_GetTrackErrorLimit)(&d, 7, 0);
        vd_note("GetTrackErrorLimit %d %.17g", r, d);
    }
}

/* Card tables: each set-up initialises with another table and ends. */
static int init_with(WORD type, WORD addr, WORD irq, int count, int null_table)
{
    SYS_CARD_CONFIG cards[16];
    memset(cards, 0, sizeof cards);
    for (int i = 0; i < 16; i++) {
        cards[i].wCardType = type;
        cards[i].wCardAddress = addr;
        cards[i].wIRQ_No = irq;
    }
    vd_mac_default(10000);
    CI(MCC_CloseAllGroups);
    vd_make_group(0, 3);
    int r = CI(MCC_InitSimulation, 1, null_table ? NULL : cards, (WORD)count);
    return r < 0;
}

#define CARD_CASE(name, type, addr, irq, count, null_table)                                \
    static int name##_setup(void) { return init_with(type, addr, irq, count, null_table); }
CARD_CASE(card_type0, 0, 0, 0, 1, 0)
CARD_CASE(card_type0_isa, 0, 0x300, 5, 1, 0)
CARD_CASE(card_type0_badirq, 0, 0x300, 4, 1, 0)
CARD_CASE(card_type0_lowaddr, 0, 0x100, 5, 1, 0)
CARD_CASE(card_type1_isa, 1, 0x200, 15, 1, 0)
CARD_CASE(card_type1_highaddr, 1, 0x3F8, 10, 1, 0)
CARD_CASE(card_type2, 2, 0, 0, 1, 0)
CARD_CASE(card_type3, 3, 0, 0, 1, 0)
CARD_CASE(card_type4, 4, 0, 0, 1, 0)
CARD_CASE(card_type5, 5, 0, 0, 1, 0)
CARD_CASE(card_type6, 6, 0, 0, 1, 0)
CARD_CASE(card_type99, 99, 0, 0, 1, 0)
CARD_CASE(card_null_table, 5, 0, 0, 1, 1)
CARD_CASE(card_null_table3, 5, 0, 0, 3, 1)
CARD_CASE(card_count0, 5, 0, 0, 0, 0)
CARD_CASE(card_count2, 5, 0, 0, 2, 0)
CARD_CASE(card_count12, 5, 0, 0, 12, 0)
CARD_CASE(card_count13, 5, 0, 0, 13, 0)

static void card_script(int t)
{
    if (t == 0) {
        vd_dump_system();
        LINE(0, 0.05, 0, 0);
    }
}

static int init_periods(void)
{
    SYS_CARD_CONFIG card[1];
    static const int p[] = {0, -1, 51, 100, 3};
    memset(card, 0, sizeof card);
    card[0].wCardType = 5;
    vd_mac_default(10000);
    CI(MCC_CloseAllGroups);
    vd_make_group(0, 3);
    for (int i = 0; i < 4; i++) {
        if (CI(MCC_InitSimulation, p[i], card, 1) >= 0)
            CI(MCC_CloseSystem);
    }
    return vd_init(3) < 0;
}

static void line_short_script(int t)
{
    if (t == 0) {
        vd_profile('T', 9, 9, 10);
        LINE(0, 0.1, 0, 0);
    }
}

/* Init and close sequences. */
static int close_without_init(void)
{
    CI(MCC_CloseSystem);
    CI(MCC_CloseSystem);
    vd_note("GetMotionStatus %d", V(MCC_GetMotionStatus)(0));
    vd_note("GetErrorCode %d", V(MCC_GetErrorCode)(0));
    CI(MCC_Line, 1, 0, 0, 0, 0, 0, 0, 0, 0, IMP_AXIS_ALL);
    CD(MCC_SetFeedSpeed, 10, 0);
    vd_note("GetFeedSpeed %.17g", V(MCC_GetFeedSpeed)(0));
    return 1;
}

static int calls_before_init(void)
{
    vd_mac_default(10000);
    CI(MCC_CloseAllGroups);
    vd_make_group(0, 3);
    CI(MCC_SetAccTime, 30, 0);
    CD(MCC_SetFeedSpeed, 7, 0);
    CI(MCC_SetAccType, 'T', 0);
    CI(MCC_SetIncrease, 0);
    CD(MCC_SetPtPSpeed, 40, 0);
    CI(MCC_SetSysMaxSpeed, 30);
    CI(MCC_Line, 1, 0, 0, 0, 0, 0, 0, 0, 0, IMP_AXIS_ALL);
    vd_note("GetFeedSpeed %.17g", V(MCC_GetFeedSpeed)(0));
    vd_note("GetAccTime %.17g", V(MCC_GetAccTime)(0));
    vd_note("GetMotionStatus %d", V(MCC_GetMotionStatus)(0));
    return vd_init(1) < 0;
}

static void dump_then_line(int t)
{
    if (t == 0) {
        vd_dump_group(0);
        LINE(0, 0.1, 0, 0);
    }
}

static void close_twice_after(void)
{
    CI(MCC_CloseSystem);
    CI(MCC_CloseSystem);
    vd_note("GetMotionStatus %d", V(MCC_GetMotionStatus)(0));
}

static void reinit_after(void)
{
    CI(MCC_CloseSystem);
    vd_note("GetFeedSpeed %.17g", V(MCC_GetFeedSpeed)(0));
    CI(MCC_CreateGroup, 3, 4, -1, -1, -1, -1, -1, -1, 0);
    vd_init(2);
    vd_note("GetFeedSpeed %.17g", V(MCC_GetFeedSpeed)(0));
    vd_note("GetAccType %d", V(MCC_GetAccType)(0));
    vd_note("GetCmdQueueSize %d", V(MCC_GetCmdQueueSize)(1));
    CI(MCC_CloseSystem);
}

/* The group table across init and close: none created, then one kept over a close. */
static int groups_table(void)
{
    vd_mac_default(10000);
    CI(MCC_CloseAllGroups);
    vd_init(1);
    vd_note("GetFeedSpeed(0) %.17g", V(MCC_GetFeedSpeed)(0));
    vd_note("GetCmdQueueSize(0) %d", V(MCC_GetCmdQueueSize)(0));
    CI(MCC_SetFeedSpeed, 10, 0);
    CI(MCC_CloseSystem);
    CI(MCC_CreateGroup, 0, 1, -1, -1, -1, -1, -1, -1, 0);
    vd_init(1);
    vd_note("GetFeedSpeed(0) %.17g", V(MCC_GetFeedSpeed)(0));
    CI(MCC_SetFeedSpeed, 10, 0);
    CI(MCC_CloseSystem);
    vd_init(1);
    vd_note("GetFeedSpeed(0) %.17g", V(MCC_GetFeedSpeed)(0));
    vd_note("GetCmdQueueSize(0) %d", V(MCC_GetCmdQueueSize)(0));
    CI(MCC_CloseSystem);
    vd_note("GetFeedSpeed(0) closed %.17g", V(MCC_GetFeedSpeed)(0));
    CI(MCC_CreateGroup, 0, 1, -1, -1, -1, -1, -1, -1, 0);
    CI(MCC_CreateGroup, 2, 3, -1, -1, -1, -1, -1, -1, 0);
    CI(MCC_CloseGroup, 0);
    CI(MCC_CreateGroup, 4, 5, -1, -1, -1, -1, -1, -1, 0);
    vd_init(1);
    vd_note("GetFeedSpeed(0,1,2) %.17g %.17g %.17g", V(MCC_GetFeedSpeed)(0),
            V(MCC_GetFeedSpeed)(1), V(MCC_GetFeedSpeed)(2));
    CI(MCC_CloseSystem);
    return 1;
}

/* Groups made while the card runs: they move at once, from where their channels are. */
static void groups_made_running(int t)
{
    if (t == 0) {
        vd_profile('T', 20, 20, 10);
        LINE(0, 0.1, 0, 0);
    }
    if (t == 60) {
        int g = CI(MCC_CreateGroup, 3, 4, -1, -1, -1, -1, -1, -1, 0);
        vd_note("group %d", g);
        if (g >= 0) {
            CI(MCC_SetFeedSpeed, 10, (WORD)g);
            LINE((WORD)g, 0.05, 0.02, 0);
        }
    }
    if (t == 120) {
        double x = -1, y = -1, z, u, v, w, a, b;
        V(MCC_GetCurPos)(&x, &y, &z, &u, &v, &w, &a, &b, 0);
        vd_note("group 0 at %.17g %.17g", x, y);
        V(MCC_GetCurPos)(&x, &y, &z, &u, &v, &w, &a, &b, 1);
        vd_note("group 1 at %.17g %.17g", x, y);
        LINE(0, 0, 0, 0);
    }
}

static void groups_after_init(int t)
{
    if (t == 0) {
        CI(MCC_CreateGroup, 3, 4, -1, -1, -1, -1, -1, -1, 0);
        CI(MCC_CreateGroupEx, 3, 4, -1, -1, -1, -1, -1, -1, 0, 10);
        CI(MCC_CloseGroup, 0);
        CI(MCC_CloseAllGroups);
        vd_note("GetMotionStatus %d", V(MCC_GetMotionStatus)(0));
        LINE(0, 0.05, 0, 0);
    }
}

static int init_twice(void)
{
    vd_std(10000, 1, 3);
    return vd_init(2) < 0;
}

static int create_group_odd(void)
{
    vd_mac_default(10000);
    CI(MCC_CloseAllGroups);
    CI(MCC_CreateGroup, -1, -1, -1, -1, -1, -1, -1, -1, 0);
    CI(MCC_CreateGroup, 8, -1, -1, -1, -1, -1, -1, -1, 0);
    CI(MCC_CreateGroup, 0, 0, -1, -1, -1, -1, -1, -1, 0);
    CI(MCC_CreateGroup, 0, 1, -1, -1, -1, -1, -1, -1, 12);
    CI(MCC_CreateGroup, 0, 1, -1, -1, -1, -1, -1, -1, -1);
    CI(MCC_CreateGroup, -1, 2, -1, -1, -1, -1, -1, -1, 0);
    CI(MCC_CreateGroupEx, 0, 1, -1, -1, -1, -1, -1, -1, 0, 0);
    CI(MCC_CreateGroupEx, 0, 1, -1, -1, -1, -1, -1, -1, 0, -5);
    CI(MCC_CloseGroup, 1);
    CI(MCC_CloseGroup, 50);
    CI(MCC_CloseGroup, -1);
    int g = CI(MCC_CreateGroup, 0, 1, 2, -1, -1, -1, -1, -1, 0);
    if (g >= 0)
        vd_group(g, 3);
    return vd_init(1) < 0;
}

static void odd_group_script(int t)
{
    if (t == 0) {
        for (WORD g = 0; g < 8; g++)
            vd_note("GetMotionStatus(%u) %d", g, V(MCC_GetMotionStatus)(g));
        LINE(0, 0.05, 0, 0);
    }
}

/* Bad arguments to motion calls and getters. */
static void bad_args(int t)
{
    double d[8];
    if (t == 0) {
        CI(MCC_Line, 1, 0, 0, 0, 0, 0, 0, 0, 1, IMP_AXIS_ALL);
        CI(MCC_Line, 1, 0, 0, 0, 0, 0, 0, 0, 96, IMP_AXIS_ALL);
        CI(MCC_Line, 1, 0, 0, 0, 0, 0, 0, 0, 65535, IMP_AXIS_ALL);
        CI(MCC_Line, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0);
        CD(MCC_SetFeedSpeed, 10, 3);
        CI(MCC_SetAccTime, 10, 3);
        CI(MCC_GetCurPos, &d[0], &d[1], &d[2], &d[3], &d[4], &d[5], &d[6], &d[7], 3);
        CI(MCC_GetCurPos, &d[0], &d[1], &d[2], &d[3], &d[4], &d[5], &d[6], &d[7], 200);
        vd_note("GetMotionStatus(3) %d", V(MCC_GetMotionStatus)(3));
        vd_note("GetErrorCode(3) %d", V(MCC_GetErrorCode)(3));
        vd_note("GetFeedSpeed(3) %.17g", V(MCC_GetFeedSpeed)(3));
        CI(MCC_ArcXY, 1, 1, 2, 0, 5);
        CI(MCC_PtP, 1, 0, 0, 0, 0, 0, 0, 0, 5, IMP_AXIS_ALL);
        CI(MCC_JogPulse, 10, 'X', 5);
        CI(MCC_DelayMotion, 10, 5);
        CI(MCC_HoldMotion, 5, 0);
        CI(MCC_AbortMotion, 5, 0);
        CI(MCC_ClearError, 5);
        vd_dump_group(0);
    }
    if (t == 1)
        LINE(0, 0.05, 0, 0);
}

static void line_nan(int t)
{
    if (t == 0) {
        vd_profile('T', 20, 20, 10);
        CI(MCC_Line, NAN, 0, 0, 0, 0, 0, 0, 0, 0, IMP_AXIS_ALL);
    }
    if (t == 50)
        vd_dump_group(0);
}

static void line_inf(int t)
{
    if (t == 0) {
        vd_profile('T', 20, 20, 10);
        CI(MCC_Line, INFINITY, 0, 0, 0, 0, 0, 0, 0, 0, IMP_AXIS_ALL);
        CI(MCC_Line, 1e300, 0, 0, 0, 0, 0, 0, 0, 0, IMP_AXIS_ALL);
        CD(MCC_SetFeedSpeed, NAN, 0);
        vd_note("GetFeedSpeed %.17g", V(MCC_GetFeedSpeed)(0));
    }
    if (t == 50)
        vd_dump_group(0);
}

/* Origins: define the position of axes where they stand. */
static void define_origin(int t)
{
    if (t == 0) {
        vd_profile('T', 20, 20, 10);
        LINE(0, 0.5, 0.25, -0.125);
    }
    if (t == 200) {
        CI(MCC_DefineOrigin, 0, 0);
        CI(MCC_DefinePos, 1, 3.5, 0);
        CI(MCC_DefinePos, 9, 1, 0);
        vd_dump_group(0);
    }
    if (t == 210)
        LINE(0, 0, 0, 0);
}

static void define_pos_here(int t)
{
    if (t == 0) {
        vd_profile('T', 20, 20, 10);
        LINE(0, 0.5, 0.25, -0.125);
    }
    if (t == 40) {
        CI(MCC_DefinePosHere, 0, IMP_AXIS_ALL);
        CI(MCC_DefineOrigin, 1, 0);
    }
    if (t == 200) {
        CI(MCC_DefinePosHere, 0, 0x3);
        vd_dump_group(0);
        LINE(0, 0, 0, 0);
    }
}

/* Compensation table: +11 pulses at X = 15 (the examples manual's table). */
static void compensation(int t)
{
    static SYS_COMP_PARAM c;
    if (t == 0) {
        memset(&c, 0, sizeof c);
        c.dwInterval = 5000;
        c.wHome_No = 0;
        for (int i = 0; i < 4; i++) {
            c.nForwardTable[i] = i == 3 ? 11 : 0;
            c.nBackwardTable[i] = i == 3 ? 11 : 0;
        }
        CI(MCC_SetCompParam, &c, 0, 0);
        CI(MCC_UpdateCompParam);
        vd_profile('T', 50, 50, 50);
        LINE(0, 15, 0, 0);
    }
    if (t == 500) {
        vd_dump_group(0);
        LINE(0, 7.5, 0, 0);
    }
}

static void convfactor(int t)
{
    if (t == 0) {
        for (WORD ch = 0; ch < 3; ch++)
            vd_note("GetConvFactor(%u) %.17g", ch, V(MCC_GetConvFactor)(ch, 0));
        vd_note("GetConvFactor(9) %.17g", V(MCC_GetConvFactor)(9, 0));
    }
}

static int frac3(void)
{
    vd_mac_default(10000);
    vd_mac(0, 1000, 3, 7);
    vd_mac(1, 2000, 0.7, 1.3);
    vd_mac(2, 4096, 5, 1);
    CI(MCC_CloseAllGroups);
    vd_make_group(0, 3);
    return vd_init(1) < 0;
}

static void command_info(int t)
{
    if (t == 0) {
        vd_profile('S', 20, 30, 10);
        LINE(0, 0.2, 0, 0);
        CI(MCC_ArcXY, 0.3, 0.1, 0.4, 0, 0);
        CD(MCC_SetPtPSpeed, 10, 0);
        PTP(0, 0, 0, 0);
        CI(MCC_DelayMotion, 20, 0);
        CI(MCC_JogPulse, 20, 'Y', 0);
    }
    if (t == 400) {
        CI(MCC_ResetCommandIndex, 0);
        CI(MCC_SetCommandIndex, 100, 1, 0);
        LINE(0, 0.1, 0, 0);
        WORD w = 0;
        int r = V(MCC_GetCommandIndex)(&w, 0);
        vd_note("GetCommandIndex %d %u", r, w);
    }
}

static void versions(int t)
{
    char ver[64];
    if (t == 0) {
        memset(ver, 0, sizeof ver);
        V(MCC_GetVersion)(ver);
        vd_note("GetVersion '%s'", ver);
        CI(MCC_EnableDryRun);
        vd_note("CheckDryRun %d", V(MCC_CheckDryRun)());
        CI(MCC_DisableDryRun);
        vd_note("CheckDryRun %d", V(MCC_CheckDryRun)());
        CI(MCC_SetMaxPulseStockNum, 100);
        vd_note("GetMaxPulseStockNum %d", V(MCC_GetMaxPulseStockNum)());
    }
}

const Scenario vd_state[] = {
    SCEN(state_after_init, std3, 0, 100),
    SCEN(state_after_reset, std3, 30, 4000),
    SCEN(state_reset_idle, std3, 200, 4000),
    SCEN(setters_feed, std3, 6, 4000),
    SCEN(setters_ptp_speed, std3, 8, 4000),
    SCEN(setters_acc, std3, 8, 4000),
    SCEN(setters_type, std3, 8, 100),
    SCEN(setters_override, std3, 9, 100),
    SCEN(setters_coord, std3, 0, 100),
    SCEN(setters_sys, std3, 6, 4000),
    SCEN(setters_pulse_limits, std3, 0, 100),
    SCEN(setters_inpos, std3, 0, 100),
    SCEN(setters_ptp_profile, std3, 0, 100),
    SCEN(setters_mac, std3, 1, 4000),
    SCEN(setters_mac_limits, std3, 0, 100),
    SCEN(setters_inpos_group, std3, 0, 100),
    SCEN(mac_dir2, std3, 1, 1000),
    {"card_type0", card_type0_setup, card_script, 0, 1000, 0},
    {"card_type0_isa", card_type0_isa_setup, card_script, 0, 1000, 0},
    {"card_type0_badirq", card_type0_badirq_setup, card_script, 0, 1000, 0},
    {"card_type0_lowaddr", card_type0_lowaddr_setup, card_script, 0, 1000, 0},
    {"card_type1_isa", card_type1_isa_setup, card_script, 0, 1000, 0},
    {"card_type1_highaddr", card_type1_highaddr_setup, card_script, 0, 1000, 0},
    {"card_type2", card_type2_setup, card_script, 0, 1000, 0},
    {"card_type3", card_type3_setup, card_script, 0, 1000, 0},
    {"card_type4", card_type4_setup, card_script, 0, 1000, 0},
    {"card_type5", card_type5_setup, card_script, 0, 1000, 0},
    {"card_type6", card_type6_setup, card_script, 0, 1000, 0},
    {"card_type99", card_type99_setup, card_script, 0, 1000, 0},
    {"card_null_table", card_null_table_setup, card_script, 0, 1000, 0},
    {"card_null_table3", card_null_table3_setup, card_script, 0, 1000, 0},
    {"card_count0", card_count0_setup, card_script, 0, 1000, 0},
    {"card_count2", card_count2_setup, card_script, 0, 1000, 0},
    {"card_count12", card_count12_setup, card_script, 0, 1000, 0},
    {"card_count13", card_count13_setup, card_script, 0, 1000, 0},
    {"init_periods", init_periods, line_short_script, 0, 1000, 0},
    {"close_without_init", close_without_init, dump_then_line, 0, 100, 0},
    {"calls_before_init", calls_before_init, dump_then_line, 0, 1000, 0},
    {"close_twice", std3, dump_then_line, 0, 1000, close_twice_after},
    {"reinit", std3, dump_then_line, 0, 1000, reinit_after},
    SCEN(groups_after_init, std3, 0, 1000),
    {"groups_table", groups_table, dump_then_line, 0, 100, 0},
    SCEN(groups_made_running, std3, 120, 1000),
    {"init_twice", init_twice, dump_then_line, 0, 1000, 0},
    {"create_group_odd", create_group_odd, odd_group_script, 0, 1000, 0},
    SCEN(bad_args, std3, 1, 1000),
    SCEN(line_nan, std3, 50, 1000),
    SCEN(line_inf, std3, 50, 1000),
    SCEN(define_origin, std3, 210, 4000),
    SCEN(define_pos_here, std3, 200, 4000),
    SCEN(compensation, std3, 500, 4000),
    {"convfactor", frac3, convfactor, 0, 100, 0},
    SCEN(command_info, std3, 400, 4000),
    SCEN(versions, std8, 0, 100),
    SCEN_END,
};
