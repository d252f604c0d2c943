#!/usr/bin/env python3
"""mc3b-app in a real browser (docs/mc3b.md): headless Chromium, driven over WebDriver by
chromedriver, works every control of every dialog of the MC3B application against
mc3b-emu on a pseudo-terminal, and after each reads the emulator's state through its
control channel (positions, speeds, the settings it holds, the frames it received).

    mc3b_app_browser.py BIN_DIR                      CTest mc3b_app_browser: every dialog,
                                                     bad input, and the pictures of
                                                     docs/mc3b-*.png checked for drift
    mc3b_app_browser.py BIN_DIR --screenshots DIR    the same run, writing the pictures
                                                     (make docs-mc3b)
    mc3b_app_browser.py BIN_DIR --disconnect         CTest mc3b_app_disconnect: a motor
                                                     running free stops when the page
                                                     closes and when the browser is killed

BIN_DIR holds mc3b-app and mc3b-emu. Standard library only; every wait has a deadline
and the whole run an alarm; the emulator, the application, chromedriver and Chromium are
ended in every case.
"""
import base64
import json
import math
import os
import queue
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time
import urllib.request

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from webdriver import NAME, fail, need_browser, start_chromedriver, wait_for  # noqa: E402

NAME[0] = "mc3b_app_browser"
TOTAL_S = 250          # the whole run (CTest's TIMEOUT is 300)
DOCS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "docs")
# The application's promise (docs/mc3b.md): a free-running motor stops within this
# long after its page closed or its browser died (heartbeat timeout 1 s, the board
# thread's next look within 0.1 s, one stop command).
STOP_BOUND_S = 1.5
# A picture has drifted when it has another size, or when more of its pixels than this
# differ from a fresh one (by more than 48 in a colour channel). Fields whose text depends
# on the host or the run (the page marks them data-varies: the port list, the pty's path,
# the estimated positions, the drawn path) are left out. Two runs on one host differ in
# under 0.01%; a button's label shortened ("Set parameters…" to "Parameters…") in 0.46%.
DRIFT_FRACTION = 0.002
PICTURES = ["port", "control", "params", "chain", "manual"]


def log(msg):
    print(f"{NAME[0]}: {msg}", flush=True)


class Lines:
    """The lines a process writes on a pipe, read by a thread, taken with a deadline."""

    def __init__(self, pipe, echo=None):
        self.q = queue.Queue()

        def pump():
            for line in pipe:
                if echo:
                    sys.stderr.write(echo + line)
                self.q.put(line.rstrip("\n"))
            self.q.put(None)
        threading.Thread(target=pump, daemon=True).start()

    def get(self, what, timeout_s=10):
        try:
            line = self.q.get(timeout=timeout_s)
        except queue.Empty:
            fail(f"no line from {what} within {timeout_s} s")
        if line is None:
            fail(f"{what} ended")
        return line


class Emu:
    """mc3b-emu and its control channel (mc3b-emu --help)."""

    def __init__(self, exe, procs):
        self.p = subprocess.Popen([exe], stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                  text=True, bufsize=1)
        procs.append(self.p)
        self.out = Lines(self.p.stdout)
        self.path = self.out.get("mc3b-emu's device path")
        if not self.path.startswith("/dev/"):
            fail(f"mc3b-emu printed {self.path!r}, not a device path")
        self.lock = threading.Lock()

    def ctl(self, cmd):
        with self.lock:
            self.p.stdin.write(cmd + "\n")
            self.p.stdin.flush()
            return self.out.get(f"mc3b-emu's answer to {cmd!r}")

    def pos(self):
        return [int(v) for v in self.ctl("pos").split()[1:]]

    def velocity(self):
        return [float(v) for v in self.ctl("velocity").split()[1:]]

    def running(self):
        return re.search(r"running=(\d+)", self.ctl("state")).group(1)

    def settings(self, m):
        return dict(kv.split("=", 1) for kv in self.ctl(f"settings {m}").split()[1:])

    def received(self):
        return {k: int(v) for k, v in (kv.split("=") for kv in self.ctl("received").split()[1:])}


def acting(emu):
    """Frames of every command that changes something (not the queries Q, B, P)."""
    r = emu.received()
    return {k: v for k, v in r.items() if k not in ("Q", "B", "P")}


PAGE_JS = """
const t = (id) => { const e = document.getElementById(id); return e ? e.textContent : null; };
const on = (id) => { const e = document.getElementById(id); return e ? e.dataset.on : null; };
const open = (id) => document.getElementById(id).classList.contains('open');
const cv = document.getElementById('c-canvas');
let ink = 0;
const d = cv.getContext('2d').getImageData(0, 0, cv.width, cv.height).data;
for (let i = 0; i < d.length; i += 4) if (d[i + 3] > 0 && d[i + 2] > 180 && d[i] < 80) ink++;
return {
  link: t('link'), port: t('port-name'), busy: t('busy'),
  inputs: [0, 1, 2, 3, 4, 5].map((b) => on('in-' + b)).join(''),
  running: [0, 1, 2].map((m) => on('m' + m + '-running')).join(''),
  home0: [0, 1, 2].map((m) => on('m' + m + '-home0')).join(''),
  home1: [0, 1, 2].map((m) => on('m' + m + '-home1')).join(''),
  pos: [0, 1, 2].map((m) => Number(t('m' + m + '-pos'))),
  control_msg: t('control-msg'), port_msg: t('port-msg'), p_msg: t('p-msg'), c_msg: t('c-msg'),
  man_msg: t('man-msg'),
  port_open: open('port-dialog'), params_open: open('params-dialog'),
  chain_open: open('chain-dialog'), manual_open: open('manual-dialog'),
  bad: [...document.querySelectorAll('.bad')].map((e) => e.id),
  trail: Number(cv.dataset.points), ink,
  updates: Number(document.body.dataset.updates || 0),
  events: [...document.querySelectorAll('#events div')].map((e) => e.textContent),
};
"""

TYPE_JS = """
const e = document.getElementById(arguments[0]);
e.value = arguments[1];
e.dispatchEvent(new Event('input', { bubbles: true }));
e.dispatchEvent(new Event('change', { bubbles: true }));
"""

# Compares a fresh picture with the committed one in the browser (both decoded by
# Chromium): sizes, and the number of pixels differing by more than 48 in a channel.
COMPARE_JS = """
const done = arguments[arguments.length - 1];
const skip = arguments[2];
const skipped = (x, y) => skip.some((r) => x >= r[0] && x < r[0] + r[2] && y >= r[1] && y < r[1] + r[3]);
const load = (b64) => new Promise((ok, ko) => { const i = new Image(); i.onload = () => ok(i);
  i.onerror = () => ko('not a PNG'); i.src = 'data:image/png;base64,' + b64; });
Promise.all([load(arguments[0]), load(arguments[1])]).then(([a, b]) => {
  const px = (img) => { const c = document.createElement('canvas'); c.width = img.width; c.height = img.height;
    const g = c.getContext('2d'); g.drawImage(img, 0, 0); return g.getImageData(0, 0, img.width, img.height).data; };
  if (a.width !== b.width || a.height !== b.height) { done({ size: [a.width, a.height, b.width, b.height] }); return; }
  const pa = px(a), pb = px(b);
  let diff = 0, total = 0;
  for (let i = 0; i < pa.length; i += 4) {
    const p = i / 4, x = p % a.width, y = Math.floor(p / a.width);
    if (skipped(x, y)) continue;
    total++;
    if (Math.max(Math.abs(pa[i] - pb[i]), Math.abs(pa[i + 1] - pb[i + 1]), Math.abs(pa[i + 2] - pb[i + 2])) > 48) diff++;
  }
  done({ size: [a.width, a.height, b.width, b.height], diff, total });
}, (e) => done({ error: String(e) }));
"""


class Run:
    def __init__(self, bin_dir, procs, profile):
        self.procs = procs
        self.emu = Emu(os.path.join(bin_dir, "mc3b-emu"), procs)
        log(f"mc3b-emu on {self.emu.path}")
        app = subprocess.Popen([os.path.join(bin_dir, "mc3b-app"), "--listen", "127.0.0.1:0"],
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        procs.append(app)
        self.app = app
        self.app_out = Lines(app.stdout, echo="mc3b-app: ")
        Lines(app.stderr, echo="mc3b-app (stderr): ")
        first = self.app_out.get("mc3b-app's address")
        m = re.search(r"open (http://\S+)", first)
        if not m:
            fail(f"mc3b-app printed {first!r}")
        self.url = m.group(1)
        log("page at " + re.sub(r"token=\w+", "token=…", self.url))
        self.drv, self.cd = start_chromedriver(procs)
        self.drv.session(profile, extra=["--hide-scrollbars", "--force-device-scale-factor=1"])
        self.drv.call("POST", self.drv.s("/url"), {"url": self.url})
        wait_for("the page gets the application's state",
                 lambda: self.page()["updates"] > 0 or None, 45)

    def page(self):
        return self.drv.js(PAGE_JS)

    def type(self, elem_id, value):
        self.drv.js(TYPE_JS, elem_id, value)

    def click(self, elem_id):
        self.drv.click("#" + elem_id)

    def wait_page(self, what, pred, timeout_s=15):
        return wait_for(what, lambda: (lambda s: s if pred(s) else None)(self.page()), timeout_s)

    def wait_emu(self, what, fn, timeout_s=15):
        deadline = time.monotonic() + timeout_s
        while time.monotonic() < deadline:
            r = fn()
            if r:
                return r
            time.sleep(0.05)
        s = self.page()
        msgs = {k: s[k] for k in ("control_msg", "port_msg", "p_msg", "c_msg", "man_msg") if s[k]}
        fail(f"{what} (within {timeout_s} s); emulator: {self.emu.ctl('state')}, "
             f"{self.emu.ctl('pos')}; page messages {msgs}; events {s['events'][:3]}")

    def idle(self):
        self.wait_emu("every motor idle", lambda: self.emu.running() == "000")

    def picture(self, name, css, shots):
        png = self.drv.screenshot(css)
        target = os.path.join(DOCS, f"mc3b-{name}.png")
        if shots is not None:
            out = os.path.join(shots, f"mc3b-{name}.png")
            with open(out, "wb") as f:
                f.write(png)
            log(f"picture {out}: {len(png)} bytes")
            return
        if not os.path.exists(target):
            fail(f"{target} is missing: run make docs-mc3b")
        with open(target, "rb") as f:
            old = f.read()
        # The marked fields' boxes, in the picture's pixels (device scale factor 1).
        skip = self.drv.js("""const d = document.querySelector(arguments[0]).getBoundingClientRect();
          return [...document.querySelectorAll(arguments[0] + ' [data-varies]')].map((e) => {
            const r = e.getBoundingClientRect();
            return [Math.floor(r.left - d.left), Math.floor(r.top - d.top), Math.ceil(r.width) + 1, Math.ceil(r.height) + 1];
          });""", css)
        r = self.drv.js_async(COMPARE_JS, base64.b64encode(png).decode(),
                              base64.b64encode(old).decode(), skip)
        if "error" in r:
            fail(f"comparing {target}: {r['error']}")
        w, h, ow, oh = r["size"]
        if (w, h) != (ow, oh):
            fail(f"docs/mc3b-{name}.png has drifted: the dialog is now {w}x{h}, the picture "
                 f"{ow}x{oh} (run make docs-mc3b and commit the pictures)")
        frac = r["diff"] / r["total"]
        log(f"picture {name}: {w}x{h}, {100 * frac:.2f}% of {r['total']} compared pixels "
            f"differ from docs/mc3b-{name}.png")
        if frac > DRIFT_FRACTION:
            fail(f"docs/mc3b-{name}.png has drifted: {100 * frac:.2f}% of its pixels differ "
                 f"(at most {100 * DRIFT_FRACTION:.1f}%): run make docs-mc3b and commit the "
                 "pictures")


def connect(run, shots):
    """§5.1: the dialog opens by itself; a missing port is refused on the page with
    nothing sent; the emulator's path finds the MC3B (0P, then 0I)."""
    emu = run.emu
    s = run.wait_page("the port selection dialog opens", lambda s: s["port_open"])
    run.type("port-path", emu.path)
    run.picture("port", "#port-box", shots)
    before = emu.received()
    run.type("port-path", "/dev/mc3b-no-such-port")
    run.click("port-ok")
    s = run.wait_page("a message for a missing port",
                      lambda s: "cannot open /dev/mc3b-no-such-port" in (s["port_msg"] or ""))
    if "port-path" not in s["bad"]:
        fail(f"the port field is not marked: {s['bad']}")
    if emu.received() != before:
        fail("something was sent for a missing port")
    log(f"missing port: {s['port_msg']!r}, nothing sent")
    run.type("port-path", "")
    run.click("port-ok")
    run.wait_page("a message for no port", lambda s: "none chosen" in (s["port_msg"] or ""))
    run.type("port-path", emu.path)
    run.click("port-ok")
    s = run.wait_page("connected", lambda s: s["link"] == "answering" and not s["port_open"])
    r = emu.received()
    if r["P"] < 1 or r["I"] != 1:
        fail(f"expected 0P and one 0I, the emulator got {r}")
    log(f"connected to {s['port']}: {s['control_msg']!r}")


def control(run, shots):
    """§5.2: limit inputs, debounce, move / run / stop / home per motor, synchronous move."""
    emu = run.emu
    # Limit inputs given to the emulator show on the page (bit 0 first here).
    for value, bits in ((37, "101001"), (10, "010100"), (0, "000000")):
        emu.ctl(f"inputs {value}")
        run.wait_page(f"inputs {value} shown", lambda s, b=bits: s["inputs"] == b, 5)
    log("limit inputs 37, 10, 0 shown")
    run.type("debounce", "7")
    run.click("debounce-set")
    run.wait_emu("debounce 7 on the board", lambda: emu.settings(0)["debounce"] == "7")
    # Move motor 0 by 200 steps in direction 0.
    run.type("m0-steps", "200")
    run.click("m0-dir0")
    run.click("m0-move")
    run.wait_emu("motor 0 at 200", lambda: emu.pos()[0] == 200)
    run.idle()
    run.wait_page("motor 0 at ≈200 on the page", lambda s: s["pos"][0] == 200)
    # Move motor 1 by 300 steps in direction 1.
    run.type("m1-steps", "300")
    run.click("m1-dir1")
    run.click("m1-move")
    run.wait_emu("motor 1 at -300", lambda: emu.pos()[1] == -300)
    run.idle()
    # Run motor 2 in direction 0, see it run on the page and on the emulator, stop it.
    run.click("m2-dir0")
    run.click("m2-run")
    run.wait_emu("motor 2 free-running at 1000 steps/s", lambda: emu.velocity()[2] == 1000.0)
    run.wait_page("motor 2 shown running", lambda s: s["running"][2] == "1")
    run.click("m2-stop")
    run.wait_emu("motor 2 stopped", lambda: emu.running()[2] == "0")
    run.wait_page("motor 2 shown stopped", lambda s: s["running"][2] == "0")
    p2 = emu.pos()[2]
    # The model starts and stops the motor when the app sends the command, the emulator
    # when it reads it off the pty: on an idle host the two agree to a step or two, on a
    # loaded 2-core host the pty can deliver tens of ms late (a step a ms at 1000
    # steps/s). 50 steps still tells a stopped estimate from one still running (it would
    # be off by 1000 a second).
    s = run.wait_page("motor 2's estimate where the emulator stopped",
                      lambda s: abs(s["pos"][2] - p2) <= 50)
    log(f"run/stop of motor 2: emulator {p2}, page ≈{s['pos'][2]}")
    # Home: refused without a limit switch in that direction, nothing sent.
    h = emu.received()["H"]
    run.click("m0-home")
    run.wait_page("homing without a limit refused",
                  lambda s: "no direction 0 limit" in (s["control_msg"] or ""))
    if emu.received()["H"] != h:
        fail("H sent for a motor without a limit")
    # The synchronous move of the three fields: 100 (dir 0), 200 (dir 1), 300 (dir 0).
    start = emu.pos()
    run.type("m0-steps", "100")
    run.click("m0-dir0")
    run.type("m1-steps", "200")
    run.click("m1-dir1")
    run.type("m2-steps", "300")
    run.click("m2-dir0")
    run.click("sync-move")
    run.wait_emu("all three moving together", lambda: emu.running() == "111")
    run.idle()
    end = emu.pos()
    want = [start[0] + 100, start[1] - 200, start[2] + 300]
    if end != want:
        fail(f"synchronous move ended at {end}, expected {want}")
    log(f"synchronous move {start} -> {end}")
    # Bad steps: a message, nothing sent.
    before = acting(emu)
    run.type("m1-steps", "12.5")
    run.click("m1-move")
    s = run.wait_page("bad steps refused", lambda s: "not a whole number" in (s["control_msg"] or ""))
    if "m1-steps" not in s["bad"] or acting(emu) != before:
        fail(f"bad steps: marked {s['bad']}, sent {acting(emu)} (was {before})")
    run.type("m1-steps", "1000")
    emu.ctl("inputs 37")
    run.wait_page("inputs 37 for the picture", lambda s: s["inputs"] == "101001", 5)
    run.click("m0-stop")  # a calm message for the picture
    run.wait_page("stop message", lambda s: (s["control_msg"] or "").startswith("stopped motor 0"))
    run.picture("control", "#control", shots)
    emu.ctl("inputs 0")


def params(run, shots):
    """§5.3: read back on opening, OK applies every value, Cancel discards, bad input
    (a velocity out of range, two limit boxes) is refused with nothing sent."""
    emu = run.emu
    run.click("m0-params")
    s = run.wait_page("the dialog shows the record", lambda s: s["params_open"] and s["p_msg"] == "")
    vals = run.drv.js("return ['p-vmax','p-acc','p-dec','p-hold','p-run'].map((i) => "
                      "document.getElementById(i).value).concat([document.getElementById('p-half').checked])")
    if vals != ["1000", "5000", "5000", "500", "2000", True]:
        fail(f"the dialog opened with {vals}, not the §6.1 defaults")
    # New values.
    run.type("p-vmax", "1500")
    run.type("p-acc", "8000")
    run.type("p-dec", "6000")
    run.click("p-half")              # full steps
    run.click("p-hold-on")
    run.type("p-hold", "300")
    run.type("p-run", "1200")
    run.click("p-l0-b2-hi")          # direction 0: bit 2 at +5 V
    run.click("p-l1-b4-hi")          # direction 1: bit 4 at +5 V
    run.picture("params", "#params-box", shots)
    # Bad: velocity 6000 and a second direction 0 box.
    before = acting(emu)
    run.type("p-vmax", "6000")
    run.click("p-l0-b3-lo")
    run.click("p-ok")
    s = run.wait_page("bad parameters refused",
                      lambda s: "6000 is out of range" in (s["p_msg"] or ""))
    if not {"p-vmax", "p-l0"} <= set(s["bad"]) or not s["params_open"]:
        fail(f"bad parameters: fields marked {s['bad']}, dialog open {s['params_open']}")
    if acting(emu) != before:
        fail(f"bad parameters sent something: {acting(emu)} (was {before})")
    log(f"bad parameters: {s['p_msg']!r}, nothing sent")
    run.click("p-l0-b3-lo")          # one box left
    run.type("p-vmax", "1500")
    run.click("p-ok")
    run.wait_page("the dialog closes", lambda s: not s["params_open"])
    got = emu.settings(0)
    want = {"v": "1500", "a": "8000", "d": "6000", "half": "0", "hold": "1", "ih": "300",
            "ir": "1200", "masks": "4,0,16,0"}
    if any(got[k] != v for k, v in want.items()):
        fail(f"motor 0 holds {got}, expected {want}")
    log(f"motor 0 holds {want}")
    # Cancel discards; reopening reads back what the board holds.
    run.click("m0-params")
    run.wait_page("the dialog reopens", lambda s: s["params_open"] and s["p_msg"] == "")
    v = run.drv.js("return document.getElementById('p-vmax').value")
    if v != "1500":
        fail(f"reopened with maximum velocity {v}, not 1500")
    before = acting(emu)
    run.type("p-vmax", "2000")
    run.click("p-cancel")
    run.wait_page("the dialog closes", lambda s: not s["params_open"])
    if acting(emu) != before or emu.settings(0)["v"] != "1500":
        fail("Cancel sent something")
    # Home motor 0 in direction 0 now that it has a limit (bit 2, +5 V).
    run.click("m0-dir0")
    run.click("m0-home")
    run.wait_emu("motor 0 homing", lambda: emu.running()[0] == "1")
    emu.ctl("input 2 1")
    run.wait_page("at home 0 shown", lambda s: s["home0"][0] == "1")
    emu.ctl("input 2 0")                 # the back-off leaves the switch
    time.sleep(0.2)
    emu.ctl("input 2 1")                 # the approach finds it again: home
    run.wait_emu("homing done", lambda: emu.running()[0] == "0")
    emu.ctl("input 2 0")
    run.click("m0-dir0")
    log("homing of motor 0 on input 2 done")
    # Motor 1 back to the defaults for the circle.
    run.click("m1-params")
    run.wait_page("motor 1's dialog", lambda s: s["params_open"] and s["p_msg"] == "")
    run.click("p-ok")
    run.wait_page("the dialog closes", lambda s: not s["params_open"])


def chain(run, shots):
    """§5.4: the circle, its steps sampled while it runs, drawn, back at the start."""
    emu = run.emu
    run.idle()
    run.click("open-chain")
    run.wait_page("the chained move dialog", lambda s: s["chain_open"])
    y0 = emu.received()["Y"]
    start = emu.pos()
    r, n = 300, 36
    run.type("c-radius", str(r))
    run.type("c-chords", str(n))
    run.click("c-ok")
    run.wait_emu("the circle runs", lambda: emu.running() == "111")
    # Sample the X-Y steps while it runs: every point lies between the chords'
    # midpoints and the circle (r cos(pi/n) - 2 .. r + 2 from the centre, the 2 for
    # rounding and the sample's moment). The centre is r steps in -X from the start.
    samples = []
    while emu.running() != "000":
        p = emu.pos()
        samples.append((p[0] - start[0] + r, p[1] - start[1]))
        time.sleep(0.05)
    lo, hi = r * math.cos(math.pi / n) - 2, r + 2
    bad = [s for s in samples if not lo <= math.hypot(*s) <= hi]
    if len(samples) < 5 or bad:
        fail(f"circle: {len(samples)} samples, off the circle: {bad[:5]}")
    quads = {(x > 0, y > 0) for x, y in samples}
    if len(quads) < 4:
        fail(f"circle: samples in {len(quads)} quadrants only")
    end = emu.pos()
    if end != start:
        fail(f"circle ended at {end}, started at {start}")
    if emu.received()["Y"] - y0 != n:
        fail(f"circle: {emu.received()['Y'] - y0} Y frames, expected {n}")
    if emu.settings(0)["chain"] != "0":
        fail("chained-move buffer not empty after the circle")
    s = run.wait_page("the circle drawn", lambda s: s["trail"] >= 10 and s["ink"] >= 300)
    log(f"circle r={r} in {n} chords: {len(samples)} samples within [{lo:.1f}, {hi:.1f}], "
        f"back at {end}; drawn: {s['trail']} points, {s['ink']} pixels")
    run.picture("chain", "#chain-box", shots)
    # Bad: 101 chords (a chain holds 100), nothing sent.
    before = acting(emu)
    run.type("c-chords", "101")
    run.click("c-ok")
    run.wait_page("101 chords refused", lambda s: "Chords must be 3 to 100" in (s["c_msg"] or ""))
    if acting(emu) != before:
        fail("101 chords sent something")
    run.type("c-chords", str(n))
    run.click("c-close")


def manual(run, shots):
    """§5.5: sliders change speed and direction on the fly, within the maximum velocity;
    stop all stops; closing the dialog stops."""
    emu = run.emu
    run.click("open-manual")
    run.wait_page("the manual control dialog", lambda s: s["manual_open"])
    # Motor 1 (maximum velocity 1000): +600, then -400 while running.
    run.type("s1", "600")
    run.wait_emu("motor 1 free-running at 600", lambda: emu.velocity()[1] == 600.0)
    run.type("s1", "-400")
    run.wait_emu("motor 1 reversed to -400 on the fly", lambda: emu.velocity()[1] == -400.0)
    if emu.settings(1)["modifier"] != "1":
        fail("the reversal did not use the direction modifier (§6.4)")
    # Motor 0's slider ends at its maximum velocity, 1500.
    mx = run.drv.js("return document.getElementById('s0').max")
    if mx != "1500":
        fail(f"motor 0's slider ends at {mx}, not its maximum velocity 1500")
    run.type("s0", "1500")
    run.wait_emu("motor 0 free-running at 1500", lambda: emu.velocity()[0] == 1500.0)
    # Beyond the maximum velocity (a request the slider cannot make): refused.
    r = run.drv.js_async("""const done = arguments[arguments.length - 1];
      fetch('/api/action', { method: 'POST', headers: { 'X-MC3B-Token': new URLSearchParams(location.search).get('token'),
        'Content-Type': 'application/json' }, body: JSON.stringify({ action: 'manual', motor: 1, speed: 1001 }) })
      .then((r) => r.json().then((j) => done([r.status, j.error])));""")
    if r[0] != 400 or "beyond its maximum velocity" not in r[1]:
        fail(f"speed 1001 for motor 1: {r}")
    if emu.velocity()[1] != -400.0:
        fail("a refused speed changed motor 1")
    run.picture("manual", "#manual-box", shots)
    run.click("man-stop")
    run.wait_emu("stop all stops both", lambda: emu.running() == "000")
    run.wait_page("sliders back in the middle",
                  lambda s: run.drv.js("return [0,1,2].map((m) => document.getElementById('s' + m).value)")
                  == ["0", "0", "0"])
    if emu.settings(0)["v"] != "1500" or emu.settings(1)["v"] != "1000":
        fail("the maximum velocities were not restored after manual control")
    run.type("s2", "-300")
    run.wait_emu("motor 2 free-running at -300", lambda: emu.velocity()[2] == -300.0)
    run.click("man-close")
    run.wait_emu("closing the dialog stops motor 2", lambda: emu.running() == "000")
    log("manual control: 600 -> -400 on the fly, 1500 at the limit, stop all, close stops")


def stop_all_button(run):
    emu = run.emu
    run.click("m1-dir0")
    run.click("m1-run")
    run.click("m2-run")
    run.wait_emu("two motors running", lambda: emu.running() == "011")
    run.click("stop-all")
    run.wait_emu("STOP ALL stops them", lambda: emu.running() == "000")
    log("STOP ALL stopped motors 1 and 2")


def descendants(pid):
    """Every process below `pid` (from /proc)."""
    children = {}
    for d in os.listdir("/proc"):
        if d.isdigit():
            try:
                with open(f"/proc/{d}/stat") as f:
                    ppid = int(f.read().rsplit(")", 1)[1].split()[1])
                children.setdefault(ppid, []).append(int(d))
            except (OSError, ValueError, IndexError):
                pass
    out, todo = [], [pid]
    while todo:
        for c in children.get(todo.pop(), []):
            out.append(c)
            todo.append(c)
    return out


def time_to_stop(run, how, act):
    """Runs motor 0 free from the page, does `act`, and measures until the emulator
    says it stands."""
    emu = run.emu
    if how == "the browser is killed":
        run.click("open-manual")
        run.wait_page("manual control", lambda s: s["manual_open"])
        run.type("s0", "800")
        run.wait_emu("motor 0 free-running at 800", lambda: emu.velocity()[0] == 800.0)
    else:
        run.click("m0-dir0")
        run.click("m0-run")
        run.wait_emu("motor 0 free-running", lambda: emu.velocity()[0] == 1000.0)
    time.sleep(0.5)
    t0 = time.monotonic()
    act()
    while emu.running()[0] == "1":
        if time.monotonic() - t0 > STOP_BOUND_S + 1:
            fail(f"motor 0 still runs {STOP_BOUND_S + 1} s after {how}")
        time.sleep(0.01)
    dt = time.monotonic() - t0
    # Why the application stopped it: the last stop in its event log.
    with urllib.request.urlopen(run.url.replace("/?", "/api/state?"), timeout=10) as r:
        events = json.loads(r.read())["events"]
    why = next((e["text"] for e in reversed(events) if e["text"].startswith("stopped")), "?")
    log(f"{how}: motor 0 stopped {1000 * dt:.0f} ms later (promised: within {STOP_BOUND_S} s); "
        f"the application says: {why}")
    if dt > STOP_BOUND_S:
        fail(f"{how}: motor 0 stopped only after {dt:.2f} s (more than {STOP_BOUND_S} s)")
    return dt


def disconnect(bin_dir, procs, profile):
    run = Run(bin_dir, procs, profile)
    run.type("port-path", run.emu.path)
    run.click("port-ok")
    run.wait_page("connected", lambda s: s["link"] == "answering")
    # 1. The page is closed (its window; the session's last).
    time_to_stop(run, "the page is closed", run.drv.close_window)
    # 2. A new browser; this one is killed (SIGKILL of every Chromium process).
    profile2 = profile + "-2"
    run.drv.quit()
    drv, cd = start_chromedriver(procs)
    drv.session(profile2)
    drv.call("POST", drv.s("/url"), {"url": run.url})
    run.drv = drv
    wait_for("the new page gets the state", lambda: run.page()["updates"] > 0 or None, 45)

    def kill_browser():
        for pid in descendants(cd.pid):
            try:
                os.kill(pid, signal.SIGKILL)
            except OSError:
                pass
    time_to_stop(run, "the browser is killed", kill_browser)
    run.drv.sid = None
    shutil.rmtree(profile2, ignore_errors=True)


def everything(bin_dir, procs, profile, shots):
    run = Run(bin_dir, procs, profile)
    connect(run, shots)
    control(run, shots)
    params(run, shots)
    chain(run, shots)
    manual(run, shots)
    stop_all_button(run)
    # Leaving the port: motors off (0I), the port dialog again.
    i = run.emu.received()["I"]
    run.click("change-port")
    run.wait_page("port dialog", lambda s: s["port_open"])
    run.click("port-cancel")
    s = run.page()
    if s["port_open"]:
        fail("Cancel did not close the port dialog while connected")
    if run.emu.received()["I"] != i:
        fail("opening the port dialog sent something")


def main():
    if len(sys.argv) < 2:
        fail("usage: mc3b_app_browser.py BIN_DIR [--screenshots DIR | --disconnect]")
    bin_dir = sys.argv[1]
    shots = sys.argv[sys.argv.index("--screenshots") + 1] if "--screenshots" in sys.argv else None
    need_browser()
    signal.signal(signal.SIGALRM, lambda *_: fail(f"the whole run took over {TOTAL_S} s"))
    signal.alarm(TOTAL_S)
    procs = []
    profile = tempfile.mkdtemp(prefix="mc3b-app-chromium-")
    t0 = time.monotonic()
    try:
        if "--disconnect" in sys.argv:
            NAME[0] = "mc3b_app_disconnect"
            disconnect(bin_dir, procs, profile)
        else:
            everything(bin_dir, procs, profile, shots)
        log(f"OK ({time.monotonic() - t0:.1f} s)")
    finally:
        signal.alarm(0)
        for p in reversed(procs):
            exe = str(p.args[0])
            if exe.endswith("chromedriver"):
                for pid in descendants(p.pid):
                    try:
                        os.kill(pid, signal.SIGKILL)
                    except OSError:
                        pass
            if p.poll() is None:
                # The application ends as a person would end it (motors off, 0I).
                if exe.endswith("mc3b-app"):
                    p.send_signal(signal.SIGTERM)
                else:
                    p.kill()
            try:
                p.wait(timeout=10)
            except subprocess.TimeoutExpired:
                p.kill()
                p.wait(timeout=10)
        shutil.rmtree(profile, ignore_errors=True)


if __name__ == "__main__":
    main()
