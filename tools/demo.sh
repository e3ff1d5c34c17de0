#!/usr/bin/env bash
# The main job on the bundled samples: post a five-axis CL file for the AC trunnion, re-execute
# the program through the kinematics and print the error; results in out/.
set -euo pipefail
cd "$(dirname "$0")/.."
mkdir -p out
echo "== post samples/hemisphere_5axis.cls for machines/ac-trunnion.toml (nominal machine)"
build/ncpost post --machine machines/ac-trunnion.toml --workpiece-origin 0,0,80 --verify \
  -o out/hemisphere_5axis.nc samples/hemisphere_5axis.cls
echo "== post the NX variable-axis path for the Haas UMC-750 with TCPC (RTCP)"
build/ncpost post --machine machines/haas-umc750.toml --rtcp --dialect haas --units inch \
  -o out/nx_variable_axis_umc750.nc ../shared/data/real/nx_APT_Variable_Axis.txt 2>&1 | grep -v '^notice' || true
echo "programs written to out/"
