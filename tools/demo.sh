#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The main job on the bundled samples (results in out/):
#  1. identify the AC trunnion's geometric errors from the bundled ballbar and sphere measurements
#     (samples/measurements/ac-trunnion/, simulated from truth.json with 0.5 um noise);
#  2. post the five-axis hemisphere path with the identified model and a 2 um nonlinear-error
#     tolerance, re-execute the program on the true machine (truth.json) and print the contour
#     error before (plain post) and after; write the NC program and an HTML report.
set -euo pipefail
cd "$(dirname "$0")/.."
mkdir -p out
S=samples/measurements/ac-trunnion
echo "== identify machines/ac-trunnion.toml from $S (2 ballbar heights + sphere)"
build/ncpost identify --machine machines/ac-trunnion.toml --report out/identify.html -o out/model.json \
  $S/ballbar_h250_data.csv $S/ballbar_h300_data.csv $S/sphere_data.csv | sed -n '/residual/,$p'
echo
echo "== post samples/hemisphere_5axis.cls with the model, --tolerance 0.002, executed on the true machine"
build/ncpost post --machine machines/ac-trunnion.toml --workpiece-origin 0,0,80 \
  --model out/model.json --tolerance 0.002 --verify-on $S/truth.json --report out/post_report.html \
  -o out/hemisphere_5axis.nc samples/hemisphere_5axis.cls 2>&1
echo
echo "== post the NX variable-axis path for the Haas UMC-750 with TCPC (RTCP)"
build/ncpost post --machine machines/haas-umc750.toml --rtcp --dialect haas --units inch \
  -o out/nx_variable_axis_umc750.nc tests/data/real/nx_APT_Variable_Axis.txt 2>&1 | grep -v '^notice' || true
echo
echo "written: out/hemisphere_5axis.nc, out/post_report.html, out/model.json, out/identify.html, out/nx_variable_axis_umc750.nc"
