#!/usr/bin/env bash
# Compiles and runs one test file alone, without CMake: scripts/quick_test.sh <name> [boost.test args]
# (builds test/Quad_remeshing/test_<name>.cpp + the test main into ${QR_QUICK_DIR:-/tmp/qr_quick}).
set -euo pipefail
name=$1; shift || true
root=$(cd "$(dirname "$0")/.." && pwd)
out=${QR_QUICK_DIR:-/tmp/qr_quick}
mkdir -p "$out"
flags="-std=c++17 ${QR_QUICK_FLAGS:--O2 -g -DNDEBUG} -I$root/include -I/usr/include/eigen3 -DBOOST_TEST_DYN_LINK -DCGAL_USE_GLPK"
flags="$flags -DQR_TEST_DATA_DIR=\"$root/data/meshes\" -DQR_TEST_BINARY_DIR=\"$out\""
if [ ! -f "$out/main.o" ]; then
  g++ $flags -c "$root/test/Quad_remeshing/main.cpp" -o "$out/main.o"
fi
g++ $flags "$root/test/Quad_remeshing/test_$name.cpp" "$out/main.o" -o "$out/test_$name" \
  -lboost_unit_test_framework -lglpk -lgmp -lmpfr -lpthread
exec "$out/test_$name" --run_test="$name" "$@"
