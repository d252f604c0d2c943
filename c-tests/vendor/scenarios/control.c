/* Trajectory control: hold, continue and abort in each phase, override up and down, delay,
 * the queue's limits, single block, several groups at once, soft limits, rates the pulse
 * output cannot give. */
#include "common.h"

STD_SETUP(std3, 10000, 1, 3)

/* A line of 2 units at 10 UU/s with 100 ms ramps: accelerating in periods 1..100,
 * cruising 100..~200, decelerating in the last 100. */
#define LONGLINE(type)                                                                     \
    do {                                                                                   \
        vd_profile(type, 100, 100, 10);                                                    \
        LINE(0, 2, 0, 0);                                                                  \
    } while (0)

#define CTRL_CASE(name, type, at, call, at2, call2)                                        \
    static void name(int t)                                                                \
    {                                                                                      \
        if (t == 0)                                                                        \
            LONGLINE(type);                                                                \
        if (t == (at))                                                                     \
            call;                                                                          \
        if (t == (at2))                                                                    \
            call2;                                                                         \
    }

CTRL_CASE(hold_acc_t, 'T', 50, CI(MCC_HoldMotion, 0, 0), 300, CI(MCC_ContiMotion, 0))
CTRL_CASE(hold_cruise_t, 'T', 150, CI(MCC_HoldMotion, 0, 0), 400, CI(MCC_ContiMotion, 0))
CTRL_CASE(hold_dec_t, 'T', 260, CI(MCC_HoldMotion, 0, 0), 400, CI(MCC_ContiMotion, 0))
CTRL_CASE(hold_acc_s, 'S', 50, CI(MCC_HoldMotion, 0, 0), 300, CI(MCC_ContiMotion, 0))
CTRL_CASE(hold_cruise_s, 'S', 150, CI(MCC_HoldMotion, 0, 0), 400, CI(MCC_ContiMotion, 0))
CTRL_CASE(hold_dec_s, 'S', 260, CI(MCC_HoldMotion, 0, 0), 400, CI(MCC_ContiMotion, 0))
CTRL_CASE(abort_acc_t, 'T', 50, CI(MCC_AbortMotion, 0, 0), 9999, (void)0)
CTRL_CASE(abort_cruise_t, 'T', 150, CI(MCC_AbortMotion, 0, 0), 9999, (void)0)
CTRL_CASE(abort_dec_t, 'T', 260, CI(MCC_AbortMotion, 0, 0), 9999, (void)0)
CTRL_CASE(abort_acc_s, 'S', 50, CI(MCC_AbortMotion, 0, 0), 9999, (void)0)
CTRL_CASE(abort_cruise_s, 'S', 150, CI(MCC_AbortMotion, 0, 0), 9999, (void)0)
CTRL_CASE(abort_dec_s, 'S', 260, CI(MCC_AbortMotion, 0, 0), 9999, (void)0)
CTRL_CASE(abortex_cruise_t, 'T', 150, CI(MCC_AbortMotionEx, 0.03, 0), 9999, (void)0)
CTRL_CASE(abortex_cruise_s, 'S', 150, CI(MCC_AbortMotionEx, 0.2, 0), 9999, (void)0)
CTRL_CASE(abortex_zero, 'T', 150, CI(MCC_AbortMotionEx, 0, 0), 9999, (void)0)
CTRL_CASE(abort_blockend, 'T', 150, CI(MCC_AbortMotion, 0, 1), 9999, (void)0)
CTRL_CASE(hold_blockend, 'T', 150, CI(MCC_HoldMotion, 0, 1), 400, CI(MCC_ContiMotion, 0))
CTRL_CASE(override_up_t, 'T', 150, CD(MCC_OverrideSpeed, 150, 0), 9999, (void)0)
CTRL_CASE(override_down_t, 'T', 150, CD(MCC_OverrideSpeed, 50, 0), 9999, (void)0)
CTRL_CASE(override_up_s, 'S', 150, CD(MCC_OverrideSpeed, 150, 0), 9999, (void)0)
CTRL_CASE(override_down_s, 'S', 150, CD(MCC_OverrideSpeed, 50, 0), 9999, (void)0)
CTRL_CASE(override_acc_phase, 'T', 30, CD(MCC_OverrideSpeed, 40, 0), 9999, (void)0)
CTRL_CASE(override_ex, 'T', 150, CD(MCC_OverrideSpeedEx, 150, 1, 0), 151,
          vd_note("GetOverrideRate %.17g", V(MCC_GetOverrideRate)(0)))
CTRL_CASE(override_ex_ramped, 'T', 150, CD(MCC_OverrideSpeedEx, 60, 0, 0), 151,
          vd_note("GetOverrideRate %.17g", V(MCC_GetOverrideRate)(0)))
CTRL_CASE(override_twice, 'T', 120, CD(MCC_OverrideSpeed, 200, 0), 160,
          CD(MCC_OverrideSpeed, 30, 0))

/* A hold in the middle of an arc (a half circle of radius 1, 10 UU/s, 'T'), with equal
 * ramps and with a shorter deceleration; and the same shorter deceleration on a line. On
 * an arc the vendor's library stops from the last period's speed along the chord. */
#define ARC_HOLD_CASE(name, dec, move)                                                     \
    static void name(int t)                                                                \
    {                                                                                      \
        if (t == 0) {                                                                      \
            vd_profile('T', 100, dec, 10);                                                 \
            move;                                                                          \
        }                                                                                  \
        if (t == 150)                                                                      \
            CI(MCC_HoldMotion, 0, 0);                                                      \
        if (t == 400)                                                                      \
            CI(MCC_ContiMotion, 0);                                                        \
    }
ARC_HOLD_CASE(arc_hold_cruise_t, 100, CI(MCC_ArcXY, 1, 1, 2, 0, 0))
ARC_HOLD_CASE(arc_hold_dec40_t, 40, CI(MCC_ArcXY, 1, 1, 2, 0, 0))
ARC_HOLD_CASE(line_hold_dec40_t, 40, LINE(0, 2, 0, 0))

/* Hold with queued commands, continue; abort with queued commands. */
static void hold_queue(int t)
{
    if (t == 0) {
        vd_profile('T', 50, 50, 10);
        LINE(0, 1, 0, 0);
        LINE(0, 1, 1, 0);
        LINE(0, 0, 0, 0);
    }
    if (t == 120)
        CI(MCC_HoldMotion, 0, 0);
    if (t == 300)
        CI(MCC_ContiMotion, 0);
}

static void abort_queue(int t)
{
    if (t == 0) {
        vd_profile('T', 50, 50, 10);
        LINE(0, 1, 0, 0);
        LINE(0, 1, 1, 0);
        LINE(0, 0, 0, 0);
    }
    if (t == 120)
        CI(MCC_AbortMotion, 0, 0);
    if (t == 300)
        LINE(0, 0, 0, 0);
}

static void hold_conti_misuse(int t)
{
    if (t == 0) {
        CI(MCC_HoldMotion, 0, 0);
        CI(MCC_ContiMotion, 0);
        CI(MCC_AbortMotion, 0, 0);
        vd_profile('T', 20, 20, 10);
        LINE(0, 0.5, 0, 0);
        CI(MCC_ContiMotion, 0);
    }
    if (t == 30) {
        CI(MCC_HoldMotion, 0, 0);
        CI(MCC_HoldMotion, 0, 0);
    }
    if (t == 100)
        LINE(0, 1, 0, 0);
    if (t == 120) {
        CI(MCC_ContiMotion, 0);
        CI(MCC_ContiMotion, 0);
    }
}

static void hold_then_abort(int t)
{
    if (t == 0)
        LONGLINE('T');
    if (t == 150)
        CI(MCC_HoldMotion, 0, 0);
    if (t == 350)
        CI(MCC_AbortMotion, 0, 0);
    if (t == 400)
        LINE(0, 0, 0, 0);
}

static void override_stopped(int t)
{
    if (t == 0) {
        CD(MCC_OverrideSpeed, 50, 0);
        vd_note("GetOverrideRate %.17g", V(MCC_GetOverrideRate)(0));
        LONGLINE('T');
    }
    if (t == 1)
        vd_note("GetOverrideRate %.17g", V(MCC_GetOverrideRate)(0));
    if (t == 2) {
        CD(MCC_OverrideSpeed, 5000, 0);
        CD(MCC_OverrideSpeed, 0, 0);
        CD(MCC_OverrideSpeed, -10, 0);
        CD(MCC_OverrideSpeed, 100, 0);
    }
}

/* Delay between lines; a zero delay; CheckDelay while it runs. */
static void delay_between(int t)
{
    if (t == 0) {
        vd_profile('T', 30, 30, 10);
        LINE(0, 0.5, 0, 0);
        CI(MCC_DelayMotion, 100, 0);
        LINE(0, 0.5, 0.5, 0);
        CI(MCC_DelayMotion, 0, 0);
    }
    if (t == 100 || t == 150 || t == 200)
        vd_note("CheckDelay %d", V(MCC_CheckDelay)(0));
}

static void delay_alone(int t)
{
    if (t == 0)
        CI(MCC_DelayMotion, 50, 0);
    if (t == 10)
        vd_note("CheckDelay %d", V(MCC_CheckDelay)(0));
}

/* The queue: its size, a small queue filled up, the index of queued commands. */
static int small_queue(void)
{
    vd_mac_default(10000);
    CI(MCC_CloseAllGroups);
    int g = CI(MCC_CreateGroupEx, 0, 1, 2, -1, -1, -1, -1, -1, 0, 4);
    if (g >= 0)
        vd_group(g, 3);
    return vd_init(1) < 0;
}

static void queue_full(int t)
{
    if (t == 0) {
        vd_profile('T', 10, 10, 10);
        for (int i = 0; i < 8; i++)
            LINE(0, 0.1 * (i + 1), 0, 0);
        vd_note("GetCmdQueueSize %d", V(MCC_GetCmdQueueSize)(0));
        int n = 0;
        V(MCC_GetCommandCount)(&n, 0);
        vd_note("GetCommandCount %d", n);
    }
    if (t == 50)
        LINE(0, 0, 0, 0);
}

static void queue_count(int t)
{
    if (t == 0) {
        vd_profile('T', 10, 10, 10);
        for (int i = 0; i < 5; i++)
            LINE(0, 0.05 * (i + 1), 0, 0);
    }
    if (t % 10 == 0 && t <= 80) {
        int n = -1;
        int r = V(MCC_GetCommandCount)(&n, 0);
        vd_note("GetCommandCount %d %d", r, n);
        vd_note("GetCmdQueueSize %d", V(MCC_GetCmdQueueSize)(0));
    }
}

static void queue_resize(int t)
{
    if (t == 0) {
        CI(MCC_SetCmdQueueSize, 3, 0);
        vd_note("GetCmdQueueSize %d", V(MCC_GetCmdQueueSize)(0));
        vd_profile('T', 10, 10, 10);
        for (int i = 0; i < 5; i++)
            LINE(0, 0.05 * (i + 1), 0, 0);
        CI(MCC_SetCmdQueueSize, 0, 0);
        CI(MCC_SetCmdQueueSize, 20000, 0);
    }
}

/* The queue size set before init: which sizes and groups are taken. */
static int queue_size_before_init(void)
{
    vd_mac_default(10000);
    CI(MCC_CloseAllGroups);
    CI(MCC_CreateGroup, 0, 1, 2, -1, -1, -1, -1, -1, 0);
    vd_note("GetCmdQueueSize %d", V(MCC_GetCmdQueueSize)(0));
    CI(MCC_SetCmdQueueSize, 0, 0);
    CI(MCC_SetCmdQueueSize, -1, 0);
    CI(MCC_SetCmdQueueSize, 2000000, 0);
    CI(MCC_SetCmdQueueSize, 5, 1);
    CI(MCC_SetCmdQueueSize, 5, 0);
    vd_note("GetCmdQueueSize %d", V(MCC_GetCmdQueueSize)(0));
    return vd_init(1) < 0;
}

static void queue_size_small(int t)
{
    if (t == 0) {
        vd_note("GetCmdQueueSize %d", V(MCC_GetCmdQueueSize)(0));
        vd_profile('T', 10, 10, 10);
        for (int i = 0; i < 7; i++)
            LINE(0, 0.01 * (i + 1), 0, 0);
        CI(MCC_SetCmdQueueSize, -1, 0);
        CI(MCC_SetCmdQueueSize, 3, 1);
    }
}

/* Several groups at once. */
static int two_groups(void)
{
    vd_mac_default(10000);
    CI(MCC_CloseAllGroups);
    vd_make_group(0, 2);
    vd_make_group(2, 3);
    return vd_init(1) < 0;
}

static void groups_two(int t)
{
    if (t == 0) {
        vd_profile_g(0, 'T', 50, 50, 10);
        vd_profile_g(1, 'S', 30, 80, 5);
        LINE(0, 1, 1, 0);
        LINE(1, -0.5, 0.5, 0.25);
    }
    if (t == 60)
        CI(MCC_HoldMotion, 1, 0);
    if (t == 200)
        CI(MCC_ContiMotion, 1);
}

static int four_groups(void)
{
    vd_mac_default(10000);
    CI(MCC_CloseAllGroups);
    vd_make_group(0, 2);
    vd_make_group(2, 2);
    vd_make_group(4, 2);
    vd_make_group(6, 2);
    return vd_init(1) < 0;
}

static void groups_four(int t)
{
    if (t == 0) {
        for (int g = 0; g < 4; g++) {
            vd_profile_g(g, g % 2 ? 'S' : 'T', 20 + 10 * g, 40, 4 + g);
            CI(MCC_Line, 0.3 * (g + 1), -0.2 * g, 0, 0, 0, 0, 0, 0, (WORD)g, IMP_AXIS_ALL);
        }
        CI(MCC_ArcXY, 0.5, 0.5, 1, 0, 2);
    }
    if (t == 100)
        CI(MCC_AbortMotion, 3, 0);
}

/* Soft limits: a line that would leave the work zone. */
static int soft_limits(void)
{
    SYS_MAC_PARAM m;
    vd_mac_default(10000);
    for (int ch = 0; ch < 3; ch++) {
        V(MCC_GetMacParam)(&m, (WORD)ch, 0);
        m.dfHighLimit = 1;
        m.dfLowLimit = -1;
        CI(MCC_SetMacParam, &m, (WORD)ch, 0);
    }
    CI(MCC_CloseAllGroups);
    vd_make_group(0, 3);
    return vd_init(1) < 0;
}

static void softlimit_line(int t)
{
    if (t == 0) {
        CI(MCC_SetOverTravelCheck, 1, 1, 1, 0, 0, 0, 0, 0, 0);
        vd_profile('T', 20, 20, 10);
        LINE(0, 0.5, 0, 0);
        LINE(0, 2, 0, 0);
    }
    if (t == 400) {
        vd_dump_group(0);
        CI(MCC_ClearError, 0);
        LINE(0, -2, 0, 0);
    }
}

/* Moves that end exactly on a soft limit, from both sides. */
static void softlimit_exact(int t)
{
    if (t == 0) {
        CI(MCC_SetOverTravelCheck, 1, 1, 1, 0, 0, 0, 0, 0, 0);
        vd_profile('T', 20, 20, 10);
        LINE(0, 1, 0.5, 0);
        LINE(0, -1, -1, 0);
        LINE(0, 0.25, 1, 0);
    }
    if (t == 700) {
        CI(MCC_ClearError, 0);
        LINE(0, 0, 0, 0);
        LINE(0, 0, -1.000001, 0);
    }
}

static void softlimit_off(int t)
{
    if (t == 0) {
        CI(MCC_SetOverTravelCheck, 0, 0, 0, 0, 0, 0, 0, 0, 0);
        vd_profile('T', 20, 20, 10);
        LINE(0, 1.5, 0, 0);
    }
}

static void softlimit_jog(int t)
{
    if (t == 0) {
        CI(MCC_SetOverTravelCheck, 1, 1, 1, 0, 0, 0, 0, 0, 0);
        CI(MCC_SetAccTime, 20, 0);
        CI(MCC_SetDecTime, 20, 0);
        CI(MCC_JogConti, 1, 10, 'X', 0);
    }
}

/* A pulse rate above what the output gives. */
static int ppr_huge(void)
{
    vd_mac_default(100000000);
    CI(MCC_CloseAllGroups);
    vd_make_group(0, 3);
    return vd_init(1) < 0;
}

static void pulse_rate_error(int t)
{
    if (t == 0) {
        vd_profile('T', 20, 20, 10);
        LINE(0, 1, 0, 0);
    }
    if (t == 200)
        vd_dump_group(0);
}

static void max_pulse_speed(int t)
{
    if (t == 0) {
        CI(MCC_SetMaxPulseSpeed, 20000, 20000, 20000, 20000, 20000, 20000, 20000, 20000, 0);
        CI(MCC_SetMaxPulseAcc, 1000, 1000, 1000, 1000, 1000, 1000, 1000, 1000, 0);
        vd_dump_system();
        vd_profile('T', 20, 20, 10);
        LINE(0, 1, 0, 0);
    }
}

static void sys_max_speed(int t)
{
    if (t == 0) {
        CI(MCC_SetSysMaxSpeed, 5);
        vd_profile('T', 20, 20, 10);
        LINE(0, 1, 0, 0);
        vd_note("GetFeedSpeed %.17g", V(MCC_GetFeedSpeed)(0));
    }
}

/* Feed speed changed while moving (MCC_ChangeFeedSpeed) and fixed speed. */
static void change_feed(int t)
{
    if (t == 0)
        LONGLINE('T');
    if (t == 150)
        CD(MCC_ChangeFeedSpeed, 5, 0);
}

static void fix_speed(int t)
{
    if (t == 0) {
        CI(MCC_FixSpeed, 1, 0);
        LONGLINE('T');
    }
    if (t == 150)
        CD(MCC_OverrideSpeed, 50, 0);
}

/* A hold that meets a delay: in its middle, in its last period, and with nothing queued
 * after it; each continued later. A delay of 100 ms is periods 1..100, then a line. */
#define DELAY_HOLD_CASE(name, hold_at, then_line)                                          \
    static void name(int t)                                                                \
    {                                                                                      \
        if (t == 0) {                                                                      \
            vd_profile('T', 100, 100, 10);                                                 \
            CI(MCC_DelayMotion, 100, 0);                                                   \
            if (then_line)                                                                 \
                LINE(0, 1, 0, 0);                                                          \
        }                                                                                  \
        if (t == (hold_at))                                                                \
            CI(MCC_HoldMotion, 0, 0);                                                      \
        if (t == 160)                                                                      \
            CI(MCC_ContiMotion, 0);                                                        \
    }

/* A PtP (1 UU in X and Y at the default PtP speed) held at period 500 and continued at
 * 700, under overrides: set before it starts (`start_pct`, 100 none), changed while it
 * runs or while it is held (`at`, -1 never, to `pct`). What speed does the continue run
 * at? [`mix_60`] */
#define PTP_HOLD_OVERRIDE_CASE(name, start_pct, at, pct)                                    \
    static void name(int t)                                                                \
    {                                                                                      \
        if (t == 0) {                                                                      \
            vd_profile('T', 100, 100, 10);                                                 \
            if ((start_pct) != 100)                                                        \
                CD(MCC_OverrideSpeed, start_pct, 0);                                       \
            PTP(0, 1, -1, 0);                                                              \
        }                                                                                  \
        if (t == (at))                                                                     \
            CD(MCC_OverrideSpeed, pct, 0);                                                 \
        if (t == 500)                                                                      \
            CI(MCC_HoldMotion, 0, 0);                                                      \
        if (t == 700)                                                                      \
            CI(MCC_ContiMotion, 0);                                                        \
    }

PTP_HOLD_OVERRIDE_CASE(ptp_hold_ovr_running, 100, 300, 150)
PTP_HOLD_OVERRIDE_CASE(ptp_hold_ovr_started, 50, -1, 50)
PTP_HOLD_OVERRIDE_CASE(ptp_hold_ovr_both, 50, 300, 80)
PTP_HOLD_OVERRIDE_CASE(ptp_hold_ovr_held, 100, 600, 150)

/* Two lines blended (S, 120 ms ramps, 8 UU/s): 1 UU in X, then 1 UU in Y; an override to
 * `pct` at period `at`, during the blend (which starts near period 66) or before it.
 * [`mix_61`] */
#define BLEND_OVERRIDE_CASE(name, at, pct)                                                 \
    static void name(int t)                                                                \
    {                                                                                      \
        if (t == 0) {                                                                      \
            vd_profile('S', 120, 120, 8);                                                  \
            CI(MCC_EnableBlend, 0);                                                        \
            LINE(0, 1, 0, 0);                                                              \
            LINE(0, 1, 1, 0);                                                              \
        }                                                                                  \
        if (t == (at))                                                                     \
            CD(MCC_OverrideSpeed, pct, 0);                                                 \
    }

BLEND_OVERRIDE_CASE(blend_ovr_mid, 150, 50)
BLEND_OVERRIDE_CASE(blend_ovr_up, 150, 130)
BLEND_OVERRIDE_CASE(blend_ovr_before, 100, 50)

DELAY_HOLD_CASE(hold_delay_mid, 50, 1)
DELAY_HOLD_CASE(hold_delay_last, 100, 1)
DELAY_HOLD_CASE(hold_delay_before_last, 99, 1)
DELAY_HOLD_CASE(hold_delay_alone, 50, 0)

const Scenario vd_control[] = {
    SCEN(hold_acc_t, std3, 300, 4000),
    SCEN(arc_hold_cruise_t, std3, 400, 4000),
    SCEN(arc_hold_dec40_t, std3, 400, 4000),
    SCEN(line_hold_dec40_t, std3, 400, 4000),
    SCEN(hold_cruise_t, std3, 400, 4000),
    SCEN(hold_dec_t, std3, 400, 4000),
    SCEN(hold_acc_s, std3, 300, 4000),
    SCEN(hold_cruise_s, std3, 400, 4000),
    SCEN(hold_dec_s, std3, 400, 4000),
    SCEN(abort_acc_t, std3, 50, 4000),
    SCEN(abort_cruise_t, std3, 150, 4000),
    SCEN(abort_dec_t, std3, 260, 4000),
    SCEN(abort_acc_s, std3, 50, 4000),
    SCEN(abort_cruise_s, std3, 150, 4000),
    SCEN(abort_dec_s, std3, 260, 4000),
    SCEN(abortex_cruise_t, std3, 150, 4000),
    SCEN(abortex_cruise_s, std3, 150, 4000),
    SCEN(abortex_zero, std3, 150, 4000),
    SCEN(abort_blockend, std3, 150, 4000),
    SCEN(hold_blockend, std3, 400, 4000),
    SCEN(override_up_t, std3, 150, 4000),
    SCEN(override_down_t, std3, 150, 4000),
    SCEN(override_up_s, std3, 150, 4000),
    SCEN(override_down_s, std3, 150, 4000),
    SCEN(override_acc_phase, std3, 30, 4000),
    SCEN(override_ex, std3, 151, 4000),
    SCEN(override_ex_ramped, std3, 151, 4000),
    SCEN(override_twice, std3, 160, 4000),
    SCEN(hold_queue, std3, 300, 4000),
    SCEN(abort_queue, std3, 300, 4000),
    SCEN(hold_conti_misuse, std3, 120, 4000),
    SCEN(hold_then_abort, std3, 400, 4000),
    SCEN(override_stopped, std3, 2, 4000),
    SCEN(delay_between, std3, 200, 4000),
    SCEN(delay_alone, std3, 10, 4000),
    SCEN(queue_full, small_queue, 50, 4000),
    SCEN(queue_count, std3, 80, 4000),
    {"queue_size_before_init", queue_size_before_init, queue_size_small, 0, 1000, 0},
    SCEN(queue_resize, std3, 0, 4000),
    SCEN(groups_two, two_groups, 200, 4000),
    SCEN(groups_four, four_groups, 100, 4000),
    SCEN(softlimit_line, soft_limits, 400, 4000),
    SCEN(softlimit_off, soft_limits, 0, 4000),
    SCEN(softlimit_exact, soft_limits, 700, 4000),
    SCEN(softlimit_jog, soft_limits, 0, 4000),
    SCEN(pulse_rate_error, ppr_huge, 200, 2000),
    SCEN(max_pulse_speed, std3, 0, 4000),
    SCEN(sys_max_speed, std3, 0, 4000),
    SCEN(change_feed, std3, 150, 4000),
    SCEN(fix_speed, std3, 150, 4000),
    SCEN(hold_delay_mid, std3, 200, 4000),
    SCEN(hold_delay_last, std3, 200, 4000),
    SCEN(hold_delay_before_last, std3, 200, 4000),
    SCEN(hold_delay_alone, std3, 200, 4000),
    SCEN(ptp_hold_ovr_running, std3, 800, 6000),
    SCEN(ptp_hold_ovr_started, std3, 800, 6000),
    SCEN(ptp_hold_ovr_both, std3, 800, 6000),
    SCEN(ptp_hold_ovr_held, std3, 800, 6000),
    SCEN(blend_ovr_mid, std3, 300, 4000),
    SCEN(blend_ovr_up, std3, 300, 4000),
    SCEN(blend_ovr_before, std3, 300, 4000),
    SCEN_END,
};
