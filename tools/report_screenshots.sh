#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# The README's report screenshots (docs/images/): identify.html (ballbar section), the laser
# report (ISO 230-2 plots) and post_report.html (the 3D path view), made from the public-clean
# scenario and the VMCL600 laser sample with headless Chromium.
# Usage: tools/report_screenshots.sh [BUILD_DIR]   (default build)
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
ncpost="$root/${1:-build}/ncpost"
out="$root/docs/images"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
S="$root/tests/data/scenarios/public-clean"
L="$root/samples/measurements/vmcl600/data"
cd "$tmp"
"$ncpost" identify --machine "$S/machine.toml" -o model.json --report identify.html --pass-tolerance-um 5 \
  "$S/ballbar_h250.csv" "$S/ballbar_h300.csv" "$S/sphere.csv" > /dev/null
"$ncpost" post --machine "$S/machine.toml" --workpiece-origin 0,0,80 --model model.json --tolerance 0.002 \
  --verify-on "$S/truth.json" --report post_report.html -o dome.nc "$S/path.cls" > /dev/null 2>&1
"$ncpost" identify --machine "$root/machines/vmcl600.toml" -o laser.json --report laser.html --pass-tolerance-um 10 \
  "$L/X1_pos.csv" "$L/X2_pos.csv" "$L/X3_pos.csv" "$L/X1_strY.csv" "$L/X1_strZ.csv" > /dev/null
shot() {  # page, width, height, first row, last row, png
  chromium --headless --no-sandbox --disable-gpu --no-first-run --disable-background-networking --hide-scrollbars \
    --virtual-time-budget=5000 --window-size="$2,$3" --screenshot="$tmp/full.png" "file://$tmp/$1" > /dev/null 2>&1
  python3 "$root/tools/png_crop.py" "$tmp/full.png" "$out/$6" "$4" "$5"
}
# rows of the sections (the pages' layout at these widths)
shot identify.html 1000 3600 1545 2300 report_identify.png
shot post_report.html 1240 1700 590 1640 report_post.png
shot laser.html 1240 1400 330 845 report_laser.png
ls -l "$out"
