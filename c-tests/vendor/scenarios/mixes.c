/* Mixed programs drawn from a fixed seed each: a profile (T or S, ramp times, feed), then
 * lines of one to three axes, 3-point arcs in XY, point-to-point moves and delays in
 * random order, with an override change and a hold/continue at random periods. What no
 * hand-written scenario combines, each the same program on both libraries (the seed is
 * part of the scenario, the generator a 32-bit xorshift, so the calls and their
 * arguments are the same bytes everywhere).
 *
 * Kept out of the draw: arcs under blending and blends whose ramps differ in time (the
 * known departures `arc_blend` and `blend_times`), timed aborts of a PtP (`ptp_abortex`),
 * and NaN or geometry-less curves (deliberate departures). */
#include "common.h"
#include <math.h>

STD_SETUP(std3, 10000, 1, 3)

typedef struct {
    unsigned s;
} Rng;

static unsigned rng_next(Rng *r)
{
    unsigned x = r->s;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    r->s = x;
    return x;
}

/* An integer in lo..hi. */
static int rng_int(Rng *r, int lo, int hi)
{
    return lo + (int)(rng_next(r) % (unsigned)(hi - lo + 1));
}

/* A coordinate in -1..1 UU, in whole thousandths. */
static double rng_coord(Rng *r)
{
    return rng_int(r, -1000, 1000) / 1000.0;
}

/* The events of a mix at periods after its commands are queued. */
typedef struct {
    int override_at;
    double override_pct;
    int hold_at;
    int conti_at;
} MixEvents;

/* The highest mix number; each MIX(k, seed) below checks that k fits. */
#define MIX_MAX 80
static MixEvents mix_events[MIX_MAX + 1];

/* Queues the mix of `seed` for group 0 and fixes its timed events in `ev`. */
static void mix_queue(unsigned seed, MixEvents *ev)
{
    Rng r = {seed * 2654435761u + 1u};
    const char type = rng_int(&r, 0, 1) ? 'S' : 'T';
    const int blend = rng_int(&r, 0, 2) == 0;
    const double acc = rng_int(&r, 2, 20) * 10.0;
    /* Under blending the deceleration takes as long as the next acceleration. */
    const double dec = blend ? acc : rng_int(&r, 2, 20) * 10.0;
    const double feed = rng_int(&r, 5, 20);
    vd_profile(type, acc, dec, feed);
    CI(MCC_SetAbsolute, 0);
    if (blend)
        CI(MCC_EnableBlend, 0);
    double x = 0, y = 0, z = 0;
    const int n = rng_int(&r, 3, 7);
    for (int i = 0; i < n; i++) {
        int kind = rng_int(&r, 0, 9);
        if (blend && kind >= 5 && kind <= 7)
            kind = 0; /* no arcs under blending */
        if (kind <= 4) {
            /* A line moving one, two or three axes. */
            const int axes = rng_int(&r, 1, 7);
            if (axes & 1)
                x = rng_coord(&r);
            if (axes & 2)
                y = rng_coord(&r);
            if (axes & 4)
                z = rng_coord(&r);
            LINE(0, x, y, z);
        } else if (kind <= 7) {
            /* A 3-point arc in XY: a circle of radius 0.1..0.8 UU through the queue's
             * end, from its angle there through a sweep of ±(30..270)°. */
            const double radius = rng_int(&r, 100, 800) / 1000.0;
            const double a0 = rng_int(&r, 0, 359) * M_PI / 180.0;
            const double sweep = rng_int(&r, 30, 270) * (rng_int(&r, 0, 1) ? 1 : -1) * M_PI / 180.0;
            const double cx = x - radius * cos(a0), cy = y - radius * sin(a0);
            const double rx = cx + radius * cos(a0 + sweep / 2), ry = cy + radius * sin(a0 + sweep / 2);
            const double ex = cx + radius * cos(a0 + sweep), ey = cy + radius * sin(a0 + sweep);
            /* The reference and end points rounded to micro-units, as the lines' are. */
            const double rxr = round(rx * 1e6) / 1e6, ryr = round(ry * 1e6) / 1e6;
            const double exr = round(ex * 1e6) / 1e6, eyr = round(ey * 1e6) / 1e6;
            CI(MCC_ArcXY, rxr, ryr, exr, eyr, 0);
            x = exr;
            y = eyr;
        } else if (kind == 8) {
            x = rng_coord(&r);
            y = rng_coord(&r);
            PTP(0, x, y, z);
        } else {
            CI(MCC_DelayMotion, (DWORD)rng_int(&r, 1, 200), 0);
        }
    }
    ev->override_at = rng_int(&r, 0, 1) ? rng_int(&r, 20, 900) : -1;
    ev->override_pct = rng_int(&r, 3, 15) * 10.0;
    ev->hold_at = rng_int(&r, 0, 1) ? rng_int(&r, 20, 900) : -1;
    /* Without a hold the continue still comes (a continue with nothing held). */
    ev->conti_at = ev->hold_at + rng_int(&r, 10, 300);
}

static void mix_script(int k, unsigned seed, int t)
{
    MixEvents *ev = &mix_events[k];
    if (t == 0)
        mix_queue(seed, ev);
    if (t == ev->override_at)
        CD(MCC_OverrideSpeed, ev->override_pct, 0);
    if (t == ev->hold_at)
        CI(MCC_HoldMotion, 0, 0);
    if (t == ev->conti_at)
        CI(MCC_ContiMotion, 0);
}

#define MIX(k, seed)                                                                       \
    _Static_assert((k) <= MIX_MAX, "mix_" #k ": raise MIX_MAX");                           \
    static void mix_##k(int t) { mix_script(k, seed, t); }
MIX(1, 1)
MIX(2, 2)
MIX(3, 3)
MIX(4, 4)
MIX(5, 5)
MIX(6, 6)
MIX(7, 7)
MIX(8, 8)
MIX(9, 9)
MIX(10, 10)
MIX(11, 11)
MIX(12, 12)
MIX(13, 13)
MIX(14, 14)
MIX(15, 15)
MIX(16, 16)
MIX(17, 17)
MIX(18, 18)
MIX(19, 19)
MIX(20, 20)
MIX(21, 21)
MIX(22, 22)
MIX(23, 23)
MIX(24, 24)
MIX(25, 25)
MIX(26, 26)
MIX(27, 27)
MIX(28, 28)
MIX(29, 29)
MIX(30, 30)
MIX(31, 31)
MIX(32, 32)
MIX(33, 33)
MIX(34, 34)
MIX(35, 35)
MIX(36, 36)
MIX(37, 37)
MIX(38, 38)
MIX(39, 39)
MIX(40, 40)
MIX(41, 41)
MIX(42, 42)
MIX(43, 43)
MIX(44, 44)
MIX(45, 45)
MIX(46, 46)
MIX(47, 47)
MIX(48, 48)
MIX(49, 49)
MIX(50, 50)
MIX(51, 51)
MIX(52, 52)
MIX(53, 53)
MIX(54, 54)
MIX(55, 55)
MIX(56, 56)
MIX(57, 57)
MIX(58, 58)
MIX(59, 59)
MIX(60, 60)
MIX(61, 61)
MIX(62, 62)
MIX(63, 63)
MIX(64, 64)
MIX(65, 65)
MIX(66, 66)
MIX(67, 67)
MIX(68, 68)
MIX(69, 69)
MIX(70, 70)
MIX(71, 71)
MIX(72, 72)
MIX(73, 73)
MIX(74, 74)
MIX(75, 75)
MIX(76, 76)
MIX(77, 77)
MIX(78, 78)
MIX(79, 79)
MIX(80, 80)

/* The script's last event is before period 1200; a mix runs at most 60 s. */
const Scenario vd_mixes[] = {
    SCEN(mix_1, std3, 1200, 60000),  SCEN(mix_2, std3, 1200, 60000),
    SCEN(mix_3, std3, 1200, 60000),  SCEN(mix_4, std3, 1200, 60000),
    SCEN(mix_5, std3, 1200, 60000),  SCEN(mix_6, std3, 1200, 60000),
    SCEN(mix_7, std3, 1200, 60000),  SCEN(mix_8, std3, 1200, 60000),
    SCEN(mix_9, std3, 1200, 60000),  SCEN(mix_10, std3, 1200, 60000),
    SCEN(mix_11, std3, 1200, 60000), SCEN(mix_12, std3, 1200, 60000),
    SCEN(mix_13, std3, 1200, 60000), SCEN(mix_14, std3, 1200, 60000),
    SCEN(mix_15, std3, 1200, 60000), SCEN(mix_16, std3, 1200, 60000),
    SCEN(mix_17, std3, 1200, 60000), SCEN(mix_18, std3, 1200, 60000),
    SCEN(mix_19, std3, 1200, 60000), SCEN(mix_20, std3, 1200, 60000),
    SCEN(mix_21, std3, 1200, 60000), SCEN(mix_22, std3, 1200, 60000),
    SCEN(mix_23, std3, 1200, 60000), SCEN(mix_24, std3, 1200, 60000),
    SCEN(mix_25, std3, 1200, 60000), SCEN(mix_26, std3, 1200, 60000),
    SCEN(mix_27, std3, 1200, 60000), SCEN(mix_28, std3, 1200, 60000),
    SCEN(mix_29, std3, 1200, 60000), SCEN(mix_30, std3, 1200, 60000),
    SCEN(mix_31, std3, 1200, 60000), SCEN(mix_32, std3, 1200, 60000),
    SCEN(mix_33, std3, 1200, 60000), SCEN(mix_34, std3, 1200, 60000),
    SCEN(mix_35, std3, 1200, 60000), SCEN(mix_36, std3, 1200, 60000),
    SCEN(mix_37, std3, 1200, 60000), SCEN(mix_38, std3, 1200, 60000),
    SCEN(mix_39, std3, 1200, 60000), SCEN(mix_40, std3, 1200, 60000),
    SCEN(mix_41, std3, 1200, 60000), SCEN(mix_42, std3, 1200, 60000),
    SCEN(mix_43, std3, 1200, 60000), SCEN(mix_44, std3, 1200, 60000),
    SCEN(mix_45, std3, 1200, 60000), SCEN(mix_46, std3, 1200, 60000),
    SCEN(mix_47, std3, 1200, 60000), SCEN(mix_48, std3, 1200, 60000),
    SCEN(mix_49, std3, 1200, 60000), SCEN(mix_50, std3, 1200, 60000),
    SCEN(mix_51, std3, 1200, 60000), SCEN(mix_52, std3, 1200, 60000),
    SCEN(mix_53, std3, 1200, 60000), SCEN(mix_54, std3, 1200, 60000),
    SCEN(mix_55, std3, 1200, 60000), SCEN(mix_56, std3, 1200, 60000),
    SCEN(mix_57, std3, 1200, 60000), SCEN(mix_58, std3, 1200, 60000),
    SCEN(mix_59, std3, 1200, 60000), SCEN(mix_60, std3, 1200, 60000),
    SCEN(mix_61, std3, 1200, 60000), SCEN(mix_62, std3, 1200, 60000),
    SCEN(mix_63, std3, 1200, 60000), SCEN(mix_64, std3, 1200, 60000),
    SCEN(mix_65, std3, 1200, 60000), SCEN(mix_66, std3, 1200, 60000),
    SCEN(mix_67, std3, 1200, 60000), SCEN(mix_68, std3, 1200, 60000),
    SCEN(mix_69, std3, 1200, 60000), SCEN(mix_70, std3, 1200, 60000),
    SCEN(mix_71, std3, 1200, 60000), SCEN(mix_72, std3, 1200, 60000),
    SCEN(mix_73, std3, 1200, 60000), SCEN(mix_74, std3, 1200, 60000),
    SCEN(mix_75, std3, 1200, 60000), SCEN(mix_76, std3, 1200, 60000),
    SCEN(mix_77, std3, 1200, 60000), SCEN(mix_78, std3, 1200, 60000),
    SCEN(mix_79, std3, 1200, 60000), SCEN(mix_80, std3, 1200, 60000),
    SCEN_END,
};

