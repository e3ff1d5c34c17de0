#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# The long runs of the residual-analysis tests, kept out of the suite (`ctest` runs the same checks
# on lighter plans): each hidden "[full]" test case — the checks of its file on the full public
# plan, the sphere every 10° of C and ballbars of 500 points — then the false-attribution sweep
# over NCPOST_SWEEP_SETS sets of each kind (default 50; tests/compensation/diagnose_open_rate_test.cpp).
# Prints each case's figures (found effects, residuals, seconds); the exit status is Catch2's.
#   bench/run_diagnose_full.sh [SETS=50]      (run from the repository root; builds in build/)
# Figures of the last run: README, "Closing the loop".
set -eu
SETS=${1:-50}
ROOT=$(cd "$(dirname "$0")/.." && pwd)
cmake -S "$ROOT" -B "$ROOT/build" -G Ninja >/dev/null
ninja -C "$ROOT/build" -j2 ncpost test_compensation >/dev/null
WORK=$(mktemp -d /tmp/ncpost-diagnose-full.XXXXXX)
trap 'rm -rf "$WORK"' EXIT INT TERM
cd "$WORK"
status=0
start=$(date +%s)
"$ROOT/build/tests/test_compensation" "[full]" --durations yes || status=1
NCPOST_SWEEP_SETS=$SETS "$ROOT/build/tests/test_compensation" "[sweep]" --durations yes || status=1
echo "total $(( $(date +%s) - start )) s"
exit $status
