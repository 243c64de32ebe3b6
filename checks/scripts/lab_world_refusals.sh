#!/bin/sh
# lab/odelab-report --world refuses before any run (issue 38): a world odelab
# refuses ends it with status 2, odelab's message naming the field, nothing
# written; --world with --only is refused with status 2 too.
# Usage: lab_world_refusals.sh ODELAB_REPORT REFUSED_WORLD GOOD_WORLD BUILD_DIR SCRATCH_DIR
report=$1 refused=$2 good=$3 build=$4 scratch=$5
rm -rf "$scratch"
said=$("$report" --world "$refused" --quick --out "$scratch/refused" --build-dir "$build" 2>&1)
status=$?
echo "$said"
[ "$status" -eq 2 ] || { echo "FAIL: a refused world gave status $status, not 2"; exit 1; }
[ ! -e "$scratch/refused" ] || { echo "FAIL: a refused world's report was written"; exit 1; }
case "$said" in
  *'odelab refuses the world'*'bodies[0].mass'*) ;;
  *) echo "FAIL: no message naming the refused field (bodies[0].mass)"; exit 1 ;;
esac
"$report" --world "$good" --only thesis --out "$scratch/only" --build-dir "$build"
status=$?
[ "$status" -eq 2 ] || { echo "FAIL: --world with --only gave status $status, not 2"; exit 1; }
[ ! -e "$scratch/only" ] || { echo "FAIL: --world with --only wrote a report"; exit 1; }
echo "PASS: both refused with status 2 before any run"
