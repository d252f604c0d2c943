/* The scenario runner: `vdiff LIBRARY SCENARIO OUT` runs one scenario against the motion
 * library at path LIBRARY and writes its trace to OUT (`-` for stdout); `vdiff --list`
 * prints the scenarios' names. See vdiff.h. */
#define __USE_MINGW_ANSI_STDIO 1
#include "vdiff.h"
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const Scenario *const tables[] = {vd_lines, vd_arcs, vd_ptp, vd_control, vd_state, vd_extra,
                                        vd_oracle_items, vd_mixes};

static const Scenario *cur;
static volatile int tick = -1; /* -1 while setting up, then the period being recorded */
static volatile int done;
static int quiet, busy, end_asked;
static int period = 1;
static int groups[MAX_GROUP_NUM], group_axes[MAX_GROUP_NUM], ngroups;

/* The trace, kept in memory while the card runs and written at the end. */
static char *buf;
static size_t len, cap;

static void out(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
static void out(const char *fmt, ...)
{
    va_list ap;
    for (;;) {
        va_start(ap, fmt);
        int n = vsnprintf(buf + len, cap - len, fmt, ap);
        va_end(ap);
        if (n < 0) {
            fprintf(stderr, "vdiff: formatting failed\n");
            exit(2);
        }
        if ((size_t)n < cap - len) {
            len += (size_t)n;
            return;
        }
        cap = cap ? cap * 2 : 1 << 20;
        buf = realloc(buf, cap);
        if (!buf) {
            fprintf(stderr, "vdiff: out of memory\n");
            exit(2);
        }
    }
}

static void stamp(char kind)
{
    if (tick < 0)
        out("%c s", kind);
    else
        out("%c %d", kind, tick);
}

void *vd_need(const char *name)
{
    void *f = vdl_sym(name);
    if (!f) {
        fprintf(stderr, "vdiff: the library has no function %s\n", name);
        exit(3);
    }
    return f;
}

int vd_ret_i(const char *label, int v)
{
    stamp('A');
    out(" %s %d\n", label, v);
    return v;
}

double vd_ret_d(const char *label, double v)
{
    stamp('A');
    out(" %s %.17g\n", label, v);
    return v;
}

void vd_note(const char *fmt, ...)
{
    char line[2048];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(line, sizeof line, fmt, ap);
    va_end(ap);
    stamp('N');
    out(" %s\n", line);
}

void vd_group(int g, int naxes)
{
    if (ngroups < MAX_GROUP_NUM) {
        groups[ngroups] = g;
        group_axes[ngroups] = naxes;
        ngroups++;
    }
}

void vd_mac(int ch, DWORD ppr, double pitch, double gear)
{
    SYS_MAC_PARAM m;
    memset(&m, 0, sizeof m);
    m.wPosToEncoderDir = 0;
    m.wRPM = 3000;
    m.dwPPR = ppr;
    m.dfPitch = pitch;
    m.dfGearRatio = gear;
    m.dfHighLimit = 50000;
    m.dfLowLimit = -50000;
    m.wPulseMode = DDA_FMT_PD;
    m.wPulseWidth = 100;
    m.wCommandMode = OCM_PULSE;
    m.wOverTravelUpSensorMode = SL_UNUSED;
    m.wOverTravelDownSensorMode = SL_UNUSED;
    CI(MCC_SetMacParam, &m, (WORD)ch, 0);
}

void vd_mac_default(DWORD ppr)
{
    for (int ch = 0; ch < MAX_AXIS_NUM; ch++)
        vd_mac(ch, ppr, 1, 1);
}

int vd_init(int period_ms)
{
    SYS_CARD_CONFIG card[1];
    memset(card, 0, sizeof card);
    card[0].wCardType = IMP_III_8_AXIS_PCI_CARD;
    period = period_ms;
    return CI(MCC_InitSimulation, period_ms, card, 1);
}

void vd_end(void)
{
    end_asked = 1;
}

static void record_group(int g, int n)
{
    /* Outputs start at 0: a getter that fails may leave them as they were. */
    long p[8] = {0};
    double c[8] = {0}, r[8] = {0}, v[8] = {0};
    COMMAND_INFO k;
    WORD w = (WORD)g;
    int st = V(MCC_GetMotionStatus)(w);
    int err = V(MCC_GetErrorCode)(w);
    int q = V(MCC_GetCmdQueueSize)(w);
    /* A getter that fails reads 0: the vendor's library writes what its memory held
     * for a group that does not exist. */
    if (V(MCC_GetPulsePos)(&p[0], &p[1], &p[2], &p[3], &p[4], &p[5], &p[6], &p[7], w))
        memset(p, 0, sizeof p);
    if (V(MCC_GetCurPos)(&c[0], &c[1], &c[2], &c[3], &c[4], &c[5], &c[6], &c[7], w))
        memset(c, 0, sizeof c);
    if (V(MCC_GetCurRefPos)(&r[0], &r[1], &r[2], &r[3], &r[4], &r[5], &r[6], &r[7], w))
        memset(r, 0, sizeof r);
    if (V(MCC_GetSpeed)(&v[0], &v[1], &v[2], &v[3], &v[4], &v[5], &v[6], &v[7], w))
        memset(v, 0, sizeof v);
    double f = V(MCC_GetCurFeedSpeed)(w);
    memset(&k, 0, sizeof k);
    int kr = V(MCC_GetCurCommand)(&k, w);
    out("T %d %d %d %d %d p", tick, g, st, err, q);
    for (int i = 0; i < n; i++)
        out(" %ld", p[i]);
    out(" c");
    for (int i = 0; i < n; i++)
        out(" %.17g", c[i]);
    out(" r");
    for (int i = 0; i < n; i++)
        out(" %.17g", r[i]);
    out(" v");
    for (int i = 0; i < n; i++)
        out(" %.17g", v[i]);
    out(" f %.17g k %d %d %d %.17g %.17g %.17g %d %d", f, kr, k.nType, k.nCommandIndex,
        k.dfFeedSpeed, k.dfAcctime, k.dfDectime, k.nMotionPhase, k.nCommandIndex_LD);
    for (int i = 0; i < n; i++)
        out(" %.17g", k.dfPos[i]);
    out("\n");
    if (st != GMS_STOP)
        busy = 1;
}

static void MCC_CALLBACK cycle(void)
{
    if (done || tick < 0)
        return;
    int t = tick, finish = 0;
    busy = 0;
    for (int i = 0; i < ngroups; i++)
        record_group(groups[i], group_axes[i]);
    /* quiet counts the periods after the script's last in which every group stood still */
    if (t > cur->last_tick) {
        quiet = busy ? 0 : quiet + 1;
        finish = quiet >= VD_QUIET;
    }
    if (!finish)
        cur->script(t);
    tick = t + 1;
    if (finish || end_asked || tick >= cur->max_ticks)
        done = 1;
}

static const Scenario *find(const char *name)
{
    for (size_t i = 0; i < sizeof tables / sizeof tables[0]; i++)
        for (const Scenario *s = tables[i]; s->name; s++)
            if (!strcmp(s->name, name))
                return s;
    return NULL;
}

int main(int argc, char **argv)
{
    if (argc == 2 && !strcmp(argv[1], "--list")) {
        for (size_t i = 0; i < sizeof tables / sizeof tables[0]; i++)
            for (const Scenario *s = tables[i]; s->name; s++)
                printf("%s\n", s->name);
        return 0;
    }
    if (argc != 4) {
        fprintf(stderr, "usage: vdiff LIBRARY SCENARIO OUT | vdiff --list\n");
        return 2;
    }
    cur = find(argv[2]);
    if (!cur) {
        fprintf(stderr, "vdiff: no scenario %s\n", argv[2]);
        return 2;
    }
    if (!vdl_open(argv[1]))
        return 3;
    out("# %s\n", cur->name);
    if (cur->setup() == 0) {
        tick = 0;
        V(MCC_SetCycleInterruptRoutine)(cycle);
        /* Both libraries run the periods while the program waits: the vendor's in real
         * time, this library's stepped clock one period per waited period. */
        while (!done)
            V(MCC_TimeDelay)((DWORD)period);
        int tick_end = tick;
        tick = -1;
        V(MCC_SetCycleInterruptRoutine)(NULL);
        out("E %d\n", tick_end);
    }
    if (cur->after)
        cur->after();
    CI(MCC_CloseSystem);
    FILE *f = strcmp(argv[3], "-") ? fopen(argv[3], "wb") : stdout;
    if (!f) {
        fprintf(stderr, "vdiff: cannot write %s\n", argv[3]);
        return 2;
    }
    fwrite(buf, 1, len, f);
    if (f != stdout)
        fclose(f);
    return 0;
}
