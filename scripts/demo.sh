#!/usr/bin/env bash
# Sets up a brand-new Debian machine if needed, builds quad_remesh in Release and remeshes the bundled
# fandisk: writes out/fandisk_quad.obj and out/fandisk_report.json and prints a summary.
#   bash scripts/demo.sh [INPUT] [quad_remesh options...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${QR_BUILD_DIR:-$root/build}
jobs=$(nproc 2>/dev/null || echo 2)
bash "$root/scripts/setup.sh"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release
cmake --build "$build" -j "$jobs" --target quad_remesh
input=${1:-$root/data/meshes/fandisk.off}
[ $# -gt 0 ] && shift
mkdir -p "$root/out"
name=$(basename "${input%.*}")
"$build/examples/Quad_remeshing/quad_remesh" "$input" -o "$root/out/${name}_quad.obj" \
  --report "$root/out/${name}_report.json" "$@"
