/* Questions the first recordings left open: queued switch types, the status right after
 * queuing, groups sharing channels and queue sizes, jogs while moving, more blends. */
#include "common.h"
#include <string.h>

STD_SETUP(std3, 10000, 1, 3)

static void inpos_switches(int t)
{
    if (t == 0) {
        vd_profile('T', 20, 20, 10);
        CI(MCC_EnableInPos, 0, IMP_AXIS_ALL);
        LINE(0, 0.1, 0, 0);
        CI(MCC_DisableInPos, 0, IMP_AXIS_ALL);
        LINE(0, 0.2, 0, 0);
    }
}

static void status_after_queue(int t)
{
    if (t == 0) {
        vd_note("GetMotionStatus %d", V(MCC_GetMotionStatus)(0));
        vd_profile('T', 20, 20, 10);
        LINE(0, 0.1, 0, 0);
        vd_note("GetMotionStatus %d", V(MCC_GetMotionStatus)(0));
        COMMAND_INFO k;
        memset(&k, 0, sizeof k);
        int r = V(MCC_GetCurCommand)(&k, 0);
        vd_note("GetCurCommand %d %d %d", r, k.nType, k.nCommandIndex);
        int n = -1;
        V(MCC_GetCommandCount)(&n, 0);
        vd_note("GetCommandCount %d", n);
    }
    if (t == 60) {
        CI(MCC_DelayMotion, 10, 0);
        vd_note("GetMotionStatus %d", V(MCC_GetMotionStatus)(0));
    }
}

/* The pulse stock while a line runs, in its last period and after it. */
static void stock_while_moving(int t)
{
    if (t == 0) {
        vd_profile('T', 20, 20, 10);
        LINE(0, 0.1, 0, 0);
    }
    if (t % 4 == 1 || (t >= 110 && t <= 116)) {
        WORD w = 77;
        int r = V(MCC_GetCurPulseStockCount)(&w, 0, 0);
        vd_note("GetCurPulseStockCount %d %u", r, w);
        r = V(MCC_GetCurPulseStockCount)(&w, 2, 0);
        vd_note("GetCurPulseStockCount %d %u", r, w);
    }
}

static int overlap_groups(void)
{
    vd_mac_default(10000);
    CI(MCC_CloseAllGroups);
    vd_make_group(0, 3);
    CI(MCC_CreateGroup, 2, 3, -1, -1, -1, -1, -1, -1, 0);
    CI(MCC_CreateGroup, 3, 4, -1, -1, -1, -1, -1, -1, 0);
    CI(MCC_CreateGroupEx, 5, -1, -1, -1, -1, -1, -1, -1, 0, 10);
    CI(MCC_CreateGroupEx, 6, -1, -1, -1, -1, -1, -1, -1, 0, 100);
    CI(MCC_CreateGroupEx, 7, -1, -1, -1, -1, -1, -1, -1, 0, 20000);
    CI(MCC_CreateGroupEx, -1, -1, -1, -1, -1, -1, -1, -1, 0, 1);
    for (WORD g = 0; g < 8; g++)
        vd_note("GetCmdQueueSize(%u) %d", g, V(MCC_GetCmdQueueSize)(g));
    return vd_init(1) < 0;
}

static void overlap_script(int t)
{
    if (t == 0) {
        vd_profile('T', 20, 20, 10);
        LINE(0, 0.1, 0.1, 0.1);
        for (WORD g = 1; g < 8; g++)
            vd_note("Line(%u) %d", g,
                    V(MCC_Line)(0.1, 0.1, 0, 0, 0, 0, 0, 0, g, IMP_AXIS_ALL));
        for (WORD g = 0; g < 8; g++)
            vd_note("GetMotionStatus(%u) %d", g, V(MCC_GetMotionStatus)(g));
    }
}

static void groups_close_running(int t)
{
    if (t == 0) {
        vd_profile('T', 20, 20, 10);
        LINE(0, 0.2, 0, 0);
    }
    if (t == 30) {
        CI(MCC_CloseGroup, 0);
        vd_note("GetMotionStatus %d", V(MCC_GetMotionStatus)(0));
        vd_note("GetErrorCode %d", V(MCC_GetErrorCode)(0));
        double x = -1, y = -1, z = -1, u, v, w, a, b;
        int r = V(MCC_GetCurPos)(&x, &y, &z, &u, &v, &w, &a, &b, 0);
        vd_note("GetCurPos %d %.17g %.17g %.17g", r, x, y, z);
    }
    if (t == 31) {
        int g = CI(MCC_CreateGroup, 0, 1, 2, -1, -1, -1, -1, -1, 0);
        vd_note("GetMotionStatus(%d) %d", g, V(MCC_GetMotionStatus)((WORD)(g < 0 ? 0 : g)));
        LINE(0, 0, 0, 0);
        LINE(1, 0, 0, 0);
    }
}

static void jog_while_moving(int t)
{
    if (t == 0) {
        vd_profile('T', 20, 20, 10);
        LINE(0, 0.2, 0, 0);
        CI(MCC_JogSpace, 0.1, 20, 1, 0);
        CI(MCC_JogConti, 1, 20, 1, 0);
        CI(MCC_JogPulse, 10, 1, 0);
    }
    if (t == 100) {
        CI(MCC_JogConti, 0, 20, 1, 0);
        CI(MCC_JogPulse, 3000, 1, 0);
        CI(MCC_JogPulse, -2049, 1, 0);
        CI(MCC_JogPulse, 7, 5, 0);
    }
    if (t == 110)
        LINE(0, 0, 0, 0);
}

static void blend_arc_arc(int t)
{
    if (t == 0) {
        vd_profile('S', 40, 40, 10);
        CI(MCC_EnableBlend, 0);
        CI(MCC_ArcXY, 0.5, 0.5, 1, 0, 0);
        CI(MCC_ArcXY, 1.5, -0.5, 2, 0, 0);
        LINE(0, 3, 0, 0);
    }
}

static void blend_line_arc_t(int t)
{
    if (t == 0) {
        vd_profile('T', 40, 40, 10);
        CI(MCC_EnableBlend, 0);
        LINE(0, 0, 1, 0);
        CI(MCC_ArcThetaXY, 1, 1, -90, 0);
        LINE(0, 1, 0, 0);
    }
}

const Scenario vd_extra[] = {
    SCEN(inpos_switches, std3, 0, 4000),
    SCEN(status_after_queue, std3, 60, 4000),
    {"overlap_groups", overlap_groups, overlap_script, 0, 1000, 0},
    SCEN(groups_close_running, std3, 31, 1000),
    SCEN(jog_while_moving, std3, 110, 4000),
    SCEN(blend_arc_arc, std3, 0, 4000),
    SCEN(blend_line_arc_t, std3, 0, 4000),
    SCEN(stock_while_moving, std3, 120, 4000),
    SCEN_END,
};
