#!/usr/bin/env bash
# Runs the batch runner over a folder of meshes and cross-checks every output with an independent
# evaluator (qmeval) when one is given. Not part of the test suite (it needs meshes and tools outside
# the repository).
#   benchmark/Quad_remeshing/evaluate_dev_set.sh MESH_DIR OUT_DIR [QMEVAL] [-- quad_remesh options]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
mesh_dir=$1; out=$2; shift 2
qmeval=""
if [ $# -gt 0 ] && [ "$1" != "--" ]; then qmeval=$1; shift; fi
[ $# -gt 0 ] && [ "$1" = "--" ] && shift
build=${QR_BUILD_DIR:-$root/build}
mkdir -p "$out"
"$build/benchmark/Quad_remeshing/quad_remesh_batch" --out "$out" --time-limit "${QR_TIME_LIMIT:-300}" \
  "$mesh_dir"/*.off -- --quiet "$@"
if [ -n "$qmeval" ]; then
  : > "$out/qmeval.txt"
  for m in "$mesh_dir"/*.off; do
    name=$(basename "${m%.*}")
    if [ -f "$out/${name}_quad.obj" ]; then
      line=$("$qmeval" "$m" "$out/${name}_quad.obj" --samples 100000 2>/dev/null | grep '^qmeval:' || echo "qmeval: failed")
      echo "$name $line" | tee -a "$out/qmeval.txt"
    else
      echo "$name (no output)" | tee -a "$out/qmeval.txt"
    fi
  done
fi
