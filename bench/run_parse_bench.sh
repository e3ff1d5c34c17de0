#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Side-by-side G-code parse benchmark: ncpost (bench/parse_bench) and the cncjs `gcode-parser` npm
# package on the same generated 1,000,000-block five-axis program, in one run.
#   bench/run_parse_bench.sh [BLOCKS]        (run from the repository root; builds in build/)
# Installs gcode-parser with npm into a temporary directory (removed at the end).
set -eu
BLOCKS=${1:-1000000}
ROOT=$(cd "$(dirname "$0")/.." && pwd)
WORK=$(mktemp -d /tmp/ncpost-parse-bench.XXXXXX)
trap 'rm -rf "$WORK"' EXIT INT TERM

cmake -S "$ROOT" -B "$ROOT/build" -G Ninja -DNCPOST_BUILD_BENCH=ON >/dev/null
ninja -C "$ROOT/build" -j2 parse_bench >/dev/null

( cd "$WORK" && npm init -y >/dev/null 2>&1 && npm install --no-audit --no-fund --silent gcode-parser >/dev/null )
cp "$ROOT/bench/gcode_parser_time.js" "$WORK/"
echo "gcode-parser $(node -p "require('$WORK/node_modules/gcode-parser/package.json').version"), node $(node --version)"

FILE="$WORK/program.ngc"
"$ROOT/build/bench/parse_bench" --blocks "$BLOCKS" --file "$FILE" --generate-only
echo "--- ncpost"
"$ROOT/build/bench/parse_bench" --file "$FILE" --keep
echo "--- cncjs gcode-parser"
( cd "$WORK" && node gcode_parser_time.js "$FILE" parseFile && node gcode_parser_time.js "$FILE" parseLine )
