#!/usr/bin/env bash
# Sets up a brand-new Debian machine if needed, builds in Release, runs every test and builds the manual.
#   bash scripts/test.sh            (build directory: build/, override with QR_BUILD_DIR)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${QR_BUILD_DIR:-$root/build}
jobs=$(nproc 2>/dev/null || echo 2)
bash "$root/scripts/setup.sh"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release
cmake --build "$build" -j "$jobs"
cmake --build "$build" --target doc
ctest --test-dir "$build" --output-on-failure -j "$jobs" --timeout 900
