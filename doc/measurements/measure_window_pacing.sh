#!/bin/sh
# Measures the figures doc/manual.md quotes from checks/bench_window_pacing.sh
# (the share of a core test0 uses in a window, running and paused) and
# writes them as a CSV with its run header, so that the page's figures are
# held by data rather than typed in:
#
#   doc/measurements/measure_window_pacing.sh [--seconds S] [--repeats R] [CSV]
#
# CSV defaults to doc/measurements/window_pacing.csv; S = 5, R = 3 (the
# benchmark's paused and running runs, repeated R times, one after another).
# Needs a build with windows in build/ (or BUILD_DIR) and xvfb-run.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
seconds=5
repeats=3
while [ $# -gt 0 ]; do
  case $1 in
    --seconds) seconds=$2; shift 2 ;;
    --repeats) repeats=$2; shift 2 ;;
    -h | --help) sed -n '2,12p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "measure_window_pacing: unknown option $1" >&2; exit 2 ;;
    *) break ;;
  esac
done
case $seconds$repeats in *[!0-9]*) echo "measure_window_pacing: --seconds and --repeats take whole numbers" >&2; exit 2 ;; esac
csv=${1:-$here/window_pacing.csv}
rows=$(mktemp)
trap 'rm -f "$rows"' EXIT
for repeat in $(seq "$repeats"); do
  # The benchmark's last line: "test0 in a window: running R% of a core, paused P% of a core (over S s each)".
  line=$("$root/checks/bench_window_pacing.sh" --frames 2 --seconds "$seconds" test0 | tail -n 1)
  running=$(echo "$line" | sed -n 's/.*running \([0-9.]*\)% of a core.*/\1/p')
  paused=$(echo "$line" | sed -n 's/.*paused \([0-9.]*\)% of a core.*/\1/p')
  [ -n "$running" ] && [ -n "$paused" ] || { echo "measure_window_pacing: unexpected output: $line" >&2; exit 1; }
  echo "$repeat,test0,$seconds,$running,$paused" >> "$rows"
done
{
  echo "# measured by: doc/measurements/measure_window_pacing.sh --seconds $seconds --repeats $repeats"
  echo "# what: the share of one core (percent) test0 uses in a 1280x720 window under Xvfb over S s, running and paused (P), from checks/bench_window_pacing.sh"
  echo "# CPU: $(sed -n 's/^model name[^:]*: //p' /proc/cpuinfo | head -n 1), $(nproc) cores; load average at the start $(cut -d' ' -f1-3 /proc/loadavg)"
  echo "# date: $(date -u '+%Y-%m-%d %H:%M:%S +0000')"
  echo "# commit: $(git -C "$root" rev-parse HEAD 2>/dev/null || echo unknown)"
  echo "repeat,program,seconds,running_percent_of_core,paused_percent_of_core"
  cat "$rows"
} > "$csv"
echo "measure_window_pacing: wrote $csv"
