#!/bin/sh
# web_peer_metrics_file.sh PEER CASE
#
# A web peer (build/peers/<engine>_lab) given a --metrics-json target that the
# file rule (checks/file_rules.json) forbids, in a fresh folder:
#   device            a character device 1,3 (what /dev/null is), made with
#                     mknod: status 2 "is a device", still a device (root only;
#                     status 77, CTest's skip, otherwise)
#   symlink           a link to a file holding 'precious': status 2 "is a
#                     symbolic link", the link and the victim's content kept
#   missing_folder    a file in a folder that does not exist, for a run of
#                     3000 s: status 2 "no such folder" within 2 s (the run
#                     never starts), no folder made
#   planted_temporary links to 'victim' at every name the old predictable
#                     temporary name (.m.json.<pid>.tmp) could take for the
#                     next 2000 process ids: status 0, the metrics written to
#                     m.json as a regular file, every link and the victim kept
# Exit 0: the case held; 1 with what went wrong.
peer=$1 case=$2
work=$(mktemp -d "${TMPDIR:-/tmp}/web_peer_metrics_file.XXXXXX") || exit 1
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
fail() { echo "FAILED: $case: $*"; [ -f err ] && sed 's/^/  stderr: /' err; exit 1; }
victim() { [ "$(cat victim 2>/dev/null)" = precious ] || fail "the victim lost its content: '$(cat victim 2>/dev/null)'"; }
# Runs the peer; $status, $seconds (whole, rounded up) and err are set after.
run() {
  start=$(date +%s%N)
  timeout 120 "$peer" "$@" >out 2>err
  status=$?
  seconds=$(( ($(date +%s%N) - start + 999999999) / 1000000000 ))
}
refused_with() {
  [ "$status" = 2 ] || fail "status $status, not 2"
  grep -q -- "$1" err || fail "the message does not say '$1'"
  echo "ok: $case: status 2 in ${seconds} s: $(head -n 1 err)"
}

echo precious > victim
case $case in
  device)
    if [ "$(id -u)" != 0 ]; then echo "skipped: mknod needs root"; exit 77; fi
    mknod d c 1 3 || fail "mknod"
    run --scene test9 --seconds 1 --metrics-json d
    [ -c d ] || fail "the device was replaced by $(ls -l d)"
    refused_with "is a device" ;;
  symlink)
    ln -s victim link
    run --scene test9 --seconds 1 --metrics-json link
    [ -L link ] || fail "the link was replaced"
    victim
    refused_with "is a symbolic link" ;;
  missing_folder)
    run --scene test2 --seconds 3000 --metrics-json missing/m.json
    [ ! -e missing ] || fail "the folder was made"
    [ "$seconds" -le 2 ] || fail "took ${seconds} s: the run happened before the refusal"
    refused_with "no such folder" ;;
  planted_temporary)
    # One process makes them all (a loop of ln would use up the ids it plants for).
    "${PYTHON:-python3}" -c 'import os
for pid in range(os.getpid(), os.getpid() + 2000): os.symlink("victim", f".m.json.{pid}.tmp")' ||
      fail "cannot plant the links"
    run --scene test9 --seconds 1 --metrics-json m.json
    [ "$status" = 0 ] || fail "status $status, not 0"
    [ -f m.json ] && [ ! -L m.json ] || fail "m.json is not a regular file: $(ls -l m.json 2>&1)"
    grep -q '"steps": 1000' m.json || fail "m.json holds no metrics"
    victim
    links=$(find . -maxdepth 1 -name '.m.json.*.tmp' -type l | wc -l)
    [ "$links" = 2000 ] || fail "$links of the 2000 planted links are left"
    echo "ok: $case: status 0, m.json written, the 2000 planted links and their victim untouched" ;;
  *) echo "no case $case"; exit 1 ;;
esac
