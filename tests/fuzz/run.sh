#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Builds the libFuzzer targets with clang-14 in build-fuzz/ (the readers instrumented with ASan +
# UBSan and coverage; the rest linked from the release build in build/, built first if missing:
# tests/fuzz/CMakeLists.txt) and runs each for
# SECONDS (default 60), starting from the seed corpus in tests/fuzz/corpus/ plus the real files
# of tests/data/real/ cut into 40-line pieces (small inputs keep the executions fast). Findings (crash-*, leak-*, timeout-*)
# land in build-fuzz/fuzz/findings/<target>/; the exit status is non-zero if any target fails.
#   tests/fuzz/run.sh [SECONDS]        (from the repository root)
# Environment: TARGETS (default: all five), FUZZ_FLAGS (extra libFuzzer flags, e.g.
# "-fork=1 -ignore_crashes=1" to keep going after a finding), JOBS (targets fuzzed at the same
# time, default: the number of cores; each target runs its SECONDS on one core either way, so 5
# targets on 2 cores take 3 x SECONDS instead of 5 x SECONDS).
set -eu
SECONDS_EACH=${1:-60}
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
BUILD="$ROOT/build-fuzz"
SAN="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fsanitize=fuzzer-no-link"

# -O1 with line tables only (what OSS-Fuzz builds with): about 15 % less compile time than -O2 -g,
# and the sanitizers' reports still name file and line. Only the five targets and the libraries
# they link are built (not the ncpost executable, the tests or the benchmarks).
if [ ! -f "$ROOT/build/tools/ncpost/libncpost_cli.a" ]; then
  cmake -S "$ROOT" -B "$ROOT/build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$ROOT/build" -j2 --target ncpost
fi
CC=clang-14 CXX=clang++-14 cmake -S "$ROOT" -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only -DNDEBUG" -DNCPOST_FUZZ_LIBS_FROM="$ROOT/build" \
  -DNCPOST_BUILD_FUZZ=ON -DNCPOST_BUILD_TESTS=OFF -DNCPOST_BUILD_BENCH=OFF -DNCPOST_FUZZ_SANITIZE="$SAN" >/dev/null
TARGETS=${TARGETS:-fuzz_gcode_block fuzz_gcode_reader fuzz_gcode_expression fuzz_apt_reader fuzz_post_cli}
FUZZ_FLAGS=${FUZZ_FLAGS:-}
ninja -C "$BUILD" -j2 $TARGETS

SHARED="$ROOT/tests/data/real"
JOBS=${JOBS:-$(nproc)}

# The corpus of a target: the seeds, plus the real files cut into 40-line pieces.
prepare_corpus() {
  target=$1
  case $target in
    fuzz_apt*) seeds="$ROOT/tests/fuzz/corpus/apt"; pattern='*.apt* *.ncl *.txt' ;;
    fuzz_gcode_expression) seeds="$ROOT/tests/fuzz/corpus/expression"; pattern='' ;;
    fuzz_post_cli) seeds="$ROOT/tests/fuzz/corpus/apt $ROOT/tests/fuzz/corpus/gcode"; pattern='*.apt* *.ncl *.nc' ;;
    *) seeds="$ROOT/tests/fuzz/corpus/gcode"; pattern='*.ngc *.nc *.gcode' ;;
  esac
  corpus="$BUILD/fuzz/corpus/$target"
  mkdir -p "$corpus" "$BUILD/fuzz/findings/$target"
  for s in $seeds; do cp "$s"/* "$corpus"/ 2>/dev/null || true; done
  if [ -d "$SHARED" ]; then
    for p in $pattern; do
      for f in "$SHARED"/$p; do
        [ -f "$f" ] && split -l 40 "$f" "$corpus/seed-$(basename "$f")-"
      done
    done
  fi
  return 0
}

# Runs one target for SECONDS_EACH; its exit status goes to $BUILD/fuzz/$target.status.
fuzz() {
  target=$1
  findings="$BUILD/fuzz/findings/$target"
  extra=""
  # The command-line target's runs print the program's messages: keep them out of the log.
  [ "$target" = fuzz_post_cli ] && extra="-close_fd_mask=3"
  rc=0
  ( cd "$findings" && "$BUILD/fuzz/$target" -max_total_time="$SECONDS_EACH" -max_len=4096 -timeout=10 \
      -rss_limit_mb=2048 -print_final_stats=1 $extra $FUZZ_FLAGS "$BUILD/fuzz/corpus/$target" \
      >"$BUILD/fuzz/$target.log" 2>&1 ) || rc=$?
  echo "$rc" > "$BUILD/fuzz/$target.status"
}

# The targets JOBS at a time, then each one's report in order.
running=0
for target in $TARGETS; do
  prepare_corpus "$target"
  echo "=== $target: $SECONDS_EACH s"
  fuzz "$target" &
  running=$((running + 1))
  if [ "$running" -ge "$JOBS" ]; then wait; running=0; fi
done
wait

status=0
for target in $TARGETS; do
  log="$BUILD/fuzz/$target.log"
  findings="$BUILD/fuzz/findings/$target"
  echo "--- $target"
  if [ "$(cat "$BUILD/fuzz/$target.status")" != 0 ]; then
    status=1
    tail -40 "$log"
  fi
  grep -E "^Done|stat::number_of_executed_units|stat::average_exec_per_sec|stat::peak_rss_mb|ERROR|SUMMARY" "$log" || true
  for f in "$findings"/crash-* "$findings"/leak-* "$findings"/timeout-*; do
    if [ -e "$f" ]; then
      echo "!!! $target: findings in $findings"
      status=1
      break
    fi
  done
done
exit $status
