#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Installs the Debian 12 build dependencies, configures and builds ncpost in build/, then runs
# the main job on the bundled samples (tools/demo.sh). Pass --no-demo to only install and build.
# The benchmarks are not built (NCPOST_BUILD_BENCH=ON to build them; bench/run_*.sh do it themselves).
set -euo pipefail
cd "$(dirname "$0")/.."
packages=(cmake ninja-build g++ libeigen3-dev libboost-dev libfmt-dev catch2 libtomlplusplus-dev libcli11-dev nlohmann-json3-dev
          chromium)  # chromium: the HTML report tests render the reports headless and take a screenshot
missing=()
for p in "${packages[@]}"; do dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p"); done
if [ ${#missing[@]} -gt 0 ]; then
  SUDO=""; [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${missing[@]}"
fi
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DNCPOST_BUILD_BENCH="${NCPOST_BUILD_BENCH:-OFF}" >/dev/null
cmake --build build -j"$(nproc)"
if [ "${1:-}" != "--no-demo" ]; then tools/demo.sh; fi
