#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Regenerates this directory with the CLI (LASER.md): plan, simulate the truth with 0.3 µm
# noise, identify. Run from the repository root after building (build/ncpost).
set -e
N=${NCPOST:-build/ncpost}
M=machines/vmcl600.toml
D=samples/measurements/vmcl600
tmp=$(mktemp -d)
"$N" plan --machine "$M" laser -o "$tmp/laser" > /dev/null
cp "$tmp/laser.nc" "$D/laser_plan.nc"
cp "$tmp/laser_X1_pos.csv" "$D/plan_X1_pos.csv"   # one plan file as an example
mkdir -p "$D/data"
seed=1
for p in "$tmp"/laser_*.csv; do
  b=$(basename "$p" .csv)
  "$N" simulate --machine "$M" --model "$D/truth.json" --noise-um 0.3 --seed $seed -o "$D/data/${b#laser_}.csv" "$p" > /dev/null
  seed=$((seed + 1))
done
"$N" identify --machine "$M" --report "$D/report.html" -o "$D/model.json" "$D"/data/*.csv > "$D/report.txt"
rm -r "$tmp"
echo "wrote $D/model.json, report.txt, report.html"
