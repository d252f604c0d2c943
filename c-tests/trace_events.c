/* trace_events.c: the events file beside MCCL_TRACE. A 1 ms card runs a line
 * that is held, continued and aborted, a bad arc records an error that is cleared, and
 * the emergency-stop input stops a second line. Each expected line is derived by hand
 * below. C99 + POSIX setenv (_putenv_s on Windows). */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "MCCL.h"
#include "MCCL_Fun.h"
#include "MCCL_Sim.h"
#include "check.h"

/* The C runtime of Windows names POSIX's setenv _putenv_s (it also sets the process's
 * environment, which the library reads). */
#ifdef _WIN32
#define setenv(name, value, overwrite) _putenv_s(name, value)
#endif

static char events[65536];

static void expect(const char *line)
{
    if (strstr(events, line) == NULL) {
        printf("FAIL: no event line \"%s\"\n", line);
        check_failures++;
    } else {
        printf("ok   %s\n", line);
        check_passes++;
    }
}

int main(int argc, char **argv)
{
    SYS_CARD_CONFIG card[1];
    const char *dir = argc > 1 ? argv[1] : ".";
    char path[512], epath[512];
    FILE *f;
    size_t n;
    /* A file of its own for each clock: CTest runs the fast and the stepped run at the
     * same time, in the same folder. */
    const char *clock_name = getenv("MCCL_CLOCK") ? getenv("MCCL_CLOCK") : "default";
    snprintf(path, sizeof path, "%s/trace_events_%s.csv", dir, clock_name);
    snprintf(epath, sizeof epath, "%s/trace_events_%s.events.csv", dir, clock_name);
    setenv("MCCL_TRACE", path, 1);
    memset(card, 0, sizeof card);
    card[0].wCardType = IMP_III_8_AXIS_PCI_CARD;
    CHECK_EQ(MCC_InitSystem(1, card, 1), NO_ERR);
    MCC_SetFeedSpeed(10.0, 0);
    /* A hold decelerates over 100 ms, so that it has stopped when the continue comes. */
    CHECK_EQ(MCC_SetDecTime(100, 0), NO_ERR);
    /* Queued at 0 ms: starts in the first tick, whose row is at 1 ms. */
    CHECK(MCC_Line(10, 0, 0, 0, 0, 0, 0, 0, 0, IMP_AXIS_ALL) == 0);
    /* Calls made between ticks are written with the next tick: 500 -> 501 ms. */
    MCC_TimeDelay(500);
    CHECK_EQ(MCC_HoldMotion(0, 0), NO_ERR);
    /* While the hold still decelerates a continue is refused, as the vendor's library
     * refuses it, and leaves no event. */
    MCC_TimeDelay(50);
    CHECK_EQ(MCC_ContiMotion(0), CONTI_ILLEGAL_ERR);
    MCC_TimeDelay(150);
    CHECK_EQ(MCC_ContiMotion(0), NO_ERR);
    MCC_TimeDelay(100);
    /* Abort at 800 ms stops at once: the abort, then command 0 ends cut short, at 801. */
    CHECK_EQ(MCC_AbortMotion(0, 0), NO_ERR);
    MCC_TimeDelay(10);
    /* A collinear arc at 810 ms is queued (index 1), as the vendor's library takes it, and
     * fails as it starts in the tick of 811 ms: 0xF104 (it never ran: no start or end). */
    CHECK_EQ(MCC_ArcXY(20, 0, 30, 0, 0), 1);
    MCC_TimeDelay(10);
    CHECK_EQ(MCC_GetErrorCode(0), 0xF104);
    CHECK_EQ(MCC_ClearError(0), NO_ERR);
    /* The next line (index 2) is queued at 820 ms and starts in the tick of 821 ms. */
    CHECK(MCC_Line(0, 0, 0, 0, 0, 0, 0, 0, 0, IMP_AXIS_ALL) == 2);
    MCC_TimeDelay(100);
    /* Emergency stop pressed at 920 ms: the input changes in the tick of 921 ms; the
     * safety check of that tick stops the group after its row was written, so the
     * group's record and the end of command 2 show in the row of 922 ms. */
    CHECK_EQ(MCCL_SimSetEmergencyStop(0, 1), NO_ERR);
    MCC_TimeDelay(10);
    CHECK_EQ(MCC_GetErrorCode(0), 0xF102);
    CHECK_EQ(MCC_CloseSystem(), NO_ERR);

    f = fopen(epath, "r");
    CHECK(f != NULL);
    if (f == NULL)
        return 1;
    n = fread(events, 1, sizeof events - 1, f);
    events[n] = 0;
    fclose(f);
    expect("time_ms,card,group,kind,detail\n");
    expect("0.000000,0,0,config,axis=x channel=0 ppr=500 rpm=3000 pitch=1.000000000 gear=1.000000000 max_speed=50.000000000 pulses_per_uu=500.000000000");
    expect("\n1.000000,0,0,cmd_start,index=0 type=LINE\n");
    expect("\n501.000000,0,0,hold,block_end=0\n");
    expect("\n701.000000,0,0,continue,\n");
    expect("\n801.000000,0,0,abort,dec_ms=0.000 block_end=0\n801.000000,0,0,cmd_end,index=0 type=LINE end=stopped\n");
    expect("\n811.000000,0,0,error_set,code=0xF104\n");
    expect("\n821.000000,0,0,error_cleared,code=0xF104\n821.000000,0,0,cmd_start,index=2 type=LINE\n");
    expect("\n921.000000,0,-1,emergency_stop,active=1\n");
    expect("\n922.000000,0,0,cmd_end,index=2 type=LINE end=stopped\n922.000000,0,0,error_set,code=0xF102\n");
    return check_done("trace_events");
}
