#!/usr/bin/env python3
"""Vendor traces: what the differential scenarios (vdiff) recorded, and the comparison of
this library's run with them. Standard library only.

    vtrace.py encode RAW STORED [--source TEXT]    raw vdiff output -> the stored form
    vtrace.py decode STORED                       the stored form -> raw (stdout)
    vtrace.py compare STORED RAW [--departures F]  exit 1 and a report when they differ
    vtrace.py replay VDIFF LIBRARY STORED [--departures F]
                                                   runs STORED's scenario against LIBRARY
                                                   on the stepped clock and compares
    vtrace.py check VDIFF TRACES                   every scenario has a trace, every
                                                   trace and departure a scenario

The raw form (what vdiff writes) has one line per record:
    # NAME                     the scenario
    A s|TICK LABEL VALUE        a call's return value, in setup (s) or at a period
    N s|TICK TEXT               what a getter wrote
    T TICK G ST ERR Q p P.. c C.. r R.. v V.. f F k RET TYPE IDX FEED ACC DEC PHASE LD POS..
                                group G at the start of period TICK: status, error record,
                                MCC_GetCmdQueueSize, pulses, positions, reference
                                positions, speeds, feed speed, MCC_GetCurCommand
    E TICK                      the run ended before period TICK
The stored form keeps every other line as it is. A T line keeps only the fields that
changed since the group's previous T line (`T 5 0 s=1 p=5,5,0`), with two shorthands:
`c=p` when every position is its pulse count divided by the axis's pulses per unit (given
once by a line `D G AXIS PULSES_PER_UNIT`), `r=c` when the reference positions are the
positions. A run of N T lines that changed nothing is written `. N` (their ticks and
groups continue the sequence: every group in turn, then the next tick). `decode` gives
the raw form back byte for byte; `encode` checks that it does.

Comparison: integers (pulses, status, error records, queue, command fields, int returns)
must be equal; doubles equal within 1e-9 relative (1e-9 absolute near 0): the freedom the
order of floating-point operations needs, far below a pulse. Speeds (the distance of a
period over the period) also within 1e-8 UU/s absolute: a difference of 1e-11 UU in a
position (the last digits of a circle's centre computed another way) over a 1 ms period.
"""
import argparse
import os
import subprocess
import sys
import tempfile

FIELDS = ("s", "e", "q", "p", "c", "r", "v", "f", "k")
VECTORS = ("p", "c", "r", "v", "f", "k")
# Doubles agree within a relative 1e-9 (the order of the libraries' operations differs).
REL = 1e-9
# Speeds (and the feed speed) agree within 1e-7 UU/s besides: a speed is a difference of
# two positions over a period, and where one library computes an axis at rest as exactly 0
# the other may find 2e-11 UU over 1 ms (an arc's first periods): a millionth of a pulse.
SPEED_ABS = 1e-7


def parse_t(line):
    """A raw T line -> (tick, group, {field: [tokens]})."""
    tok = line.split()
    rec = {"s": [tok[3]], "e": [tok[4]], "q": [tok[5]]}
    key = None
    for t in tok[6:]:
        if t in VECTORS:
            key = t
            rec[key] = []
        else:
            rec[key].append(t)
    return int(tok[1]), int(tok[2]), rec


def format_t(tick, g, rec):
    parts = ["T", str(tick), str(g), rec["s"][0], rec["e"][0], rec["q"][0]]
    for key in VECTORS:
        parts.append(key)
        parts.extend(rec[key])
    return " ".join(parts)


class Sequence:
    """The order of T lines: every group in turn (in the order they first appeared), then
    the next tick."""

    def __init__(self):
        self.groups = []
        self.last = None  # (tick, group index)

    def see(self, tick, g):
        if g not in self.groups:
            self.groups.append(g)
        self.last = (tick, self.groups.index(g))

    def next(self):
        tick, i = self.last
        if i + 1 < len(self.groups):
            self.last = (tick, i + 1)
        else:
            self.last = (tick + 1, 0)
        return self.last[0], self.groups[self.last[1]]


def g17(x):
    """A double as vdiff prints it (C's %.17g)."""
    return "%.17g" % x


def positions_from_pulses(p, c, div):
    """Whether every position is its pulse count / the axis's pulses per unit `div`."""
    for i, (pi, ci) in enumerate(zip(p, c)):
        if i not in div:
            if pi != "0" or ci != "0":
                return False
        elif g17(int(pi) / div[i]) != ci:
            return False
    return True


def learn_divisors(p, c, div, out, g):
    """Learns an axis's pulses per unit from its first nonzero pulse count, when a whole
    number gives the printed position back."""
    for i, (pi, ci) in enumerate(zip(p, c)):
        if i in div or pi == "0":
            continue
        try:
            d = round(int(pi) / float(ci))
        except (ValueError, ZeroDivisionError, OverflowError):
            continue
        if d != 0 and g17(int(pi) / d) == ci:
            div[i] = d
            out.append("D %d %d %d" % (g, i, d))


def encode(raw_lines):
    out, prev, run, divs = [], {}, 0, {}

    def end_run():
        nonlocal run
        if run:
            out.append(". %d" % run)
            run = 0

    for line in raw_lines:
        if not line.startswith("T "):
            end_run()
            out.append(line)
            continue
        tick, g, rec = parse_t(line)
        last = prev.get(g)
        div = divs.setdefault(g, {})
        parts = []
        for key in FIELDS:
            val = rec[key]
            if last is not None and last[key] == val:
                continue
            if key == "r" and val == rec["c"]:
                parts.append("r=c")
            elif key == "c" and positions_from_pulses(rec["p"], val, div):
                parts.append("c=p")
            else:
                if key == "c":
                    learned = []
                    learn_divisors(rec["p"], val, div, learned, g)
                    if learned and positions_from_pulses(rec["p"], val, div):
                        end_run()
                        out.extend(learned)
                        parts.append("c=p")
                        continue
                    end_run()
                    out.extend(learned)
                parts.append(key + "=" + ",".join(val))
        prev[g] = rec
        if parts or last is None:
            end_run()
            out.append(" ".join(["T", str(tick), str(g)] + parts))
        else:
            run += 1
    end_run()
    return out


def decode(stored_lines):
    out, state, seq, divs = [], {}, Sequence(), {}
    for line in stored_lines:
        if line.startswith("D "):
            _, g, i, d = line.split()
            divs.setdefault(int(g), {})[int(i)] = int(d)
            continue
        if line.startswith(". "):
            for _ in range(int(line.split()[1])):
                tick, g = seq.next()
                out.append(format_t(tick, g, state[g]))
            continue
        if not line.startswith("T "):
            out.append(line)
            continue
        tok = line.split()
        tick, g = int(tok[1]), int(tok[2])
        rec = dict(state.get(g, {}))
        keys = []
        for item in tok[3:]:
            key, val = item.split("=", 1)
            keys.append(key)
            rec[key] = None if val in ("c", "p") else (val.split(",") if val else [])
        if rec.get("c") is None:
            div = divs.get(g, {})
            rec["c"] = [g17(int(pi) / div[i]) if i in div else "0" for i, pi in enumerate(rec["p"])]
        if rec.get("r") is None:
            rec["r"] = list(rec["c"])
        state[g] = rec
        seq.see(tick, g)
        out.append(format_t(tick, g, rec))
    return out


# ---- comparison -------------------------------------------------------------------------


def parse_raw(lines):
    """Raw lines -> a structure to compare: setup calls, per-tick group states and calls,
    the end tick and the calls after it."""
    run = {"setup": [], "ticks": {}, "end": None, "after": []}
    for line in lines:
        if not line or line.startswith("#"):
            continue
        kind = line[0]
        if kind == "T":
            tick, g, rec = parse_t(line)
            run["ticks"].setdefault(tick, {"groups": {}, "calls": []})["groups"][g] = rec
        elif kind in "AN":
            tok = line.split(" ", 2)
            entry = (kind, tok[2])
            if tok[1] == "s":
                (run["after"] if run["end"] is not None else run["setup"]).append(entry)
            else:
                tick = int(tok[1])
                run["ticks"].setdefault(tick, {"groups": {}, "calls": []})["calls"].append(entry)
        elif kind == "E":
            run["end"] = int(line.split()[1])
    return run


def close(a, b, abs_tol=0.0):
    """Two tokens agree: equal text, or equal integers, or doubles within REL (or
    `abs_tol`)."""
    if a == b:
        return True
    try:
        x, y = float(a), float(b)
    except ValueError:
        return False
    if x == y:
        return True
    if "." not in a + b and "e" not in (a + b).lower() and "n" not in (a + b).lower():
        return False  # two different integers
    d = abs(x - y)
    return d <= REL * max(1.0, abs(x), abs(y)) or d <= abs_tol


def tokens_agree(a, b, abs_tol=0.0):
    return len(a) == len(b) and all(close(x, y, abs_tol) for x, y in zip(a, b))


FIELD_NAMES = {
    "s": "status",
    "e": "error record",
    "q": "MCC_GetCmdQueueSize",
    "p": "pulses",
    "c": "positions",
    "r": "reference positions",
    "v": "speeds",
    "f": "feed speed",
    "k": "current command",
}


class Report:
    def __init__(self):
        self.kinds = {}  # key -> [first tick, vendor, ours, count]
        self.order = []

    def add(self, key, tick, vendor, ours):
        if key not in self.kinds:
            self.kinds[key] = [tick, vendor, ours, 0]
            self.order.append(key)
        self.kinds[key][3] += 1

    def lines(self):
        out = []
        for key in self.order:
            tick, vendor, ours, count = self.kinds[key]
            where = "setup" if tick is None else "period %s" % tick
            out.append(
                "  %s: first at %s: vendor %s, this library %s (%d period(s) differ)"
                % (key, where, vendor, ours, count)
            )
        return out


def load_departures(path, scenario):
    """The documented departures of `scenario`: {"from": tick} (nothing compared from that
    period on), labels of calls whose return value is not compared, and fields of the
    per-period rows that are not compared ("field k": the current command)."""
    dep = {"from": None, "calls": set(), "fields": set()}
    if not path or not os.path.exists(path):
        return dep
    with open(path) as f:
        for line in f:
            line = line.split("#", 1)[0].strip()
            if not line:
                continue
            name, what, *rest = line.split()
            if name != scenario:
                continue
            if what == "from":
                dep["from"] = int(rest[0])
            elif what == "call":
                dep["calls"].add(rest[0])
            elif what == "field":
                dep["fields"].add(rest[0])
            else:
                sys.exit("vtrace: %s: unknown departure %r" % (path, line))
    return dep


def compare(vendor, ours, dep):
    rep = Report()
    stop = dep["from"]

    def calls(where, a, b):
        for i in range(max(len(a), len(b))):
            va = a[i] if i < len(a) else ("-", "(none)")
            ob = b[i] if i < len(b) else ("-", "(none)")
            label = (va[1] if va[0] != "-" else ob[1]).split(" ", 1)[0]
            if label in dep["calls"]:
                continue
            if va[0] != ob[0] or not tokens_agree(va[1].split(), ob[1].split()):
                rep.add("call %s #%d" % (label, i), where, repr(va[1]), repr(ob[1]))

    calls(None, vendor["setup"], ours["setup"])
    ticks = sorted(set(vendor["ticks"]) | set(ours["ticks"]))
    for tick in ticks:
        if stop is not None and tick >= stop:
            break
        a = vendor["ticks"].get(tick)
        b = ours["ticks"].get(tick)
        if a is None or b is None:
            rep.add("periods recorded", tick, "present" if a else "absent",
                    "present" if b else "absent")
            continue
        for g in sorted(set(a["groups"]) | set(b["groups"])):
            ra, rb = a["groups"].get(g), b["groups"].get(g)
            if ra is None or rb is None:
                rep.add("group %d recorded" % g, tick, ra is not None, rb is not None)
                continue
            for key in FIELDS:
                if key in dep["fields"]:
                    continue
                tol = SPEED_ABS if key in ("v", "f") else 0.0
                if not tokens_agree(ra[key], rb[key], tol):
                    rep.add("group %d %s" % (g, FIELD_NAMES[key]), tick,
                            " ".join(ra[key]), " ".join(rb[key]))
        calls(tick, a["calls"], b["calls"])
    if stop is None:
        if vendor["end"] != ours["end"]:
            rep.add("end of the run", None, vendor["end"], ours["end"])
        calls(None, vendor["after"], ours["after"])
    return rep


def read_lines(path):
    with open(path) as f:
        return f.read().splitlines()


def cmd_encode(args):
    raw = read_lines(args.raw)
    enc = encode(raw)
    if decode(enc) != raw:
        sys.exit("vtrace: encoding %s does not decode to the same lines" % args.raw)
    head = ["# vdiff trace 1"]
    if args.source:
        head.append("# recorded from " + args.source)
    with open(args.stored, "w") as f:
        f.write("\n".join(head + enc) + "\n")


def scenario_of(lines):
    for line in lines:
        if line.startswith("# ") and not line.startswith("# vdiff") and not line.startswith(
            "# recorded"
        ):
            return line[2:].strip()
    sys.exit("vtrace: no scenario name in the trace")


def run_compare(stored_path, raw_lines, departures):
    stored = decode(read_lines(stored_path))
    name = scenario_of(stored)
    dep = load_departures(departures, name)
    rep = compare(parse_raw(stored), parse_raw(raw_lines), dep)
    if rep.order:
        print("%s: differs from the vendor's trace:" % name)
        for line in rep.lines()[:40]:
            print(line)
        if len(rep.order) > 40:
            print("  ... and %d more kinds of difference" % (len(rep.order) - 40))
        return 1
    print("%s: agrees with the vendor's trace at every period" % name)
    return 0


def cmd_compare(args):
    sys.exit(run_compare(args.stored, read_lines(args.raw), args.departures))


def cmd_replay(args):
    name = scenario_of(decode(read_lines(args.stored)))
    env = dict(os.environ, MCCL_CLOCK="stepped")
    with tempfile.TemporaryDirectory() as tmp:
        raw = os.path.join(tmp, name + ".raw")
        try:
            p = subprocess.run([args.vdiff, args.library, name, raw], env=env,
                               timeout=args.timeout)
        except subprocess.TimeoutExpired:
            sys.exit("%s: vdiff did not end within %d s" % (name, args.timeout))
        if p.returncode != 0:
            sys.exit("%s: vdiff exited with %d" % (name, p.returncode))
        sys.exit(run_compare(args.stored, read_lines(raw), args.departures))


def cmd_check(args):
    """Every scenario of the runner has a trace and every trace a scenario; every
    departure names a scenario."""
    names = subprocess.run([args.vdiff, "--list"], capture_output=True, text=True,
                           check=True).stdout.split()
    traces = {f[:-len(".vtrace")] for f in os.listdir(args.traces) if f.endswith(".vtrace")}
    bad = ["no trace for scenario %s" % n for n in sorted(set(names) - traces)]
    bad += ["no scenario for trace %s" % t for t in sorted(traces - set(names))]
    dep = os.path.join(os.path.dirname(os.path.abspath(__file__)), "departures.txt")
    with open(dep) as f:
        for line in f:
            line = line.split("#", 1)[0].split()
            if line and line[0] not in traces:
                bad.append("departure for unknown scenario %s" % line[0])
    for b in bad:
        print(b)
    if bad:
        sys.exit(1)
    print("%d scenarios, each with its trace" % len(names))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    sub = ap.add_subparsers(dest="cmd", required=True)
    e = sub.add_parser("encode")
    e.add_argument("raw")
    e.add_argument("stored")
    e.add_argument("--source")
    e.set_defaults(func=cmd_encode)
    d = sub.add_parser("decode")
    d.add_argument("stored")
    d.set_defaults(func=lambda a: print("\n".join(decode(read_lines(a.stored)))))
    c = sub.add_parser("compare")
    c.add_argument("stored")
    c.add_argument("raw")
    c.add_argument("--departures")
    c.set_defaults(func=cmd_compare)
    r = sub.add_parser("replay")
    r.add_argument("vdiff")
    r.add_argument("library")
    r.add_argument("stored")
    r.add_argument("--departures")
    r.add_argument("--timeout", type=int, default=120)
    r.set_defaults(func=cmd_replay)
    k = sub.add_parser("check")
    k.add_argument("vdiff")
    k.add_argument("traces")
    k.set_defaults(func=cmd_check)
    args = ap.parse_args()
    args.func(args)


if __name__ == "__main__":
    main()
