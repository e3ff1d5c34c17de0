#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Recount what the real files of tests/data/real/ contain, independently of ncpost's code.

A check run by the tests (ctest: data/corpus_counts): it cross-checks the hand-written manifest
tests/data/real/expected.json. For every file named there it reads the file itself and prints
(or, with --check, compares against the manifest) the counts defined in SOURCES.md:

  tools    the tool changes in order (APT LOAD/TOOL,n or LOADTL/n; G-code T<n> with M6),
           a change to the tool already loaded collapsed;
  motions  APT: GOTO records that are neither a cycle's hole positions nor the end point of a
           CIRCLE; G-code: G0/G1 blocks with an axis word (X Y Z A B C);
  cycles   per kind, the hole positions (APT: GOTOs between CYCLE/<kind> and CYCLE/OFF;
           G-code: blocks with an axis word while a G73/G81..G89 cycle is modal);
  arcs     APT: CIRCLE records (+ the GOTO after each), cw/ccw seen from +Z of the program
           frame, the APT convention being counter-clockwise about the CIRCLE axis (i,j,k);
           G-code: G2 (cw) / G3 (ccw) blocks in G17;
  cutcom   CUTCOM/LEFT|RIGHT records, G41/G42 words;
  units, extents of the tip (W), and the tool axes (3-axis, 3+2, 5-axis simultaneous).

Usage: tools/corpus_counts.py [--check] [FILE...]   (default: every file of expected.json)
"""
import json
import math
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
REAL = os.path.join(ROOT, "tests", "data", "real")

APT_CYCLE_CONTROL = {"OFF", "INIT", "CLEAR", "ON"}


def collapse(tools):
    out = []
    for t in tools:
        if not out or out[-1] != t:
            out.append(t)
    return out


def numbers(text):
    return [float(v) for v in re.findall(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?", text)]


def apt_statements(path):
    """(line number, statement) with $ continuations joined and $$ comments dropped."""
    with open(path, "rb") as f:
        lines = f.read().decode("latin-1").replace("\r", "").split("\n")
    buf, start = "", 0
    for no, raw in enumerate(lines, 1):
        line = raw.split("$$")[0].rstrip()
        if not buf:
            start = no
        if line.endswith("$"):
            buf += line[:-1]
            continue
        buf += line
        if buf.strip():
            yield start, buf.strip()
        buf = ""


def count_apt(path):
    r = {"kind": "apt", "units": None, "tools": [], "motions": 0, "rapids": 0, "repeats": 0, "cycles": {}, "cycle_first": {},
         "arcs": {"cw": 0, "ccw": 0, "other_plane": 0}, "arc_tangent_check": {"agree": 0, "disagree": 0},
         "cutcom": {"left": 0, "right": 0, "off": 0}, "axes": set(), "simultaneous": False, "fini": False,
         "lo": [math.inf] * 3, "hi": [-math.inf] * 3}
    cycle = None
    circle = None
    rapid = False
    last = None  # (tip, axis)
    prev_tip = prev2 = None
    for no, st in apt_statements(path):
        major, _, rest = st.partition("/")
        major = major.strip().upper()
        words = [w.strip().upper() for w in rest.split(",")]
        if major in ("UNITS", "UNIT"):
            r["units"] = "inch" if words[0].startswith("IN") else "mm"
        elif major == "LOAD" and words and words[0] == "TOOL":
            r["tools"].append(int(float(words[1])))
        elif major == "LOADTL":
            r["tools"].append(int(float(words[0])))
        elif major == "CUTCOM":
            k = words[0].lower()
            if k in r["cutcom"]:
                r["cutcom"][k] += 1
        elif major == "CYCLE":
            kind = words[0]
            if kind == "OFF":
                cycle = None
            elif kind not in APT_CYCLE_CONTROL:
                cycle = kind.lower()
                r["cycles"].setdefault(cycle, 0)
                params = {}
                for i, w in enumerate(words[1:-1], 1):
                    if re.fullmatch(r"[-+]?(\d+\.?\d*|\.\d+)", words[i + 1] or "x"):
                        params[w] = float(words[i + 1])
                r["_params"] = params
        elif major == "CIRCLE":
            circle = numbers(rest)
        elif major in ("RAPID",):
            rapid = True
        elif major == "FINI":
            r["fini"] = True
        elif major in ("GOTO", "FROM"):
            v = numbers(rest)
            tip = v[0:3]
            axis = tuple(round(x, 6) for x in v[3:6]) if len(v) >= 6 else (last[1] if last else (0.0, 0.0, 1.0))
            if major == "FROM":
                last = (tip, axis)
                continue
            for i in range(3):
                r["lo"][i] = min(r["lo"][i], tip[i])
                r["hi"][i] = max(r["hi"][i], tip[i])
            r["axes"].add(axis)
            if last and not rapid and axis != last[1] and cycle is None:
                r["simultaneous"] = True
            if cycle is not None:
                r["cycles"][cycle] += 1
                if cycle not in r["cycle_first"]:
                    p = r["_params"]
                    first = {"line": no, "x": tip[0], "y": tip[1], "z": tip[2]}
                    if "FEDTO" in p:
                        first["z_bottom"] = round(tip[2] - p["FEDTO"], 6)
                    if "RAPTO" in p:
                        first["r_plane"] = round(tip[2] + p["RAPTO"], 6)
                    if "RTRCTO" in p:
                        first["retract"] = round(tip[2] + p["RTRCTO"], 6)
                    r["cycle_first"][cycle] = first
            elif circle is not None:
                c, k = circle[0:3], circle[3:6]
                along = sum(a * b for a, b in zip(k, axis))  # circle axis . tool axis
                if abs(abs(along) - 1.0) > 1e-6:
                    r["arcs"]["other_plane"] += 1  # not normal to the tool axis
                else:
                    ccw = along > 0  # seen from the spindle, as the tool sees the plane
                    if abs(abs(k[2]) - 1.0) > 1e-6:
                        r["arcs"]["tilted"] = r["arcs"].get("tilted", 0) + 1
                    r["arcs"]["ccw" if ccw else "cw"] += 1
                    # the move into the arc, where it is tangent, must agree with that direction
                    if prev_tip is not None and abs(abs(k[2]) - 1.0) <= 1e-6:
                        s = prev_tip
                        d = (s[0] - (prev2[0] if prev2 else s[0]), s[1] - (prev2[1] if prev2 else s[1]))
                        rad = (s[0] - c[0], s[1] - c[1])
                        tangent_ccw = (-rad[1] * k[2], rad[0] * k[2])  # ccw about the CIRCLE axis
                        n = math.hypot(*d) * math.hypot(*rad)
                        if n > 1e-9:
                            cosang = (d[0] * tangent_ccw[0] + d[1] * tangent_ccw[1]) / n
                            if abs(cosang) > 0.99:
                                agree = cosang > 0  # the file moves ccw about its CIRCLE axis
                                r["arc_tangent_check"]["agree" if agree else "disagree"] += 1
                circle = None
            else:
                r["motions"] += 1
                if rapid:
                    r["rapids"] += 1
                if last and tip == last[0] and axis == last[1]:
                    r["repeats"] += 1
            prev2 = prev_tip
            prev_tip = tip
            if cycle is not None and last is not None:
                # after a hole the tool stands above it on the retract plane: GOTO + RTRCTO along the
                # tool axis, else the level it came from (G98)
                p = r["_params"]
                up = p["RTRCTO"] if "RTRCTO" in p else sum((a - b) * k for a, b, k in zip(last[0], tip, axis))
                last = ([t + up * k for t, k in zip(tip, axis)], axis)
            else:
                last = (tip, axis)
            rapid = False
    r.pop("_params", None)
    return r


GWORD = re.compile(r"([A-Z])\s*([-+]?(?:\d+\.?\d*|\.\d+))")


def count_gcode(path):
    r = {"kind": "gcode", "units": None, "tools": [], "motions": 0, "rapids": 0, "repeats": 0, "cycles": {}, "cycle_first": {},
         "arcs": {"cw": 0, "ccw": 0, "other_plane": 0}, "cutcom": {"left": 0, "right": 0, "off": 0},
         "axes": set(), "simultaneous": False, "fini": False, "unsupported": [],
         "lo": [math.inf] * 3, "hi": [-math.inf] * 3}
    mode, plane, pending_t = None, 17, None
    pos = [None, None, None]
    held = False  # the rapids so far started before every axis was programmed
    with open(path, "rb") as f:
        text = f.read().decode("latin-1").replace("\r", "")
    for no, raw in enumerate(text.split("\n"), 1):
        line = re.sub(r"\([^)]*\)", "", raw).split(";")[0].upper()
        if "#" in line or re.match(r"\s*O", line):
            if line.strip():
                r["unsupported"].append((no, "parameters/subroutines"))
            continue
        words = GWORD.findall(line)
        # G80 first: beside G0/G1/G2/G3 in one block (Fanuc's safe-start line) it cancels the
        # cycle and the motion code sets the mode (Fanuc group 09)
        gs = sorted((float(v) for k, v in words if k == "G"), key=lambda g: g != 80.0)
        ms = [float(v) for k, v in words if k == "M"]
        vals = {k: float(v) for k, v in words if k not in "GM"}
        for g in gs:
            if g in (20.0, 21.0):
                r["units"] = "inch" if g == 20 else "mm"
            elif g in (0, 1, 2, 3) or g == 73 or 81 <= g <= 89:
                mode = g
            elif g == 80:
                mode = None
            elif g in (17, 18, 19):
                plane = int(g)
            elif g == 41:
                r["cutcom"]["left"] += 1
            elif g == 42:
                r["cutcom"]["right"] += 1
            elif g == 40:
                r["cutcom"]["off"] += 1
            elif g == 10:
                r["unsupported"].append((no, "G10"))
        if "T" in vals:
            pending_t = int(vals["T"])
        if 6.0 in ms and pending_t is not None:
            r["tools"].append(pending_t)
        if 30.0 in ms or 2.0 in ms:
            r["fini"] = True
        has_axis = any(k in vals for k in "XYZABC")
        has_ijk = any(k in vals for k in "IJKR")
        if mode is None or not (has_axis or (mode in (2, 3) and has_ijk)):
            continue
        before = list(pos)
        for i, k in enumerate("XYZ"):
            if k in vals:
                pos[i] = vals[k]
        if mode in (0, 1) and before == pos:
            r["repeats"] += 1
        elif mode == 0 and held and all(before[i] is None for i, k in enumerate("XYZ") if k in vals):
            # rapids before every axis is programmed take the axes' first values (the program starts
            # where it first says): a rapid that only programs axes unknown so far coincides with the
            # one before it
            r["repeats"] += 1
        held = mode == 0 and (held or r["motions"] == 0) and None in pos
        if None not in pos:
            for i in range(3):
                r["lo"][i] = min(r["lo"][i], pos[i])
                r["hi"][i] = max(r["hi"][i], pos[i])
        if mode in (0, 1):
            r["motions"] += 1
            r["rapids"] += mode == 0
        elif mode in (2, 3):
            key = ("cw" if mode == 2 else "ccw") if plane == 17 else "other_plane"
            r["arcs"][key] += 1
        else:
            kind = "G%d" % mode
            r["cycles"][kind] = r["cycles"].get(kind, 0) + 1
    r["axes"].add((0.0, 0.0, 1.0))
    return r


def count(path):
    with open(path, "rb") as f:
        head = f.read(4096).decode("latin-1").upper()
    if re.search(r"^\s*(GOTO|UNITS?|PARTNO|LOAD|MULTAX|TOOL PATH)\s*/", head, re.M):
        return count_apt(path)
    return count_gcode(path)


def summary(r):
    axes = sorted(r["axes"])
    tilted = [a for a in axes if a != (0.0, 0.0, 1.0)]
    return {
        "kind": r["kind"], "units": r["units"], "tools": collapse(r["tools"]), "motions": r["motions"],
        "rapids": r["rapids"], "repeats": r["repeats"], "cycles": r["cycles"], "cycle_first": r["cycle_first"], "arcs": r["arcs"],
        "cutcom": r["cutcom"], "axis_kind": "5axis" if r["simultaneous"] else ("3+2" if tilted else "3axis"),
        "tool_axes": [list(a) for a in axes], "terminated": r["fini"],
        "extent_lo": [round(v, 3) for v in r["lo"]], "extent_hi": [round(v, 3) for v in r["hi"]],
        "arc_tangent_check": r.get("arc_tangent_check"), "unsupported": r.get("unsupported", [])[:5],
    }


def main(argv):
    check = "--check" in argv
    files = [a for a in argv if not a.startswith("--")]
    mpath = os.path.join(REAL, "expected.json")
    entries = {e["file"]: e for e in json.load(open(mpath))["files"]} if os.path.exists(mpath) else {}
    if not files:
        files = list(entries)
    bad = 0
    for name in files:
        e = entries.get(os.path.basename(name), {})
        if check and str(e.get("counted", "")).startswith("by hand"):
            print("HAND " + name + " (" + e["counted"] + ")")  # not compared: not counted (2 MB files among them)
            continue
        s = summary(count(os.path.join(REAL, os.path.basename(name))))
        if not check:
            print(os.path.basename(name), json.dumps(s))
            continue
        got = {"units": s["units"], "tools": s["tools"], "motions": s["motions"], "repeats": s["repeats"],
               "cycles": sorted([k.lower(), v] for k, v in s["cycles"].items()),
               "arcs": [s["arcs"]["cw"], s["arcs"]["ccw"]], "axis_kind": s["axis_kind"]}
        want = {"units": e["units"], "tools": e["tools"], "motions": e["motions"]["count"], "repeats": e["motions"]["repeats"],
                "cycles": sorted([c["kind"].lower(), c["count"]] for c in e["cycles"]),
                "arcs": [e["arcs"]["cw"], e["arcs"]["ccw"]], "axis_kind": e["axis_kind"]}
        diff = {k: (want[k], got[k]) for k in want if want[k] != got[k]}
        print(("OK   " if not diff else "DIFF ") + name + ("" if not diff else " " + json.dumps(diff)))
        bad += bool(diff)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
