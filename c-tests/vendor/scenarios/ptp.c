/* Point-to-point and jog: speeds, per-axis distances, single axes, synchronous PtP, the
 * PtP profile settings, and the three jogs. */
#include "common.h"

STD_SETUP(std3, 10000, 1, 3)
STD_SETUP(std8, 10000, 1, 8)

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

/* Channels of different speeds: 3000, 1500 and 600 rpm. */
static int rpm3(void)
{
    SYS_MAC_PARAM m;
    vd_mac_default(10000);
    for (int ch = 0; ch < 3; ch++) {
        V(MCC_GetMacParam)(&m, (WORD)ch, 0);
        m.wRPM = (WORD)(ch == 0 ? 3000 : ch == 1 ? 1500 : 600);
        CI(MCC_SetMacParam, &m, (WORD)ch, 0);
    }
    CI(MCC_CloseAllGroups);
    vd_make_group(0, 3);
    return vd_init(1) < 0;
}

#define PTP_CASE(name, ratio, acc, dec, call)                                              \
    static void name(int t)                                                                \
    {                                                                                      \
        if (t == 0) {                                                                      \
            CI(MCC_SetAccTime, acc, 0);                                                    \
            CI(MCC_SetDecTime, dec, 0);                                                    \
            CD(MCC_SetPtPSpeed, ratio, 0);                                                 \
            call;                                                                          \
        }                                                                                  \
    }

PTP_CASE(ptp_default, 1, 100, 100, PTP(0, 0.2, 0.1, -0.05))
PTP_CASE(ptp_10, 10, 50, 50, PTP(0, 1, 0.5, -0.25))
PTP_CASE(ptp_50, 50, 50, 50, PTP(0, 10, 5, 2))
PTP_CASE(ptp_100, 100, 50, 50, PTP(0, 10, 5, 2))
PTP_CASE(ptp_short, 50, 100, 100, PTP(0, 0.01, 0.003, 0))
PTP_CASE(ptp_asym, 20, 20, 150, PTP(0, 2, -1, 0.5))
PTP_CASE(ptp_over_100, 150, 50, 50, PTP(0, 0.05, 0, 0))
PTP_CASE(ptp_rpm, 50, 50, 50, PTP(0, 5, 5, 5))
PTP_CASE(ptp_frac, 20, 50, 50, PTP(0, 1, 1, 1))
PTP_CASE(syncptp_50, 50, 50, 50, CI(MCC_SyncPtP, 10, 5, 2, 0, 0, 0, 0, 0, 0, IMP_AXIS_ALL))
PTP_CASE(syncptp_rpm, 50, 50, 50, CI(MCC_SyncPtP, 5, 5, 5, 0, 0, 0, 0, 0, 0, IMP_AXIS_ALL))
PTP_CASE(ptpx_single, 30, 40, 40, CI(MCC_PtPX, 3, 0))
PTP_CASE(ptpy_single, 30, 40, 40, CI(MCC_PtPY, -3, 0))
PTP_CASE(ptpz_single, 30, 40, 40, CI(MCC_PtPZ, 0.7, 0))
PTP_CASE(ptp_mask, 30, 40, 40,
         CI(MCC_PtP, 1, 2, 3, 0, 0, 0, 0, 0, 0, 0x6))

static void ptp_axes8(int t)
{
    if (t == 0) {
        CD(MCC_SetPtPSpeed, 20, 0);
        CI(MCC_PtP, 1, -1, 2, -2, 0.5, -0.5, 3, 0.1, 0, IMP_AXIS_ALL);
        CI(MCC_PtPU, 0, 0);
        CI(MCC_PtPV, 0, 0);
        CI(MCC_PtPW, 0, 0);
        CI(MCC_PtPA, 0, 0);
        CI(MCC_PtPB, 0, 0);
    }
}

static void ptp_s_type(int t)
{
    if (t == 0) {
        vd_dump_group(0);
        CI(MCC_SetPtPAccType, 'S', 'S', 'T', 'T', 'T', 'T', 'T', 'T', 0);
        CI(MCC_SetPtPDecType, 'T', 'S', 'S', 'T', 'T', 'T', 'T', 'T', 0);
        vd_dump_group(0);
        CD(MCC_SetPtPSpeed, 20, 0);
        PTP(0, 2, 2, 2);
    }
}

static void ptp_axis_times(int t)
{
    if (t == 0) {
        CI(MCC_SetPtPAccTime, 20, 80, 150, 100, 100, 100, 100, 100, 0);
        CI(MCC_SetPtPDecTime, 150, 80, 20, 100, 100, 100, 100, 100, 0);
        vd_dump_group(0);
        CD(MCC_SetPtPSpeed, 20, 0);
        PTP(0, 2, 2, 2);
    }
}

static void ptp_relative_seq(int t)
{
    if (t == 0) {
        CI(MCC_SetIncrease, 0);
        CD(MCC_SetPtPSpeed, 25, 0);
        PTP(0, 1, 0.5, 0);
        PTP(0, -0.5, 0.5, 0.25);
        LINE(0, 0.25, 0.25, 0.25);
    }
}

static void ptp_then_line(int t)
{
    if (t == 0) {
        CD(MCC_SetPtPSpeed, 25, 0);
        vd_profile('T', 30, 30, 10);
        PTP(0, 1, 0.5, 0);
        LINE(0, 0, 0, 0);
    }
}

/* Jog: by pulses, by units, continuous with an abort. */
static void jog_pulse(int t)
{
    if (t == 0) {
        CI(MCC_SetAccTime, 50, 0);
        CI(MCC_SetDecTime, 50, 0);
        CI(MCC_JogPulse, 100, 'X', 0);
    }
    if (t == 100)
        CI(MCC_JogPulse, -37, 'Y', 0);
}

static void jog_pulse_500(int t)
{
    if (t == 0)
        CI(MCC_JogPulse, 500, 'X', 0);
    if (t == 300)
        CI(MCC_JogPulse, 2047, 'Y', 0);
    if (t == 600)
        CI(MCC_JogPulse, 2048, 'Z', 0);
}

static void jog_pulse_then_line(int t)
{
    if (t == 0)
        CI(MCC_JogPulse, 50, 'X', 0);
    if (t == 200) {
        LINE(0, 1, 0, 0);
        CI(MCC_JogSpace, 0.1, 20, 'Y', 0);
        CI(MCC_JogConti, 1, 20, 'Z', 0);
    }
    if (t == 210) {
        CI(MCC_AbortMotionEx, 0.05, 0);
    }
    if (t == 300)
        LINE(0, 1, 0, 0);
}

static void jog_space(int t)
{
    if (t == 0) {
        CI(MCC_SetAccTime, 50, 0);
        CI(MCC_SetDecTime, 50, 0);
        CI(MCC_JogSpace, 0.5, 30, 'X', 0);
    }
    if (t == 400)
        CI(MCC_JogSpace, -0.25, 80, 'Z', 0);
}

static void jog_space_short(int t)
{
    if (t == 0) {
        CI(MCC_SetAccTime, 100, 0);
        CI(MCC_SetDecTime, 100, 0);
        CI(MCC_JogSpace, 0.01, 50, 'Y', 0);
    }
}

static void jog_conti(int t)
{
    if (t == 0) {
        CI(MCC_SetAccTime, 50, 0);
        CI(MCC_SetDecTime, 80, 0);
        CI(MCC_JogConti, 1, 20, 'X', 0);
    }
    if (t == 300)
        CI(MCC_AbortMotion, 0, 0);
    if (t == 500)
        CI(MCC_JogConti, -1, 40, 'Y', 0);
    if (t == 700)
        CI(MCC_AbortMotionEx, 0.02, 0);
}

/* Jog with the axis given as a number 0..7 (the vendor's cAxis). */
static void jog_num_pulse(int t)
{
    if (t == 0) {
        CI(MCC_SetAccTime, 50, 0);
        CI(MCC_SetDecTime, 50, 0);
        CI(MCC_JogPulse, 100, 0, 0);
    }
    if (t == 200)
        CI(MCC_JogPulse, -37, 1, 0);
    if (t == 400) {
        CI(MCC_JogPulse, 500, 2, 0);
        CI(MCC_JogPulse, 500, 2, 0);
    }
    if (t == 900)
        CI(MCC_AbortMotionEx, 0.01, 0);
    if (t == 950)
        CI(MCC_JogPulse, 2047, 0, 0);
    if (t == 1400) {
        CI(MCC_JogPulse, 2048, 1, 0);
        CI(MCC_JogPulse, 0, 1, 0);
        CI(MCC_JogPulse, 5, 8, 0);
        CI(MCC_JogPulse, 5, -1, 0);
    }
}

static void jog_num_space(int t)
{
    if (t == 0) {
        CI(MCC_SetAccTime, 50, 0);
        CI(MCC_SetDecTime, 80, 0);
        CI(MCC_JogSpace, 0.5, 30, 0, 0);
    }
    if (t == 300)
        LINE(0, 0, 0, 0);
    if (t == 310)
        CI(MCC_AbortMotionEx, 0.01, 0);
    if (t == 400)
        CI(MCC_JogSpace, -0.25, 80, 2, 0);
    if (t == 700) {
        CI(MCC_AbortMotionEx, 0.01, 0);
        CI(MCC_JogSpace, 0.01, 50, 1, 0);
    }
    if (t == 900) {
        CI(MCC_JogSpace, 0.01, 0, 1, 0);
        CI(MCC_JogSpace, 0.01, 101, 1, 0);
        CI(MCC_JogSpace, 0.01, -5, 1, 0);
    }
}

static void jog_num_conti(int t)
{
    if (t == 0) {
        CI(MCC_SetAccTime, 50, 0);
        CI(MCC_SetDecTime, 80, 0);
        CI(MCC_JogConti, 1, 20, 0, 0);
    }
    if (t == 300)
        CI(MCC_AbortMotion, 0, 0);
    if (t == 400)
        CI(MCC_JogConti, -1, 40, 1, 0);
    if (t == 600)
        CI(MCC_AbortMotionEx, 0.02, 0);
    if (t == 700)
        CI(MCC_JogConti, 1, 10, 2, 0);
    if (t == 800)
        CI(MCC_HoldMotion, 0, 0);
    if (t == 900)
        CI(MCC_ContiMotion, 0);
    if (t == 1000)
        CI(MCC_AbortMotionEx, 0.05, 0);
}

/* The feed speed a PtP reports: axes of different distances and speeds. */
static void ptp_feed_axis(int t)
{
    if (t == 0) {
        CD(MCC_SetPtPSpeed, 20, 0);
        PTP(0, 0.5, 2, 1);
    }
    if (t == 400)
        PTP(0, 0, 0, -1);
}

/* A timed abort of a PtP at cruise, of two lengths, and of a PtP still accelerating. */
static void ptp_abortex(int t)
{
    if (t == 0) {
        vd_profile('T', 20, 20, 10);
        CD(MCC_SetPtPSpeed, 20, 0);
        PTP(0, 5, 2, 0);
    }
    if (t == 300)
        CI(MCC_AbortMotionEx, 0.1, 0);
    if (t == 500)
        PTP(0, 0, 0, 0);
    if (t == 800)
        CI(MCC_AbortMotionEx, 0.004, 0);
    if (t == 900)
        PTP(0, 5, 2, 0);
    if (t == 1000)
        CI(MCC_AbortMotionEx, 0.02, 0);
}

/* What a jog by pulses leaves behind: which commands it refuses after, and what clears it. */
static void jog_pulse_after(int t)
{
    if (t == 0)
        CI(MCC_JogPulse, 100, 0, 0);
    if (t == 20) {
        LINE(0, 0.1, 0, 0);
        CI(MCC_JogSpace, 0.1, 20, 1, 0);
        CI(MCC_JogConti, 1, 20, 1, 0);
        PTP(0, 0.1, 0, 0);
        CI(MCC_DelayMotion, 5, 0);
        CI(MCC_ArcXY, 0.2, 0.1, 0.3, 0, 0);
        vd_note("GetMotionStatus %d", V(MCC_GetMotionStatus)(0));
        vd_note("GetErrorCode %d", V(MCC_GetErrorCode)(0));
        CI(MCC_JogPulse, 10, 1, 0);
    }
    if (t == 40) {
        LINE(0, 0.1, 0, 0);
        CI(MCC_ClearError, 0);
        LINE(0, 0.1, 0, 0);
        CI(MCC_AbortMotion, 0, 0);
        LINE(0, 0.1, 0, 0);
        CI(MCC_ResetMotion);
        LINE(0, 0.1, 0, 0);
    }
    if (t == 60) {
        CI(MCC_AbortMotionEx, 0.01, 0);
        LINE(0, 0.2, 0, 0);
    }
}

static void jog_bad_axis(int t)
{
    if (t == 0) {
        CI(MCC_JogPulse, 10, 'Q', 0);
        CI(MCC_JogSpace, 0.1, 10, 'x', 0);
        CI(MCC_JogConti, 1, 10, 'D', 0);
        CI(MCC_JogSpace, 0.1, 0, 'X', 0);
        CI(MCC_JogSpace, 0.1, 150, 'X', 0);
        CI(MCC_JogConti, 0, 10, 'X', 0);
    }
}

const Scenario vd_ptp[] = {
    SCEN(ptp_default, std3, 0, 8000),
    SCEN(ptp_abortex, std3, 1000, 8000),
    SCEN(jog_pulse_after, std3, 60, 8000),
    SCEN(ptp_10, std3, 0, 8000),
    SCEN(ptp_50, std3, 0, 8000),
    SCEN(ptp_100, std3, 0, 8000),
    SCEN(ptp_short, std3, 0, 8000),
    SCEN(ptp_asym, std3, 0, 8000),
    SCEN(ptp_over_100, std3, 0, 8000),
    SCEN(ptp_rpm, rpm3, 0, 8000),
    SCEN(ptp_frac, frac3, 0, 8000),
    SCEN(syncptp_50, std3, 0, 8000),
    SCEN(syncptp_rpm, rpm3, 0, 8000),
    SCEN(ptpx_single, std3, 0, 8000),
    SCEN(ptpy_single, std3, 0, 8000),
    SCEN(ptpz_single, std3, 0, 8000),
    SCEN(ptp_mask, std3, 0, 8000),
    SCEN(ptp_axes8, std8, 0, 8000),
    SCEN(ptp_s_type, std3, 0, 8000),
    SCEN(ptp_axis_times, std3, 0, 8000),
    SCEN(ptp_relative_seq, std3, 0, 8000),
    SCEN(ptp_then_line, std3, 0, 8000),
    SCEN(jog_pulse, std3, 100, 4000),
    SCEN(jog_pulse_500, std3, 600, 4000),
    SCEN(jog_pulse_then_line, std3, 300, 4000),
    SCEN(jog_space, std3, 400, 4000),
    SCEN(jog_space_short, std3, 0, 4000),
    SCEN(jog_conti, std3, 700, 4000),
    SCEN(jog_bad_axis, std3, 0, 2000),
    SCEN(jog_num_pulse, std3, 1400, 4000),
    SCEN(jog_num_space, std3, 900, 4000),
    SCEN(jog_num_conti, std3, 1000, 4000),
    SCEN(ptp_feed_axis, rpm3, 400, 4000),
    SCEN_END,
};
