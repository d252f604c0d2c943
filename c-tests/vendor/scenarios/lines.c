/* Lines: curve types, lengths (long, short, very short, none), 1 to 8 axes, absolute and
 * relative, axis masks, periods, pulses that are not whole numbers of units. */
#include "common.h"
#include <math.h>

STD_SETUP(std3, 10000, 1, 3)
STD_SETUP(std3_ppr1000, 1000, 1, 3)
STD_SETUP(std3_ppr1e6, 1000000, 1, 3)
STD_SETUP(std3_p2, 10000, 2, 3)
STD_SETUP(std3_p5, 10000, 5, 3)
STD_SETUP(std3_p10, 10000, 10, 3)
STD_SETUP(std1, 10000, 1, 1)
STD_SETUP(std2, 10000, 1, 2)
STD_SETUP(std4, 10000, 1, 4)
STD_SETUP(std5, 10000, 1, 5)
STD_SETUP(std6, 10000, 1, 6)
STD_SETUP(std7, 10000, 1, 7)
STD_SETUP(std8, 10000, 1, 8)

/* Channels with pitch and gear that make a unit a fraction of pulses. */
static int frac3(void)
{
    vd_mac_default(10000);
    vd_mac(0, 1000, 3, 7);      /* 1000*7/3 = 2333.33 pulses a unit */
    vd_mac(1, 2000, 0.7, 1.3);  /* 3714.29 */
    vd_mac(2, 4096, 5, 1);      /* 819.2 */
    CI(MCC_CloseAllGroups);
    vd_make_group(0, 3);
    return vd_init(1) < 0;
}

static void line_t_long(int t)
{
    if (t == 0) {
        CI(MCC_SetAbsolute, 0);
        vd_profile('T', 100, 100, 10);
        LINE(0, 10, 10, 0);
    }
}

static void line_s_long(int t)
{
    if (t == 0) {
        CI(MCC_SetAbsolute, 0);
        vd_profile('S', 100, 100, 10);
        LINE(0, 10, 10, 0);
    }
}

static void line_default_profile(int t)
{
    if (t == 0) {
        vd_dump_group(0);
        LINE(0, 0.2, 0.1, 0.05);
    }
}

#define LINE_CASE(name, type, acc, dec, feed, x, y, z)                                     \
    static void name(int t)                                                                \
    {                                                                                      \
        if (t == 0) {                                                                      \
            vd_profile(type, acc, dec, feed);                                              \
            LINE(0, x, y, z);                                                              \
        }                                                                                  \
    }

LINE_CASE(line_t_mid, 'T', 50, 50, 20, 3, -4, 0)
LINE_CASE(line_s_mid, 'S', 50, 50, 20, 3, -4, 0)
LINE_CASE(line_t_short, 'T', 100, 100, 10, 0.05, 0, 0)
LINE_CASE(line_s_short, 'S', 100, 100, 10, 0.05, 0, 0)
LINE_CASE(line_t_veryshort, 'T', 100, 100, 10, 0.0005, 0, 0)
LINE_CASE(line_s_veryshort, 'S', 100, 100, 10, 0.0005, 0.0002, 0)
LINE_CASE(line_t_onepulse, 'T', 20, 20, 10, 0.0001, 0, 0)
LINE_CASE(line_zero_length, 'T', 20, 20, 10, 0, 0, 0)
LINE_CASE(line_t_asym, 'T', 30, 120, 10, 1, 2, 2)
LINE_CASE(line_s_asym, 'S', 120, 30, 10, -1, 2, -2)
LINE_CASE(line_t_acc0, 'T', 0, 0, 10, 1, 0, 0)
LINE_CASE(line_s_acc1, 'S', 1, 1, 10, 1, 0, 0)
LINE_CASE(line_t_negative, 'T', 40, 40, 7, -1.23456, -0.5, -2.00001)
LINE_CASE(line_t_frac_target, 'T', 40, 40, 5, 1.2345, 0.00015, -0.00015)
LINE_CASE(line_t_slow, 'T', 20, 20, 0.5, 0.05, 0.02, 0)
LINE_CASE(line_t_fast, 'T', 50, 50, 200, 20, 10, 5)
LINE_CASE(line_s_fast, 'S', 50, 50, 200, 20, 10, 5)
LINE_CASE(line_t_feed_over_max, 'T', 50, 50, 1000, 30, 0, 0)
LINE_CASE(line_t_feed_exact_ticks, 'T', 20, 20, 10, 1, 0, 0)

static void line_mixed_types(int t)
{
    if (t == 0) {
        CI(MCC_SetAccType, 'T', 0);
        CI(MCC_SetDecType, 'S', 0);
        CI(MCC_SetAccTime, 60, 0);
        CI(MCC_SetDecTime, 80, 0);
        CD(MCC_SetFeedSpeed, 10, 0);
        LINE(0, 1, 1, 0);
        vd_dump_group(0);
    }
}

static void line_ppr1e6(int t)
{
    if (t == 0) {
        vd_profile('S', 50, 50, 10);
        LINE(0, 1.2345678, -0.7654321, 0.1111111);
    }
}

static void line_ppr1000_frac(int t)
{
    if (t == 0) {
        vd_profile('T', 50, 50, 10);
        LINE(0, 1.2345, 0.0015, -0.0025);
    }
}

static void line_pitch_gear(int t)
{
    if (t == 0) {
        vd_profile('T', 50, 50, 10);
        LINE(0, 1, 1, 1);
    }
    if (t == 400)
        LINE(0, -0.3, 0.123, 2.5);
}

static void line_s_pitch_gear(int t)
{
    if (t == 0) {
        vd_profile('S', 40, 60, 8);
        LINE(0, 0.777, -0.333, 0.1);
    }
}

/* 1..8 axes: every axis moves a different distance. */
#define AXES_CASE(name, n)                                                                 \
    static void name(int t)                                                                \
    {                                                                                      \
        if (t == 0) {                                                                      \
            vd_profile('T', 40, 40, 10);                                                   \
            double d[8] = {1, -0.5, 0.25, 2, -1.5, 0.75, -0.125, 1.25};                    \
            for (int i = n; i < 8; i++)                                                    \
                d[i] = 0;                                                                  \
            LINE8(0, d[0], d[1], d[2], d[3], d[4], d[5], d[6], d[7]);                      \
        }                                                                                  \
    }
AXES_CASE(line_axes1, 1)
AXES_CASE(line_axes2, 2)
AXES_CASE(line_axes3, 3)
AXES_CASE(line_axes4, 4)
AXES_CASE(line_axes5, 5)
AXES_CASE(line_axes6, 6)
AXES_CASE(line_axes7, 7)
AXES_CASE(line_axes8, 8)

/* Only auxiliary axes (U, V) move: the path speed of a move without X, Y, Z. */
static void line_aux_only(int t)
{
    if (t == 0) {
        vd_profile('T', 40, 40, 10);
        LINE8(0, 0, 0, 0, 1, -2, 0, 0, 0);
    }
}

static void line_s_axes8(int t)
{
    if (t == 0) {
        vd_profile('S', 40, 40, 10);
        LINE8(0, 0.5, 0.5, 0.5, 1, 1, 1, -1, -1);
    }
}

static void line_relative(int t)
{
    if (t == 0) {
        CI(MCC_SetIncrease, 0);
        vd_profile('T', 30, 30, 10);
        LINE(0, 0.5, 0.2, 0);
        LINE(0, 0.5, -0.4, 0.1);
        vd_note("GetCoordType %d", V(MCC_GetCoordType)(0));
    }
}

static void line_abs_after_rel(int t)
{
    if (t == 0) {
        CI(MCC_SetIncrease, 0);
        vd_profile('T', 30, 30, 10);
        LINE(0, 0.5, 0.2, 0);
        CI(MCC_SetAbsolute, 0);
        LINE(0, 0.5, 0.2, 0.3);
    }
}

static void line_mask(int t)
{
    if (t == 0) {
        vd_profile('T', 30, 30, 10);
        CI(MCC_Line, 1, 1, 1, 0, 0, 0, 0, 0, 0, 0x5); /* X and Z only */
    }
    if (t == 250)
        CI(MCC_Line, 2, 2, 2, 0, 0, 0, 0, 0, 0, 0x2); /* Y only */
}

static void line_seq3(int t)
{
    if (t == 0) {
        vd_profile('T', 30, 30, 10);
        LINE(0, 1, 0, 0);
        LINE(0, 1, 1, 0);
        LINE(0, 0, 0, 0);
    }
}

static void line_seq_s(int t)
{
    if (t == 0) {
        vd_profile('S', 30, 30, 10);
        LINE(0, 1, 0, 0);
        LINE(0, 1, 1, 0);
    }
}

static void line_blend_t(int t)
{
    if (t == 0) {
        vd_profile('T', 50, 50, 10);
        CI(MCC_EnableBlend, 0);
        LINE(0, 1, 0, 0);
        LINE(0, 1, 1, 0);
        LINE(0, 2, 1, 0);
        vd_note("CheckBlend %d", V(MCC_CheckBlend)(0));
    }
}

static void line_blend_s(int t)
{
    if (t == 0) {
        vd_profile('S', 50, 50, 10);
        CI(MCC_EnableBlend, 0);
        LINE(0, 1, 0, 0);
        LINE(0, 1, 1, 0);
        LINE(0, 2, 1, 0);
    }
}

static void line_blend_off(int t)
{
    if (t == 0) {
        vd_profile('T', 50, 50, 10);
        CI(MCC_EnableBlend, 0);
        LINE(0, 1, 0, 0);
        CI(MCC_DisableBlend, 0);
        LINE(0, 1, 1, 0);
        LINE(0, 2, 1, 0);
    }
    if (t == 2 || t == 5)
        vd_note("CheckBlend %d", V(MCC_CheckBlend)(0));
}

static void line_blend_speeds(int t)
{
    if (t == 0) {
        vd_profile('T', 40, 40, 5);
        CI(MCC_EnableBlend, 0);
        LINE(0, 0.5, 0, 0);
        CD(MCC_SetFeedSpeed, 15, 0);
        LINE(0, 1.5, 0.5, 0);
        CD(MCC_SetFeedSpeed, 3, 0);
        LINE(0, 1.5, 0.8, 0);
    }
}

static void line_blend_short(int t)
{
    if (t == 0) {
        vd_profile('T', 50, 50, 10);
        CI(MCC_EnableBlend, 0);
        LINE(0, 0.1, 0, 0);
        LINE(0, 0.1, 0.1, 0);
        LINE(0, 0.12, 0.1, 0);
    }
}

static void line_feed_change_queued(int t)
{
    if (t == 0) {
        vd_profile('T', 30, 30, 10);
        LINE(0, 1, 0, 0);
        CD(MCC_SetFeedSpeed, 4, 0);
        CI(MCC_SetAccTime, 80, 0);
        LINE(0, 1, 1, 0);
    }
    if (t == 50)
        CD(MCC_SetFeedSpeed, 20, 0); /* the running line keeps its own */
}

static void line_period(int t)
{
    if (t == 0) {
        vd_profile('T', 50, 50, 10);
        LINE(0, 1, 0.5, 0);
    }
}

static void line_period_s(int t)
{
    if (t == 0) {
        vd_profile('S', 50, 30, 10);
        LINE(0, 0.3, 0.5, 0);
    }
}

/* Where the pulse count turns over: axis i ends 10^-(i+1) pulses short of a whole pulse,
 * then as far past one on the negative side. */
STD_SETUP(std8_ppr1000, 1000, 1, 8)
static void pulse_epsilon(int t)
{
    double d[8];
    for (int i = 0; i < 8; i++)
        d[i] = 1 - pow(10, -(i + 1)) / 1000;
    if (t == 0) {
        vd_profile('T', 10, 10, 10);
        LINE8(0, d[0], d[1], d[2], d[3], d[4], d[5], d[6], d[7]);
    }
    if (t == 200)
        LINE8(0, -d[0], -d[1], -d[2], -d[3], -d[4], -d[5], -d[6], -d[7]);
    if (t == 400)
        LINE8(0, 1 + d[0] - 1, 1 + d[1] - 1, 2 - d[2], 2 - d[3], 3 - d[4], 3 - d[5], -2 + d[6],
              -2 + d[7]);
}

/* Ramp times that are not whole periods. */
static void line_ramp_fraction(int t)
{
    if (t == 0) {
        vd_profile('T', 25, 35, 10);
        LINE(0, 0.5, 0.25, 0);
    }
    if (t == 100) {
        vd_profile('S', 14, 6, 10);
        LINE(0, 0, 0, 0);
    }
}

static void line_ramp_halfms(int t)
{
    if (t == 0) {
        vd_profile('T', 0.5, 1.5, 10);
        LINE(0, 0.1, 0, 0);
    }
    if (t == 30) {
        vd_profile('S', 2.7, 3.2, 10);
        LINE(0, 0, 0.1, 0);
    }
}

/* Where the pulse count turns over, finer: each line ends every axis a fraction of a
 * millionth of a pulse short of (or past) a whole pulse. */
static void pulse_epsilon2(int t)
{
    static const double delta[8] = {1.5e-7, 2e-7, 3e-7, 4e-7, 5e-7, 6e-7, 7e-7, 8e-7};
    double d[8];
    int step = t / 100;
    if (t % 100 != 0 || step > 3)
        return;
    for (int i = 0; i < 8; i++) {
        double whole = step % 2 ? -(2 + step) : 2 + step;
        double off = step < 2 ? -delta[i] : delta[i];
        d[i] = (whole + (whole > 0 ? off : -off)) / 1000;
    }
    if (t == 0)
        vd_profile('T', 10, 10, 10);
    LINE8(0, d[0], d[1], d[2], d[3], d[4], d[5], d[6], d[7]);
}

/* How acc/dec times become whole periods: one short line a pair of times. */
static void ramp_rules(int t)
{
    static const double pairs[][2] = {{1, 2}, {2, 3}, {3, 3}, {2.5, 2.5}, {0.4, 0.4},
                                      {1, 1}, {3, 8}, {7, 2}, {4.4, 4.6}, {0, 3}};
    int i = t / 40;
    if (t % 40 != 0 || i >= 10)
        return;
    CI(MCC_SetAccTime, pairs[i][0], 0);
    CI(MCC_SetDecTime, pairs[i][1], 0);
    vd_note("GetAccTime %.17g", V(MCC_GetAccTime)(0));
    vd_note("GetDecTime %.17g", V(MCC_GetDecTime)(0));
    LINE(0, i % 2 ? 0 : 0.1, 0, 0);
}

static void ramp_rules_p10(int t)
{
    static const double pairs[][2] = {{30, 50}, {20, 40}, {10, 10}, {15, 15},
                                      {10, 30}, {40, 10}, {25, 25}, {0, 20}};
    int i = t / 20;
    if (t % 20 != 0 || i >= 8)
        return;
    CI(MCC_SetAccTime, pairs[i][0], 0);
    CI(MCC_SetDecTime, pairs[i][1], 0);
    LINE(0, i % 2 ? 0 : 0.3, 0, 0);
}

static void ramp_rules_s(int t)
{
    static const double pairs[][2] = {{1, 2}, {2, 3}, {3, 8}, {7, 2}};
    int i = t / 40;
    if (t % 40 != 0 || i >= 4)
        return;
    if (t == 0) {
        CI(MCC_SetAccType, 'S', 0);
        CI(MCC_SetDecType, 'S', 0);
    }
    CI(MCC_SetAccTime, pairs[i][0], 0);
    CI(MCC_SetDecTime, pairs[i][1], 0);
    LINE(0, i % 2 ? 0 : 0.1, 0, 0);
}

/* Blending when the first line's deceleration and the second's acceleration differ. */
static void blend_times(int t)
{
    if (t == 0) {
        CI(MCC_EnableBlend, 0);
        vd_profile('T', 20, 60, 10);
        LINE(0, 1, 0, 0);
        vd_profile('T', 30, 10, 5);
        LINE(0, 1, 0.5, 0);
        vd_profile('S', 80, 40, 8);
        LINE(0, 0.5, 0.5, 0);
    }
}

const Scenario vd_lines[] = {
    SCEN(line_t_long, std3, 0, 4000),
    SCEN(line_s_long, std3, 0, 4000),
    SCEN(line_default_profile, std3_ppr1e6, 0, 20000),
    SCEN(line_t_mid, std3, 0, 4000),
    SCEN(line_s_mid, std3, 0, 4000),
    SCEN(line_t_short, std3, 0, 4000),
    SCEN(line_s_short, std3, 0, 4000),
    SCEN(line_t_veryshort, std3, 0, 4000),
    SCEN(line_s_veryshort, std3, 0, 4000),
    SCEN(line_t_onepulse, std3, 0, 4000),
    SCEN(line_zero_length, std3, 0, 4000),
    SCEN(line_t_asym, std3, 0, 4000),
    SCEN(line_s_asym, std3, 0, 4000),
    SCEN(line_t_acc0, std3, 0, 4000),
    SCEN(line_s_acc1, std3, 0, 4000),
    SCEN(line_t_negative, std3, 0, 4000),
    SCEN(line_t_frac_target, std3_ppr1000, 0, 4000),
    SCEN(line_t_slow, std3, 0, 4000),
    SCEN(line_t_fast, std3, 0, 4000),
    SCEN(line_s_fast, std3, 0, 4000),
    SCEN(line_t_feed_over_max, std3, 0, 4000),
    SCEN(line_t_feed_exact_ticks, std3, 0, 4000),
    SCEN(line_mixed_types, std3, 0, 4000),
    SCEN(line_ppr1e6, std3_ppr1e6, 0, 4000),
    SCEN(line_ppr1000_frac, std3_ppr1000, 0, 4000),
    SCEN(line_pitch_gear, frac3, 400, 4000),
    SCEN(line_s_pitch_gear, frac3, 0, 4000),
    SCEN(line_axes1, std1, 0, 4000),
    SCEN(line_axes2, std2, 0, 4000),
    SCEN(line_axes3, std3, 0, 4000),
    SCEN(line_axes4, std4, 0, 4000),
    SCEN(line_axes5, std5, 0, 4000),
    SCEN(line_axes6, std6, 0, 4000),
    SCEN(line_axes7, std7, 0, 4000),
    SCEN(line_axes8, std8, 0, 4000),
    SCEN(line_aux_only, std8, 0, 4000),
    SCEN(line_s_axes8, std8, 0, 4000),
    SCEN(line_relative, std3, 0, 4000),
    SCEN(line_abs_after_rel, std3, 0, 4000),
    SCEN(line_mask, std3, 250, 4000),
    SCEN(line_seq3, std3, 0, 4000),
    SCEN(line_seq_s, std3, 0, 4000),
    SCEN(line_blend_t, std3, 0, 4000),
    SCEN(line_blend_s, std3, 0, 4000),
    SCEN(line_blend_off, std3, 5, 4000),
    SCEN(line_blend_speeds, std3, 0, 4000),
    SCEN(line_blend_short, std3, 0, 4000),
    SCEN(line_feed_change_queued, std3, 50, 4000),
    {"line_period2", std3_p2, line_period, 0, 2000, 0},
    {"line_period5", std3_p5, line_period, 0, 1000, 0},
    {"line_period10", std3_p10, line_period, 0, 500, 0},
    {"line_period10_s", std3_p10, line_period_s, 0, 500, 0},
    SCEN(pulse_epsilon, std8_ppr1000, 400, 4000),
    {"line_ramp_fraction", std3_p10, line_ramp_fraction, 100, 500, 0},
    SCEN(line_ramp_halfms, std3, 30, 500),
    SCEN(pulse_epsilon2, std8_ppr1000, 300, 4000),
    SCEN(ramp_rules, std3, 360, 4000),
    {"ramp_rules_p10", std3_p10, ramp_rules_p10, 140, 1000, 0},
    SCEN(ramp_rules_s, std3, 120, 4000),
    SCEN(blend_times, std3, 0, 4000),
    SCEN_END,
};
