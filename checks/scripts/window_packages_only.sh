#!/usr/bin/env bash
# The project configures and builds on a machine that has only what the
# window programs need (what `scripts/odelab.sh run` installs), and names
# each optional part it left out once, with the Debian package that brings
# it. On this machine everything is installed, so the rest is hidden:
#  - Bullet: pkg-config sees a private folder holding only the .pc files of
#    the modules the top-level CMakeLists.txt requires, and what they require;
#  - MuJoCo and GoogleTest: CMAKE_DISABLE_FIND_PACKAGE_<name>;
#  - Node, and (second configure) Wine, Chromium, Emscripten, Dask, Slurm:
#    their cache variables set to NOTFOUND (find_program looks in /usr/bin
#    whatever PATH says, so PATH cannot hide them).
# 1. Default configure, window packages only: status 0; Bullet, MuJoCo, Node
#    and GoogleTest each named in exactly one line with its package; no
#    check; then test0 (and the window module it loads) builds, a 1 s
#    headless run ends with status 0 and its metrics, and its --list-engines
#    names Bullet and MuJoCo as not built, with their packages.
# 2. Configure with the checks (GoogleTest visible) and every optional tool
#    hidden: status 0; Wine, Chromium, Emscripten, Dask and Slurm each named
#    in exactly one line with its package(s); checks registered, but none of
#    the peers, windows, web, Dask or Slurm checks.
# Usage: window_packages_only.sh SOURCE_DIR WORK_DIR   (status 0 passed, 1 failed)
set -uo pipefail
source_dir=$(cd "$1" && pwd)
work=$2
rm -rf "$work" && mkdir -p "$work/pkgconfig"
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
started=$(date +%s)
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)

# ---- the private pkg-config folder ---------------------------------------
# The modules CMakeLists.txt requires (pkg_check_modules(... REQUIRED ...)),
# and everything they require, public or private (--cflags reads both).
modules=$(sed -n 's/^ *pkg_check_modules([A-Z0-9_]* REQUIRED IMPORTED_TARGET \([^ )]*\)).*/\1/p' \
          "$source_dir/CMakeLists.txt")
[ -n "$modules" ] || { echo "FAIL: no pkg_check_modules(... REQUIRED ...) found in CMakeLists.txt"; exit 1; }
seen=" "
queue=($modules)
while [ ${#queue[@]} -gt 0 ]; do
  module=${queue[0]}
  queue=("${queue[@]:1}")
  case "$seen" in *" $module "*) continue ;; esac
  seen="$seen$module "
  pc=$(pkg-config --variable=pcfiledir "$module" 2>/dev/null)/$module.pc
  [ -f "$pc" ] || { fail "pkg-config module $module (needed by the window programs) not found"; continue; }
  ln -sf "$pc" "$work/pkgconfig/"
  queue+=($( (pkg-config --print-requires "$module"; pkg-config --print-requires-private "$module") 2>/dev/null |
             awk '{print $1}'))
done
export PKG_CONFIG_LIBDIR=$work/pkgconfig
unset PKG_CONFIG_PATH
# The hiding itself is checked, so that a pass cannot come from a peer that
# was visible after all.
! pkg-config --exists bullet-float64 || fail "bullet-float64 is still visible to pkg-config"
echo "window's pkg-config modules:$seen"

# Exactly one line of the configure output names PACKAGE-TEXT.
named_once() {  # LOG TEXT WHAT
  local n
  n=$(grep -cF -- "$2" "$1")
  [ "$n" -eq 1 ] || fail "$3 is named in $n lines of the configure output, not 1 (looked for '$2')"
}

# ---- 1. window packages only ------------------------------------------------
hide_node=(-DODELAB_NODE=ODELAB_NODE-NOTFOUND)
if cmake -S "$source_dir" -B "$work/window" -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" \
     -DCMAKE_DISABLE_FIND_PACKAGE_mujoco=ON -DCMAKE_DISABLE_FIND_PACKAGE_GTest=ON "${hide_node[@]}" \
     >"$work/window.log" 2>&1; then
  named_once "$work/window.log" "Debian's libbullet-dev brings it" "Bullet"
  named_once "$work/window.log" "Debian's libmujoco-dev and libqhull-dev bring it" "MuJoCo"
  named_once "$work/window.log" "Debian's nodejs brings it" "Node"
  named_once "$work/window.log" "Debian's libgtest-dev brings it" "GoogleTest"
  targets=$(cmake --build "$work/window" --target help 2>/dev/null)
  [ -n "$targets" ] || fail "cmake --build --target help listed no targets"
  printf '%s\n' "$targets" | grep -qw test0 || fail "no target test0"
  tests=$(cd "$work/window" && ctest -N 2>/dev/null | sed -n 's/^Total Tests: //p')
  [ "${tests:-0}" -eq 0 ] || fail "$tests checks registered without GoogleTest"
  # test0 and what it loads, built from scratch (a compiler cache helps).
  if cmake --build "$work/window" -j 2 --target test0 >"$work/build.log" 2>&1; then
    [ -f "$work/window/tests/odelab_window.so" ] || [ -f "$work/window/tests/odelab_window.dll" ] ||
      grep -q "ODELAB_WINDOW_MODULE:BOOL=OFF" "$work/window/CMakeCache.txt" ||
      fail "building test0 did not build the window module it loads (tests/odelab_window.so)"
    (cd "$work" && "$work/window/tests/test0" --headless --seconds 1 >"$work/run.log" 2>&1)
    status=$?
    [ $status -eq 0 ] || fail "test0 --headless --seconds 1 ended with status $status: $(tail -n 3 "$work/run.log")"
    grep -q "^sim_seconds = 1$" "$work/run.log" || fail "test0's headless run printed no sim_seconds = 1"
    engines=$("$work/window/tests/test0" --list-engines)
    grep -q "^bullet: not available" <<<"$engines" && grep -q "libbullet-dev" <<<"$engines" ||
      fail "test0 --list-engines does not name Bullet as missing with its package"
    grep -q "^mujoco: not available" <<<"$engines" && grep -q "libmujoco-dev" <<<"$engines" ||
      fail "test0 --list-engines does not name MuJoCo as missing with its package"
  else
    fail "building test0 failed: $(tail -n 10 "$work/build.log")"
  fi
else
  fail "configure with the window's packages only failed: $(tail -n 10 "$work/window.log")"
fi

# ---- 2. the checks on, every optional tool hidden ------------------------------
if cmake -S "$source_dir" -B "$work/checks" -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" \
     -DCMAKE_DISABLE_FIND_PACKAGE_mujoco=ON "${hide_node[@]}" -DODELAB_WEB_SITE="$work/no-site" \
     -DODELAB_WINE=ODELAB_WINE-NOTFOUND -DODELAB_CHROMIUM=ODELAB_CHROMIUM-NOTFOUND -DODELAB_EMCC=ODELAB_EMCC-NOTFOUND \
     -DODELAB_DASK=ODELAB_DASK-NOTFOUND -DODELAB_MUNGED=ODELAB_MUNGED-NOTFOUND -DODELAB_SLURMCTLD=ODELAB_SLURMCTLD-NOTFOUND \
     -DODELAB_SLURMD=ODELAB_SLURMD-NOTFOUND -DODELAB_SALLOC=ODELAB_SALLOC-NOTFOUND \
     >"$work/checks.log" 2>&1; then
  named_once "$work/checks.log" "Debian's wine and wine64 bring it" "Wine"
  named_once "$work/checks.log" "Debian's chromium brings it" "Chromium"
  named_once "$work/checks.log" "Debian's emscripten brings it" "Emscripten"
  named_once "$work/checks.log" "Debian's python3-distributed brings it" "Dask"
  named_once "$work/checks.log" "Debian's munge slurmctld slurmd slurm-client bring them" "Slurm"
  named_once "$work/checks.log" "Debian's nodejs brings it" "Node"
  named_once "$work/checks.log" "Debian's libbullet-dev brings it" "Bullet"
  listed=$(cd "$work/checks" && ctest -N 2>/dev/null)
  total=$(printf '%s\n' "$listed" | sed -n 's/^Total Tests: //p')
  [ "${total:-0}" -gt 0 ] || fail "no checks registered with GoogleTest visible"
  left=$(printf '%s\n' "$listed" | grep -E "Test +#[0-9]+: ([a-z0-9]+_on_(havok|jolt|rapier|physx)|engine_physx_|engines_without_node|windows_|web_|lab_dask_|lab_slurm_|lab_report_quick)" |
         head -n 5)
  [ -z "$left" ] || fail "checks of a hidden part were registered: $left"
  echo "with the checks on: ${total:-0} checks registered, none of a hidden part"
else
  fail "configure with the checks and every optional tool hidden failed: $(tail -n 10 "$work/checks.log")"
fi

elapsed=$(( $(date +%s) - started ))
if [ $failures -eq 0 ]; then
  echo "window packages only: configures, names each missing part once with its package, builds test0," \
       "which runs headless with status 0 ($elapsed s)"
  rm -rf "$work"
fi
exit $((failures > 0))
