#!/usr/bin/env bash
# Measures what the browser build adds to CI, from nothing: the libraries
# (fetched and built in an empty cache), the site (in a scratch folder), and
# the checks labelled web (run from BUILD_DIR, default build/, against the
# site its configuration names, build-web/site). Appends one
# row per stage to CSV (doc/measurements/web-ci-times.csv), after a header
# naming the machine, with the load average at the start, since the machine
# may be shared.
#
#   scripts/web/measure-ci.sh CSV
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
[ $# -eq 1 ] || { echo "usage: $0 CSV" >&2; exit 2; }
csv=$1
build_dir=${BUILD_DIR:-$root/build}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
# A cold cache: no compiler cache either, as on a fresh CI machine.
export CCACHE_DISABLE=1 XDG_CACHE_HOME=$scratch/cache

if [ ! -f "$csv" ]; then
  {
    echo "# emcc: $(emcc --version | head -n 1)"
    echo "# chromium: $(chromium --version 2>/dev/null | head -n 1)"
    echo "# CPU: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'), $(nproc) cores"
    echo "# date: $(date -u '+%Y-%m-%d %H:%M:%S +0000')"
    echo "# commit: $(git -C "$root" rev-parse HEAD)"
    echo "stage,seconds,load_average_1min_at_start"
  } >"$csv"
fi
stage() {
  local name=$1 load start
  shift
  load=$(cut -d' ' -f1 /proc/loadavg)
  start=$(date +%s.%N)
  "$@" >"$scratch/$name.log" 2>&1 || { echo "error: $name failed, see its log:" >&2; tail -n 20 "$scratch/$name.log" >&2; exit 1; }
  printf '%s,%.1f,%s\n' "$name" "$(echo "$(date +%s.%N) - $start" | bc)" "$load" >>"$csv"
}
stage libraries_from_debian_sources "$here/build-deps.sh"
stage scenes_and_site "$here/build.sh" "$scratch/build-web"
stage ctest_label_web ctest --test-dir "$build_dir" -L web
