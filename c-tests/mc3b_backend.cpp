// mc3b_backend.cpp: MCC_* motion on a card whose channels 0..2 are an MC3B (`mc3b_port`
// in MCCL_SIM), against the mc3b-emu emulator on a real pseudo-terminal.
//
//   mc3b_backend <path to mc3b-emu>
//
// The same program (an XY square, a line, a circle, a half circle, a point-to-point move)
// runs twice: first on the plain virtual card (fast clock), recording MCC_GetPulsePos
// after each step; then on the MC3B, where after each step the emulator's own step
// counters ("pos" on its control channel) must equal what the virtual card put out:
// every command ends exactly on its rounded end point (the last chord of an arc ends on
// the arc's end), so the tolerance at command ends is 0 steps. MCC_GetPulsePos and
// MCC_GetCurPos on the MC3B card must report those same confirmed steps.
//
// Go home (mode 9) runs the MC3B's own homing: X's − limit switch is MC3B input 0
// (`mc3b_limit_bits`, active high as wOverTravelDownSensorMode = SL_NORMAL_OPEN says); the
// test works the switch through the emulator's control channel while X seeks, backs off
// at 10 steps/s and approaches again; then phase 3 moves dfOffset (1 UU = 100 steps) up
// and X reads 0 there.
//
// Then what is MC3B-specific: two groups on one MC3B (GROUP_PARAMETER_ERR),
// MCC_InitSimulation (never opens the port), refused functions and their codes,
// MCC_JogConti stopped by MCC_AbortMotion (the position is then an estimate; the error
// against the emulator's counter is printed and bounded), and the emulator quitting
// mid-program (the group stops with error record 0xF901). The emulator runs in real time:
// every wait is bounded and says what it waited for; after the first failed check of a
// section the test stops (a wrong position makes every later wait pointless), and a
// watchdog (WATCHDOG_S) ends a run that hangs anyway, saying where it was. The waits are
// generous for a loaded 2-core host (the longest step takes under 3 s unloaded).
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>
#include "MCCL.h"
#include "MCCL_Fun.h"
#include "MCCL_Sim.h"
#include "check.h"

static const double K = 100.0;              // pulses (= MC3B steps) per UU
static const int ERR_MC3B_LINK = 0xF901;    // docs/mc3b.md: no reply / line failed
static const unsigned WATCHDOG_S = 150;     // below CTest's 180 s TIMEOUT
static const double STEP_LIMIT_S = 20;      // one program step (under 3 s unloaded)

// What the test is doing, for the watchdog's message.
static const char *volatile g_phase = "starting";

static void on_watchdog(int)
{
    static const char head[] = "mc3b_backend: watchdog: no end after the time limit, while: ";
    ssize_t r = write(2, head, sizeof head - 1);
    const char *p = g_phase;
    r = write(2, p, strlen(p));
    r = write(2, "\n", 1);
    (void)r;
    _exit(1);
}

struct Emu {
    pid_t pid = -1;
    FILE *ctl = nullptr;   // its stdin: control commands
    FILE *out = nullptr;   // its stdout: the device path, then one reply per command
    std::string path;
};

static bool spawn(const char *exe, Emu &e)
{
    int in[2], out[2];
    if (pipe(in) != 0 || pipe(out) != 0)
        return false;
    pid_t pid = fork();
    if (pid < 0)
        return false;
    if (pid == 0) {
        dup2(in[0], 0);
        dup2(out[1], 1);
        close(in[1]);
        close(out[0]);
        execl(exe, exe, (char *)nullptr);
        _exit(127);
    }
    close(in[0]);
    close(out[1]);
    e.pid = pid;
    e.ctl = fdopen(in[1], "w");
    e.out = fdopen(out[0], "r");
    char line[256];
    if (!e.ctl || !e.out || !fgets(line, sizeof line, e.out))
        return false;
    line[strcspn(line, "\r\n")] = 0;
    e.path = line;
    return e.path.rfind("/dev/", 0) == 0;
}

static std::string ctl(Emu &e, const char *cmd)
{
    char line[256] = {0};
    fprintf(e.ctl, "%s\n", cmd);
    fflush(e.ctl);
    if (!fgets(line, sizeof line, e.out))
        return "";
    line[strcspn(line, "\r\n")] = 0;
    return line;
}

static bool emu_pos(Emu &e, long p[3])
{
    std::string r = ctl(e, "pos");
    return sscanf(r.c_str(), "pos %ld %ld %ld", &p[0], &p[1], &p[2]) == 3;
}

static void reap(Emu &e);

// After a section with a failed check: stop here, with a message, instead of running
// into waits that can only time out.
static void give_up_if_failed(Emu &e, const char *section)
{
    if (check_failures == 0)
        return;
    fprintf(stderr, "mc3b_backend: giving up after the failed checks of: %s\n", section);
    MCC_CloseSystem();
    reap(e);
    exit(check_done("mc3b_backend"));
}

static void reap(Emu &e)
{
    if (e.ctl) {
        fclose(e.ctl);   // end of file on its stdin: the emulator exits
        e.ctl = nullptr;
    }
    if (e.out) {
        fclose(e.out);
        e.out = nullptr;
    }
    if (e.pid > 0) {
        int st;
        for (int i = 0; i < 200 && waitpid(e.pid, &st, WNOHANG) == 0; i++)
            usleep(10000);
        if (waitpid(e.pid, &st, WNOHANG) == 0) {
            kill(e.pid, SIGKILL);
            waitpid(e.pid, &st, 0);
        }
        e.pid = -1;
    }
}

static double now_s()
{
    using namespace std::chrono;
    return duration<double>(steady_clock::now().time_since_epoch()).count();
}

// Waits for GMS_STOP, at most `limit` seconds of real time; returns the time it took.
// A group that records an error ends the wait too (it runs nothing more until
// MCC_ClearError): the caller's checks of the error code and positions then say what
// went wrong, without waiting out the limit.
static double wait_stop(WORD g, double limit, const char *what)
{
    double t0 = now_s();
    while (MCC_GetMotionStatus(g) != GMS_STOP) {
        if (MCC_GetErrorCode(g) != 0) {
            fprintf(stderr, "mc3b_backend: %s: the group recorded error 0x%X (status %d)\n",
                    what, (unsigned)MCC_GetErrorCode(g), MCC_GetMotionStatus(g));
            break;
        }
        if (now_s() - t0 > limit) {
            fprintf(stderr, "mc3b_backend: %s did not stop within %.0f s (status %d)\n", what,
                    limit, MCC_GetMotionStatus(g));
            CHECK(!"motion stopped in time");
            return -1;
        }
        MCC_TimeDelay(5);
    }
    return now_s() - t0;
}

static void set_params()
{
    SYS_MAC_PARAM p;
    memset(&p, 0, sizeof p);
    p.dwPPR = 100;   // 100 pulses per UU: one pulse = one MC3B (half) step
    p.wRPM = 3000;   // PtP 100 % = 50 UU/s = 5000 steps/s, the MC3B's top speed
    p.dfPitch = 1.0;
    p.dfGearRatio = 1.0;
    p.dfHighLimit = 50000.0;
    p.dfLowLimit = -50000.0;
    p.wPulseMode = DDA_FMT_PD;
    p.wPulseWidth = 100;   // the vendor's library refuses a pulse width of 0
    p.wCommandMode = OCM_PULSE;
    p.wOverTravelUpSensorMode = SL_UNUSED;
    p.wOverTravelDownSensorMode = SL_UNUSED;
    for (WORD ch = 0; ch < MAX_AXIS_NUM; ch++)
        CHECK_EQ(MCC_SetMacParam(&p, ch, 0), NO_ERR);
    // X's − limit switch is wired normally open (on the MC3B: input 0, active at +5 V).
    p.wOverTravelDownSensorMode = SL_NORMAL_OPEN;
    CHECK_EQ(MCC_SetMacParam(&p, 0, 0), NO_ERR);
    CHECK_EQ(MCC_CloseAllGroups(), NO_ERR);
    // X, Y, Z on the MC3B's motors 0..2, U on channel 3 (which the MC3B does not have).
    CHECK_EQ(MCC_CreateGroup(0, 1, 2, 3, -1, -1, -1, -1, 0), 0);
}

static int init()
{
    SYS_CARD_CONFIG card[MAX_CARD_NUM];
    memset(card, 0, sizeof card);
    card[0].wCardType = IMP_III_8_AXIS_PCI_CARD;
    return MCC_InitSystem(1, card, 1);
}

struct Pulses {
    long p[3];
};

static Pulses pulses(WORD g)
{
    long a[8] = {0};
    CHECK_EQ(MCC_GetPulsePos(&a[0], &a[1], &a[2], &a[3], &a[4], &a[5], &a[6], &a[7], g), NO_ERR);
    Pulses r = {{a[0], a[1], a[2]}};
    return r;
}

static const char *STEP_NAMES[] = {"square (4 chained lines)", "line to (3.33, 7.77)",
                                   "circle about (8.33, 7.77)", "half circle to (13.33, 7.77)",
                                   "PtP to (0, 0)"};

// The motion program; after each step `at(step)` looks at where the axes are.
template <class F> static void program(WORD g, F at)
{
    CHECK(MCC_SetFeedSpeed(20, g) == 20.0);   // 2000 steps/s
    CHECK_EQ(MCC_SetAccTime(20, g), NO_ERR);
    CHECK_EQ(MCC_SetDecTime(20, g), NO_ERR);
    CHECK(MCC_SetPtPSpeed(20, g) == 20.0);    // 10 UU/s = 1000 steps/s
    CHECK_EQ(MCC_Line(10, 0, 0, 0, 0, 0, 0, 0, g), 0);
    CHECK_EQ(MCC_Line(10, 10, 0, 0, 0, 0, 0, 0, g), 1);
    CHECK_EQ(MCC_Line(0, 10, 0, 0, 0, 0, 0, 0, g), 2);
    CHECK_EQ(MCC_Line(0, 0, 0, 0, 0, 0, 0, 0, g), 3);
    at(0);
    CHECK(MCC_Line(3.33, 7.77, 0, 0, 0, 0, 0, 0, g) >= 0);
    at(1);
    CHECK(MCC_CircleXY(8.33, 7.77, CIR_CCW, g) >= 0);
    at(2);
    CHECK(MCC_ArcXY(8.33, 12.77, 13.33, 7.77, g) >= 0);
    at(3);
    CHECK(MCC_PtP(0, 0, 0, 0, 0, 0, 0, 0, g) >= 0);
    at(4);
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: mc3b_backend <mc3b-emu>\n");
        return 2;
    }
    signal(SIGPIPE, SIG_IGN);
    signal(SIGALRM, on_watchdog);
    alarm(WATCHDOG_S);
    Emu emu;
    if (!spawn(argv[1], emu)) {
        fprintf(stderr, "mc3b_backend: cannot start %s\n", argv[1]);
        return 1;
    }
    printf("mc3b-emu on %s\n", emu.path.c_str());

    char simfile[] = "/tmp/mc3b_backend_XXXXXX";
    int fd = mkstemp(simfile);
    CHECK(fd >= 0);
    std::string toml = "[[card]]\nindex = 0\nmc3b_port = \"" + emu.path + "\"\n"
                       "[[card.channel]]\nindex = 0\nmc3b_limit_bits = [-1, 0]\n";
    CHECK(write(fd, toml.data(), toml.size()) == (ssize_t)toml.size());
    close(fd);
    char badfile[] = "/tmp/mc3b_backend_bad_XXXXXX";
    fd = mkstemp(badfile);
    const char *bad = "[[card]]\nindex = 0\nmc3b_port = \"/nonexistent/ttyMC3B\"\n";
    CHECK(write(fd, bad, strlen(bad)) == (ssize_t)strlen(bad));
    close(fd);

    set_params();

    // 1. The virtual card: where it puts the axes after each step.
    std::vector<Pulses> want;
    std::vector<double> vtime;   // virtual ms each step took (to 5 ms)
    unsetenv("MCCL_SIM");
    setenv("MCCL_CLOCK", "fast", 1);
    CHECK_EQ(init(), NO_ERR);
    double t_prev = 0;
    program(0, [&](int step) {
        wait_stop(0, 60, STEP_NAMES[step]);
        want.push_back(pulses(0));
        double t_ms = 0;
        CHECK_EQ(MCCL_SimGetTime(&t_ms), NO_ERR);
        vtime.push_back(t_ms - t_prev);
        t_prev = t_ms;
    });
    CHECK_EQ(MCC_CloseSystem(), NO_ERR);
    CHECK_EQ((long)want.size(), 5L);

    // 2. A port that does not open: MCC_InitSystem fails (message on stderr).
    setenv("MCCL_SIM", badfile, 1);
    CHECK_EQ(init(), INITIAL_MOTION_ERR);

    // MCC_InitSimulation never uses the hardware: the unopenable port is not touched.
    SYS_CARD_CONFIG sim_card[MAX_CARD_NUM];
    memset(sim_card, 0, sizeof sim_card);
    sim_card[0].wCardType = IMP_III_8_AXIS_PCI_CARD;
    CHECK_EQ(MCC_InitSimulation(1, sim_card, 1), NO_ERR);
    CHECK_EQ(MCC_EnableDryRun(), NO_ERR);
    CHECK_EQ(MCC_CloseSystem(), NO_ERR);

    // 3. The MC3B. Two groups on its channels 0..2 cannot share it.
    setenv("MCCL_SIM", simfile, 1);
    setenv("MCCL_CLOCK", "realtime", 1);
    CHECK_EQ(MCC_CloseAllGroups(), NO_ERR);
    CHECK_EQ(MCC_CreateGroup(0, -1, -1, -1, -1, -1, -1, -1, 0), 0);
    CHECK_EQ(MCC_CreateGroup(1, -1, -1, -1, -1, -1, -1, -1, 0), 1);
    CHECK_EQ(init(), GROUP_PARAMETER_ERR);
    set_params();
    CHECK_EQ(init(), NO_ERR);
    double total = 0;
    program(0, [&](int step) {
        g_phase = STEP_NAMES[step];
        double t = wait_stop(0, STEP_LIMIT_S, STEP_NAMES[step]);
        total += t;
        long dev[3] = {0, 0, 0};
        CHECK(emu_pos(emu, dev));
        Pulses got = pulses(0);
        const Pulses &w = want[step];
        printf("%-30s virtual card %5.2f s %5ld %5ld %5ld | MC3B %5.2f s %5ld %5ld %5ld, reported %5ld %5ld %5ld\n",
               STEP_NAMES[step], vtime[step] / 1000.0, w.p[0], w.p[1], w.p[2], t, dev[0], dev[1],
               dev[2], got.p[0], got.p[1], got.p[2]);
        for (int i = 0; i < 3; i++) {
            CHECK_EQ(dev[i], w.p[i]);      // the device is where the virtual card put the axis
            CHECK_EQ(got.p[i], dev[i]);    // and reports the steps it confirmed
        }
        CHECK_EQ(MCC_GetErrorCode(0), 0);
        give_up_if_failed(emu, STEP_NAMES[step]);
    });
    printf("the program took %.2f s on the MC3B\n", total);
    double x, y, z, u, v, w, a, b;
    CHECK_EQ(MCC_GetCurPos(&x, &y, &z, &u, &v, &w, &a, &b, 0), NO_ERR);
    CHECK_NEAR(x, 0.0, 0.5 / K);
    CHECK_NEAR(y, 0.0, 0.5 / K);

    // What the MC3B cannot do is refused, and nothing is queued.
    CHECK_EQ(MCC_EnableBlend(0), COMMAND_NOTACCEPTED_ERR);
    CHECK_EQ(MCC_EnableDryRun(), COMMAND_NOTACCEPTED_ERR);
    CHECK_EQ(MCC_Home(0, 0, 0, 255, 255, 255, 255, 255, 0), COMMAND_NOTACCEPTED_ERR);
    // No homing was started: the go-home status still reads 1, as the vendor's library
    // reads it after init.
    CHECK_EQ(MCC_GetGoHomeStatus(), 1);
    CHECK_EQ(MCC_Line(0, 0, 0, 5, 0, 0, 0, 0, 0), PARAMETER_ERR);   // U: channel 3
    CHECK(MCC_Line(30, 0, 0, 0, 0, 0, 0, 0, 0) >= 0);
    // Once the line runs on the device (a hold with nothing running changes nothing and
    // answers NO_ERR, as the vendor's library answers): no pause mid-move.
    long dev[3];
    double line0 = now_s();
    while (emu_pos(emu, dev) && dev[0] == 0 && now_s() - line0 < 10)
        usleep(2000);
    CHECK(dev[0] > 0);
    CHECK_EQ(MCC_HoldMotion(0, 0), COMMAND_NOTACCEPTED_ERR);
    CHECK(MCC_OverrideSpeed(50, 0) == (double)COMMAND_NOTACCEPTED_ERR);
    g_phase = "refused functions, line to (30, 0)";
    wait_stop(0, STEP_LIMIT_S, "line to (30, 0)");
    CHECK(emu_pos(emu, dev));
    CHECK_EQ(dev[0], 3000);

    give_up_if_failed(emu, "refused functions, line to (30, 0)");

    // JogConti: runs until MCC_AbortMotion stops it (S); the position is then estimated.
    g_phase = "JogConti and its abort";
    CHECK(MCC_JogConti(-1, 20, 0, 0) >= 0);   // X (axis 0: the vendor's library takes no letter), 10 UU/s = 1000 steps/s
    // Abort once the jog has made 300 steps (about 0.3 s; a loaded host may start it
    // late, so the test waits for the steps rather than for a time).
    double jog0 = now_s();
    while (emu_pos(emu, dev) && dev[0] > 3000 - 300 && now_s() - jog0 < 10)
        usleep(2000);
    CHECK(dev[0] <= 3000 - 300);
    CHECK_EQ(MCC_GetMotionStatus(0), GMS_RUNNING);
    double abort0 = now_s();
    CHECK_EQ(MCC_AbortMotion(0), NO_ERR);
    wait_stop(0, 10, "the aborted jog");
    // From the abort to the group's stop: at least the S's round trip. The estimate
    // takes the S at the time it was sent; an emulator starved by a loaded host acts on
    // it later (the jog runs on at 1000 steps/s meanwhile), so beyond 50 ms the bound
    // grows by those steps.
    double abort_s = now_s() - abort0;
    CHECK(emu_pos(emu, dev));
    Pulses est = pulses(0);
    long err = est.p[0] - dev[0];
    printf("JogConti stopped after %.2f s (abort took %.3f s): MC3B at %ld steps, estimate "
           "%ld (error %ld steps)\n",
           now_s() - jog0, abort_s, dev[0], est.p[0], err);
    long stopped_at = dev[0];
    usleep(100000);
    CHECK(emu_pos(emu, dev));
    CHECK_EQ(dev[0], stopped_at);                   // the abort stopped the motor
    double late_s = abort_s > 0.05 ? abort_s - 0.05 : 0.0;
    CHECK(labs(err) <= 25 + (long)(1000.0 * late_s));
    CHECK_EQ(MCC_GetErrorCode(0), 0);
    give_up_if_failed(emu, "JogConti and its abort");

    // Go home, mode 9, down at 10 UU/s (1000 steps/s), dfOffset 1 UU.
    g_phase = "go home";
    SYS_HOME_CONFIG h;
    memset(&h, 0, sizeof h);
    h.wMode = 9;
    h.wDirection = 1;
    h.dfHighSpeed = 10;
    h.dfLowSpeed = 2;
    h.dfAccTime = 20;
    h.dfDecTime = 20;
    h.dfOffset = 1;
    CHECK_EQ(MCC_SetHomeConfig(&h, 0, 0), NO_ERR);
    CHECK(emu_pos(emu, dev));
    long from = dev[0];
    CHECK_EQ(MCC_Home(0, 255, 255, 255, 255, 255, 255, 255, 0), NO_ERR);
    CHECK_EQ(MCC_GetGoHomeStatus(), 0);
    CHECK_EQ(MCC_Home(0, 255, 255, 255, 255, 255, 255, 255, 0), COMMAND_NOTFINISHED_ERR);
    CHECK_EQ(MCC_Line(1, 0, 0, 0, 0, 0, 0, 0, 0), COMMAND_NOTACCEPTED_ERR);
    // Waits (at most 5 s) until X's step counter passes `edge` downwards (down) or upwards.
    auto wait_x = [&](long edge, bool down, const char *what) {
        double t0 = now_s();
        long d[3] = {0, 0, 0};
        while (emu_pos(emu, d) && (down ? d[0] > edge : d[0] < edge) && now_s() - t0 < 5)
            usleep(2000);
        if (down ? d[0] > edge : d[0] < edge) {
            fprintf(stderr, "mc3b_backend: %s: X at %ld, not past %ld\n", what, d[0], edge);
            CHECK(!"X moved as the homing should");
        }
        return d[0];
    };
    wait_x(from - 300, true, "seeking the - limit");
    CHECK(ctl(emu, "home 0 1 1").rfind("ok", 0) == 0);          // the switch closes: X stops, backs off
    long stop = wait_x(from - 300, true, "stopped");
    wait_x(stop + 2, false, "backing off at 10 steps/s");
    CHECK(ctl(emu, "home 0 1 0").rfind("ok", 0) == 0);          // off the switch: it approaches again
    long back = wait_x(stop + 2, false, "turned");
    wait_x(back - 1, true, "approaching at 10 steps/s");
    CHECK(ctl(emu, "home 0 1 1").rfind("ok", 0) == 0);          // on the switch: the machine home
    CHECK(emu_pos(emu, dev));
    long edge = dev[0];
    double t0 = now_s();
    while (MCC_GetGoHomeStatus() == 0 && now_s() - t0 < 5)
        MCC_TimeDelay(5);
    CHECK_EQ(MCC_GetGoHomeStatus(), 1);
    CHECK(emu_pos(emu, dev));
    printf("go home on the MC3B: switch found at %ld steps, working home at %ld\n", edge, dev[0]);
    CHECK(labs(dev[0] - (edge + 100)) <= 1);        // phase 3: dfOffset = 100 steps up
    CHECK_EQ(MCC_GetCurPos(&x, &y, &z, &u, &v, &w, &a, &b, 0), NO_ERR);
    CHECK_EQ(x, 0.0);
    CHECK_EQ(pulses(0).p[0], 0L);
    long home = dev[0];
    CHECK(MCC_Line(2, 0, 0, 0, 0, 0, 0, 0, 0) >= 0);
    wait_stop(0, 10, "the move from the working home");
    CHECK(emu_pos(emu, dev));
    CHECK_EQ(dev[0], home + 200);
    CHECK_EQ(MCC_GetErrorCode(0), 0);
    // Modes that need a home sensor or the index: not on an MC3B.
    h.wMode = 3;
    CHECK_EQ(MCC_SetHomeConfig(&h, 0, 0), NO_ERR);
    CHECK_EQ(MCC_Home(0, 255, 255, 255, 255, 255, 255, 255, 0), COMMAND_NOTACCEPTED_ERR);

    give_up_if_failed(emu, "go home");

    // The emulator goes away: the next move fails and the group records 0xF901.
    g_phase = "the emulator quits";
    CHECK(ctl(emu, "quit") == "ok");
    reap(emu);
    CHECK(MCC_Line(0, 0, 0, 0, 0, 0, 0, 0, 0) >= 0);
    double t = wait_stop(0, 10, "the move to a dead MC3B");
    printf("dead MC3B: group stopped after %.2f s with error 0x%X\n", t, MCC_GetErrorCode(0));
    CHECK_EQ(MCC_GetErrorCode(0), ERR_MC3B_LINK);
    CHECK_EQ(MCC_CloseSystem(), NO_ERR);

    unlink(simfile);
    unlink(badfile);
    return check_done("mc3b_backend");
}
