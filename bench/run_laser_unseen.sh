#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# The three-axis laser loop on five unseen simulated VMCs (issue 25 item 6; bench/laser_unseen_bench.cpp,
# truths of tests/support/laser_unseen_truth.hpp, seeds 1..5, 0.4 µm noise): identification, then the
# dome and the volume path posted with the identified model and executed on the truth, before/after.
#   bench/run_laser_unseen.sh [first seed=1] [sets=5] [noise µm=0.4]   (from the repository root; builds in build/)
# One core, about a minute per set. Figures in compensation/LASER.md.
set -eu
ROOT=$(cd "$(dirname "$0")/.." && pwd)
WORK=$(mktemp -d /tmp/ncpost-laser-unseen.XXXXXX)
trap 'rm -rf "$WORK"' EXIT INT TERM
cmake -S "$ROOT" -B "$ROOT/build" -G Ninja -DNCPOST_BUILD_BENCH=ON >/dev/null
ninja -C "$ROOT/build" -j2 laser_unseen_bench >/dev/null
"$ROOT/build/bench/laser_unseen_bench" "${1:-1}" "${2:-5}" "${3:-0.4}" "$WORK"
