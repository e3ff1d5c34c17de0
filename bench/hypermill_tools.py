#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""A tool table (docs/formats.md "Tool tables") from the tool comments hyperMILL writes before each
TOOL CALL in its Heidenhain programs, for counting a local corpus with bench/run_nc_corpus.py:

    * - TOOL: T1755863337 | GUH-5640-AF8_H63H16L95 / DM=8 CR=0 TL=357
    TOOL CALL "AF08000002620277" Z S50 DL+0 DR+0

gives "AF08000002620277" = { number = n, diameter = 8.0 } (n: the tools numbered in the order met).

    bench/hypermill_tools.py DIR > tools.toml
"""
import os
import re
import sys

DM = re.compile(r"^\s*\d*\s*\*.*\bDM=([0-9.]+)")
CALL = re.compile(r'^\s*\d*\s*TOOL CALL\s+"([^"]+)"')


def main():
    diameters = {}
    for dp, _, fs in os.walk(sys.argv[1]):
        for f in sorted(fs):
            last = None
            with open(os.path.join(dp, f), errors="replace") as text:
                for line in text:
                    if m := DM.match(line):
                        last = float(m.group(1))
                    elif (m := CALL.match(line)) and last is not None:
                        diameters.setdefault(m.group(1), last)
                        last = None
    print("[tools]")
    for n, (name, d) in enumerate(sorted(diameters.items()), start=1):
        print(f'"{name}" = {{ number = {n}, diameter = {d:g} }}')


if __name__ == "__main__":
    main()
