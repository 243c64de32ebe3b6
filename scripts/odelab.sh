#!/usr/bin/env bash
# ODE Lab's one entry point for a fresh Debian machine.
#
#   scripts/odelab.sh run  [TEST] [ARGS...]  install what the window needs, build TEST quietly, start it
#                                             (default test0) in a window; with no display, say so and
#                                             run it headless
#   scripts/odelab.sh test                    install what is missing, build, run the sanitizer check
#                                             (checks/sanitize.sh) and the whole CTest suite
#   scripts/odelab.sh windows                 install MinGW-w64 and Wine, cross-build the programs for
#                                             Windows into build-windows/ (doc/building-on-windows.md)
#   scripts/odelab.sh web [--serve [PORT]]    build the scenes for the browser into build-web/site
#                                             (doc/web.md); --serve serves it on 127.0.0.1 (default 8080)
#
# Environment: BUILD_DIR (default: build), JOBS (default: number of cores).
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir=${BUILD_DIR:-$root/build}
jobs=${JOBS:-$(nproc 2>/dev/null || echo 2)}

# Debian packages: compiler and build tools, the libraries, the HUD font; for
# the windowed checks an X server with Mesa's software OpenGL; for the lab's
# report (lab/odelab-report) Debian's Python with matplotlib and tqdm, and
# jsonschema for the check of doc/world.schema.json.
# The peer engines (peers/, doc/peers.md): Bullet and MuJoCo (whose CMake
# package needs qhull); SDFormat for SDF world files (doc/world-format.md,
# "SDF"). The lab on a cluster (doc/cluster.md): Dask, and Slurm with
# munge for the single-node check (the check starts and stops the daemons
# itself). debootstrap for the check that runs `run` in a fresh
# Debian root (checks/fresh.cmake).
packages=(
  g++ make cmake pkg-config
  libode-dev libsdl2-dev libsdl2-ttf-dev libglew-dev libgl-dev
  libcli11-dev libstb-dev libglm-dev libgtest-dev libimgui-dev nlohmann-json3-dev
  fonts-dejavu-core
  xvfb xauth libgl1-mesa-dri
  python3 python3-matplotlib python3-tqdm python3-jsonschema
  libbullet-dev libmujoco-dev libqhull-dev libsdformat-dev
  python3-distributed munge slurmctld slurmd slurm-client
  debootstrap
)

# The Windows cross-build (scripts/windows/) and its checks under Wine: the
# MinGW-w64 compilers, the autotools and dpkg-source for the libraries'
# Debian sources, Wine to run the programs.
windows_packages=(
  g++-mingw-w64-x86-64-posix autoconf automake libtool dpkg-dev pkg-config make
  wine wine64
)

# The browser build (doc/web.md): Emscripten, the tools that unpack and
# build Debian's source packages, and Chromium with Node for its checks.
# npm only where no npm is on PATH: a Node from elsewhere brings its own,
# which Debian's npm package conflicts with.
web_packages=(emscripten ninja-build dpkg-dev nodejs chromium)
command -v npm >/dev/null || web_packages+=(npm)

# What `run` needs for one program in a window: no checks, peers or lab
# (nlohmann-json3-dev: every program reads and writes its metrics with it).
window_packages=(
  g++ make cmake pkg-config
  libode-dev libsdl2-dev libsdl2-ttf-dev libglew-dev libgl-dev
  libcli11-dev libstb-dev libglm-dev libimgui-dev nlohmann-json3-dev
  fonts-dejavu-core
)

say() { printf 'odelab: %s\n' "$*" >&2; }

install_missing() {  # install_missing [PACKAGE...] (default: the packages above)
  local missing=() wanted=("$@")
  [ $# -gt 0 ] || wanted=("${packages[@]}")
  for p in "${wanted[@]}"; do
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

# The engines' packages (peers/wasm) and web/'s (esbuild, which bundles them
# into the site, and the driver the checks use), then the site in build-web/site.
build_web() {
  local folder
  for folder in peers/wasm web; do
    (cd "$root/$folder" && npm ci --no-audit --no-fund --loglevel=error >&2) ||
      say "npm ci failed in $folder: the site is built without Havok, Jolt, Rapier and PhysX"
  done
  bash "$root/scripts/web/build.sh" "${WEB_BUILD_DIR:-$root/build-web}"
}

# Everything: checks and peers on, also in a folder that `run` configured
# with them off.
build() {
  cmake -S "$root" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DODELAB_BUILD_CHECKS=ON -DODELAB_BUILD_PEERS=ON >/dev/null
  cmake --build "$build_dir" -j "$jobs"
}

# One program, its output kept in a log that is shown only when the build
# fails. A build folder configured before keeps its options (the checks
# stay on where `test` turned them on); a new one has no checks and no
# peers, so that only the window's packages are needed to configure it.
# The program's target brings what it loads: the window module
# (odelab_window.so, a dependency of odelab_main) and the shaders.
build_quietly() {
  local target=$1 log
  log=$(mktemp)
  local configure=()
  [ -f "$build_dir/CMakeCache.txt" ] || configure=(-DODELAB_BUILD_CHECKS=OFF -DODELAB_BUILD_PEERS=OFF)
  say "building $target (log: $log)"
  if ! { cmake -S "$root" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release "${configure[@]}" &&
         cmake --build "$build_dir" -j "$jobs" --target "$target"; } >"$log" 2>&1; then
    tail -n 40 "$log" >&2
    say "error: the build failed; the whole log is $log"
    exit 1
  fi
  rm -f "$log"
}

command=${1:-}
[ $# -gt 0 ] && shift
case "$command" in
  run)
    program=test0
    if [ $# -gt 0 ] && [[ "$1" != -* ]]; then program=$1; shift; fi
    # The scenes' list (tests/scenes/scenes.txt), read before anything is built.
    programs=$(sed -n 's/^\([a-z][a-z0-9_]*\)[[:space:]].*/\1/p' "$root/tests/scenes/scenes.txt" | tr '\n' ' ')
    if ! [[ " $programs" == *" $program "* ]]; then
      say "error: no program '$program'; the programs are ${programs% } (see README.md)"
      exit 2
    fi
    install_missing "${window_packages[@]}"
    build_quietly "$program"
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
  windows)
    install_missing "${windows_packages[@]}"
    exec "$root/scripts/windows/build.sh"
    ;;
  test)
    # Everything the checks need, in one apt run: the programs' packages,
    # the Windows cross-build's, the browser build's.
    install_missing "${packages[@]}" "${windows_packages[@]}" "${web_packages[@]}"
    # The engines that run in Node.js (peers/wasm, doc/peers.md): Havok, Jolt,
    # Rapier and PhysX from the npm registry, pinned by the lockfile; offline after this.
    if command -v node >/dev/null && command -v npm >/dev/null; then
      (cd "$root/peers/wasm" && npm ci --no-audit --no-fund --loglevel=error) ||
        say "npm ci failed in peers/wasm: --engine havok, jolt, rapier and physx and their checks are skipped"
    else
      say "no node/npm: --engine havok, jolt, rapier and physx and their checks are skipped"
    fi
    build
    # The programs cross-built for Windows, which the label `windows` runs
    # under Wine.
    JOBS=$jobs "$root/scripts/windows/build.sh"
    # The unit tests and a short run of every program under AddressSanitizer
    # and UndefinedBehaviorSanitizer, in build-sanitize/ (about 6 minutes
    # from scratch on 2 cores).
    JOBS=$jobs sh "$root/checks/sanitize.sh"
    # The scenes in the browser, for the checks labelled web (checks/web.cmake).
    ODELAB_JOBS=$jobs build_web
    cd "$build_dir"
    # --no-tests=error: a build that lost its checks (GoogleTest missing:
    # the configure output says so) fails here instead of passing with none.
    exec ctest --output-on-failure --no-tests=error -j "$jobs"
    ;;
  web)
    serve=0 port=8080
    if [ "${1:-}" = --serve ]; then
      serve=1
      shift
      if [ $# -gt 0 ]; then port=$1; shift; fi
      [[ "$port" =~ ^[0-9]+$ ]] && [ "$port" -ge 1 ] && [ "$port" -le 65535 ] ||
        { say "error: --serve takes a port number from 1 to 65535, not '$port'"; exit 2; }
    fi
    [ $# -eq 0 ] || { say "error: web takes only --serve [PORT], not '$*'"; exit 2; }
    install_missing "${web_packages[@]}"
    ODELAB_JOBS=$jobs build_web
    if [ "$serve" -eq 1 ]; then
      say "serving http://127.0.0.1:$port/ (Ctrl+C stops)"
      exec python3 -m http.server --bind 127.0.0.1 --directory "${WEB_BUILD_DIR:-$root/build-web}/site" "$port"
    fi
    ;;
  *)
    sed -n '2,13p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'
    case "$command" in -h | --help) exit 0 ;; esac
    [ -n "$command" ] && say "error: unknown command '$command'"
    exit 2
    ;;
esac
