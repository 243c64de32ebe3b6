#!/bin/sh
# Measures the world reader's speed, the figures doc/world-format.md and
# doc/hardening.md quote, from `world_read_tool bench` (checks/world_read_tool.cpp:
# CPU seconds and peak memory to read generated worlds of 10,000 and 100,000
# bodies), and writes each figure's median and range over the runs as a CSV
# with its run header:
#
#   doc/measurements/measure_world_read.sh [--repeats R] [--before TOOL --before-commit SHA] [CSV]
#
# CSV defaults to doc/measurements/world_read.csv; R = 7 runs of each tool.
# --before names a world_read_tool built from an earlier commit (SHA): its
# runs alternate with this build's, one after the other, so that both see the
# same load on a shared machine, and its rows are labelled "before".
# Needs build/checks/world_read_tool (or BUILD_DIR's).
set -eu
USAGE_LINES='2,14p'
repeats=7
before=
before_commit=
while [ $# -gt 0 ]; do
  case $1 in
    --repeats) repeats=$2; shift 2 ;;
    --before) before=$2; shift 2 ;;
    --before-commit) before_commit=$2; shift 2 ;;
    -h | --help) break ;;
    -*) echo "measure_world_read: unknown option $1" >&2; exit 2 ;;
    *) break ;;
  esac
done
. "$(dirname "$0")/common.sh"
case $repeats in '' | *[!0-9]* | 0) echo "measure_world_read: --repeats takes a whole number above 0" >&2; exit 2 ;; esac
if [ -n "$before" ] && { [ ! -x "$before" ] || [ -z "$before_commit" ]; }; then
  echo "measure_world_read: --before takes an executable world_read_tool and --before-commit its commit" >&2
  exit 2
fi
tool=$build/checks/world_read_tool
[ -x "$tool" ] || { echo "measure_world_read: no $tool: build the target world_read_tool" >&2; exit 2; }
csv=${1:-$root/doc/measurements/world_read.csv}
runs=$(mktemp)
trap 'rm -f "$runs"' EXIT

# One run of TOOL as LABEL: a line "LABEL BODIES CPU_S WALL_S PEAK_MIB" per world read.
run() {  # LABEL TOOL
  "$2" bench | sed -n "s/^read \([0-9]*\) bodies ([0-9.]* MB): \([0-9.]*\) s CPU (\([0-9.]*\) s wall), peak memory \([0-9]*\) MiB$/$1 \1 \2 \3 \4/p" >> "$runs"
}
for repeat in $(seq "$repeats"); do
  [ -z "$before" ] || run before "$before"
  run after "$tool"
done
tools=1
[ -z "$before" ] || tools=2
[ "$(wc -l < "$runs")" -eq $(( repeats * tools * 2 )) ] ||
  { echo "measure_world_read: world_read_tool bench printed unexpected lines" >&2; exit 1; }

# Per label and size: the runs' CPU seconds in order, their median, least and
# most, the median wall seconds and the median peak memory.
summary() {  # LABEL BODIES
  awk -v label="$1" -v bodies="$2" '
    function median(v, n,   i, j, t) {
      for (i = 2; i <= n; i++) { t = v[i]; for (j = i - 1; j >= 1 && v[j] > t; j--) v[j + 1] = v[j]; v[j + 1] = t }
      return n % 2 ? v[(n + 1) / 2] : (v[n / 2] + v[n / 2 + 1]) / 2
    }
    $1 == label && $2 == bodies { n++; cpu[n] = $3; wall[n] = $4; peak[n] = $5; all = all (n > 1 ? " " : "") $3 }
    END {
      m = median(cpu, n); least = cpu[1]; most = cpu[n]
      printf "%s,%s,%d,%.3f,%.3f,%.3f,%.3f,%.0f,%s\n", label, bodies, n, m, least, most, median(wall, n), median(peak, n), all
    }' "$runs"
}
{
  measurement_header "doc/measurements/measure_world_read.sh --repeats $repeats${before:+ --before world_read_tool@$before_commit}"
  echo "# what: world_read_tool bench (checks/world_read_tool.cpp), R runs of each build, alternating: CPU and wall seconds to read a generated world of N bodies, and the process's peak memory so far"
  [ -z "$before" ] || echo "# before: the reader at commit $before_commit; after: the reader at the commit above"
  echo "build,bodies,runs,cpu_s,cpu_s_min,cpu_s_max,wall_s,peak_mib,cpu_s_each_run"
  for label in ${before:+before} after; do
    summary "$label" 10000
    summary "$label" 100000
  done
} > "$csv"
echo "measure_world_read: wrote $csv"
