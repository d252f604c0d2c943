/* init_close_cycles.c: MCC_InitSystem/MCC_CloseSystem N times in one process. Asserts that no thread is left behind and memory stays flat, and prints
 * the cycle times (median, p99, max). Usage: init_close_cycles [N=10000] [--no-rss] */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "MCCL.h"
#include "MCCL_Fun.h"
#include "check.h"

static long status_field(const char *key)
{
    char line[256];
    long v = -1;
    size_t n = strlen(key);
    FILE *f = fopen("/proc/self/status", "r");
    if (!f) return -1;
    while (fgets(line, sizeof line, f))
        if (strncmp(line, key, n) == 0) { v = strtol(line + n, NULL, 10); break; }
    fclose(f);
    return v;
}

static double now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec * 1e3 + ts.tv_nsec / 1e6;
}

/* The thread count once joined threads have left it, within 5 s. pthread_join returns
 * when the kernel clears the thread's id, a moment before the thread stops being counted
 * in /proc/self/status: read at once, the last cycle's joined engine thread could still
 * be counted. Returns the count then (the caller compares it with `want`). */
static long threads_after_joins(long want)
{
    struct timespec ms = {0, 1000000};
    long now = status_field("Threads:");
    int i;
    for (i = 0; i < 5000 && now != want; i++) {
        nanosleep(&ms, NULL);
        now = status_field("Threads:");
    }
    return now;
}

static int cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int main(int argc, char **argv)
{
    int n = argc > 1 ? atoi(argv[1]) : 10000;
    /* "--no-rss": under valgrind the RSS says nothing about the program's memory, and the
     * cycle times say nothing about the library's (valgrind starts each engine thread
     * slowly, more so on a loaded host): only the thread count is checked then. */
    int native = !(argc > 2 && strcmp(argv[2], "--no-rss") == 0);
    int i, warm = n / 10;
    long rss_warm = 0, threads0;
    double *t = (double *)malloc(sizeof(double) * (size_t)n);
    SYS_CARD_CONFIG card[1];
    memset(card, 0, sizeof card);
    card[0].wCardType = IMP_III_8_AXIS_PCI_CARD;
    if (!t || n < 1) return 2;

    threads0 = status_field("Threads:");
    for (i = 0; i < n; i++) {
        double t0 = now_ms();
        int a = MCC_InitSystem(1, card, 1);
        int b = MCC_CloseSystem();
        t[i] = now_ms() - t0;
        if (a != NO_ERR || b != NO_ERR) { CHECK_EQ(a, NO_ERR); CHECK_EQ(b, NO_ERR); break; }
        if (i == warm) rss_warm = status_field("VmRSS:");
    }
    {
        long threads1 = threads_after_joins(threads0);
        long rss1 = status_field("VmRSS:");
        qsort(t, (size_t)n, sizeof(double), cmp);
        printf("%d init/close cycles: median %.3f ms, p99 %.3f ms, max %.3f ms\n",
               n, t[n / 2], t[(int)(n * 0.99)], t[n - 1]);
        printf("threads before %ld after %ld; RSS after %d cycles %ld kB, at the end %ld kB\n",
               threads0, threads1, warm, rss_warm, rss1);
        CHECK_EQ(threads1, threads0);                 /* no engine thread left behind */
        if (native) {
            CHECK(rss1 - rss_warm < 1024);            /* flat: < 1 MB growth after warm-up */
            CHECK(t[n / 2] < 10.0);                   /* generous: typical cycles are far below */
        }
    }
    free(t);
    return check_done("init_close_cycles");
}
