#!/usr/bin/env bash
# Installs the Debian packages the package needs, if any is missing (needs root or sudo).
set -euo pipefail
packages=(cmake g++ make libcgal-dev libeigen3-dev libglpk-dev libboost-graph-dev libboost-test-dev
          libgmp-dev libmpfr-dev doxygen clang libclang-rt-14-dev)
packages+=(chromium fonts-liberation)          # browser test of the HTML report
command -v npm >/dev/null 2>&1 || packages+=(nodejs npm)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# three.js for the HTML report, pinned by viewer/package-lock.json
if [ ! -f "$(dirname "$0")/../viewer/node_modules/three/build/three.module.js" ]; then
  echo "setup: three.js for the HTML report (npm ci in viewer/)"
  (cd "$(dirname "$0")/../viewer" && npm ci --no-audit --no-fund --loglevel=error)
fi
