#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Checks the rotary positions ncpost writes for `L A+Q120 C+Q122` after `PLANE SPATIAL ... STAY` in
Heidenhain programs posted for machines/ac-trunnion.toml (or tests/data/machines/ac-trunnion-references.toml),
against the control's definition, computed here on its own:

- the working plane of PLANE SPATIAL SPA a SPB b SPC c is the machine frame turned about the machine-based
  X by a, then Y by b, then Z by c: its axes in the workpiece frame are the columns of Rz(c) Ry(b) Rx(a);
- on the A/C trunnion a positive command turns the table right-handed and C is carried by A
  (machines/ac-trunnion.toml, docs/conventions.md): the workpiece turns by Rx(A) Rz(C), so the tool axis
  in the workpiece frame is Rz(-C) Rx(-A) e_z, and TABLE ROT (the table turns the whole frame) needs
  Rz(-C) Rx(-A) = Rz(c) Ry(b) Rx(a);
- SEQ- asks for the solution with A <= 0, SEQ+ for A >= 0.

hyperMILL writes the positions it expects as a comment before each plane (`; A-90 C0`), for its own
machine, which turns the other way (ISO 841: tool axis Rz(C) Rx(A) e_z): their tool axis is printed too,
as a check of the definition above by a second source.

    ncpost post --machine M --input-kind klartext --dialect heidenhain ... -o PROG.h.out PROG.h
    bench/plane_stay_check.py PROG.h ...     (reads PROG.h and PROG.h.out)
"""
import math
import re
import sys

PLANE = re.compile(r"PLANE SPATIAL SPA(\S+) SPB(\S+) SPC(\S+) STAY SEQ([+-])")
CAM_COMMENT = re.compile(r"\d+ ; A(-?[\d.]+) C(-?[\d.]+)\s*$")
LINE_BLOCK = re.compile(r"\d+ L ")
ROTARY_WORD = re.compile(r" ([AC])([-+][\d.]+)")


def rotation(axis, deg):
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    if axis == "x":
        return [[1, 0, 0], [0, c, -s], [0, s, c]]
    if axis == "y":
        return [[c, 0, s], [0, 1, 0], [-s, 0, c]]
    return [[c, -s, 0], [s, c, 0], [0, 0, 1]]


def product(*ms):
    out = [[1.0 if i == j else 0.0 for j in range(3)] for i in range(3)]
    for m in ms:
        out = [[sum(out[i][k] * m[k][j] for k in range(3)) for j in range(3)] for i in range(3)]
    return out


def largest_difference(a, b):
    return max(abs(a[i][j] - b[i][j]) for i in range(3) for j in range(3))


def planes_of(program_lines):
    """(SPA, SPB, SPC, SEQ) of every PLANE SPATIAL ... STAY, in order."""
    found = []
    for line in program_lines:
        if m := PLANE.search(line):
            found.append((float(m.group(1)), float(m.group(2)), float(m.group(3)), m.group(4)))
    return found


def positions_after_comments(posted_lines):
    """For every `; A.. C..` comment the posted program kept: hyperMILL's (A, C) and the (A, C) standing
    after the next L block (modal: the writer leaves out an axis that does not move)."""
    cams, posted, current, pending = [], [], {"A": 0.0, "C": 0.0}, False
    for line in posted_lines:
        if m := CAM_COMMENT.match(line):
            cams.append((float(m.group(1)), float(m.group(2))))
            pending = True
        elif LINE_BLOCK.match(line):
            for axis, value in ROTARY_WORD.findall(line):
                current[axis] = float(value)
            if pending:
                posted.append((current["A"], current["C"]))
                pending = False
    return cams, posted


def main():
    worst, count, wrong = 0.0, 0, 0
    for program in sys.argv[1:]:
        with open(program, encoding="latin-1") as f:
            planes = planes_of(f.read().splitlines())
        with open(program + ".out", encoding="latin-1") as f:
            cams, posted = positions_after_comments(f.read().splitlines())
        if not len(planes) == len(cams) == len(posted):
            sys.exit(f"{program}: {len(planes)} planes, {len(cams)} comments, {len(posted)} positions")
        for (a, b, c, seq), (a_cam, c_cam), (a_out, c_out) in zip(planes, cams, posted):
            frame = product(rotation("z", c), rotation("y", b), rotation("x", a))
            error = largest_difference(frame, product(rotation("z", -c_out), rotation("x", -a_out)))
            cam_axis = product(rotation("z", c_cam), rotation("x", a_cam))
            cam_error = max(abs(cam_axis[i][2] - frame[i][2]) for i in range(3))
            seq_ok = a_out <= 1e-9 if seq == "-" else a_out >= -1e-9
            worst, count = max(worst, error), count + 1
            wrong += error > 1e-9 or not seq_ok
            print(f"{program}: SPA{a:g} SPB{b:g} SPC{c:g} SEQ{seq}: ncpost A{a_out:g} C{c_out:g}, frame error "
                  f"{error:.1e}, SEQ {'kept' if seq_ok else 'NOT KEPT'}; hyperMILL's A{a_cam:g} C{c_cam:g} "
                  f"(ISO sense): tool axis error {cam_error:.1e}")
    print(f"{count} planes, largest frame error {worst:.1e}, {wrong} wrong")
    return 1 if wrong else 0


if __name__ == "__main__":
    sys.exit(main())
