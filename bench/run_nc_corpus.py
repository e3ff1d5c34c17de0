#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Post every Heidenhain / Sinumerik program under a folder and count the outcomes by reason.

    bench/run_nc_corpus.py DIR [--machine machines/head-table-bc.toml] [--dialect heidenhain]
                           [--origin 0,0,-400] [--tool-length 100] [--tool-table FILE] [--show N]

For the corpora that may not be committed (their repositories state no licence: SOURCES.md): the
outcome of each file is exit 0 (posted), 2 (refused: the message's reason, with numbers, names
and quoted text blanked so that the same reason counts once) or 3 (beyond the machine), printed
as a table, most frequent reason first. Runs one ncpost at a time (a shared 2-core machine).
"""
import argparse
import collections
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def reason(message):
    """The reason of a refusal with the file, line, numbers and quoted names blanked."""
    first = message.strip().splitlines()[0] if message.strip() else "(no message)"
    first = re.sub(r"^.*?:\d+(:\d+)?: ", "", first)            # file:line:col:
    first = re.sub(r"^(error|ncpost): ", "", first)
    first = re.sub(r'"[^"]*"', '"…"', first)
    first = re.sub(r"'[^']*'", "'…'", first)
    first = re.sub(r"[-+]?\d+(\.\d+)?", "#", first)
    return first[:150]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("dir")
    ap.add_argument("--machine", default=os.path.join(ROOT, "machines", "head-table-bc.toml"))
    ap.add_argument("--dialect", default="heidenhain")
    ap.add_argument("--origin", default="0,0,-400")
    ap.add_argument("--tool-length", default="100")
    ap.add_argument("--tool-table")
    ap.add_argument("--ncpost", default=os.path.join(ROOT, "build", "ncpost"))
    ap.add_argument("--show", type=int, default=1, help="files shown per reason")
    ap.add_argument("--extra", default="", help="further options, blank-separated")
    a = ap.parse_args()
    files = sorted(os.path.join(dp, f) for dp, _, fs in os.walk(a.dir) for f in fs)
    outcomes = collections.Counter()
    examples = collections.defaultdict(list)
    out = os.path.join(tempfile.mkdtemp(prefix="nc-corpus-"), "out.nc")
    for f in files:
        cmd = [a.ncpost, "post", "--machine", a.machine, "--dialect", a.dialect, "--workpiece-origin", a.origin,
               "--tool-length", a.tool_length, "-o", out, f] + a.extra.split()
        if a.tool_table:
            cmd += ["--tool-table", a.tool_table]
        p = subprocess.run(cmd, capture_output=True, text=True, errors="replace")
        key = ("posted", "") if p.returncode == 0 else (f"exit {p.returncode}", reason(p.stderr))
        outcomes[key] += 1
        if len(examples[key]) < a.show:
            examples[key].append((f, p.stderr.strip().splitlines()[0] if p.stderr.strip() else ""))
    print(f"{len(files)} files, {a.machine}, dialect {a.dialect}")
    for (kind, why), n in outcomes.most_common():
        print(f"{n:5d}  {kind:8s} {why}")
        for f, m in examples[(kind, why)]:
            print(f"         e.g. {os.path.basename(f)}: {m[:200]}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
