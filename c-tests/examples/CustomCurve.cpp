// CustomCurve.cpp: a custom curve the way an integrator writes one (MCC_CustomMotion,
// MCC_InfiniteMotion; docs/compatibility.md, "Custom motion"). The library runs its own
// speed profile (feed, acc/dec, override, hold, abort) over the distance the start
// callback returns; each period the interpolation callback turns the distance into an
// offset from the start.
//
// The curve: one full circle of radius R = 5 through the start point, counter-clockwise,
// centre 5 UU to the left of the start, given by arc length s: θ = s/R,
// offset = (R cos θ − R, R sin θ). Length L = 2πR = 31.4159 UU.
// Expected (F = 10 UU/s, Ta = Td = 300 ms, 1 ms period):
//   the profile is a line's on the grid of periods: 300 + ceil(3141.59 - 300) + 300 =
//   3442 periods; the command is taken at the first tick and each offset is shown one
//   tick after it was computed, so it ends 3443 ms after it was queued (stepped clock);
//   every position on the way lies on the circle (within 1e-9);
//   cleanup runs exactly once; MCC_GetCurPos works from inside the callback and reads
//   the position the callback is given, in whole pulses toward 0 (as it reads every
//   position).
// Then an infinite motion along +X whose callback sets *AbortThisCommand past 3.005 UU.
#include "MotionSys.h"

static const double R = 5.0;

struct CurveState
{
    double dfCenterX, dfCenterY;   // absolute centre (set in the start callback)
    int nCalls;
    int nCleanups;
    int nOffCircle;                // positions seen off the circle
    int nGetPosFailures;
    double dfLastDist;
    bool bMonotonic;
};

static double MCC_CALLBACK CircleStart(int nGroup, int nSynAxisNum, int nCommandIndex, BOOL bAbsolute,
                                       const double *pdfStartPos, void *pvBuffer)
{
    (void)nGroup; (void)nSynAxisNum; (void)nCommandIndex; (void)bAbsolute;
    CurveState *s = (CurveState *)pvBuffer;
    s->dfCenterX = pdfStartPos[0] - R;
    s->dfCenterY = pdfStartPos[1];
    return 2.0 * M_PI * R;   // total distance
}

static BOOL MCC_CALLBACK CircleInterp(int nGroup, int nSynAxisNum, int nCommandIndex,
                                      const double *pdfStartPos, const double *pdfCurPos,
                                      double dfCurDist, double dfTotDist,
                                      double *pdfNextPosOffset, void *pvBuffer)
{
    (void)nSynAxisNum; (void)nCommandIndex; (void)pdfStartPos; (void)dfTotDist;
    CurveState *s = (CurveState *)pvBuffer;
    s->nCalls++;
    if (dfCurDist < s->dfLastDist) s->bMonotonic = false;
    s->dfLastDist = dfCurDist;
    // Where the axes are now must be on the circle.
    double r = hypot(pdfCurPos[0] - s->dfCenterX, pdfCurPos[1] - s->dfCenterY);
    if (fabs(r - R) > 1e-9) s->nOffCircle++;
    // Status calls are allowed from here (no library lock is held).
    double p[8];
    if (MCC_GetCurPos(&p[0], &p[1], &p[2], &p[3], &p[4], &p[5], &p[6], &p[7], (WORD)nGroup) != NO_ERR
        || p[0] != PulsesOf(pdfCurPos[0]) / (double)EX_PPR
        || p[1] != PulsesOf(pdfCurPos[1]) / (double)EX_PPR)
        s->nGetPosFailures++;
    double th = dfCurDist / R;
    pdfNextPosOffset[0] = R * cos(th) - R;
    pdfNextPosOffset[1] = R * sin(th);
    return 1;
}

static void MCC_CALLBACK Cleanup(int nGroup, int nCommandIndex, void *pvBuffer)
{
    (void)nGroup; (void)nCommandIndex;
    ((CurveState *)pvBuffer)->nCleanups++;
}

static BOOL MCC_CALLBACK StraightInterp(int nGroup, int nSynAxisNum, int nCommandIndex,
                                        const double *pdfStartPos, const double *pdfCurPos,
                                        double dfCurDist, double dfTotDist,
                                        double *pdfNextPosOffset, void *pvBuffer,
                                        BOOL *pbAbortThisCommand)
{
    (void)nGroup; (void)nSynAxisNum; (void)nCommandIndex; (void)pdfStartPos;
    (void)pdfCurPos; (void)dfTotDist;
    CurveState *s = (CurveState *)pvBuffer;
    s->nCalls++;
    pdfNextPosOffset[0] = dfCurDist;
    if (dfCurDist > 3.005) *pbAbortThisCommand = 1;
    return 1;
}

int main()
{
    if (InitSys8() != NO_ERR)
        return check_done("CustomCurve");
    WORD g = (WORD)g_nGroupIndex;
    MCC_SetFeedSpeed(10, g);
    CHECK(MCC_Line(10, 0, 0, 0, 0, 0, 0, 0, g) >= 0);
    WaitStop(g);

    CurveState s;
    memset(&s, 0, sizeof(s));
    s.bMonotonic = true;
    int nIdx = MCC_CustomMotion(CircleStart, CircleInterp, Cleanup, &s, g);
    CHECK(nIdx >= 0);
    CheckEndsIn(g, 3443, "custom circle");
    WaitStop(g);
    MCC_TimeDelay(1);   // the stage after the last tick calls the cleanup
    printf("  custom circle: %d interpolation calls, %d cleanup(s), last distance %.6f\n",
           s.nCalls, s.nCleanups, s.dfLastDist);
    CHECK_EQ(s.nCleanups, 1);
    CHECK_EQ(s.nOffCircle, 0);
    CHECK_EQ(s.nGetPosFailures, 0);
    CHECK(s.bMonotonic);
    CHECK_NEAR(s.dfLastDist, 2.0 * M_PI * R, 1e-12);
    if (SteppedClock()) CHECK_EQ(s.nCalls, 3442);   // one a period of the profile
    double p[8];
    GetPos(g, p);
    CHECK_NEAR(p[0], 10, 1e-9);   // a full turn: back at the start
    CHECK_NEAR(p[1], 0, 1e-9);

    // Refusals: NULL callbacks and a bad group queue nothing.
    CHECK_EQ(MCC_CustomMotion(NULL, CircleInterp, Cleanup, &s, g), PARAMETER_ERR);
    CHECK_EQ(MCC_CustomMotion(CircleStart, NULL, Cleanup, &s, g), PARAMETER_ERR);
    CHECK_EQ(MCC_CustomMotion(CircleStart, CircleInterp, Cleanup, &s, BAD_GROUP), GROUP_PARAMETER_ERR);

    // Infinite motion: cruises at the feed until the callback raises its flag past 3.005 UU.
    CurveState t;
    memset(&t, 0, sizeof(t));
    CHECK(MCC_InfiniteMotion(CircleStart, StraightInterp, Cleanup, &t, 1, g) >= 0);
    WaitStop(g);
    MCC_TimeDelay(1);
    GetPos(g, p);
    printf("  infinite motion: stopped at X = %.4f after %d calls, %d cleanup(s)\n",
           p[0], t.nCalls, t.nCleanups);
    // Past the 0.3 s ramp s = 1.5 + 10 (t - 0.3): the first distance over 3.005 is
    // s(0.451 s) = 3.01 (call 451), where it ends: X = 10 + 3.01.
    CHECK_NEAR(p[0], 13.01, 1e-9);
    if (SteppedClock()) CHECK_EQ(t.nCalls, 451);
    CHECK_EQ(t.nCleanups, 1);

    Close();
    return check_done("CustomCurve");
}
