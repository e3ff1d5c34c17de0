#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Side-by-side benchmark of issue 4's speed target: N CL points (a dense five-axis spiral over a dome,
# bench/post_bench.cpp) posted by the real CLI with an error model and a tolerance,
#   ncpost post --model truth.json --tolerance 0.005   (public-clean AC trunnion)
# on 2 threads (the default) and on 1, against the cncjs `gcode-parser` npm package merely parsing
# the program that comes out (parseFile: its streaming API; parseLine: the parser alone), in one run.
#   bench/run_post_bench.sh [N=1000000] [spiral|dense]   (from the repository root; builds in build/)
# (dense: 400 turns, tool axis 5 -> 70 deg, issue 26's second path)
# Wall time and peak memory from /usr/bin/time (GNU time, Debian package `time`, or the shell's
# clock when absent). gcode-parser is installed with npm into a temporary directory.
set -eu
N=${1:-1000000}
ROOT=$(cd "$(dirname "$0")/.." && pwd)
WORK=$(mktemp -d /tmp/ncpost-post-bench.XXXXXX)
trap 'rm -rf "$WORK"' EXIT INT TERM
S="$ROOT/tests/data/scenarios/public-clean"

cmake -S "$ROOT" -B "$ROOT/build" -G Ninja -DNCPOST_BUILD_BENCH=ON >/dev/null
ninja -C "$ROOT/build" -j2 ncpost post_bench >/dev/null
( cd "$WORK" && npm init -y >/dev/null 2>&1 && npm install --no-audit --no-fund --silent gcode-parser >/dev/null )
cp "$ROOT/bench/gcode_parser_time.js" "$WORK/"
echo "gcode-parser $(node -p "require('$WORK/node_modules/gcode-parser/package.json').version"), node $(node --version), $(nproc) cores"

"$ROOT/build/bench/post_bench" "$N" "$WORK" "${2:-spiral}" write-only
run() {  # label, then the command
  label=$1; shift
  if [ -x /usr/bin/time ]; then
    /usr/bin/time -f "$label: %e s wall, %U s user, peak RSS %M KB" "$@"
  else
    start=$(date +%s.%N); "$@"; end=$(date +%s.%N)
    echo "$label: $(echo "$end - $start" | bc) s wall"
  fi
}
for threads in 2 1; do
  run "ncpost post --model --tolerance 0.005 --threads $threads" \
    "$ROOT/build/ncpost" post "$WORK/bench_path.cls" --machine "$S/machine.toml" --workpiece-origin 0,0,80 \
    --model "$S/truth.json" --tolerance 0.005 --threads "$threads" -o "$WORK/out_t$threads.nc"
done
cmp -s "$WORK/out_t1.nc" "$WORK/out_t2.nc" && echo "the two programs are identical ($(wc -l < "$WORK/out_t2.nc") lines)"
echo "--- cncjs gcode-parser on the program that came out"
( cd "$WORK" && node gcode_parser_time.js "$WORK/out_t2.nc" parseFile && node gcode_parser_time.js "$WORK/out_t2.nc" parseLine )
