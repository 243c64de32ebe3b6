#!/usr/bin/env bash
# Builds ODE Lab for the browser into BUILD (default build-web/ in the
# checkout): the libraries first (scripts/web/build-deps.sh, cached outside
# the tree), then every scene as BUILD/site/<scene>.js/.wasm/.data, and the
# page from web/ beside them with scenes.json, the list it shows.
#
#   scripts/web/build.sh [BUILD]
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
build=${1:-$root/build-web}
say() { printf 'web: %s\n' "$*" >&2; }

export NODE_PATH=${NODE_PATH:-/usr/share/nodejs}
deps=$("$here/build-deps.sh" | tail -n 1)

# glm, CLI11, stb and nlohmann-json are header-only: Debian's headers are
# used as they are, through a folder holding just them (all of /usr/include
# would bring glibc's headers in front of Emscripten's).
headers=$build/system-headers
mkdir -p "$headers"
for dir in /usr/include/glm /usr/include/CLI /usr/include/stb /usr/include/nlohmann; do
  [ -d "$dir" ] ||
    { say "error: $dir is missing (apt-get install libglm-dev libcli11-dev libstb-dev nlohmann-json3-dev)"; exit 1; }
  ln -sfn "$dir" "$headers/$(basename "$dir")"
done
font=/usr/share/fonts/truetype/dejavu/DejaVuSansMono.ttf
[ -f "$font" ] || { say "error: $font is missing (apt-get install fonts-dejavu-core)"; exit 1; }

launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
emcmake cmake -S "$here" -B "$build" -G Ninja -Wno-dev -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" \
  -DODELAB_WEB_DEPS="$deps" -DODELAB_WEB_SYSTEM_HEADERS="$headers" -DODELAB_WEB_FONT="$font" >"$build/configure.log" 2>&1 ||
  { say "error: configuring failed, see $build/configure.log"; exit 1; }
nice cmake --build "$build" -j "${ODELAB_JOBS:-2}" ||
  { say "error: the build failed"; exit 1; }

site=$build/site
cp "$root"/web/*.html "$root"/web/*.js "$root"/web/*.css "$root"/web/*.svg "$site/"
# The web engines for the page (web/engines/): bundled where `npm ci`
# has brought esbuild (web/) and the engines' packages (peers/wasm/).
# Without them the page runs ODE alone and its list of engines says why.
rm -rf "$site/engines"
if [ -d "$root/web/node_modules/esbuild" ] && [ -f "$root/peers/wasm/node_modules/.package-lock.json" ]; then
  node "$root/web/engines/bundle.mjs" "$site/engines" || { say "error: bundling the engines failed"; exit 1; }
else
  say "engines left out: run npm ci in web/ and in peers/wasm/ for Havok, Jolt, Rapier and PhysX in the page"
  # None, for the index page, which offers no side-by-side links then.
  mkdir -p "$site/engines" && echo '{}' >"$site/engines/engines.json"
fi
say "site ready: $site"
