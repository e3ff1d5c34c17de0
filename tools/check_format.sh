#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The code is formatted by .clang-format (Google style, 120 columns) with clang-format 14 (Debian 12). Without arguments: lists the
# files clang-format would change and fails if there is one. With --fix: formats them in place.
# Data under tests/data is kept byte for byte (tests/data/.clang-format disables formatting).
set -euo pipefail
cd "$(dirname "$0")/.."
CLANG_FORMAT=${CLANG_FORMAT:-clang-format-14}
mapfile -t files < <(git ls-files '*.cpp' '*.hpp' '*.h' | grep -v '^tests/data/')
if [ "${1:-}" = "--fix" ]; then
  "$CLANG_FORMAT" -i "${files[@]}"
  exit 0
fi
if ! "$CLANG_FORMAT" --dry-run -Werror "${files[@]}" 2>/tmp/ncpost-format.$$; then
  grep -o '^[^:]*:[0-9]*:[0-9]*: error' /tmp/ncpost-format.$$ | cut -d: -f1 | sort -u | sed 's/^/not formatted: /' >&2
  rm -f /tmp/ncpost-format.$$
  echo "run tools/check_format.sh --fix (clang-format, .clang-format at the top)" >&2
  exit 1
fi
rm -f /tmp/ncpost-format.$$
echo "format: ${#files[@]} files as .clang-format writes them"
