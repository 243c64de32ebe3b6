# Sourced by the checks of a program's output FILE (output_files.sh,
# every_ending_marked.sh) once they have set $program, $file and
# $check_name: a scratch folder $root removed at exit with every pid left
# in $pids killed, the failure count, and a wait for the file to grow.
root=$(mktemp -d "${TMPDIR:-/tmp}/odelab_$check_name.XXXXXX") || exit 2
pids=
trap 'for p in $pids; do kill -KILL "$p" 2>/dev/null; done; rm -rf "$root"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
ok() { echo "ok:   $*"; }
# Waits until FILE in folder $1 holds at least $2 lines (60 s at most).
wait_lines() {
  n=0
  while [ "$(cat "$1/$file" 2>/dev/null | wc -l)" -lt "$2" ]; do
    [ "$n" -ge 600 ] && return 1
    sleep 0.1
    n=$((n + 1))
  done
}
