#!/usr/bin/env bash
# Install the Debian packages poundfe needs (only those missing) and build
# Release into build/. Idempotent and non-interactive.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(libdeal.ii-dev libeigen3-dev zlib1g-dev libboost-test-dev tcl-dev numdiff gmsh gnuplot-nox cmake g++ make python3
          libmuparser-dev libfmt-dev libsiconos-numerics-dev pybind11-dev python3-pybind11 python3-dev python3-numpy python3-matplotlib python3-siconos)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  sudo_cmd=""
  [ "$(id -u)" -ne 0 ] && sudo_cmd="sudo"
  $sudo_cmd apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# The log stays inside build/ (the tree stays clean); ccache, where installed,
# makes a rebuild of unchanged files instant.
# Paths below the clone are hashed relative to it, so clones at other paths
# share the cache; the precompiled header needs the two sloppiness options.
launcher=()
if command -v ccache > /dev/null; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$PWD}" CCACHE_NOHASHDIR=1
  export CCACHE_SLOPPINESS="${CCACHE_SLOPPINESS:-pch_defines,time_macros,include_file_mtime,include_file_ctime}"
fi
mkdir -p build
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" > build/build.log 2>&1 ||
  { cat build/build.log; exit 1; }
cmake --build build -j2 >> build/build.log 2>&1 || { tail -50 build/build.log; exit 1; }
echo "setup: build/poundfe is ready; Python: PYTHONPATH=build/python python3 -c 'import poundfe'"
