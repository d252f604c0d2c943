"""A small WebDriver client for the browser tests: headless Chromium driven by
chromedriver (Debian's `chromium` and `chromium-driver`) over the WebDriver protocol.

Standard library only. Every call has a deadline; a failure is a message and exit
status 1, never a hang. Used by panel_browser.py and mc3b_app_browser.py.
"""
import base64
import json
import shutil
import socket
import subprocess
import time
import urllib.error
import urllib.request

CALL_S = 60            # one WebDriver call (a loaded 2-core host starts Chromium slowly)
NAME = ["browser"]     # the test's name in messages (set by the test)


def fail(msg):
    print(f"{NAME[0]}: FAIL: {msg}", flush=True)
    raise SystemExit(1)


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def need_browser():
    for exe in ("chromium", "chromedriver"):
        if not shutil.which(exe):
            fail(f"{exe} not found: install Debian's chromium and chromium-driver "
                 "(scripts/install-deps.sh does)")


def wait_for(what, fn, timeout_s, every=0.2):
    deadline = time.monotonic() + timeout_s
    last = None
    while time.monotonic() < deadline:
        last = fn()
        if last:
            return last
        time.sleep(every)
    fail(f"{what} (within {timeout_s} s; last seen {last!r})")


class Driver:
    """The WebDriver calls the tests use."""

    def __init__(self, port):
        self.base = f"http://127.0.0.1:{port}"
        self.sid = None

    def call(self, method, path, body=None):
        data = None if body is None else json.dumps(body).encode()
        req = urllib.request.Request(self.base + path, data=data, method=method,
                                     headers={"Content-Type": "application/json"})
        try:
            with urllib.request.urlopen(req, timeout=CALL_S) as r:
                return json.loads(r.read() or b"{}").get("value")
        except urllib.error.HTTPError as e:
            fail(f"WebDriver {method} {path}: {e.code} {e.read()[:400]!r}")
        except (urllib.error.URLError, OSError) as e:
            fail(f"WebDriver {method} {path}: {e}")

    def wait_ready(self, deadline):
        while time.monotonic() < deadline:
            try:
                with urllib.request.urlopen(self.base + "/status", timeout=5) as r:
                    if json.loads(r.read())["value"].get("ready"):
                        return
            except (OSError, ValueError, KeyError):
                pass
            time.sleep(0.2)
        fail("chromedriver did not become ready")

    def session(self, profile, size=(1500, 1050), extra=()):
        """Starts headless Chromium with the flags known to work on this kind of host
        (no background networking: the closed network refuses it), and `extra`."""
        args = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
                "--no-first-run", "--disable-background-networking",
                "--disable-component-update", "--disable-sync", "--disable-dev-shm-usage",
                f"--window-size={size[0]},{size[1]}", f"--user-data-dir={profile}",
                *extra]
        opts = {"args": args}
        binary = shutil.which("chromium")
        if binary:
            opts["binary"] = binary
        v = self.call("POST", "/session", {"capabilities": {"alwaysMatch": {
            "browserName": "chrome", "goog:chromeOptions": opts,
            "timeouts": {"script": 20000, "pageLoad": 60000}}}})
        self.sid = v["sessionId"]

    def s(self, path):
        return f"/session/{self.sid}{path}"

    def js(self, script, *args):
        return self.call("POST", self.s("/execute/sync"), {"script": script, "args": list(args)})

    def js_async(self, script, *args):
        return self.call("POST", self.s("/execute/async"), {"script": script, "args": list(args)})

    def element(self, css):
        el = self.call("POST", self.s("/element"), {"using": "css selector", "value": css})
        return next(iter(el.values()))

    def click(self, css):
        self.call("POST", self.s(f"/element/{self.element(css)}/click"), {})

    def screenshot(self, css=None):
        """PNG bytes of the viewport, or of the element `css`."""
        path = self.s(f"/element/{self.element(css)}/screenshot") if css else self.s("/screenshot")
        return base64.b64decode(self.call("GET", path))

    def close_window(self):
        self.call("DELETE", self.s("/window"))

    def quit(self):
        if self.sid:
            try:
                req = urllib.request.Request(self.base + self.s(""), method="DELETE")
                urllib.request.urlopen(req, timeout=20).read()
            except OSError:
                pass


def start_chromedriver(procs):
    """Starts chromedriver on a free port (appended to `procs`) and waits for it."""
    port = free_port()
    cd = subprocess.Popen(["chromedriver", f"--port={port}"], stdout=subprocess.DEVNULL,
                          stderr=subprocess.DEVNULL)
    procs.append(cd)
    drv = Driver(port)
    drv.wait_ready(time.monotonic() + 30)
    return drv, cd
