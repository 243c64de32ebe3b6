#!/bin/sh
# bounded_reader_refusals.sh PROGRAM [ARGS...]
#
# PROGRAM reads the file named last on its command line (after ARGS) through
# the one bounded reader (checks/file_rules.json, "reader"): what is not a
# small regular file is refused with status 2 and a message naming why, at
# once (within 10 s), reading nothing: /dev/zero ("is a device"; it read
# until memory ran out), a FIFO with no writer ("is a FIFO"; it waited for
# ever), a folder ("is a folder") and a path that does not exist ("does not
# exist").
program=$1
shift
root=$(mktemp -d "${TMPDIR:-/tmp}/odelab_bounded_reader.XXXXXX") || exit 2
trap 'rm -rf "$root"' EXIT
mkfifo "$root/fifo" && mkdir "$root/folder" || exit 2
failures=0
for pair in "/dev/zero:is a device" "$root/fifo:is a FIFO" "$root/folder:is a folder" "$root/absent:does not exist"; do
  input=${pair%%:*} phrase=${pair#*:}
  timeout 10 "$program" "$@" "$input" >/dev/null 2>"$root/err"
  status=$?
  if [ "$status" = 2 ] && grep -q "$phrase" "$root/err"; then
    echo "ok:   $input refused: $(head -1 "$root/err")"
  else
    [ "$status" = 124 ] && status="124 (still reading after 10 s)"
    echo "FAIL: $input: status $status, message '$(head -1 "$root/err")'"
    failures=$((failures + 1))
  fi
done
[ "$failures" = 0 ]
