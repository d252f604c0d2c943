#!/usr/bin/env python3
"""The browser panel in a real browser (docs/panel.md): headless Chromium, driven over the
WebDriver protocol by chromedriver (Debian's `chromium` and `chromium-driver`), opens the
panel of a running program under the realtime clock and checks what the page shows.

    panel_browser.py PANEL_DEMO                       the CTest `panel_browser`
    panel_browser.py PANEL_DEMO --screenshot out.png  also saves the page (make docs-panel)

Checks: the positions shown change, the path is drawn (canvas pixels of the path's
colour), the emergency-stop button stops the group (status STOP, error record 0xF102 on
the page, the positions stand still, and the program itself reads 0xF102).

Standard library only. Every wait has a deadline and the whole run an alarm: a failure is
a message and exit status 1, never a hang. Chromedriver, Chromium and the program are
ended in every case.
"""
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from webdriver import NAME, fail, need_browser, start_chromedriver, wait_for  # noqa: E402

NAME[0] = "panel_browser"
TOTAL_S = 200          # the whole run (CTest's TIMEOUT is 240)


STATE_JS = """
const t = (id) => { const e = document.getElementById(id); return e ? e.textContent : null; };
const c = document.getElementById('path');
let ink = 0;
if (c) {
  const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
  for (let i = 0; i < d.length; i += 4)
    if (d[i + 3] > 0 && d[i + 2] > 180 && d[i] < 120 && d[i + 1] < 160) ink++;
}
return { x: t('g0-pos-0'), y: t('g0-pos-1'), status: t('g0-status'), error: t('g0-error'),
         clock: t('clock'), rate: t('rate'), points: c ? Number(c.dataset.points) : 0, ink };
"""


def main():
    if len(sys.argv) < 2:
        fail("usage: panel_browser.py PANEL_DEMO [--screenshot out.png]")
    demo = sys.argv[1]
    shot = sys.argv[sys.argv.index("--screenshot") + 1] if "--screenshot" in sys.argv else None
    need_browser()
    signal.signal(signal.SIGALRM, lambda *_: fail(f"the whole run took over {TOTAL_S} s"))
    signal.alarm(TOTAL_S)

    procs = []
    profile = tempfile.mkdtemp(prefix="mccl-panel-chromium-")
    drv = None
    try:
        env = dict(os.environ, MCCL_CLOCK="realtime", MCCL_PANEL="127.0.0.1:0")
        env.pop("MCCL_TRACE", None)
        prog = subprocess.Popen([demo, "120", "8000"], env=env, stdout=subprocess.PIPE,
                                stderr=subprocess.PIPE, text=True)
        procs.append(prog)
        out_lines = []
        threading.Thread(target=lambda: out_lines.extend(prog.stdout), daemon=True).start()
        url_box = []

        def read_err():
            for line in prog.stderr:
                sys.stderr.write("program: " + line)
                m = re.search(r"panel at (http://\S+)", line)
                if m:
                    url_box.append(m.group(1))
        threading.Thread(target=read_err, daemon=True).start()
        url = wait_for("the program prints the panel's URL", lambda: url_box and url_box[0], 20)
        print("panel_browser: panel at", re.sub(r"token=\w+", "token=…", url), flush=True)

        drv, _ = start_chromedriver(procs)
        drv.session(profile)
        drv.call("POST", drv.s("/url"), {"url": url})

        def number(v):
            try:
                return float(v)
            except (TypeError, ValueError):
                return None

        first = wait_for("the page shows group 0's X position",
                         lambda: (lambda s: s if number(s["x"]) is not None else None)(drv.js(STATE_JS)), 45)
        print("panel_browser: first state", first, flush=True)
        if "realtime" not in (first["clock"] or ""):
            fail(f"clock shown {first['clock']!r}, expected realtime")
        moved = wait_for("the positions shown change",
                         lambda: (lambda s: s if (s["x"], s["y"]) != (first["x"], first["y"]) else None)(drv.js(STATE_JS)), 20)
        print("panel_browser: moved to", moved["x"], moved["y"], flush=True)
        drawn = wait_for("the path is drawn (>= 10 points, >= 100 pixels of its colour)",
                         lambda: (lambda s: s if s["points"] >= 10 and s["ink"] >= 100 else None)(drv.js(STATE_JS)), 30)
        print(f"panel_browser: path drawn: {drawn['points']} points, {drawn['ink']} pixels, "
              f"{drawn['rate']} updates/s", flush=True)
        # Updates per second, counted by the page over its last second, once it has run
        # a few seconds: the panel sends 25 a second; below 10 the page is not live.
        time.sleep(3)
        rate = number(drv.js(STATE_JS)["rate"]) or 0
        print(f"panel_browser: {rate:.0f} updates/s shown after 3 s more", flush=True)
        if rate < 10:
            fail(f"only {rate} updates/s reach the page")
        if drawn["status"] != "RUNNING":
            fail(f"status before the emergency stop: {drawn['status']!r}")
        if shot:
            time.sleep(4)   # some more path for the picture
            png = drv.screenshot()
            with open(shot, "wb") as f:
                f.write(png)
            print("panel_browser: screenshot", shot, len(png), "bytes", flush=True)

        drv.click("#estop-0")
        stopped = wait_for("the group stops with 0xF102 after the emergency stop",
                           lambda: (lambda s: s if s["status"] == "STOP" and s["error"] == "0xF102" else None)(drv.js(STATE_JS)), 20)
        time.sleep(1.0)
        later = drv.js(STATE_JS)
        if (later["x"], later["y"]) != (stopped["x"], stopped["y"]):
            fail(f"still moving after the stop: {stopped['x']},{stopped['y']} -> {later['x']},{later['y']}")
        print("panel_browser: stopped at", later["x"], later["y"], "status", later["status"],
              "error", later["error"], flush=True)
        try:
            prog.wait(timeout=30)
        except subprocess.TimeoutExpired:
            fail("the program did not end after the stop")
        text = "".join(out_lines)
        if "error record 0xF102" not in text:
            fail(f"the program did not read 0xF102: {text!r}")
        if prog.returncode != 0:
            fail(f"the program exited {prog.returncode}")
        print("panel_browser: OK", flush=True)
    finally:
        signal.alarm(0)
        if drv:
            drv.quit()
        for p in reversed(procs):
            if p.poll() is None:
                p.kill()
            try:
                p.wait(timeout=10)
            except subprocess.TimeoutExpired:
                pass
        shutil.rmtree(profile, ignore_errors=True)


if __name__ == "__main__":
    main()
