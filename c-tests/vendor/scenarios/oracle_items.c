/* What the vendor's library does where the manuals leave a question open: hold and
 * continue with nothing to hold or continue, the override rate OverrideSpeedEx sets, a
 * group that drives no axis, the go-home parameters it takes, a custom motion whose
 * interpolation fails, kinematics registered before the card starts. */
#include "common.h"
#include <math.h>
#include <stdio.h>
#include <string.h>

STD_SETUP(std3, 10000, 1, 3)

/* ---- Kinematics registered before the card starts. ----
 * A two-link arm: joint 0 the shoulder, joint 1 the elbow (degrees), links of 200 and 150
 * UU, joint 2 is Z; joints 3..7 carry the other Cartesian axes. Posture bit 0: elbow with
 * a negative joint 1. */
#define L1 200.0
#define L2 150.0
static const double kDeg = 3.14159265358979323846 / 180.0;
static volatile int k_inits;

static void MCC_CALLBACK k_init(void *ext)
{
    (void)ext;
    k_inits++;
}

static BOOL MCC_CALLBACK k_forward(int g, int n, const double *j, double *c, DWORD *posture,
                                   void *ext)
{
    (void)g, (void)posture, (void)ext;
    double q1 = j[0] * kDeg, q12 = (j[0] + j[1]) * kDeg;
    c[0] = L1 * cos(q1) + L2 * cos(q12);
    c[1] = L1 * sin(q1) + L2 * sin(q12);
    for (int i = 2; i < n && i < 8; i++)
        c[i] = j[i];
    return 1;
}

static BOOL MCC_CALLBACK k_inverse(int g, int n, const double *c, const double *prev, double *j,
                                   DWORD *posture, void *ext)
{
    (void)g, (void)prev, (void)ext;
    double c2 = (c[0] * c[0] + c[1] * c[1] - L1 * L1 - L2 * L2) / (2 * L1 * L2);
    if (c2 < -1 || c2 > 1)
        return 0;
    double s2 = sqrt(1 - c2 * c2) * ((*posture & 1) ? -1.0 : 1.0);
    j[0] = (atan2(c[1], c[0]) - atan2(L2 * s2, L1 + L2 * c2)) / kDeg;
    j[1] = atan2(s2, c2) / kDeg;
    for (int i = 2; i < n && i < 8; i++)
        j[i] = c[i];
    return 1;
}

/* Registered before MCC_InitSimulation (accepted; the initialiser runs in the init), then
 * again after it (refused). */
static int kine_registered(void)
{
    vd_mac_default(10000);
    CI(MCC_CloseAllGroups);
    vd_make_group(0, 3);
    CI(MCC_SetKinematicTrans, k_forward, k_inverse, 16, k_init, 0);
    vd_note("KinematicsInits %d", k_inits);
    int r = vd_init(1);
    vd_note("KinematicsInits %d", k_inits);
    CI(MCC_SetKinematicTrans, k_forward, k_inverse, 16, k_init, 0);
    return r < 0;
}

static void cur_pos_note(void)
{
    double c[8] = {0};
    int r = V(MCC_GetCurPos)(&c[0], &c[1], &c[2], &c[3], &c[4], &c[5], &c[6], &c[7], 0);
    vd_note("GetCurPos %d %.17g %.17g %.17g", r, c[0], c[1], c[2]);
}

/* MCC_PtP_V6 to the joints (22, -81, 5) at the full PtP speed: the joints move as a
 * point-to-point move does, and every position a program reads is the joints'. */
static void kine_ptp_v6(int t)
{
    if (t == 0) {
        cur_pos_note();
        CD(MCC_SetPtPSpeed, 100, 0);
        vd_profile('T', 100, 100, 50);
        CI(MCC_PtP_V6, 22, -81, 5, 0, 0, 0, 0, 0, 0, IMP_AXIS_ALL);
    }
    if (t == 1800)
        cur_pos_note();
}

/* Without kinematics: MCC_SetKinematicTrans after init is refused, and MCC_PtP_V6 and
 * MCC_Line_V6 move the axes as MCC_PtP and MCC_Line do. */
static void kine_after_init(int t)
{
    if (t == 0) {
        CI(MCC_SetKinematicTrans, k_forward, k_inverse, 16, k_init, 0);
        vd_note("KinematicsInits %d", k_inits);
        CD(MCC_SetPtPSpeed, 100, 0);
        vd_profile('T', 20, 20, 10);
        CI(MCC_PtP_V6, 0.2, -0.1, 0.05, 0, 0, 0, 0, 0, 0, IMP_AXIS_ALL);
        CI(MCC_Line_V6, 0.1, 0, 0, 0, 0, 0, 0, 0, 0, 0, IMP_AXIS_ALL);
    }
}

/* ---- Hold and continue when there is nothing to hold or continue; the override rate
 * OverrideSpeedEx sets. ---- */

/* A hold while the group stands (nothing ever ran), a line queued while "held", then
 * continue. */
static void hold_idle_then_line(int t)
{
    if (t == 0) {
        vd_profile('T', 20, 20, 10);
        CI(MCC_HoldMotion, 0, 0);
        vd_note("GetMotionStatus %d", V(MCC_GetMotionStatus)(0));
        CI(MCC_HoldMotion, 0, 1);
    }
    if (t == 3)
        LINE(0, 0.1, 0, 0);
    if (t == 150)
        CI(MCC_ContiMotion, 0);
}

/* Continue while a line runs (not held), and once it stopped. */
static void conti_not_held(int t)
{
    if (t == 0) {
        CI(MCC_ContiMotion, 0);
        vd_profile('T', 20, 20, 10);
        LINE(0, 0.2, 0, 0);
    }
    if (t == 30)
        CI(MCC_ContiMotion, 0);
    if (t == 200) {
        CI(MCC_ContiMotion, 0);
        CI(MCC_HoldMotion, 0, 0);
        vd_note("GetMotionStatus %d", V(MCC_GetMotionStatus)(0));
    }
    if (t == 210)
        LINE(0, 0, 0, 0);
}

/* MCC_GetOverrideRate around MCC_OverrideSpeedEx(150), while a line runs (instant and
 * ramped) and while the group stands. */
static void override_ex_rate(int t)
{
    if (t == 0) {
        CD(MCC_OverrideSpeedEx, 150, 1, 0);
        vd_note("GetOverrideRate %.17g", V(MCC_GetOverrideRate)(0));
    }
    if (t >= 1 && t <= 3)
        vd_note("GetOverrideRate %.17g", V(MCC_GetOverrideRate)(0));
    if (t == 5) {
        CD(MCC_OverrideSpeedEx, 100, 1, 0);
        vd_profile('T', 50, 50, 10);
        LINE(0, 2, 0, 0);
    }
    if (t == 100) {
        CD(MCC_OverrideSpeedEx, 150, 1, 0);
        vd_note("GetOverrideRate %.17g", V(MCC_GetOverrideRate)(0));
    }
    if (t == 150) {
        CD(MCC_OverrideSpeedEx, 50, 0, 0);
        vd_note("GetOverrideRate %.17g", V(MCC_GetOverrideRate)(0));
    }
    if ((t >= 101 && t <= 103) || (t >= 151 && t <= 153) || t == 250)
        vd_note("GetOverrideRate %.17g", V(MCC_GetOverrideRate)(0));
}

/* ---- A group of no axis; the home configuration's ranges. ---- */

static int group_no_axes(void)
{
    vd_mac_default(10000);
    CI(MCC_CloseAllGroups);
    vd_make_group(0, 0);
    vd_make_group(0, 3);
    return vd_init(1) < 0;
}

static void group_no_axes_script(int t)
{
    if (t == 0) {
        for (WORD g = 0; g < 3; g++)
            vd_note("GetMotionStatus(%u) %d", g, V(MCC_GetMotionStatus)(g));
        vd_profile_g(0, 'T', 20, 20, 10);
        vd_profile_g(1, 'T', 20, 20, 10);
        LINE(0, 0.1, 0, 0);
        PTP(0, 0.1, 0, 0);
        CI(MCC_DelayMotion, 20, 0);
        LINE(1, 0.1, 0.1, 0);
    }
}

static void group_no_axes_line(int t)
{
    if (t == 0) {
        vd_profile_g(0, 'T', 20, 20, 10);
        LINE(0, 0.1, 0, 0);
    }
}

static void group_no_axes_ptp(int t)
{
    if (t == 0)
        PTP(0, 0.1, 0, 0);
    if (t == 50) {
        CI(MCC_JogSpace, 0.1, 20, 0, 0);
        CI(MCC_JogPulse, 10, 0, 0);
    }
}

static void home_cfg(SYS_HOME_CONFIG *h)
{
    memset(h, 0, sizeof *h);
    h->wMode = 2;
    h->wDirection = 1;
    h->wSensorMode = 0;
    h->nIndexCount = 0;
    h->dfAccTime = 300;
    h->dfDecTime = 300;
    h->dfHighSpeed = 10;
    h->dfLowSpeed = 2;
    h->dfOffset = 0;
}

static void home_note(const char *what)
{
    SYS_HOME_CONFIG h;
    memset(&h, 0xAB, sizeof h);
    int r = V(MCC_GetHomeConfig)(&h, 0, 0);
    vd_note("GetHomeConfig(%s) %d %u %u %u %d %.17g %.17g %.17g %.17g %.17g", what, r, h.wMode,
            h.wDirection, h.wSensorMode, h.nIndexCount, h.dfAccTime, h.dfDecTime,
            h.dfHighSpeed, h.dfLowSpeed, h.dfOffset);
}

/* Every wMode 0..20 and some beyond, then each other field's edge values, one at a time
 * on a good configuration; the configuration read back after each. */
static void home_config_all(void)
{
    static const unsigned modes[] = {0,  1,  2,  3,  4,  5,  6,  7,  8,  9,      10,     11,
                                     12, 13, 14, 15, 16, 17, 18, 19, 20, 0x7FFF, 0xFFFE, 0xFFFF};
    SYS_HOME_CONFIG h;
    char what[32];
    for (size_t i = 0; i < sizeof modes / sizeof modes[0]; i++) {
        home_cfg(&h);
        h.wMode = (WORD)modes[i];
        snprintf(what, sizeof what, "mode %u", modes[i]);
        vd_note("SetHomeConfig(%s) %d", what, V(MCC_SetHomeConfig)(&h, 0, 0));
        home_note(what);
    }
    static const struct {
        const char *what;
        int field;
        double v;
    } edits[] = {
        {"dir 0", 0, 0},      {"dir 2", 0, 2},        {"dir 0xFFFF", 0, 0xFFFF},
        {"sensor 1", 1, 1},   {"sensor 2", 1, 2},     {"sensor 0xFFFF", 1, 0xFFFF},
        {"index -1", 2, -1},  {"index 5", 2, 5},      {"acc 0", 3, 0},
        {"acc -1", 3, -1},    {"dec 0", 4, 0},        {"dec -1", 4, -1},
        {"dec 0.5", 4, 0.5},  {"high 0", 5, 0},       {"high -1", 5, -1},
        {"low 0", 6, 0},      {"low -1", 6, -1},      {"low > high", 6, 20},
        {"offset -5", 7, -5}, {"offset 1e9", 7, 1e9},
    };
    for (size_t i = 0; i < sizeof edits / sizeof edits[0]; i++) {
        home_cfg(&h);
        double v = edits[i].v;
        switch (edits[i].field) {
        case 0: h.wDirection = (WORD)v; break;
        case 1: h.wSensorMode = (WORD)v; break;
        case 2: h.nIndexCount = (int)v; break;
        case 3: h.dfAccTime = v; break;
        case 4: h.dfDecTime = v; break;
        case 5: h.dfHighSpeed = v; break;
        case 6: h.dfLowSpeed = v; break;
        default: h.dfOffset = v; break;
        }
        vd_note("SetHomeConfig(%s) %d", edits[i].what, V(MCC_SetHomeConfig)(&h, 0, 0));
        home_note(edits[i].what);
    }
    home_cfg(&h);
    vd_note("SetHomeConfig(channel 8) %d", V(MCC_SetHomeConfig)(&h, 8, 0));
    vd_note("SetHomeConfig(card 1) %d", V(MCC_SetHomeConfig)(&h, 0, 1));
}

static int home_config_before(void)
{
    vd_mac_default(10000);
    CI(MCC_CloseAllGroups);
    vd_make_group(0, 3);
    home_config_all();
    return vd_init(1) < 0;
}

static void home_config_after(int t)
{
    if (t == 0)
        home_config_all();
}

/* ---- A custom motion whose interpolation returns FALSE. ---- */

static volatile int c_start, c_interp, c_cleanup, c_fail_at;
static int c_seen[3];

static double MCC_CALLBACK c_start_fn(int g, int n, int idx, BOOL abs_, const double *p, void *b)
{
    (void)g, (void)n, (void)idx, (void)abs_, (void)p, (void)b;
    c_start++;
    return 0.2;
}

static BOOL MCC_CALLBACK c_interp_fn(int g, int n, int idx, const double *s, const double *c,
                                     double cur, double tot, double *next, void *b)
{
    (void)g, (void)n, (void)idx, (void)s, (void)c, (void)tot, (void)b;
    c_interp++;
    next[0] = cur; /* along X, also in the call that returns FALSE */
    return c_interp < c_fail_at;
}

static void MCC_CALLBACK c_cleanup_fn(int g, int idx, void *b)
{
    (void)g, (void)idx, (void)b;
    c_cleanup++;
}

/* Notes the callbacks' counts when they changed (CustomStart / CustomInterp /
 * CustomCleanup: one label each, so that each can be compared or not on its own). */
static void custom_counts(void)
{
    int now[3] = {c_start, c_interp, c_cleanup};
    static const char *names[3] = {"CustomStart", "CustomInterp", "CustomCleanup"};
    for (int i = 0; i < 3; i++)
        if (now[i] != c_seen[i]) {
            vd_note("%s %d", names[i], now[i]);
            c_seen[i] = now[i];
        }
}

static void custom_false_at(int t, int fail_at)
{
    if (t == 0) {
        c_fail_at = fail_at;
        vd_profile('T', 20, 20, 10);
        CI(MCC_CustomMotion, c_start_fn, c_interp_fn, c_cleanup_fn, NULL, 0, IMP_AXIS_ALL);
        LINE(0, 0.1, 0.1, 0);
    }
    custom_counts();
    if (t == 150) {
        vd_note("GetErrorCode %d", V(MCC_GetErrorCode)(0));
        LINE(0, 0, 0, 0);
        CI(MCC_ClearError, 0);
    }
    if (t == 160)
        LINE(0, 0, 0, 0);
}

static void custom_false(int t)
{
    custom_false_at(t, 30);
}

static void custom_false_first(int t)
{
    custom_false_at(t, 1);
}

const Scenario vd_oracle_items[] = {
    {"kine_ptp_v6", kine_registered, kine_ptp_v6, 1800, 4000, 0},
    SCEN(kine_after_init, std3, 0, 4000),
    SCEN(hold_idle_then_line, std3, 150, 4000),
    SCEN(conti_not_held, std3, 210, 4000),
    SCEN(override_ex_rate, std3, 250, 4000),
    {"group_no_axes", group_no_axes, group_no_axes_script, 0, 1000, 0},
    {"group_no_axes_line", group_no_axes, group_no_axes_line, 0, 1000, 0},
    {"group_no_axes_ptp", group_no_axes, group_no_axes_ptp, 50, 1000, 0},
    {"home_config_ranges", home_config_before, home_config_after, 0, 100, 0},
    SCEN(custom_false, std3, 160, 4000),
    SCEN(custom_false_first, std3, 160, 4000),
    SCEN_END,
};
