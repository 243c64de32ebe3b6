#!/bin/sh
# world_round_trip.sh PROGRAM LAUNCHER SECONDS ARGS...
#
# The world file leaves nothing out: PROGRAM ARGS --export-world writes the
# scene as built; LAUNCHER --world runs that file; both run SECONDS headless
# and must end on the same state_hash, which covers every body's position,
# orientation and velocities bit for bit, the step count and the world's
# settings (utils/StateHash.h).
program=$1 launcher=$2 seconds=$3
shift 3
root=$(mktemp -d "${TMPDIR:-/tmp}/odelab_round_trip.XXXXXX") || exit 2
trap 'rm -rf "$root"' EXIT
mkdir "$root/program" "$root/file"
hash_of() {
  sed -n 's/^ *"state_hash": *\([0-9][0-9]*\).*/\1/p' "$1"
}
"$program" "$@" --export-world "$root/world.json" >/dev/null || { echo "FAIL: --export-world ended with status $?"; exit 1; }
(cd "$root/program" && timeout 300 "$program" "$@" --headless --seconds "$seconds" --metrics-json m.json >/dev/null) ||
  { echo "FAIL: the program's run ended with status $?"; exit 1; }
(cd "$root/file" && timeout 300 "$launcher" --world "$root/world.json" --headless --seconds "$seconds" --metrics-json m.json >/dev/null) ||
  { echo "FAIL: odelab --world ended with status $?"; exit 1; }
a=$(hash_of "$root/program/m.json") b=$(hash_of "$root/file/m.json")
steps_a=$(sed -n 's/^ *"steps": *\([0-9]*\).*/\1/p' "$root/program/m.json")
steps_b=$(sed -n 's/^ *"steps": *\([0-9]*\).*/\1/p' "$root/file/m.json")
if [ -z "$a" ] || [ "$a" != "$b" ]; then
  echo "FAIL: the program ends on state_hash $a after $steps_a steps, its world file on $b after $steps_b"
  exit 1
fi
echo "ok:   state_hash $a after $steps_a steps, from the program and from its world file"
