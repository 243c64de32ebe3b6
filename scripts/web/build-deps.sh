#!/usr/bin/env bash
# Cross-builds the browser build's libraries with Emscripten from Debian's
# source packages: SDL2, freetype, SDL2_ttf, ODE (double precision) and
# Dear ImGui with its SDL2 and OpenGL ES 3 back ends. Emscripten's own ports
# are not used: Debian's emscripten has a frozen cache without them.
#
#   scripts/web/build-deps.sh [CACHE]
#
# CACHE defaults to ${XDG_CACHE_HOME:-$HOME/.cache}/odelab. The libraries go
# to CACHE/web-<key>, the key naming every source version and emcc's, so a
# new version builds afresh beside the old. Prints that folder (include/,
# lib/, lib/cmake/) on its last line. Progress goes to stderr.
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
say() { printf 'web deps: %s\n' "$*" >&2; }

cache=${1:-${XDG_CACHE_HOME:-$HOME/.cache}/odelab}
for tool in emcc emcmake emar cmake ninja; do
  command -v "$tool" >/dev/null || { say "error: $tool is missing (apt-get install emscripten cmake ninja-build)"; exit 1; }
done
# emcc's JavaScript tools look for Debian's node modules there when the
# node on PATH is not Debian's.
export NODE_PATH=${NODE_PATH:-/usr/share/nodejs}

mapfile -t trees < <("$here/../deps/debian-source.sh" "$cache" libsdl2 freetype libsdl2-ttf ode imgui)
[ ${#trees[@]} -eq 5 ] || { say "error: expected five source trees, got ${#trees[@]}"; exit 1; }
sdl=${trees[0]} freetype=${trees[1]} ttf=${trees[2]} ode=${trees[3]} imgui=${trees[4]}

emcc_version=$(emcc -dumpversion)
key=$(for t in "${trees[@]}"; do basename "$t"; done | tr '\n' '_')emcc-$emcc_version
# The recipe's own version: raise it when a flag below changes, so caches
# built the old way are left alone.
key=$key-recipe1
prefix=$cache/web-$key
if [ -f "$prefix/.complete" ]; then
  say "using $prefix"
  printf '%s\n' "$prefix"
  exit 0
fi
mkdir -p "$prefix"
work=$prefix/build
jobs=${ODELAB_JOBS:-2}

# Configure, build and install one CMake project into the prefix.
# A library already installed by an interrupted earlier run is kept.
cmake_install() {
  local name=$1 source=$2
  shift 2
  [ -f "$prefix/.done-$name" ] && return 0
  say "building $name"
  emcmake cmake -S "$source" -B "$work/$name" -G Ninja -Wno-dev \
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX="$prefix" \
    -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_FIND_ROOT_PATH="$prefix" \
    -DBUILD_SHARED_LIBS=OFF "$@" >"$work/$name.log" 2>&1 ||
    { say "error: configuring $name failed, see $work/$name.log"; exit 1; }
  nice cmake --build "$work/$name" -j "$jobs" >>"$work/$name.log" 2>&1 ||
    { say "error: building $name failed, see $work/$name.log"; exit 1; }
  cmake --install "$work/$name" >>"$work/$name.log" 2>&1 ||
    { say "error: installing $name failed, see $work/$name.log"; exit 1; }
  touch "$prefix/.done-$name"
}
mkdir -p "$work"

cmake_install sdl2 "$sdl" -DSDL_SHARED=OFF -DSDL_STATIC=ON -DSDL_TEST=OFF -DSDL_PTHREADS=OFF
cmake_install freetype "$freetype" -DFT_DISABLE_ZLIB=ON -DFT_DISABLE_BZIP2=ON -DFT_DISABLE_PNG=ON \
  -DFT_DISABLE_HARFBUZZ=ON -DFT_DISABLE_BROTLI=ON
cmake_install sdl2_ttf "$ttf" -DSDL2TTF_SAMPLES=OFF -DSDL2TTF_VENDORED=OFF -DSDL2TTF_HARFBUZZ=OFF \
  -DSDL2_DIR="$prefix/lib/cmake/SDL2"

# ODE knows no Emscripten target: its platform check is told the browser
# is a Linux, and the x86 cycle-counter timer (inline assembly) is kept out.
# The patch goes on a copy so the unpacked source stays Debian's.
ode_src=$work/ode-src
rm -rf "$ode_src"
cp -a "$ode" "$ode_src"
sed -i 's/^#elif defined(__linux__)/#elif defined(__linux__) || defined(__EMSCRIPTEN__)/' "$ode_src/config.h.cmake.in"
sed -i 's/^if(CMAKE_SYSTEM_PROCESSOR MATCHES "i686/if(NOT EMSCRIPTEN AND CMAKE_SYSTEM_PROCESSOR MATCHES "i686/' "$ode_src/CMakeLists.txt"
grep -q '__EMSCRIPTEN__' "$ode_src/config.h.cmake.in" && grep -q 'NOT EMSCRIPTEN' "$ode_src/CMakeLists.txt" ||
  { say "error: the ODE patch no longer applies to $(basename "$ode")"; exit 1; }
cmake_install ode "$ode_src" -DODE_DOUBLE_PRECISION=ON -DODE_WITH_DEMOS=OFF -DODE_WITH_TESTS=OFF \
  -DODE_WITH_LIBCCD=ON

# Dear ImGui ships no build of its own: the core and the two back ends the
# control panel uses, the OpenGL one in its ES 3 (WebGL2) flavour. Headers
# are laid out as Debian's libimgui-dev has them (imgui.h, backends/...).
build_imgui() {
  [ -f "$prefix/.done-imgui" ] && return 0
  say "building imgui"
  mkdir -p "$work/imgui" "$prefix/include/imgui/backends" "$prefix/lib"
  objects=()
  for source in imgui.cpp imgui_draw.cpp imgui_tables.cpp imgui_widgets.cpp \
                backends/imgui_impl_sdl.cpp backends/imgui_impl_opengl3.cpp; do
    object=$work/imgui/$(basename "$source" .cpp).o
    nice emcc -O2 -std=c++17 -DIMGUI_IMPL_OPENGL_ES3 -I"$imgui" -I"$prefix/include/SDL2" \
      -c "$imgui/$source" -o "$object" 2>>"$work/imgui.log" ||
      { say "error: compiling imgui's $source failed, see $work/imgui.log"; exit 1; }
    objects+=("$object")
  done
  emar rcs "$prefix/lib/libimgui.a" "${objects[@]}"
  cp "$imgui"/*.h "$prefix/include/imgui/"
  cp "$imgui"/backends/imgui_impl_sdl.h "$imgui"/backends/imgui_impl_opengl3*.h "$prefix/include/imgui/backends/"
  touch "$prefix/.done-imgui"
}
build_imgui

rm -rf "$work"
touch "$prefix/.complete"
say "done: $prefix"
printf '%s\n' "$prefix"
