/* Getter dumps: every value a program can read of a group or of the system, one note a
 * getter, `Name return value...`. */
#define __USE_MINGW_ANSI_STDIO 1
#include "vdiff.h"
#include <stdio.h>
#include <string.h>

#define P8(a) &a[0], &a[1], &a[2], &a[3], &a[4], &a[5], &a[6], &a[7]

static void note_d8(const char *name, int r, const double *v)
{
    vd_note("%s %d %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g", name, r, v[0], v[1], v[2],
            v[3], v[4], v[5], v[6], v[7]);
}

static void note_i8(const char *name, int r, const long *v)
{
    vd_note("%s %d %ld %ld %ld %ld %ld %ld %ld %ld", name, r, v[0], v[1], v[2], v[3], v[4], v[5],
            v[6], v[7]);
}

static void note_n8(const char *name, int r, const int *v)
{
    long l[8];
    for (int i = 0; i < 8; i++)
        l[i] = v[i];
    note_i8(name, r, l);
}

static void note_c8(const char *name, int r, const char *v)
{
    long l[8];
    for (int i = 0; i < 8; i++)
        l[i] = v[i];
    note_i8(name, r, l);
}

static void note_b8(const char *name, int r, const BYTE *v)
{
    long l[8];
    for (int i = 0; i < 8; i++)
        l[i] = v[i];
    note_i8(name, r, l);
}

void vd_dump_group(int g)
{
    WORD w = (WORD)g;
    double d[8];
    int n[8], r;
    long l[8];
    char c[8];
    BYTE b[8];
    WORD wv = 0;

    vd_note("GetFeedSpeed %.17g", V(MCC_GetFeedSpeed)(w));
    vd_note("GetPtPSpeed %.17g", V(MCC_GetPtPSpeed)(w));
    vd_note("GetAccType %d", V(MCC_GetAccType)(w));
    vd_note("GetDecType %d", V(MCC_GetDecType)(w));
    vd_note("GetAccTime %.17g", V(MCC_GetAccTime)(w));
    vd_note("GetDecTime %.17g", V(MCC_GetDecTime)(w));
    vd_note("GetCoordType %d", V(MCC_GetCoordType)(w));
    vd_note("GetOverrideRate %.17g", V(MCC_GetOverrideRate)(w));
    vd_note("GetCmdQueueSize %d", V(MCC_GetCmdQueueSize)(w));
    vd_note("GetMotionStatus %d", V(MCC_GetMotionStatus)(w));
    vd_note("GetErrorCode %d", V(MCC_GetErrorCode)(w));
    vd_note("CheckBlend %d", V(MCC_CheckBlend)(w));
    vd_note("CheckDelay %d", V(MCC_CheckDelay)(w));
    vd_note("GetOverSpeed %.17g", V(MCC_GetOverSpeed)(w));
    vd_note("GetCurFeedSpeed %.17g", V(MCC_GetCurFeedSpeed)(w));
    memset(c, 0, sizeof c);
    r = V(MCC_GetPtPAccType)(P8(c), w);
    note_c8("GetPtPAccType", r, c);
    memset(c, 0, sizeof c);
    r = V(MCC_GetPtPDecType)(P8(c), w);
    note_c8("GetPtPDecType", r, c);
    memset(d, 0, sizeof d);
    r = V(MCC_GetPtPAccTime)(P8(d), w);
    note_d8("GetPtPAccTime", r, d);
    memset(d, 0, sizeof d);
    r = V(MCC_GetPtPDecTime)(P8(d), w);
    note_d8("GetPtPDecTime", r, d);
    n[0] = 0;
    r = V(MCC_GetCommandCount)(&n[0], w);
    vd_note("GetCommandCount %d %d", r, n[0]);
    r = V(MCC_GetCommandIndex)(&wv, w);
    vd_note("GetCommandIndex %d %d", r, wv);
    memset(d, 0, sizeof d);
    r = V(MCC_GetInPosToleranceEx)(P8(d), w);
    note_d8("GetInPosToleranceEx", r, d);
    memset(b, 0, sizeof b);
    r = V(MCC_GetInPosStatus)(P8(b), w);
    note_b8("GetInPosStatus", r, b);
    memset(n, 0, sizeof n);
    r = V(MCC_GetOverTravelCheck)(P8(n), w);
    note_n8("GetOverTravelCheck", r, n);
    d[0] = 0;
    r = V(MCC_GetTrackErrorLimit)(&d[0], 'X', w);
    vd_note("GetTrackErrorLimit %d %.17g", r, d[0]);
    memset(d, 0, sizeof d);
    r = V(MCC_GetCurRefPos)(P8(d), w);
    note_d8("GetCurRefPos", r, d);
    memset(d, 0, sizeof d);
    r = V(MCC_GetCurPos)(P8(d), w);
    note_d8("GetCurPos", r, d);
    memset(l, 0, sizeof l);
    r = V(MCC_GetPulsePos)(P8(l), w);
    note_i8("GetPulsePos", r, l);
    memset(d, 0, sizeof d);
    r = V(MCC_GetSpeed)(P8(d), w);
    note_d8("GetSpeed", r, d);
}

void vd_dump_system(void)
{
    int n[8], r;
    WORD wv = 0;
    SYS_MAC_PARAM m;
    SYS_ENCODER_CONFIG e;
    SYS_HOME_CONFIG h;
    char ver[64];

    memset(ver, 0, sizeof ver);
    V(MCC_GetVersion)(ver);
    vd_note("GetVersion %s", ver);
    vd_note("GetSysMaxSpeed %.17g", V(MCC_GetSysMaxSpeed)());
    memset(n, 0, sizeof n);
    r = V(MCC_GetMaxPulseSpeed)(P8(n), 0);
    note_n8("GetMaxPulseSpeed", r, n);
    memset(n, 0, sizeof n);
    r = V(MCC_GetMaxPulseAcc)(P8(n), 0);
    note_n8("GetMaxPulseAcc", r, n);
    vd_note("GetMaxPulseStockNum %d", V(MCC_GetMaxPulseStockNum)());
    vd_note("CheckDryRun %d", V(MCC_CheckDryRun)());
    vd_note("GetGoHomeStatus %d", V(MCC_GetGoHomeStatus)());
    vd_note("GetConvFactor %.17g", V(MCC_GetConvFactor)(0, 0));
    memset(&m, 0, sizeof m);
    r = V(MCC_GetMacParam)(&m, 0, 0);
    vd_note("GetMacParam %d %u %u %lu %.17g %.17g %.17g %.17g %.17g %.17g %u %u %u %u %u", r,
            m.wPosToEncoderDir, m.wRPM, (unsigned long)m.dwPPR, m.dfPitch, m.dfGearRatio,
            m.dfHighLimit, m.dfLowLimit, m.dfHighLimitOffset, m.dfLowLimitOffset, m.wPulseMode,
            m.wPulseWidth, m.wCommandMode, m.wOverTravelUpSensorMode,
            m.wOverTravelDownSensorMode);
    memset(&e, 0, sizeof e);
    r = V(MCC_GetEncoderConfig)(&e, 0, 0);
    vd_note("GetEncoderConfig %d %u %u %u %u %u %u", r, e.wType, e.wAInverse, e.wBInverse,
            e.wCInverse, e.wABSwap, e.wInputRate);
    memset(&h, 0, sizeof h);
    r = V(MCC_GetHomeConfig)(&h, 0, 0);
    vd_note("GetHomeConfig %d %u %u %u %d %.17g %.17g %.17g %.17g %.17g", r, h.wMode,
            h.wDirection, h.wSensorMode, h.nIndexCount, h.dfAccTime, h.dfDecTime,
            h.dfHighSpeed, h.dfLowSpeed, h.dfOffset);
    r = V(MCC_GetEmgcStopStatus)(&wv, 0);
    vd_note("GetEmgcStopStatus %d %u", r, wv);
    wv = 0;
    r = V(MCC_GetCurPulseStockCount)(&wv, 0, 0);
    vd_note("GetCurPulseStockCount %d %u", r, wv);
}
