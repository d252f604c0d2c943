/* Shared set-ups of the scenario files. */
#ifndef VDIFF_COMMON_H
#define VDIFF_COMMON_H
#include "../vdiff.h"

/* Group `g` on channels first..first+naxes-1 of card 0, recorded. */
static inline void vd_make_group(int first, int naxes)
{
    int ch[8];
    for (int i = 0; i < 8; i++)
        ch[i] = i < naxes ? first + i : -1;
    int g = CI(MCC_CreateGroup, ch[0], ch[1], ch[2], ch[3], ch[4], ch[5], ch[6], ch[7], 0);
    if (g >= 0)
        vd_group(g, naxes);
}

/* Card 0 with every channel at PPR `ppr` (pitch 1, gear 1), group 0 on channels
 * 0..naxes-1, MCC_InitSimulation(period): the usual start. Nonzero when init failed. */
static inline int vd_std(DWORD ppr, int period, int naxes)
{
    vd_mac_default(ppr);
    CI(MCC_CloseAllGroups);
    vd_make_group(0, naxes);
    return vd_init(period) < 0;
}

/* The acc/dec types ('T' or 'S'), times (ms) and feed speed of group g. */
static inline void vd_profile_g(int g, char type, double acc_ms, double dec_ms, double feed)
{
    CI(MCC_SetAccType, type, (WORD)g);
    CI(MCC_SetDecType, type, (WORD)g);
    CI(MCC_SetAccTime, acc_ms, (WORD)g);
    CI(MCC_SetDecTime, dec_ms, (WORD)g);
    CD(MCC_SetFeedSpeed, feed, (WORD)g);
}
#define vd_profile(type, acc, dec, feed) vd_profile_g(0, type, acc, dec, feed)

#define LINE(g, x, y, z) CI(MCC_Line, x, y, z, 0, 0, 0, 0, 0, g, IMP_AXIS_ALL)
#define LINE8(g, a, b, c, d, e, f, h, i) CI(MCC_Line, a, b, c, d, e, f, h, i, g, IMP_AXIS_ALL)
#define PTP(g, x, y, z) CI(MCC_PtP, x, y, z, 0, 0, 0, 0, 0, g, IMP_AXIS_ALL)
#define SCEN(name, setup, last, max) {#name, setup, name, last, max, 0}
#define SCEN_END {0, 0, 0, 0, 0, 0}

/* Set-ups: PPR, period (ms), axes of group 0. */
#define STD_SETUP(fn, ppr, period, naxes)                                                  \
    static int fn(void) { return vd_std(ppr, period, naxes); }
#endif
