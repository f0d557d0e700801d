#!/usr/bin/env bash
# Installs the Debian packages the package needs, if any is missing (needs root or sudo).
set -euo pipefail
packages=(cmake g++ make libcgal-dev libeigen3-dev libglpk-dev libboost-graph-dev libboost-test-dev
          libgmp-dev libmpfr-dev doxygen clang libclang-rt-14-dev)
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
