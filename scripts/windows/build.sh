#!/usr/bin/env bash
# Builds the eleven ODE Lab programs for 64-bit Windows (test0.exe ...
# test10.exe, with the shaders and the HUD font beside them) by cross-
# compiling with MinGW-w64, against the libraries scripts/windows/deps.sh
# builds (and caches). scripts/odelab.sh windows installs the tools first.
#
#   scripts/windows/build.sh        the programs land in build-windows/tests/
#
# Environment: WINDOWS_BUILD_DIR (default: build-windows), JOBS (default 2).
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
build_dir=${WINDOWS_BUILD_DIR:-$root/build-windows}
jobs=${JOBS:-2}

prefix=$("$root/scripts/windows/deps.sh")
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
# The checks stay with the Linux build, which runs these programs under Wine
# (checks/windows.cmake).
cmake -S "$root" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_TOOLCHAIN_FILE="$root/cmake/mingw-w64-x86_64.cmake" -DODELAB_WINDOWS_PREFIX="$prefix" \
  -DODELAB_BUILD_CHECKS=OFF "${launcher[@]}" >/dev/null
cmake --build "$build_dir" -j "$jobs"
printf 'windows: the programs are in %s/tests (libraries from %s)\n' "$build_dir" "$prefix" >&2
