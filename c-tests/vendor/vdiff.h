/* Differential scenarios: one C source that runs unchanged against the vendor's
 * MCCLPCI_IMP3.dll (built with mingw, run under Wine) and against this library (built with
 * gcc, run on the stepped virtual clock), and writes what the library did, period by period,
 * as a text trace (the format is in docs/testing.md, "Vendor traces").
 *
 * A scenario sets the machine up before the card starts (`setup`), then issues every later
 * call from the cycle routine at fixed tick numbers (`script`): the cycle routine runs once
 * per interpolation period on both libraries, so a command issued at tick N starts at the
 * same period whatever the wall clock did. At the start of every period, before the script
 * runs, the state of every recorded group is written: pulses, positions, speeds, status,
 * error record, queue length, current command. */
#ifndef VDIFF_H
#define VDIFF_H
#include "MCCL.h"
#include "MCCL_Fun.h"
#include "vdl.h"

/* `V(MCC_Line)(...)` calls the loaded library's MCC_Line through the header's prototype. */
#define V(name)                                                                            \
    (*({                                                                                   \
        static void *vd_f_;                                                                \
        if (!vd_f_)                                                                        \
            vd_f_ = vd_need(#name);                                                        \
        (__typeof__(&name))vd_f_;                                                          \
    }))

/* Calls `fn` and records its int or double return value under the function's name. */
#define CI(fn, ...) vd_ret_i(#fn, V(fn)(__VA_ARGS__))
#define CD(fn, ...) vd_ret_d(#fn, V(fn)(__VA_ARGS__))

typedef struct {
    const char *name;
    /* Before the card starts: machine parameters, groups, MCC_InitSimulation (with
     * vd_init). Returns 0 to go on to the script, or nonzero when the scenario is over
     * (init refused on purpose). */
    int (*setup)(void);
    /* Called at every period `t` (0, 1, ...) from the cycle routine, after the state of
     * period `t` was recorded. */
    void (*script)(int t);
    /* The script's last tick: the run ends once every recorded group has stood still with
     * an empty queue for VD_QUIET periods after it, or at `max_ticks`. */
    int last_tick;
    int max_ticks;
    /* Optional: called by the main thread once the run ended, before the final
     * MCC_CloseSystem (closing and starting again, calls without a system). */
    void (*after)(void);
} Scenario;

#define VD_QUIET 10

/* The scenario tables of the scenario files, ended by an entry with name NULL. */
extern const Scenario vd_lines[], vd_arcs[], vd_ptp[], vd_control[], vd_state[], vd_extra[],
    vd_oracle_items[], vd_mixes[];

void *vd_need(const char *name);
int vd_ret_i(const char *label, int v);
double vd_ret_d(const char *label, double v);
/* Records a free-form note (values a getter wrote). */
void vd_note(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

/* Records group `g` (its first `naxes` axes) at every period. */
void vd_group(int g, int naxes);
/* The default machine: every channel of card 0 with PPR `ppr`, pitch 1, gear 1, limits
 * ±50000, pulse width 100, 3000 rpm, sensors unused. Each MCC_SetMacParam is recorded. */
void vd_mac_default(DWORD ppr);
/* One channel with given PPR, pitch and gear (the rest as vd_mac_default). */
void vd_mac(int ch, DWORD ppr, double pitch, double gear);
/* MCC_InitSimulation(period, one IMP-III PCI card); returns its value. */
int vd_init(int period_ms);
/* Ends the run after this period (the script's own end). */
void vd_end(void);

/* Getter dumps: every value a program can read of group `g` / of the system. */
void vd_dump_group(int g);
void vd_dump_system(void);
#endif
