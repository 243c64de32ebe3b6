# Sourced by the measure_*.sh scripts beside it: what every measurement
# shares. After `. common.sh "$@"` (with USAGE_LINES naming the lines of the
# script's opening comment to print for --help): $root is the checkout,
# $build the build folder (BUILD_DIR, default build/), $load the load
# average at the start, and $1, if given, the CSV to write. measurement_header
# COMMAND prints the run header every CSV here starts with.
root=$(cd "$(dirname "$0")/../.." && pwd)
case ${1:-} in
  -h | --help) sed -n "$USAGE_LINES" "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
  -*) echo "$(basename "$0" .sh): unknown option $1" >&2; exit 2 ;;
esac
build=${BUILD_DIR:-$root/build}
load=$(cut -d' ' -f1-3 /proc/loadavg)

measurement_header() {  # COMMAND
  echo "# measured by: $1"
  echo "# CPU: $(sed -n 's/^model name[^:]*: //p' /proc/cpuinfo | head -n 1), $(nproc) cores, shared with other work"
  echo "# load average at the start: $load"
  echo "# date: $(date -u '+%Y-%m-%d %H:%M:%S +0000')"
  echo "# commit: $(git -C "$root" rev-parse HEAD 2>/dev/null || echo unknown)"
}
