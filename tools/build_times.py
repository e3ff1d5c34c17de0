#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Compile seconds per folder and the slowest units, from a build's .ninja_log (issue 26).

Usage: tools/build_times.py [BUILD_DIR] [--top N]
Reads BUILD_DIR/.ninja_log (default build/), keeps the newest entry of each output that the build
still makes (`ninja -t targets all`), and prints: the seconds per target folder (a library's
objects, a test program's, precompiled headers and links each on their own line), the total, and
the N slowest steps. The times are wall seconds of each step as ninja measured them: on a build
with ccache they are the times of the cache lookups for the units it found, so measure a build
with CCACHE_DISABLE=1 (or a cold cache) to see the compiler's time.
"""
import argparse
import collections
import os
import re
import subprocess
import sys


def read_log(path):
    newest = {}  # output -> (start_ms, end_ms, mtime); the log appends, so the last line wins
    with open(path) as log:
        header = log.readline()
        if not header.startswith("# ninja log v"):
            sys.exit(f"{path}: not a ninja log (first line {header.strip()!r})")
        for line in log:
            fields = line.rstrip("\n").split("\t")
            if len(fields) != 5:
                continue
            start_ms, end_ms, mtime, output = int(fields[0]), int(fields[1]), int(fields[2]), fields[3]
            newest[output] = (start_ms, end_ms, mtime)
    return newest


def current_outputs(build_dir):
    text = subprocess.run(["ninja", "-C", build_dir, "-t", "targets", "all"], check=True,
                          capture_output=True, text=True).stdout
    return {line.split(":")[0] for line in text.splitlines() if ":" in line}


def group_of(output):
    """The folder a step belongs to: 'ncpost_postproc objects', 'test_postproc pch', 'link', ..."""
    m = re.search(r"CMakeFiles/([^/]+)\.dir/", output)
    if not m:
        return "link and other steps"
    target = m.group(1)
    if output.endswith((".gch", ".pch")):
        return f"{target} (precompiled header)"
    return target


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("build_dir", nargs="?", default="build")
    parser.add_argument("--top", type=int, default=20)
    args = parser.parse_args()
    entries = read_log(os.path.join(args.build_dir, ".ninja_log"))
    alive = current_outputs(args.build_dir)
    steps = [(out, (end - start) / 1000.0) for out, (start, end, _) in entries.items() if out in alive]
    per_group = collections.Counter()
    count = collections.Counter()
    for out, seconds in steps:
        per_group[group_of(out)] += seconds
        count[group_of(out)] += 1
    total = sum(per_group.values())
    print(f"{'seconds':>9} {'steps':>5}  target")
    for group, seconds in per_group.most_common():
        print(f"{seconds:9.1f} {count[group]:5d}  {group}")
    print(f"{total:9.1f} {len(steps):5d}  total ({total / 60:.1f} min of compiler and linker time)")
    print(f"\nthe {args.top} slowest steps:")
    for out, seconds in sorted(steps, key=lambda s: -s[1])[:args.top]:
        print(f"{seconds:9.1f}  {out}")


if __name__ == "__main__":
    main()
