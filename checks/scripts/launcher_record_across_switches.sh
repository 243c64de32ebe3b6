#!/bin/sh
# launcher_record_across_switches.sh ODELAB
#
# odelab --record DIR numbers frames over the whole window: test3 (3
# frames), Page Up to test2 (6 frames), Page Down to test3 again (10 frames,
# the last the quit's) leave 19 PNGs numbered 1 to 19, each number once, so
# the second visit to test3 adds to the first's frames instead of replacing
# them. (--events frame numbers count each scene's frames from 1.)
program=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
root=$(mktemp -d "${TMPDIR:-/tmp}/odelab_record_switch.XXXXXX") || exit 2
trap 'rm -rf "$root"' EXIT
cd "$root" || exit 2
mkdir frames
printf '3 key PageUp\n6 key PageDown\n10 quit\n' > switch.events
timeout 120 xvfb-run -a -s "-screen 0 1280x800x24" "$program" --scene test3 --events switch.events \
  --record frames --width 320 --height 240 >out.txt 2>err.txt
status=$?
[ "$status" = 0 ] || { echo "FAIL: status $status"; cat err.txt; exit 1; }
ls frames > names.txt
count=$(wc -l < names.txt)
numbers=$(sed 's/.*_frame_0*\([0-9]*\)\.png$/\1/' names.txt | sort -n | tr '\n' ' ')
expected=$(seq 1 19 | tr '\n' ' ')
visits=$(grep -c '^test3_' names.txt)/$(grep -c '^test2_' names.txt)
if [ "$count" = 19 ] && [ "$numbers" = "$expected" ] && [ "$visits" = 13/6 ]; then
  echo "ok:   19 frames numbered 1 to 19, test3/test2 $visits"
else
  echo "FAIL: $count frames (test3/test2 $visits), numbered: $numbers; expected 19 numbered 1 to 19, test3/test2 13/6"
  exit 1
fi
