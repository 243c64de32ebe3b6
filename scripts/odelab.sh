#!/usr/bin/env bash
# ODE Lab's one entry point for a fresh Debian machine.
#
#   scripts/odelab.sh run  [TEST] [ARGS...]  install what is missing, build, start TEST (default test0)
#                                             in a window; with no display, say so and run it headless
#   scripts/odelab.sh test                    install what is missing, build, run the sanitizer check
#                                             (checks/sanitize.sh) and the whole CTest suite
#
# Environment: BUILD_DIR (default: build), JOBS (default: number of cores).
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir=${BUILD_DIR:-$root/build}
jobs=${JOBS:-$(nproc 2>/dev/null || echo 2)}

# Debian packages: compiler and build tools, the libraries, the HUD font; for
# the windowed checks an X server with Mesa's software OpenGL; for the lab's
# report (lab/odelab-report) Debian's Python with matplotlib.
# The peer engines (peers/, doc/peers.md): Bullet and MuJoCo (whose CMake
# package needs qhull). The lab on a cluster (doc/cluster.md): Dask, and
# Slurm with munge for the single-node check (the check starts and stops
# the daemons itself).
packages=(
  g++ make cmake pkg-config
  libode-dev libsdl2-dev libsdl2-ttf-dev libglew-dev libgl-dev
  libcli11-dev libstb-dev libglm-dev libgtest-dev libimgui-dev
  fonts-dejavu-core
  xvfb xauth libgl1-mesa-dri
  python3 python3-matplotlib
  libbullet-dev libmujoco-dev libqhull-dev
  python3-distributed munge slurmctld slurmd slurm-client
)

say() { printf 'odelab: %s\n' "$*" >&2; }

install_missing() {
  local missing=()
  for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  say "installing: ${missing[*]}"
  local sudo=()
  if [ "$(id -u)" -ne 0 ]; then
    if ! command -v sudo >/dev/null; then
      say "error: not root and no sudo; install these packages first: ${missing[*]}"
      exit 1
    fi
    sudo=(sudo)
  fi
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -qq
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

build() {
  cmake -S "$root" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$build_dir" -j "$jobs"
}

command=${1:-}
[ $# -gt 0 ] && shift
case "$command" in
  run)
    program=test0
    if [ $# -gt 0 ] && [[ "$1" != -* ]]; then program=$1; shift; fi
    # CMake's one list of programs, read before anything is built.
    programs=$(sed -n 's/^odelab_add_program(\([A-Za-z0-9_]*\) .*/\1/p' "$root/CMakeLists.txt" | tr '\n' ' ')
    if ! [[ " $programs" == *" $program "* ]]; then
      say "error: no program '$program'; the programs are ${programs% } (see README.md)"
      exit 2
    fi
    install_missing
    build
    if [ -z "${DISPLAY:-}" ] && [ -z "${WAYLAND_DISPLAY:-}" ]; then
      say "no display (DISPLAY is not set): running $program headless instead of in a window"
      exec "$build_dir/tests/$program" --headless "$@"
    fi
    # A display that is set but cannot be opened (exit status 6) falls back
    # to a headless run too.
    status=0
    "$build_dir/tests/$program" "$@" || status=$?
    if [ "$status" -eq 6 ]; then
      say "cannot open a window on DISPLAY='${DISPLAY:-}': running $program headless instead"
      exec "$build_dir/tests/$program" --headless "$@"
    fi
    exit "$status"
    ;;
  test)
    install_missing
    build
    # The unit tests and a short run of every program under AddressSanitizer
    # and UndefinedBehaviorSanitizer, in build-sanitize/ (about 6 minutes
    # from scratch on 2 cores).
    JOBS=$jobs sh "$root/checks/sanitize.sh"
    cd "$build_dir"
    exec ctest --output-on-failure -j "$jobs"
    ;;
  *)
    sed -n '2,9p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'
    case "$command" in -h | --help) exit 0 ;; esac
    [ -n "$command" ] && say "error: unknown command '$command'"
    exit 2
    ;;
esac
