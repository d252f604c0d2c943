/* fuzz_rt.h: the interface between the random-call fuzzer's runtime (fuzz.c) and the
 * dispatch table that tools/mccl-fuzzgen generates from the library's headers at build
 * time (one caller per exported function, one routine per callback type). */
#ifndef MCCL_FUZZ_RT_H
#define MCCL_FUZZ_RT_H
#include <stddef.h>

typedef struct fz fz_t;

/* Value classes of a parameter, chosen by the generator from its type and name. Every
 * class also draws the edge values of the parameter's type now and then. */
enum {
    FZ_H_ANY,       /* the whole type */
    FZ_H_GROUP,     /* group indices: 0..3 mostly */
    FZ_H_CARD,      /* card indices: 0 mostly */
    FZ_H_CARDNO,    /* number of cards: 1 mostly */
    FZ_H_CARDTYPE,  /* card types: IMP III mostly */
    FZ_H_MAPCH,     /* channel of a group axis, -1 = none */
    FZ_H_INTERP,    /* interpolation period in ms: 1..5 mostly */
    FZ_H_CHANNEL,   /* channels, points, axes: 0..7 mostly */
    FZ_H_SET,       /* remote I/O set: 0..1 */
    FZ_H_SLAVE,     /* remote I/O slave or port: 0..31 */
    FZ_H_ORDER,     /* go-home order: 0..7, 255 */
    FZ_H_MASK,      /* bit masks */
    FZ_H_DIR,       /* directions */
    FZ_H_BOOL,      /* 0/1 (and 2, -1) */
    FZ_H_SMALL,     /* modes, types, sources: 0..16 */
    FZ_H_PPR,       /* pulses per revolution, rpm */
    FZ_H_PERIOD,    /* timer counts and periods */
    FZ_H_TIMEDELAY, /* MCC_TimeDelay: bounded, the calling thread waits */
    FZ_H_QSIZE,     /* queue sizes: capped, a size is reserved up front */
    FZ_H_COMPORT,   /* MC3B COM port: only ports that do not exist */
    FZ_H_DELAY,     /* MCC_DelayMotion */
    FZ_H_AXISCHAR,  /* 'X'..'B', 0..7 */
    FZ_H_ACCTYPE,   /* 'T', 'S' */
    FZ_H_VOLT,      /* volts: -12..12 */
    FZ_H_RATIO,     /* pitch, gear ratio: 0.1..10 */
    FZ_H_SPEED,     /* speeds, ratios, rates: 0..200 */
    FZ_H_TIMEMS,    /* times in ms: 0..500 */
    FZ_H_LIMIT,     /* limits, tolerances */
    FZ_H_POS        /* positions: -100..100 */
};

/* How a return value is checked. */
enum { FZ_CODES_NONE, FZ_CODES_VENDOR, FZ_CODES_MCL };

/* Function flags. */
enum { FZ_F_INIT = 1, FZ_F_CLOSE = 2, FZ_F_ROUTINE_SETTER = 4 };

typedef struct {
    const char *name;
    const char *header;
    void (*call)(fz_t *);
    int flags;
} fz_func_t;

typedef struct {
    const char *name; /* the callback typedef, e.g. LIOISR */
    const char *arg;  /* its argument struct, e.g. LIOINT */
    void (*fn)(void); /* the fuzzer's routine of that type */
    int setters;      /* exported functions that take this type */
    int command;      /* 1: a queued command's callback (custom motion), not a routine */
} fz_cb_t;

/* Generated. */
extern const fz_func_t fz_funcs[];
extern const int fz_nfuncs;
extern const fz_cb_t fz_cbs[];
extern const int fz_ncbs;
void fz_register_all(fz_t *z, int card);

/* Runtime: argument generators. */
long long fz_int(fz_t *z, int hint, int bits, int is_signed);
int fz_char(fz_t *z, int hint);
double fz_real(fz_t *z, int hint, int is_float);
unsigned char *fz_ptr(fz_t *z, int slot, size_t elem, size_t count);
void (*fz_callback(fz_t *z, int cb))(void);
/* Runtime: a routine of callback type cb was delivered with argument p of size bytes. */
void fz_routine(int cb, const void *p, size_t size);

/* Runtime: the log line of a call, the call, its result. */
void fz_begin(fz_t *z, int f);
void fz_log_i(fz_t *z, const char *name, long long v);
void fz_log_u(fz_t *z, const char *name, unsigned long long v);
void fz_log_c(fz_t *z, const char *name, int v);
void fz_log_r(fz_t *z, const char *name, double v);
void fz_log_p(fz_t *z, const char *name, int slot);
void fz_log_cb(fz_t *z, const char *name, void (*fn)(void));
void fz_log_raw(fz_t *z, const char *s);
/* A floating-point argument passed by value (a NaN or infinity must be refused). */
void fz_arg_real(fz_t *z, double v);
void fz_call_start(fz_t *z, int f);
void fz_end_void(fz_t *z, int f);
void fz_end_int(fz_t *z, int f, long long r, int codes);
void fz_end_real(fz_t *z, int f, double r, int codes);
/* After a successful call: the count doubles (floats) at p, if any, must be finite. */
void fz_check_finite(fz_t *z, int slot, const unsigned char *p, int count, int is_float);

#endif
