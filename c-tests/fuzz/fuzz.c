/* fuzz.c: the random-call fuzzer of libMCCLPCI_IMP (runtime; the dispatch table over
 * every exported function is generated from the headers by tools/mccl-fuzzgen).
 *
 * The parent process runs workers one after the other, each in a child process, and
 * watches them: a crash (signal), a hang (one call running longer than --hang-ms), a
 * failure the worker found (a panic inside the library, caught at the C boundary and seen
 * by its message on stderr, a write past an argument buffer, a
 * non-finite double written or returned, a routine delivered with a NULL argument, a
 * thread left running after the final MCC_CloseSystem) is reported with the seed, the
 * clock, the command that replays it, and the last calls. A worker runs --threads
 * program threads that call random functions with random arguments (seeded: thread t of
 * seed s always makes the same calls), routines of every callback type that call back
 * into the library (also MCC_InitSystem and MCC_CloseSystem), and every --arm-every
 * calls a fixed step that arms every cause of an interrupt routine on the simulated
 * machine of machine.toml. Run `mccl_fuzz --help` for the options. */
#define _GNU_SOURCE
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <float.h>
#include <inttypes.h>
#include <limits.h>
#include <math.h>
#include <poll.h>
#include <pthread.h>
#include <signal.h>
#include <stdarg.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "MCCL.h"
#include "MCCL_Fun.h"
#include "MCCL_Sim.h"
#include "fuzz_rt.h"

#ifndef FZ_MACHINE_TOML
#define FZ_MACHINE_TOML "machine.toml"
#endif

#define FZ_MAXF 1024    /* functions */
#define FZ_MAXCB 32     /* callback types */
#define FZ_RING 64      /* calls kept for a report */
#define FZ_LINE 480     /* characters of one logged call */
#define FZ_SLOTS 8      /* watched threads: 0..1 program, 2..6 routine, 7 main */
#define FZ_PSLOTS 16    /* pointer arguments of one call */
#define FZ_PBUF 4096    /* bytes of one pointer argument */
#define FZ_GUARD 32     /* canary bytes before and after each pointer argument */
#define FZ_CANARY 0xA5
#define FZ_POOL 64      /* contexts for routine threads */
#define FZ_EXIT_FAIL 10 /* worker exit code: a failure is in the shared block */

/* ---- options ---- */
static unsigned long long opt_seed = 1;
static long long opt_calls = 200000;
static int opt_workers = 8;
static int opt_threads = 2;
static const char *opt_clock = "mix";
static int opt_hang_ms = 5000;
static int opt_last = 20;
static int opt_arm_every = 500;
static int opt_max_delay = 3;
static int opt_routine_init = 2; /* 0 off, 1 safe, 2 free */
static int opt_full = 0;
static int opt_replay = 0;
static long long opt_upto = -1;
static int opt_require_routines = 0;
static int opt_keep_going = 0;
static int opt_mem_mb = 4096;
static int opt_stats = 0;
static int opt_gdb = 0;
static int opt_strict = 0;
static int opt_tolerate_nonfinite = 0;
static const char *opt_scenario = NULL;

/* ---- shared with the parent (MAP_SHARED before fork) ---- */
typedef struct {
    _Atomic unsigned long long seq; /* global call number + 1; 0 = empty */
    char text[FZ_LINE];
} fz_entry_t;

typedef struct {
    _Atomic unsigned long long next_seq;
    fz_entry_t ring[FZ_RING];
    _Atomic long long slot_start_ns[FZ_SLOTS];
    _Atomic unsigned long long slot_seq[FZ_SLOTS];
    _Atomic unsigned long long calls[FZ_MAXF];
    _Atomic unsigned long long deliveries[FZ_MAXCB];
    _Atomic unsigned long long tolerated[FZ_MAXF];
    _Atomic unsigned long long prog_calls;
    _Atomic unsigned long long routine_calls;
    _Atomic int failed;
    char fail[2048];
    char replay[256];
} fz_shared_t;

static fz_shared_t *sh;

/* ---- per-thread context ---- */
struct fz {
    unsigned long long rng;
    int tid;  /* 0.. program threads, 100+ routine contexts, 99 main */
    int slot; /* watchdog slot */
    unsigned long long idx;
    char line[FZ_LINE];
    size_t len;
    unsigned long long seq;
    int f;
    unsigned char *arena;
    unsigned char *pstart[FZ_PSLOTS];
    size_t psize[FZ_PSLOTS];
    int pmode[FZ_PSLOTS]; /* 0 NULL, 1 aligned, 2 misaligned */
    unsigned used;
    int in_routine;
    int holds_init;
    int depth;
    int nonfinite_arg;
};

static pthread_mutex_t init_lock = PTHREAD_MUTEX_INITIALIZER;
static fz_t prog_ctx[2];
static fz_t main_ctx;
static fz_t pool_ctx[FZ_POOL];
static _Atomic int pool_next;
static _Thread_local int tl_pool = -1;
static long long per_thread_calls;
static int *weights;
static long long total_weight;

static long long now_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (long long)ts.tv_sec * 1000000000LL + ts.tv_nsec;
}

static unsigned long long mix64(unsigned long long x)
{
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
    return x ^ (x >> 31);
}

static unsigned long long rnd(fz_t *z)
{
    return mix64(z->rng += 0x9E3779B97F4A7C15ULL);
}

static int pct(fz_t *z, int p) { return (int)(rnd(z) % 100) < p; }

#define PICK(z, arr) ((arr)[rnd(z) % (sizeof(arr) / sizeof((arr)[0]))])

static double unit(fz_t *z) { return (double)(rnd(z) >> 11) * 0x1p-53; }

/* ---- failure ---- */
static void fz_fail(fz_t *z, const char *fmt, ...)
{
    int expected = 0;
    if (!atomic_compare_exchange_strong(&sh->failed, &expected, 1))
        _exit(FZ_EXIT_FAIL); /* another thread reported first */
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(sh->fail, sizeof sh->fail, fmt, ap);
    va_end(ap);
    if (z)
        snprintf(sh->replay, sizeof sh->replay, "thread %d call %llu", z->tid, z->idx);
    fflush(stdout);
    _exit(FZ_EXIT_FAIL);
}

/* ---- panics inside the library ----
 * A panic inside the library is caught at the C boundary and answered RUN_TIME_ERR, a
 * code the vendor's library also returns on its own (a second MCC_InitSystem while one
 * runs, a motion command while an error record stands, MCC_SetCmdQueueSize), so the
 * code alone no longer tells a panic. Rust writes a panic's message ("... panicked
 * at ...") to stderr before it unwinds, so before the call returns: the worker's stderr
 * goes through a pipe that is read here (and forwarded to the real stderr). A call
 * answering RUN_TIME_ERR reads what the pipe holds at once, so the panic is reported
 * with the call that caused it; a watcher thread reads it meanwhile and reports a panic
 * any other call caught. */
static int stderr_orig = -1;
static int stderr_pipe = -1;
static pthread_mutex_t stderr_lock = PTHREAD_MUTEX_INITIALIZER;
static char stderr_tail[32]; /* the last bytes read: a message split across reads */
static atomic_int panic_seen;

/* Reads what the pipe holds now, forwards it and looks for a panic's message; whether
 * one was ever seen. */
static int stderr_drain(void)
{
    if (stderr_pipe < 0)
        return 0;
    char buf[4096 + sizeof stderr_tail];
    pthread_mutex_lock(&stderr_lock);
    for (;;) {
        size_t keep = strlen(stderr_tail);
        memcpy(buf, stderr_tail, keep);
        ssize_t n = read(stderr_pipe, buf + keep, 4096);
        if (n <= 0)
            break;
        ssize_t w = write(stderr_orig, buf + keep, (size_t)n);
        (void)w;
        size_t total = keep + (size_t)n;
        buf[total] = 0;
        for (size_t i = 0; i < total; i++)
            if (buf[i] == 0)
                buf[i] = ' ';
        if (strstr(buf, "panicked at"))
            atomic_store(&panic_seen, 1);
        size_t t = total < sizeof stderr_tail - 1 ? total : sizeof stderr_tail - 1;
        memcpy(stderr_tail, buf + total - t, t);
        stderr_tail[t] = 0;
    }
    pthread_mutex_unlock(&stderr_lock);
    return atomic_load(&panic_seen);
}

static void *stderr_watch(void *arg)
{
    (void)arg;
    for (;;) {
        struct pollfd p = {stderr_pipe, POLLIN, 0};
        poll(&p, 1, 50);
        if (stderr_drain())
            fz_fail(NULL, "a panic inside the library, caught at the C boundary (its message is above)");
    }
    return NULL;
}

/* The worker's stderr into the pipe the watcher reads. */
static void stderr_watch_start(void)
{
    int fds[2];
    if (pipe(fds) != 0)
        return;
    fflush(stderr);
    stderr_orig = dup(2);
    dup2(fds[1], 2);
    close(fds[1]);
    stderr_pipe = fds[0];
    fcntl(stderr_pipe, F_SETFL, fcntl(stderr_pipe, F_GETFL) | O_NONBLOCK);
    pthread_t t;
    pthread_create(&t, NULL, stderr_watch, NULL);
    pthread_detach(t);
}

/* ---- argument generators ---- */
static long long type_edge(fz_t *z, int bits, int sg)
{
    long long min, max;
    if (sg) {
        min = bits == 64 ? LLONG_MIN : -(1LL << (bits - 1));
        max = bits == 64 ? LLONG_MAX : (1LL << (bits - 1)) - 1;
    } else {
        min = 0;
        max = bits == 64 ? -1 : (long long)((1ULL << bits) - 1);
    }
    const long long v[] = {0, 1, -1, 2, min, max, min + 1, max - 1, 7, 8, 12, 255, 256,
                           0x7FFF, 0x8000, 0xFFFF, 0x10000, 0x7FFFFFFF, 0x80000000LL,
                           0xFFFFFFFFLL};
    return PICK(z, v);
}

long long fz_int(fz_t *z, int hint, int bits, int sg)
{
    int bounded = hint == FZ_H_TIMEDELAY || hint == FZ_H_QSIZE || hint == FZ_H_COMPORT;
    if (!bounded && pct(z, 10))
        return type_edge(z, bits, sg);
    switch (hint) {
    case FZ_H_GROUP: { static const long long v[] = {0, 0, 0, 0, 0, 1, 1, 2, 3, 4, 95, 96, 97}; return PICK(z, v); }
    case FZ_H_CARD: { static const long long v[] = {0, 0, 0, 0, 0, 0, 0, 1, 1, 2, 11, 12}; return PICK(z, v); }
    case FZ_H_CARDNO: { static const long long v[] = {1, 1, 1, 1, 1, 2, 2, 0, 12, 13}; return PICK(z, v); }
    case FZ_H_CARDTYPE: { static const long long v[] = {0, 1, 3, 6}; return pct(z, 90) ? (pct(z, 80) ? IMP_III_8_AXIS_PCI_CARD : IMP_II_8_AXIS_PCI_CARD) : PICK(z, v); }
    case FZ_H_MAPCH: return (long long)(rnd(z) % 10) - 2;
    case FZ_H_INTERP: { static const long long v[] = {1, 1, 1, 1, 2, 5, 10, 50, 0, 51}; return PICK(z, v); }
    case FZ_H_CHANNEL: return pct(z, 25) ? (long long)(rnd(z) % 26) : (long long)(rnd(z) % 9);
    case FZ_H_SET: { static const long long v[] = {0, 0, 0, 1, 2}; return PICK(z, v); }
    case FZ_H_SLAVE: return pct(z, 50) ? (long long)(rnd(z) % 4) : (long long)(rnd(z) % 34);
    case FZ_H_ORDER: { static const long long v[] = {0, 1, 2, 7, 8, 255, 255, 255, 255}; return PICK(z, v); }
    case FZ_H_MASK: { static const long long v[] = {0xFF, 0x7, 1, 2, 0, 0xFFFF, 0xFFFFFFFFLL}; return pct(z, 20) ? (long long)(rnd(z) & 0xFFFF) : PICK(z, v); }
    case FZ_H_DIR: { static const long long v[] = {0, 1, 0, 1, 2, -1}; return PICK(z, v); }
    case FZ_H_BOOL: { static const long long v[] = {0, 1, 0, 1, 2, -1}; return PICK(z, v); }
    case FZ_H_SMALL: return pct(z, 10) ? -1 : (long long)(rnd(z) % 17);
    case FZ_H_PPR: { static const long long v[] = {500, 500, 1000, 3000, 1, 10000, 0}; return PICK(z, v); }
    case FZ_H_PERIOD: { static const long long v[] = {1, 10, 100, 1000, 100000, 1000000, 0}; return pct(z, 30) ? (long long)(rnd(z) % 200000) : PICK(z, v); }
    case FZ_H_TIMEDELAY: return (long long)(rnd(z) % (unsigned)(opt_max_delay + 1));
    case FZ_H_QSIZE: {
        /* Capped: the library reserves a queue of the size asked for up front (a
         * known defect: 1,000,000 per group reserves gigabytes). --full adds it. */
        static const long long v[] = {1, 2, 16, 64, 1000, 4096, 0, -1, INT_MIN, INT_MAX, 1000001};
        if (opt_full && pct(z, 10))
            return 1000000;
        return PICK(z, v);
    }
    case FZ_H_COMPORT: { static const long long v[] = {-1, 0, 1, 2, 3, 4, INT_MIN, INT_MAX}; return PICK(z, v); }
    case FZ_H_DELAY: { static const long long v[] = {0, 1, 10, 100, 1000}; return pct(z, 50) ? (long long)(rnd(z) % 500) : PICK(z, v); }
    default:
        return pct(z, 50) ? type_edge(z, bits, sg) : (long long)(rnd(z) % 2001) - 1000;
    }
}

int fz_char(fz_t *z, int hint)
{
    static const int edge[] = {0, 255, 'X', 'T', 'S', 127, 128, 1, 'x'};
    static const int axis[] = {'X', 'Y', 'Z', 'U', 'V', 'W', 'A', 'B', 'x', 'y', 'C', 0, 1, 2, 7, 8};
    static const int acc[] = {'T', 'S', 'T', 'S', 't', 's', 'X', 'A'};
    if (pct(z, 10))
        return PICK(z, edge);
    if (hint == FZ_H_AXISCHAR)
        return PICK(z, axis);
    if (hint == FZ_H_ACCTYPE)
        return PICK(z, acc);
    return pct(z, 50) ? PICK(z, axis) : PICK(z, acc);
}

double fz_real(fz_t *z, int hint, int is_float)
{
    static const double dedge[] = {0.0, -0.0, 1.0, -1.0, NAN, INFINITY, -INFINITY, 1e300,
                                   -1e300, DBL_MAX, -DBL_MAX, DBL_MIN, 4.9406564584124654e-324,
                                   -4.9406564584124654e-324, 2.2250738585072009e-308, 1e-300,
                                   1e9, -1e9, 0.5};
    static const double fedge[] = {0.0, -0.0, 1.0, -1.0, NAN, INFINITY, -INFINITY, FLT_MAX,
                                   -FLT_MAX, FLT_MIN, 1.40129846e-45, -1.40129846e-45, 1e30,
                                   -1e30, 1e300, 0.5};
    if (pct(z, 12))
        return is_float ? PICK(z, fedge) : PICK(z, dedge);
    switch (hint) {
    case FZ_H_INTERP: { static const double v[] = {1, 1, 1, 2, 0.5, 1.5, 10, 50, 50.5, 0}; return PICK(z, v); }
    case FZ_H_VOLT: return unit(z) * 24.0 - 12.0;
    case FZ_H_RATIO: return 0.1 + unit(z) * 9.9;
    case FZ_H_SPEED: { static const double v[] = {1, 10, 50, 100, 1000}; return pct(z, 30) ? PICK(z, v) : unit(z) * 200.0; }
    case FZ_H_TIMEMS: return pct(z, 20) ? (double)(rnd(z) % 4) : unit(z) * 500.0;
    case FZ_H_LIMIT: return pct(z, 50) ? unit(z) * 100.0 : (pct(z, 50) ? 50000.0 : -50000.0);
    case FZ_H_POS: return pct(z, 20) ? (double)((long long)(rnd(z) % 5) - 2) : unit(z) * 200.0 - 100.0;
    default: return is_float ? PICK(z, fedge) : PICK(z, dedge);
    }
}

unsigned char *fz_ptr(fz_t *z, int slot, size_t elem, size_t count)
{
    size_t size = elem * count;
    if (slot >= FZ_PSLOTS || size > FZ_PBUF)
        fz_fail(z, "fuzzer limit: pointer argument %d of %zu bytes", slot, size);
    int r = (int)(rnd(z) % 100);
    int mode = r < 8 ? 0 : r < 16 ? 2 : 1;
    z->pmode[slot] = mode;
    if (mode == 0) {
        z->pstart[slot] = NULL;
        return NULL;
    }
    unsigned char *base = z->arena + (size_t)slot * (FZ_PBUF + 3 * FZ_GUARD);
    unsigned char *start = base + FZ_GUARD + (mode == 2 ? 1 : 0);
    memset(base, FZ_CANARY, (size_t)(start - base));
    memset(start + size, FZ_CANARY, FZ_GUARD);
    z->pstart[slot] = start;
    z->psize[slot] = size;
    z->used |= 1u << slot;
    return start;
}

void (*fz_callback(fz_t *z, int cb))(void)
{
    return pct(z, 15) ? NULL : fz_cbs[cb].fn;
}

/* ---- the log line ---- */
static void appendf(fz_t *z, const char *fmt, ...)
{
    if (z->len >= FZ_LINE - 48) {
        if (z->len < FZ_LINE - 4) {
            memcpy(z->line + z->len, "...", 4);
            z->len += 3;
        }
        return;
    }
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(z->line + z->len, FZ_LINE - 44 - z->len, fmt, ap);
    va_end(ap);
    if (n > 0)
        z->len += (size_t)n < FZ_LINE - 44 - z->len ? (size_t)n : FZ_LINE - 45 - z->len;
}

static void sep(fz_t *z)
{
    if (z->len && z->line[z->len - 1] != '(' && z->line[z->len - 1] != '{')
        appendf(z, ", ");
}

void fz_begin(fz_t *z, int f)
{
    z->len = 0;
    z->used = 0;
    z->f = f;
    z->nonfinite_arg = 0;
    if (z->tid >= 100)
        appendf(z, "R%d ", z->tid - 100);
    else if (z->tid == 99)
        appendf(z, "main ");
    else
        appendf(z, "T%d#%llu ", z->tid, z->idx);
    appendf(z, "%s(", f >= 0 ? fz_funcs[f].name : "?");
}

void fz_log_i(fz_t *z, const char *n, long long v) { sep(z); appendf(z, "%s=%lld", n, v); }
void fz_log_u(fz_t *z, const char *n, unsigned long long v) { sep(z); appendf(z, "%s=%llu", n, v); }
void fz_log_c(fz_t *z, const char *n, int v)
{
    sep(z);
    unsigned char c = (unsigned char)v;
    if (c >= 32 && c < 127)
        appendf(z, "%s='%c'", n, c);
    else
        appendf(z, "%s=%d", n, (int)c);
}
void fz_log_r(fz_t *z, const char *n, double v) { sep(z); appendf(z, "%s=%.17g", n, v); }
void fz_log_raw(fz_t *z, const char *s) { appendf(z, "%s", s); }
void fz_arg_real(fz_t *z, double v) { z->nonfinite_arg |= !isfinite(v); }
void fz_log_p(fz_t *z, const char *n, int slot)
{
    sep(z);
    if (z->pmode[slot] == 0)
        appendf(z, "%s=NULL", n);
    else
        appendf(z, "%s=&buf[%zu]%s", n, z->psize[slot], z->pmode[slot] == 2 ? "+1(misaligned)" : "");
}
void fz_log_cb(fz_t *z, const char *n, void (*fn)(void))
{
    sep(z);
    const char *name = "NULL";
    for (int i = 0; fn && i < fz_ncbs; i++)
        if (fz_cbs[i].fn == fn)
            name = fz_cbs[i].name;
    appendf(z, "%s=%s", n, fn ? name : "NULL");
}

static void publish(fz_t *z)
{
    fz_entry_t *e = &sh->ring[z->seq % FZ_RING];
    memcpy(e->text, z->line, z->len);
    e->text[z->len] = 0;
    atomic_store(&e->seq, z->seq + 1);
}

void fz_call_start(fz_t *z, int f)
{
    appendf(z, ")");
    z->seq = atomic_fetch_add(&sh->next_seq, 1);
    publish(z);
    if (!z->in_routine && opt_routine_init == 1 && (fz_funcs[f].flags & (FZ_F_INIT | FZ_F_CLOSE)) &&
        !z->holds_init) {
        pthread_mutex_lock(&init_lock);
        z->holds_init = 1;
    }
    atomic_store(&sh->slot_seq[z->slot], z->seq);
    atomic_store(&sh->slot_start_ns[z->slot], now_ns());
}

static void finish(fz_t *z, int f)
{
    long long took = now_ns() - atomic_load(&sh->slot_start_ns[z->slot]);
    atomic_store(&sh->slot_start_ns[z->slot], 0);
    if (took > 100000000LL)
        appendf(z, " [took %lld ms]", took / 1000000);
    if (z->holds_init == 1 && !z->in_routine) {
        /* a program thread's own init/close lock (routines release theirs) */
        z->holds_init = 0;
        pthread_mutex_unlock(&init_lock);
    }
    publish(z);
    if (f >= 0)
        atomic_fetch_add(&sh->calls[f], 1);
    if (z->in_routine)
        atomic_fetch_add(&sh->routine_calls, 1);
    else
        atomic_fetch_add(&sh->prog_calls, 1);
    for (int s = 0; s < FZ_PSLOTS; s++) {
        if (!(z->used & (1u << s)))
            continue;
        unsigned char *base = z->arena + (size_t)s * (FZ_PBUF + 3 * FZ_GUARD);
        unsigned char *start = z->pstart[s];
        for (unsigned char *q = base; q < start; q++)
            if (*q != FZ_CANARY)
                fz_fail(z, "write before pointer argument %d (%td bytes before it): %s", s,
                        start - q, z->line);
        for (size_t k = 0; k < FZ_GUARD; k++)
            if (start[z->psize[s] + k] != FZ_CANARY)
                fz_fail(z, "write past pointer argument %d (%zu bytes, byte %zu after it): %s", s,
                        z->psize[s], k, z->line);
    }
    if (opt_replay)
        printf("%s\n", z->line);
}

/* Non-finite doubles that are the documented answer, counted instead of failing
 * (--strict fails on them). */
static const char *const tolerated_nonfinite[] = {
    /* +inf while no limit was set: "no limit" (docs/testing.md "Fuzzing") */
    "MCC_GetTrackErrorLimit",
};

/* Functions that take a NaN or infinite argument as the vendor's library takes it (not
 * a motion target: nothing moves to it): MCC_SetInPosToleranceEx keeps a tolerance as a
 * 32-bit pulse count, and a value too large for one (NaN and infinities too) becomes
 * 2^31 pulses there (measured: scenario setters_inpos_group). */
static const char *const accepts_nonfinite[] = {
    "MCC_SetInPosToleranceEx",
};

static int nonfinite_accepted(fz_t *z)
{
    if (z->f < 0)
        return 0;
    for (size_t i = 0; i < sizeof accepts_nonfinite / sizeof accepts_nonfinite[0]; i++)
        if (strcmp(fz_funcs[z->f].name, accepts_nonfinite[i]) == 0)
            return 1;
    return 0;
}

static int tolerated(fz_t *z)
{
    if (opt_strict || z->f < 0)
        return 0;
    if (opt_tolerate_nonfinite) {
        atomic_fetch_add(&sh->tolerated[z->f], 1);
        return 1;
    }
    for (size_t i = 0; i < sizeof tolerated_nonfinite / sizeof tolerated_nonfinite[0]; i++)
        if (strcmp(fz_funcs[z->f].name, tolerated_nonfinite[i]) == 0) {
            atomic_fetch_add(&sh->tolerated[z->f], 1);
            return 1;
        }
    return 0;
}

void fz_end_void(fz_t *z, int f)
{
    finish(z, f);
    z->idx += !z->in_routine;
}

void fz_end_int(fz_t *z, int f, long long r, int codes)
{
    appendf(z, " = %lld", r);
    finish(z, f);
    if (codes == FZ_CODES_VENDOR && r == RUN_TIME_ERR && stderr_drain())
        fz_fail(z, "RUN_TIME_ERR (a panic caught at the C boundary): %s", z->line);
    if (codes == FZ_CODES_MCL && (r < 0 || r > 7))
        fz_fail(z, "return value outside the MCL_* codes: %s", z->line);
    if (codes == FZ_CODES_VENDOR && z->nonfinite_arg && r >= 0 && !nonfinite_accepted(z)
        && !tolerated(z))
        fz_fail(z, "a NaN or infinite argument was accepted: %s", z->line);
    z->idx += !z->in_routine;
}

void fz_end_real(fz_t *z, int f, double r, int codes)
{
    appendf(z, " = %.17g", r);
    finish(z, f);
    if (codes == FZ_CODES_VENDOR && r == (double)RUN_TIME_ERR && stderr_drain())
        fz_fail(z, "RUN_TIME_ERR (a panic caught at the C boundary): %s", z->line);
    if (!isfinite(r) && !tolerated(z))
        fz_fail(z, "non-finite double returned: %s", z->line);
    if (codes == FZ_CODES_VENDOR && z->nonfinite_arg && r >= 0 && !nonfinite_accepted(z)
        && !tolerated(z))
        fz_fail(z, "a NaN or infinite argument was accepted: %s", z->line);
    z->idx += !z->in_routine;
}

void fz_check_finite(fz_t *z, int slot, const unsigned char *p, int count, int is_float)
{
    for (int i = 0; p && i < count; i++) {
        double v;
        if (is_float) {
            float fv;
            memcpy(&fv, p + (size_t)i * sizeof fv, sizeof fv);
            v = fv;
        } else {
            memcpy(&v, p + (size_t)i * sizeof v, sizeof v);
        }
        if (!isfinite(v) && !tolerated(z))
            fz_fail(z, "non-finite value %g written to pointer argument %d by a successful call: %s", v,
                    slot, z->line);
    }
}

/* ---- scripted calls (the arming step, routines, scenarios) ---- */
static int fz_find(const char *name)
{
    for (int i = 0; i < fz_nfuncs; i++)
        if (strcmp(fz_funcs[i].name, name) == 0)
            return i;
    return -1;
}

/* One scripted call of `fname`, logged with `args` and watched like a generated call: its
 * table index is looked up once, then `run` makes the call and ends it (as `f_`). */
#define FZ_SCRIPTED(z, fname, args, run)                                             \
    do {                                                                             \
        static _Atomic int f_ = -2;                                                  \
        if (atomic_load(&f_) == -2)                                                  \
            atomic_store(&f_, fz_find(fname));                                       \
        fz_begin(z, f_);                                                             \
        fz_log_raw(z, args);                                                         \
        fz_call_start(z, f_);                                                        \
        run;                                                                         \
    } while (0)
/* A function returning an integer (a vendor code), nothing, or a double. */
#define FZ_DO(z, fname, args, expr)                                                  \
    FZ_SCRIPTED(z, fname, args, long long r_ = (long long)(expr);                    \
                fz_end_int(z, f_, r_, FZ_CODES_VENDOR))
#define FZ_DO_VOID(z, fname, args, expr)                                             \
    FZ_SCRIPTED(z, fname, args, (expr); fz_end_void(z, f_))
#define FZ_DO_REAL(z, fname, args, expr)                                             \
    FZ_SCRIPTED(z, fname, args, double r_ = (double)(expr);                          \
                fz_end_real(z, f_, r_, FZ_CODES_VENDOR))

static SYS_CARD_CONFIG good_cards[MAX_CARD_NUM];

/* The fuzzer's routine of callback type `name` (NULL if there is none). */
static void (*routine_named(const char *name))(void)
{
    for (int i = 0; i < fz_ncbs; i++)
        if (strcmp(fz_cbs[i].name, name) == 0)
            return fz_cbs[i].fn;
    return NULL;
}

static void init_good(fz_t *z)
{
    FZ_DO(z, "MCC_InitSystem", "1, {IMP_III}, 1", MCC_InitSystem(1, good_cards, 1));
}

/* Arms every cause of an interrupt routine on card 0 of machine.toml and lets ticks run:
 * a sane machine, all routines registered, timer (TMR), ADC conversions (ADC), a home
 * sensor forced on and off (LIO), index pulses and a compare value passed (ENC), an
 * error-count threshold below the lag of channel 0 during a move (PCL), a looped-back
 * remote output toggled (RIO), a robot group's move (kinematics, pre-process). HSK:
 * nothing in the library raises the handshake cause (Interrupt::Handshake is never raised
 * in src/), so the HSK routine is registered but cannot be delivered; it is excluded from
 * --require-routines. */
static void arm(fz_t *z)
{
    SYS_MAC_PARAM mac;
    memset(&mac, 0, sizeof mac);
    mac.wRPM = 3000;
    mac.dwPPR = 500;
    mac.dfPitch = 1;
    mac.dfGearRatio = 1;
    mac.dfHighLimit = 50000;
    mac.dfLowLimit = -50000;
    mac.wPulseMode = DDA_FMT_PD;
    mac.wOverTravelUpSensorMode = SL_UNUSED;
    mac.wOverTravelDownSensorMode = SL_UNUSED;
    if (opt_routine_init == 1) {
        pthread_mutex_lock(&init_lock);
        z->holds_init = 2; /* held over the whole re-init below */
    }
    FZ_DO(z, "MCC_CloseSystem", "", MCC_CloseSystem());
    for (WORD ch = 0; ch < 8; ch++)
        FZ_DO(z, "MCC_SetMacParam", "&sane, ch, 0", MCC_SetMacParam(&mac, ch, 0));
    FZ_DO(z, "MCC_CloseAllGroups", "", MCC_CloseAllGroups());
    FZ_DO(z, "MCC_CreateGroup", "0..7, card 0", MCC_CreateGroup(0, 1, 2, 3, 4, 5, 6, 7, 0));
    /* Group 1: a robot on channel 7 (B), below. */
    FZ_DO(z, "MCC_CreateGroup", "B on 7, card 0", MCC_CreateGroup(-1, -1, -1, -1, -1, -1, -1, 7, 0));
    /* Group 1 becomes a robot with the fuzzer's routines as its kinematics, registered
     * before the card starts as the vendor's library takes them (their joints stay where
     * they are: channel 7 stays at 0, as group 0 commands it). */
    FZ_DO(z, "MCC_SetKinematicTrans", "fz routines, 64, fz routine, 1",
          MCC_SetKinematicTrans((FWDKINEFUN)routine_named("FWDKINEFUN"),
                                (INVKINEFUN)routine_named("INVKINEFUN"), 64,
                                (INIT_EXTENSION)routine_named("INIT_EXTENSION"), 1));
    int ok = MCC_GetMotionStatus(0); /* not counted: the status before init */
    (void)ok;
    init_good(z);
    if (z->holds_init == 2) {
        z->holds_init = 0;
        pthread_mutex_unlock(&init_lock);
    }
    fz_register_all(z, 0);
    FZ_DO(z, "MCC_SetTimer", "100000 (1 ms), 0", MCC_SetTimer(100000, 0));
    FZ_DO(z, "MCC_EnableTimer", "0", MCC_EnableTimer(0));
    FZ_DO(z, "MCC_EnableTimerTrigger", "0", MCC_EnableTimerTrigger(0));
    FZ_DO(z, "MCC_SetDACOutput", "2.5, 0, 0", MCC_SetDACOutput(2.5f, 0, 0));
    FZ_DO(z, "MCC_EnableADCConvChannel", "0, 0", MCC_EnableADCConvChannel(0, 0));
    FZ_DO(z, "MCC_EnableADCConvTrigger", "0", MCC_EnableADCConvTrigger(0));
    FZ_DO(z, "MCC_StartADCConv", "0", MCC_StartADCConv(0));
    FZ_DO(z, "MCC_EnableLIOTrigger", "16 (HOME0), 0", MCC_EnableLIOTrigger(16, 0));
    FZ_DO(z, "MCC_EnableLIOTrigger", "0 (OTP0), 0", MCC_EnableLIOTrigger(0, 0));
    FZ_DO(z, "MCC_EnableENCIndexTrigger", "0, 0", MCC_EnableENCIndexTrigger(0, 0));
    FZ_DO(z, "MCC_SetENCCompValue", "200, 0, 0", MCC_SetENCCompValue(200, 0, 0));
    FZ_DO(z, "MCC_EnableENCCompTrigger", "0, 0", MCC_EnableENCCompTrigger(0, 0));
    FZ_DO(z, "MCC_SetErrorCountThreshold", "0, 20, 20, 0", MCC_SetErrorCountThreshold(0, 20, 20, 0));
    FZ_DO(z, "MCC_EnableRIOSetControl", "0, 0", MCC_EnableRIOSetControl(0, 0));
    FZ_DO(z, "MCC_EnableRIOSlaveControl", "0, 0, 0", MCC_EnableRIOSlaveControl(0, 0, 0));
    FZ_DO(z, "MCC_SetRIOTriggerType", "RIO_INT_LEVEL, 0, 0, 0", MCC_SetRIOTriggerType(RIO_INT_LEVEL, 0, 0, 0));
    FZ_DO(z, "MCC_EnableRIOInputTrigger", "0, 0, 0", MCC_EnableRIOInputTrigger(0, 0, 0));
    FZ_DO(z, "MCC_SetRIOOutputValue", "1, 0, 0, 0", MCC_SetRIOOutputValue(1, 0, 0, 0));
    FZ_DO(z, "MCCL_SimSetSensor", "0, 0, HOME, 1", MCCL_SimSetSensor(0, 0, MCCL_SIM_HOME, 1));
    FZ_DO_VOID(z, "MCC_TimeDelay", "3", MCC_TimeDelay(3));
    FZ_DO(z, "MCCL_SimSetSensor", "0, 0, HOME, FOLLOW", MCCL_SimSetSensor(0, 0, MCCL_SIM_HOME, MCCL_SIM_FOLLOW));
    FZ_DO(z, "MCC_SetRIOOutputValue", "0, 0, 0, 0", MCC_SetRIOOutputValue(0, 0, 0, 0));
    FZ_DO_REAL(z, "MCC_SetFeedSpeed", "100, 0", MCC_SetFeedSpeed(100, 0));
    FZ_DO(z, "MCC_Line", "35, 0.., 0, ALL", MCC_Line(35, 0, 0, 0, 0, 0, 0, 0, 0, IMP_AXIS_ALL));
    /* Group 1, a robot (its kinematics registered before init, above), gets the
     * fuzzer's pre-process routine, which runs when its Cartesian move starts. */
    FZ_DO(z, "MCC_SetPreProcessMotionCommandCallback", "fz routine, 1",
          MCC_SetPreProcessMotionCommandCallback(
              (PRE_PROCESS_MOTION_COMMAND)routine_named("PRE_PROCESS_MOTION_COMMAND"), 1));
    FZ_DO(z, "MCC_Line_V6", "0.., b 1, posture 0, 1, ALL",
          MCC_Line_V6(0, 0, 0, 0, 0, 0, 0, 1, 0, 1, IMP_AXIS_ALL));
    FZ_DO_VOID(z, "MCC_TimeDelay", "40", MCC_TimeDelay(40));
}

/* ---- routines ---- */
static fz_t *routine_ctx(void)
{
    if (tl_pool < 0)
        tl_pool = atomic_fetch_add(&pool_next, 1) % FZ_POOL;
    fz_t *z = &pool_ctx[tl_pool];
    return z;
}

static int pick_func(fz_t *z)
{
    long long w = (long long)(rnd(z) % (unsigned long long)total_weight);
    for (int i = 0; i < fz_nfuncs; i++) {
        w -= weights[i];
        if (w < 0)
            return i;
    }
    return fz_nfuncs - 1;
}

/* A routine may call init/close: off never, safe only while no program thread is in
 * one (a fuzzer lock tried, never waited for), free always. */
static int routine_may_init(fz_t *z)
{
    if (opt_routine_init == 0)
        return 0;
    if (opt_routine_init == 1) {
        if (pthread_mutex_trylock(&init_lock) != 0)
            return 0;
        z->holds_init = 1;
    }
    return 1;
}

static void routine_done_init(fz_t *z)
{
    if (z->holds_init) {
        z->holds_init = 0;
        pthread_mutex_unlock(&init_lock);
    }
}

static int scenario_init_tmr;

void fz_routine(int cb, const void *p, size_t size)
{
    fz_t *z = routine_ctx();
    unsigned long long n = atomic_fetch_add(&sh->deliveries[cb], 1);
    if (size && !p)
        fz_fail(z, "routine %s delivered with a NULL %s", fz_cbs[cb].name, fz_cbs[cb].arg);
    if (p) {
        volatile unsigned sum = 0;
        for (size_t i = 0; i < size; i++)
            sum += ((const unsigned char *)p)[i];
        (void)sum;
    }
    if (z->depth > 0)
        return;
    z->depth++;
    z->rng = mix64(opt_seed * 1000003ULL + (unsigned long long)cb * 7919ULL + n);
    if (scenario_init_tmr) {
        if (n % 5 == 4) {
            if (routine_may_init(z)) {
                init_good(z);
                routine_done_init(z);
            }
        } else
            FZ_DO_REAL(z, "MCC_GetConvFactor", "0, 0", MCC_GetConvFactor(0, 0));
        z->depth--;
        return;
    }
    int u = (int)(rnd(z) % 1000);
    if (u < 500) {
        int f = pick_func(z);
        if (fz_funcs[f].flags & (FZ_F_INIT | FZ_F_CLOSE)) {
            if (routine_may_init(z)) {
                fz_funcs[f].call(z);
                routine_done_init(z);
            }
        } else {
            fz_funcs[f].call(z);
        }
    } else if (u < 515) {
        if (routine_may_init(z)) {
            FZ_DO(z, "MCC_CloseSystem", "", MCC_CloseSystem());
            routine_done_init(z);
        }
    } else if (u < 530) {
        if (routine_may_init(z)) {
            init_good(z);
            routine_done_init(z);
        }
    }
    z->depth--;
}

/* ---- program threads ---- */
static _Atomic int stop_all;

static void *prog_thread(void *arg)
{
    fz_t *z = arg;
    for (long long i = 0; i < per_thread_calls && !atomic_load(&stop_all); i++) {
        if (opt_upto >= 0 && (long long)z->idx >= opt_upto)
            break;
        if (z->tid == 0 && opt_arm_every > 0 && i % opt_arm_every == opt_arm_every / 10) {
            arm(z);
            continue;
        }
        fz_funcs[pick_func(z)].call(z);
    }
    return NULL;
}

static void (*tmr_routine(void))(void)
{
    for (int i = 0; i < fz_ncbs; i++)
        if (strcmp(fz_cbs[i].name, "TMRISR") == 0)
            return fz_cbs[i].fn;
    return NULL;
}

/* The known deadlock's program: init, a 1 ms timer routine, a few ticks, sometimes
 * close; its routine calls MCC_InitSystem every 5th time, else MCC_GetConvFactor. */
static void *scenario_thread(void *arg)
{
    fz_t *z = arg;
    for (long long i = 0; i < per_thread_calls / 6 && !atomic_load(&stop_all); i++) {
        init_good(z);
        FZ_DO(z, "MCC_SetTMRRoutine", "TMRISR, 0", MCC_SetTMRRoutine((TMRISR)tmr_routine(), 0));
        FZ_DO(z, "MCC_SetTimer", "100000, 0", MCC_SetTimer(100000, 0));
        FZ_DO(z, "MCC_EnableTimer", "0", MCC_EnableTimer(0));
        FZ_DO(z, "MCC_EnableTimerTrigger", "0", MCC_EnableTimerTrigger(0));
        DWORD d = 1 + (DWORD)(rnd(z) % 3);
        static const char *const ms[] = {"0", "1", "2", "3"};
        FZ_DO_VOID(z, "MCC_TimeDelay", ms[d], MCC_TimeDelay(d));
        if (rnd(z) % 4 == 0)
            FZ_DO(z, "MCC_CloseSystem", "", MCC_CloseSystem());
    }
    return NULL;
}

static int count_tasks(void)
{
    DIR *d = opendir("/proc/self/task");
    int n = 0;
    struct dirent *e;
    if (!d)
        return -1;
    while ((e = readdir(d)))
        if (e->d_name[0] != '.')
            n++;
    closedir(d);
    return n;
}

static void ctx_init(fz_t *z, int tid, int slot, unsigned long long seed)
{
    memset(z, 0, sizeof *z);
    z->tid = tid;
    z->slot = slot;
    z->rng = mix64(seed * 0x100000001B3ULL + (unsigned long long)tid + 1);
    if (posix_memalign((void **)&z->arena, 64, (size_t)FZ_PSLOTS * (FZ_PBUF + 3 * FZ_GUARD)))
        abort();
}

static int worker(unsigned long long seed, const char *clock)
{
    setenv("MCCL_CLOCK", clock, 1);
    if (!getenv("MCCL_SIM"))
        setenv("MCCL_SIM", FZ_MACHINE_TOML, 1);
    /* The MC3B library opens COM ports: the ones drawn (1..4) name paths that do not
     * exist, the others /dev/ttyS<N-1> with N < 1 or huge, which do not exist either. */
    for (int i = 1; i <= 4; i++) {
        char k[32];
        snprintf(k, sizeof k, "MCL_COM%d", i);
        setenv(k, "/nonexistent/mccl-fuzz-com", 1);
    }
    setenv("MCL_TIMEOUT_MS", "20", 1);
    if (opt_mem_mb > 0) {
        struct rlimit rl = {(rlim_t)opt_mem_mb << 20, (rlim_t)opt_mem_mb << 20};
        setrlimit(RLIMIT_AS, &rl);
    }
    opt_seed = seed;
    for (int i = 0; i < MAX_CARD_NUM; i++)
        good_cards[i].wCardType = IMP_III_8_AXIS_PCI_CARD;
    stderr_watch_start(); /* before the threads are counted: it stays to the end */
    int tasks_before = count_tasks();
    per_thread_calls = opt_calls / opt_threads;
    pthread_t th[2];
    for (int t = 0; t < opt_threads; t++)
        ctx_init(&prog_ctx[t], t, t, seed);
    for (int i = 0; i < FZ_POOL; i++)
        ctx_init(&pool_ctx[i], 100 + i, 2 + i % 5, seed);
    ctx_init(&main_ctx, 99, 7, seed);
    for (int i = 0; i < FZ_POOL; i++)
        pool_ctx[i].in_routine = 1;
    for (int t = 0; t < opt_threads; t++)
        pthread_create(&th[t], NULL, opt_scenario ? scenario_thread : prog_thread, &prog_ctx[t]);
    for (int t = 0; t < opt_threads; t++)
        pthread_join(th[t], NULL);
    FZ_DO(&main_ctx, "MCC_CloseSystem", "(final)", MCC_CloseSystem());
    /* A thread the library started must be gone after the final close (a closing
     * engine thread may take a moment to end after a close from its own routine). */
    int tasks_after = count_tasks();
    for (int i = 0; i < 200 && tasks_after > tasks_before; i++) {
        usleep(10000);
        tasks_after = count_tasks();
    }
    if (tasks_after > tasks_before)
        fz_fail(&main_ctx, "thread leak: %d threads before the first call, %d after the final MCC_CloseSystem",
                tasks_before, tasks_after);
    for (int t = 0; t < opt_threads; t++)
        free(prog_ctx[t].arena);
    for (int i = 0; i < FZ_POOL; i++)
        free(pool_ctx[i].arena);
    free(main_ctx.arena);
    free(weights);
    fflush(stderr);
    if (stderr_drain())
        fz_fail(&main_ctx, "a panic inside the library, caught at the C boundary (its message is above)");
    fflush(stdout);
    return 0;
}

/* ---- parent ---- */
static void print_last(int n)
{
    unsigned long long next = atomic_load(&sh->next_seq);
    unsigned long long from = next > (unsigned long long)n ? next - (unsigned long long)n : 0;
    if (n > FZ_RING)
        from = next > FZ_RING ? next - FZ_RING : 0;
    fprintf(stderr, "last calls (oldest first; a call without \" = \" had not returned):\n");
    for (unsigned long long s = from; s < next; s++) {
        fz_entry_t *e = &sh->ring[s % FZ_RING];
        if (atomic_load(&e->seq) == s + 1)
            fprintf(stderr, "  [%llu] %s\n", s, e->text);
    }
}

static const char *clock_for(int w)
{
    if (strcmp(opt_clock, "mix") != 0)
        return opt_clock;
    /* mostly fast; every 4th worker stepped, every 8th realtime */
    return w % 8 == 7 ? "realtime" : w % 4 == 3 ? "stepped" : "fast";
}

static void usage(void)
{
    printf("usage: mccl_fuzz [options]\n"
           "  --seed N            first seed (worker w runs seed N+w; default 1)\n"
           "  --calls N           program-thread calls over all workers (default 200000)\n"
           "  --workers N         child processes run one after the other (default 8)\n"
           "  --threads 1|2       program threads per worker (default 2)\n"
           "  --clock C           fast, stepped, realtime or mix (default mix: mostly fast)\n"
           "  --routine-init M    routines call MCC_InitSystem/CloseSystem: free (default),\n"
           "                      safe (only while no program thread is in one), off\n"
           "  --arm-every N       arm every routine cause every N calls of thread 0 (500; 0 off)\n"
           "  --max-delay MS      largest MCC_TimeDelay drawn (default 3)\n"
           "  --hang-ms MS        a call running longer is a hang (default 5000)\n"
           "  --last N            calls printed with a failure (default 20)\n"
           "  --mem-mb MB         address-space limit of a worker (default 4096; 0 none)\n"
           "  --full              also queue sizes the library reserves up front (1000000)\n"
           "  --require-routines  fail unless every routine type that can be raised was delivered\n"
           "  --keep-going        run the remaining workers after a failure\n"
           "  --replay            print every call (use with --seed, --workers 1, --upto)\n"
           "  --upto N            stop each program thread after its call N\n"
           "  --stats             print the call count of every function\n"
           "  --gdb               on a hang, print every thread's stack (gdb -p) first\n"
           "  --strict            fail on the reported findings tolerated so far (see fuzz.c)\n"
           "  --tolerate-nonfinite count every non-finite double instead of failing\n"
           "  --scenario init-tmr the call pattern of a fixed init/timer-routine deadlock\n");
}

int main(int argc, char **argv)
{
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char *v = i + 1 < argc ? argv[i + 1] : NULL;
#define ARG(name) (strcmp(a, name) == 0 && v && (i++, 1))
        if (ARG("--seed")) opt_seed = strtoull(v, NULL, 0);
        else if (ARG("--calls")) opt_calls = atoll(v);
        else if (ARG("--workers")) opt_workers = atoi(v);
        else if (ARG("--threads")) opt_threads = atoi(v);
        else if (ARG("--clock")) opt_clock = v;
        else if (ARG("--hang-ms")) opt_hang_ms = atoi(v);
        else if (ARG("--last")) opt_last = atoi(v);
        else if (ARG("--arm-every")) opt_arm_every = atoi(v);
        else if (ARG("--max-delay")) opt_max_delay = atoi(v);
        else if (ARG("--mem-mb")) opt_mem_mb = atoi(v);
        else if (ARG("--upto")) opt_upto = atoll(v);
        else if (ARG("--scenario")) opt_scenario = v;
        else if (ARG("--routine-init")) {
            opt_routine_init = strcmp(v, "off") == 0 ? 0 : strcmp(v, "safe") == 0 ? 1 : 2;
            if (strcmp(v, "off") && strcmp(v, "safe") && strcmp(v, "free")) {
                fprintf(stderr, "--routine-init: free, safe or off\n");
                return 2;
            }
        }
        else if (strcmp(a, "--full") == 0) opt_full = 1;
        else if (strcmp(a, "--replay") == 0) opt_replay = 1;
        else if (strcmp(a, "--require-routines") == 0) opt_require_routines = 1;
        else if (strcmp(a, "--keep-going") == 0) opt_keep_going = 1;
        else if (strcmp(a, "--stats") == 0) opt_stats = 1;
        else if (strcmp(a, "--gdb") == 0) opt_gdb = 1;
        else if (strcmp(a, "--strict") == 0) opt_strict = 1;
        else if (strcmp(a, "--tolerate-nonfinite") == 0) opt_tolerate_nonfinite = 1;
        else {
            usage();
            return strcmp(a, "--help") == 0 ? 0 : 2;
        }
#undef ARG
    }
    if (opt_threads < 1 || opt_threads > 2 || opt_workers < 1 || opt_calls < 1) {
        fprintf(stderr, "mccl_fuzz: --threads 1..2, --workers >= 1, --calls >= 1\n");
        return 2;
    }
    if (opt_scenario && strcmp(opt_scenario, "init-tmr") != 0) {
        fprintf(stderr, "mccl_fuzz: unknown scenario %s\n", opt_scenario);
        return 2;
    }
    scenario_init_tmr = opt_scenario != NULL;
    if (fz_nfuncs > FZ_MAXF || fz_ncbs > FZ_MAXCB) {
        fprintf(stderr, "mccl_fuzz: raise FZ_MAXF/FZ_MAXCB\n");
        return 2;
    }
    /* Weights: waits and status polls often (they let ticks and routines run), inits
     * more often than closes (most calls should meet a running card). */
    static const struct { const char *name; int w; } wt[] = {
        {"MCC_TimeDelay", 60}, {"MCC_GetMotionStatus", 20}, {"MCC_InitSystem", 8},
        {"MCC_InitSystemEx", 3}, {"MCC_InitSimulation", 3}, {"MCC_CloseSystem", 3},
        {"MCC_Line", 12}, {"MCC_PtP", 8}, {"MCC_ArcXY", 6}, {"MCC_CircleXY", 6},
    };
    weights = calloc((size_t)fz_nfuncs, sizeof *weights);
    total_weight = 0;
    for (int i = 0; i < fz_nfuncs; i++) {
        weights[i] = 4;
        for (size_t k = 0; k < sizeof wt / sizeof wt[0]; k++)
            if (strcmp(fz_funcs[i].name, wt[k].name) == 0)
                weights[i] = wt[k].w;
        total_weight += weights[i];
    }
    sh = mmap(NULL, sizeof *sh, PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
    if (sh == MAP_FAILED) {
        perror("mmap");
        return 2;
    }
    static unsigned long long calls[FZ_MAXF], deliveries[FZ_MAXCB], tolerated_n[FZ_MAXF];
    unsigned long long prog = 0, rout = 0;
    int failures = 0;
    long long t_all = now_ns();
    const char *mode = opt_routine_init == 0 ? "off" : opt_routine_init == 1 ? "safe" : "free";
    printf("mccl_fuzz: %d functions, %d callback types; seeds %llu..%llu, %lld calls, %d thread(s), "
           "clock %s, routine init/close %s%s\n",
           fz_nfuncs, fz_ncbs, opt_seed, opt_seed + (unsigned long long)opt_workers - 1, opt_calls,
           opt_threads, opt_clock, mode, opt_scenario ? ", scenario init-tmr" : "");
    fflush(stdout);
    for (int w = 0; w < opt_workers; w++) {
        unsigned long long seed = opt_seed + (unsigned long long)w;
        const char *clock = clock_for(w);
        memset(sh, 0, sizeof *sh);
        long long calls_w = opt_calls / opt_workers + (w < opt_calls % opt_workers);
        long long t0 = now_ns();
        pid_t pid = fork();
        if (pid < 0) {
            perror("fork");
            return 2;
        }
        if (pid == 0) {
            opt_calls = calls_w;
            _exit(worker(seed, clock));
        }
        int status = 0, hung = 0;
        for (;;) {
            pid_t r = waitpid(pid, &status, WNOHANG);
            if (r == pid)
                break;
            if (r < 0 && errno != EINTR) {
                perror("waitpid");
                return 2;
            }
            long long now = now_ns();
            for (int s = 0; s < FZ_SLOTS && !hung; s++) {
                long long st = atomic_load(&sh->slot_start_ns[s]);
                if (st && now - st > (long long)opt_hang_ms * 1000000LL) {
                    unsigned long long q = atomic_load(&sh->slot_seq[s]);
                    fz_entry_t *e = &sh->ring[q % FZ_RING];
                    fprintf(stderr, "\nHANG: seed %llu clock %s: call [%llu] has run for %.1f s (> %d ms):\n  %s\n",
                            seed, clock, q, (double)(now - st) / 1e9, opt_hang_ms,
                            atomic_load(&e->seq) == q + 1 ? e->text : "(no longer in the log)");
                    hung = 1;
                }
            }
            if (hung) {
                if (opt_gdb) {
                    char cmd[512];
                    snprintf(cmd, sizeof cmd,
                             "gdb -q -p %d -batch -ex 'thread apply all bt' > /tmp/mccl_fuzz-gdb-%d.txt 2>&1; "
                             "grep -E '^Thread|MCCLPCI_IMP::[a-z_:]*[A-Za-z_]+ \\(|join|fz_|MCC_|deliver|mutex' "
                             "/tmp/mccl_fuzz-gdb-%d.txt | "
                             "grep -v 'core::panic\\|catch_unwind\\|lifecycle' | cut -c1-150 1>&2; "
                             "echo '(all stacks: /tmp/mccl_fuzz-gdb-%d.txt)' 1>&2",
                             (int)pid, (int)pid, (int)pid, (int)pid);
                    if (system(cmd) != 0)
                        fprintf(stderr, "(gdb failed)\n");
                }
                kill(pid, SIGKILL);
                waitpid(pid, &status, 0);
                break;
            }
            usleep(20000);
        }
        double secs = (double)(now_ns() - t0) / 1e9;
        unsigned long long p = atomic_load(&sh->prog_calls), rc = atomic_load(&sh->routine_calls);
        prog += p;
        rout += rc;
        for (int i = 0; i < fz_nfuncs; i++)
            calls[i] += atomic_load(&sh->calls[i]);
        for (int i = 0; i < fz_ncbs; i++)
            deliveries[i] += atomic_load(&sh->deliveries[i]);
        for (int i = 0; i < fz_nfuncs; i++)
            tolerated_n[i] += atomic_load(&sh->tolerated[i]);
        printf("worker %d: seed %llu clock %-8s %8llu program + %7llu routine calls in %6.2f s (%.0f calls/s)\n",
               w, seed, clock, p, rc, secs, (double)(p + rc) / (secs > 0 ? secs : 1));
        fflush(stdout);
        int failed = 0;
        if (hung) {
            failed = 1;
        } else if (WIFSIGNALED(status)) {
            fprintf(stderr, "\nCRASH: seed %llu clock %s: the worker died of signal %d (%s)\n", seed,
                    clock, WTERMSIG(status), strsignal(WTERMSIG(status)));
            for (int s = 0; s < FZ_SLOTS; s++)
                if (atomic_load(&sh->slot_start_ns[s]))
                    fprintf(stderr, "  running: call [%llu]\n", atomic_load(&sh->slot_seq[s]));
            failed = 1;
        } else if (WEXITSTATUS(status) == FZ_EXIT_FAIL) {
            fprintf(stderr, "\nFAILURE: seed %llu clock %s, %s: %s\n", seed, clock, sh->replay, sh->fail);
            failed = 1;
        } else if (WEXITSTATUS(status) != 0) {
            fprintf(stderr, "\nFAILURE: seed %llu clock %s: the worker exited with %d (valgrind error?)\n",
                    seed, clock, WEXITSTATUS(status));
            failed = 1;
        }
        if (failed) {
            print_last(opt_last);
            fprintf(stderr,
                    "replay: mccl_fuzz --seed %llu --workers 1 --calls %lld --threads %d --clock %s "
                    "--routine-init %s --arm-every %d --max-delay %d%s --replay\n",
                    seed, calls_w, opt_threads, clock, mode, opt_arm_every, opt_max_delay,
                    opt_full ? " --full" : "");
            failures++;
            if (!opt_keep_going)
                break;
        }
    }
    double secs = (double)(now_ns() - t_all) / 1e9;
    printf("total: %llu program + %llu routine calls = %llu calls in %.2f s: %.0f calls/s\n", prog, rout,
           prog + rout, secs, (double)(prog + rout) / (secs > 0 ? secs : 1));
    printf("routine deliveries:");
    int missing = 0;
    for (int i = 0; i < fz_ncbs; i++) {
        printf(" %s=%llu", fz_cbs[i].name, deliveries[i]);
        /* Types no function takes (CYCLE_INTERRUPT_ISR) cannot be registered. HSKISR:
         * nothing in the library raises the handshake cause yet (see arm()). A command's
         * callbacks (custom motion) run only while such a command happens to run (the
         * blending ones only with blending on as well): counted, not required. */
        int excluded = fz_cbs[i].setters == 0 || strcmp(fz_cbs[i].name, "HSKISR") == 0
                       || fz_cbs[i].command;
        if (!deliveries[i] && !excluded)
            missing++;
    }
    printf("\n");
    for (int i = 0; i < fz_nfuncs; i++)
        if (tolerated_n[i])
            printf("tolerated finding (--strict fails): %s gave a non-finite double %llu times\n",
                   fz_funcs[i].name, tolerated_n[i]);
    int never = 0;
    for (int i = 0; i < fz_nfuncs; i++)
        never += calls[i] == 0;
    printf("functions called: %d of %d\n", fz_nfuncs - never, fz_nfuncs);
    if (opt_stats || (never && !failures && !opt_scenario && opt_upto < 0)) {
        for (int i = 0, col = 0; i < fz_nfuncs; i++) {
            if (!opt_stats && calls[i])
                continue;
            printf("  %-32s %9llu%s", fz_funcs[i].name, calls[i], ++col % 3 == 0 ? "\n" : "");
        }
        printf("\n");
    }
    if (opt_require_routines && missing && !failures) {
        fprintf(stderr, "FAILURE: %d routine type(s) that can be raised were never delivered\n", missing);
        failures++;
    }
    munmap(sh, sizeof *sh);
    printf("%s\n", failures ? "mccl_fuzz: FAILED" : "mccl_fuzz: ok");
    return failures ? 1 : 0;
}
