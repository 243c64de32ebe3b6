#!/usr/bin/env bash
# Cross-builds ODE Lab's libraries for 64-bit Windows (x86_64-w64-mingw32)
# from Debian's source packages, static, into a prefix cached outside the
# tree, and prints that prefix.
#
#   scripts/windows/deps.sh           builds the prefix if needed, prints it
#   scripts/windows/deps.sh --built   prints it if it is built, else exits 1
#
# The prefix is ${XDG_CACHE_HOME:-$HOME/.cache}/odelab/windows-<key>; the
# key covers the source versions, the compiler's version and RECIPE below,
# so a change to any of them builds a new prefix and a finished one is
# reused as it is. Needs the mingw-w64 compilers, autoconf, automake,
# libtool, pkg-config and dpkg-dev (scripts/odelab.sh windows installs them).
# Environment: JOBS (default 2).
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)
jobs=${JOBS:-2}
host=x86_64-w64-mingw32
cache=${XDG_CACHE_HOME:-${HOME:?HOME is not set}/.cache}/odelab

say() { printf 'windows-deps: %s\n' "$*" >&2; }

# The -posix compilers: with the win32 thread model std::thread and
# std::mutex do not exist, and ODE Lab uses both.
cc=$host-gcc-posix
cxx=$host-g++-posix
for tool in "$cc" "$cxx" "$host-ar" "$host-ranlib" autoreconf pkg-config make; do
  command -v "$tool" >/dev/null || { say "error: $tool is missing (scripts/odelab.sh windows installs it)"; exit 1; }
done
# The build steps' version: raise it whenever a step below changes what is
# built (a flag, a patch, a library), so the cached prefix is rebuilt.
RECIPE=1
launcher=()
command -v ccache >/dev/null && launcher=(ccache)

packages=(ode libsdl2 freetype libsdl2-ttf glew imgui libstb glm cli11 nlohmann-json3)
mapfile -t sources < <("$root/scripts/deps/debian-source.sh" "$cache/windows-src" "${packages[@]}")
[ ${#sources[@]} -eq ${#packages[@]} ] || { say "error: not every source package was unpacked"; exit 1; }
src() { # the unpacked folder of one package
  local i
  for i in "${!packages[@]}"; do [ "${packages[$i]}" = "$1" ] && { printf '%s\n' "${sources[$i]}"; return; }; done
  return 1
}

key=$({
  for s in "${sources[@]}"; do basename "$s"; done
  "$cxx" -dumpfullversion
  echo "recipe $RECIPE"
} | sha256sum | cut -c1-12)
prefix=$cache/windows-$key
if [ -f "$prefix/.complete" ]; then
  printf '%s\n' "$prefix"
  exit 0
fi
if [ "${1:-}" = --built ]; then
  say "$prefix is not built"
  exit 1
fi

# One build at a time per prefix: a second caller waits for the first.
mkdir -p "$cache"
exec 9>"$prefix.lock"
flock 9
if [ -f "$prefix/.complete" ]; then
  printf '%s\n' "$prefix"
  exit 0
fi
rm -rf "$prefix"
work=$(mktemp -d "$cache/windows-build.XXXXXX")
trap 'rm -rf "$work"' EXIT
mkdir -p "$prefix/include" "$prefix/lib/pkgconfig"

export PKG_CONFIG_LIBDIR=$prefix/lib/pkgconfig PKG_CONFIG_PATH=
# Paths inside the (randomly named) build folder are hashed relative to it,
# so a compiler cache serves a rebuild of the same sources.
export CCACHE_BASEDIR=$work
export CC="${launcher[*]} $cc" CXX="${launcher[*]} $cxx" AR=$host-ar RANLIB=$host-ranlib
configure_flags=(--host="$host" --prefix="$prefix" --disable-shared --enable-static)
started=$(date +%s)

# A copy of each source: the cache's unpacked trees stay as Debian made them.
copy() { cp -a "$(src "$1")" "$work/$1"; printf '%s\n' "$work/$1"; }
log() { # runs a step quietly, showing its log only when it fails
  local name=$1
  shift
  if ! "$@" >"$work/$name.log" 2>&1; then
    tail -n 40 "$work/$name.log" >&2
    say "error: $name failed (log above)"
    exit 1
  fi
}

say "ODE"
dir=$(copy ode)
# MinGW's headers are lower case; the file names <Windows.h>, which only a
# case-insensitive file system finds.
sed -i 's/<Windows\.h>/<windows.h>/' "$dir/ode/src/threading_pool_win.cpp"
log ode-configure sh -c "cd '$dir' && ./configure ${configure_flags[*]} --enable-double-precision --disable-demos --with-drawstuff=none"
log ode-build make -C "$dir" -j"$jobs" install

say "SDL2"
dir=$(copy libsdl2)
log sdl2-configure sh -c "cd '$dir' && ./configure ${configure_flags[*]}"
log sdl2-build make -C "$dir" -j"$jobs" install

say "FreeType"
dir=$(copy freetype)
log freetype-configure sh -c "cd '$dir' && ./configure ${configure_flags[*]} --with-zlib=no --with-png=no --with-bzip2=no --with-brotli=no --with-harfbuzz=no"
log freetype-build make -C "$dir" -j"$jobs" install

say "SDL2_ttf"
dir=$(copy libsdl2-ttf)
# Debian's tarball leaves out the generated configure and the bundled
# FreeType and HarfBuzz; the prefix's FreeType is used.
log sdl2-ttf-autoreconf sh -c "cd '$dir' && autoreconf -fi -I acinclude"
log sdl2-ttf-configure sh -c "cd '$dir' && ./configure ${configure_flags[*]} --disable-freetype-builtin --disable-harfbuzz"
log sdl2-ttf-build make -C "$dir" -j"$jobs" install

# The rest are built by hand: GLEW is one C file, Dear ImGui and stb have no
# build of their own for Windows, glm, CLI11 and nlohmann-json are headers
# only.
compile_archive() { # compile_archive LIBRARY COMPILER FLAGS... -- SOURCES...
  local library=$1 compiler=$2 flags=() objects=() source object
  shift 2
  while [ "$1" != -- ]; do flags+=("$1"); shift; done
  shift
  mkdir -p "$work/obj/$library"
  for source in "$@"; do
    object=$work/obj/$library/$(basename "${source%.*}").o
    log "$library-$(basename "$source")" $compiler "${flags[@]}" -c "$source" -o "$object"
    objects+=("$object")
  done
  log "$library-archive" "$host-ar" rcs "$prefix/lib/lib$library.a" "${objects[@]}"
}
pc() { # pc NAME VERSION CFLAGS LIBS [REQUIRES]
  printf 'prefix=%s\nName: %s\nDescription: %s for ODE Lab on Windows\nVersion: %s\nRequires: %s\nCflags: %s\nLibs: %s\n' \
    "$prefix" "$1" "$1" "$2" "${5:-}" "$3" "$4" >"$prefix/lib/pkgconfig/$1.pc"
}
version_of() { basename "$(src "$1")" | sed 's/^[^0-9]*-\([0-9][^+~]*\).*/\1/'; }

say "GLEW"
dir=$(src glew)
mkdir -p "$prefix/include/GL"
cp "$dir"/include/GL/{glew.h,wglew.h} "$prefix/include/GL/"
compile_archive glew32 "$CC" -O2 -DGLEW_STATIC -I"$dir/include" -- "$dir/src/glew.c"
pc glew "$(version_of glew)" '-I${prefix}/include -DGLEW_STATIC' '-L${prefix}/lib -lglew32 -lopengl32'

say "stb"
dir=$(src libstb)
mkdir -p "$prefix/include/stb"
cp "$dir"/stb_*.h "$prefix/include/stb/"
cat >"$work/stb.c" <<'EOF'
/* The parts of stb ODE Lab uses, compiled once (Debian's libstb does the same). */
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>
EOF
compile_archive stb "$CC" -O2 -I"$prefix/include" -- "$work/stb.c"
pc stb "$(version_of libstb)" '-I${prefix}/include/stb' '-L${prefix}/lib -lstb'

say "Dear ImGui"
dir=$(src imgui)
mkdir -p "$prefix/include/imgui/backends"
cp "$dir"/*.h "$prefix/include/imgui/"
cp "$dir"/backends/imgui_impl_{sdl,opengl3,opengl3_loader}.h "$prefix/include/imgui/backends/"
# shellcheck disable=SC2046  # the SDL flags are words
compile_archive imgui "$CXX" -O2 -I"$dir" $(pkg-config --cflags sdl2) -- \
  "$dir"/imgui.cpp "$dir"/imgui_draw.cpp "$dir"/imgui_tables.cpp "$dir"/imgui_widgets.cpp \
  "$dir"/backends/imgui_impl_sdl.cpp "$dir"/backends/imgui_impl_opengl3.cpp
pc imgui "$(version_of imgui)" '-I${prefix}/include/imgui' '-L${prefix}/lib -limgui -lopengl32' sdl2

say "glm, CLI11, nlohmann-json"
cp -a "$(src glm)/glm" "$prefix/include/"
cp -a "$(src cli11)/include/CLI" "$prefix/include/"
# The headers as Debian's nlohmann-json3-dev installs them (not the one-file
# single_include/ copy); no CMake package: CMakeLists.txt finds the header.
cp -a "$(src nlohmann-json3)/include/nlohmann" "$prefix/include/"

touch "$prefix/.complete"
say "built $prefix in $(($(date +%s) - started)) s"
printf '%s\n' "$prefix"
