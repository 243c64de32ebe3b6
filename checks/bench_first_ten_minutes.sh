#!/usr/bin/env bash
# The first ten minutes (issue 32), measured, not asserted: prints figures
# and appends them to doc/measurements/first_ten_minutes.csv; passes or
# fails nothing but its own runs.
#
#   checks/bench_first_ten_minutes.sh [--runs N] [--suite | --suite-cached] [--csv FILE]
#
# --runs N (default 3; 0: none): the time from nothing to the first picture,
#   N times: the README's first command, `scripts/odelab.sh run`, in a fresh
#   Debian 12 root (checks/scripts/fresh_root.sh: install the window's
#   packages, configure, build test0 with no compiler cache, run it headless).
#   One row per run, then the median, the fastest and the slowest.
#   Target: 300 s (5 minutes from a fresh clone).
# --suite: the whole test suite, `scripts/odelab.sh test`, in a new clone of
#   this checkout on this machine (its packages already installed), twice:
#   fresh (no build folder, and an empty cache folder, XDG_CACHE_HOME, so
#   the Windows and browser libraries and the fresh root are made anew),
#   then warm (the same clone and caches again). Targets: 1800 s fresh,
#   600 s warm. Needs root for the checks that need it, and an hour or more
#   on 2 cores.
# --suite-cached: the whole suite once in a new clone with this user's cache
#   folder as it is (the Windows and browser libraries and the fresh root
#   already made): what CI meets on a machine that has run it before.
#
# Every row says the cores, the load average at the start and the commit:
# on a shared machine the load is part of the figure.
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
runs=3 suite=0 csv=$root/doc/measurements/first_ten_minutes.csv
while [ $# -gt 0 ]; do
  case $1 in
    --runs) [[ "${2:-}" =~ ^[0-9]+$ ]] || { echo "bench: --runs takes a count" >&2; exit 2; }; runs=$2; shift 2 ;;
    --suite) suite=1; shift ;;
    --suite-cached) suite=2; shift ;;
    --csv) [ -n "${2:-}" ] || { echo "bench: --csv takes a file" >&2; exit 2; }; csv=$2; shift 2 ;;
    -h | --help) sed -n '2,26p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "bench: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done

commit=$(git -C "$root" rev-parse --short=12 HEAD 2>/dev/null || echo unknown)
[ -z "$(git -C "$root" status --porcelain --untracked-files=no 2>/dev/null)" ] || commit="$commit+changes"
if [ ! -f "$csv" ]; then
  {
    echo "# The first ten minutes (issue 32): rows appended by checks/bench_first_ten_minutes.sh, one per run."
    echo "# first_picture: scripts/odelab.sh run in a fresh Debian 12 root made by debootstrap (checks/scripts/fresh_root.sh):"
    echo "# the window's packages installed from the archive, configure, test0 built with no compiler cache, run headless."
    echo "# suite_fresh / suite_warm: scripts/odelab.sh test in a new clone (empty caches), then again in it;"
    echo "# suite_cached_libraries: scripts/odelab.sh test once in a new clone, the user's cache folder as it was."
    echo "# load: the load average (1 5 15 min) at the start of the run; the machine is shared with other work."
    echo "date,commit,quantity,value,unit,cores,load,note"
  } >"$csv"
fi
row() {  # QUANTITY VALUE UNIT LOAD NOTE
  echo "$(date -u '+%Y-%m-%d %H:%M'),$commit,$1,$2,$3,$(nproc),$4,$5" >>"$csv"
  echo "bench: $1 = $2 $3 (load at start $4)"
}
load() { cut -d' ' -f1-3 /proc/loadavg; }

# ---- nothing to the first picture, N times -----------------------------------
times=()
for ((i = 1; i <= runs; i++)); do
  at=$(load)
  log=$(mktemp)
  bash "$root/checks/scripts/fresh_root.sh" "$root" >"$log" 2>&1
  status=$?
  seconds=$(sed -n 's/^fresh root: first run in \([0-9]*\) s.*/\1/p' "$log")
  if [ "$status" -ne 0 ] || [ -z "$seconds" ]; then
    tail -n 20 "$log"
    echo "bench: fresh-root run $i ended with status $status and no time: not counted" >&2
    rm -f "$log"
    continue
  fi
  rm -f "$log"
  times+=("$seconds")
  row first_picture "$seconds" s "$at" "run $i of $runs"
done
if [ ${#times[@]} -gt 0 ]; then
  sorted=($(printf '%s\n' "${times[@]}" | sort -n))
  n=${#sorted[@]}
  if [ $((n % 2)) -eq 1 ]; then median=${sorted[$((n / 2))]}
  else median=$(( (sorted[n / 2 - 1] + sorted[n / 2]) / 2 )); fi
  row first_picture_median "$median" s "$(load)" "median of $n runs (target 300 s)"
  row first_picture_fastest "${sorted[0]}" s "$(load)" "fastest of $n runs"
  row first_picture_slowest "${sorted[$((n - 1))]}" s "$(load)" "slowest of $n runs"
fi

# ---- the whole suite, fresh then warm ----------------------------------------
if [ "$suite" -ne 0 ]; then
  work=$(mktemp -d /var/tmp/odelab-bench-suite.XXXXXX)
  git clone -q --no-hardlinks "$root" "$work/odelab" || { echo "bench: cannot clone $root" >&2; exit 1; }
  # Uncommitted changes travel too, so that the tree measured is this one.
  (cd "$root" && git diff HEAD) | (cd "$work/odelab" && git apply --allow-empty 2>/dev/null) || true
  mkdir -p "$work/cache"
  kinds=(fresh warm) cache=$work/cache
  [ "$suite" -eq 2 ] && kinds=(cached_libraries) cache=${XDG_CACHE_HOME:-$HOME/.cache}
  for kind in "${kinds[@]}"; do
    at=$(load)
    started=$(date +%s)
    (cd "$work/odelab" && XDG_CACHE_HOME=$cache scripts/odelab.sh test) >"$work/suite-$kind.log" 2>&1
    status=$?
    seconds=$(( $(date +%s) - started ))
    target=$([ $kind = warm ] && echo 600 || echo 1800)
    row suite_$kind "$seconds" s "$at" "scripts/odelab.sh test; status $status (target $target s)"
    [ "$status" -eq 0 ] || { tail -n 30 "$work/suite-$kind.log"; echo "bench: the $kind suite failed (log: $work/suite-$kind.log)" >&2; }
  done
  echo "bench: the clone and its logs are in $work (remove it when done)"
fi
echo "bench: appended to $csv"
