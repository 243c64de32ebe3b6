#!/usr/bin/env bash
# A twelfth scene takes one line of tests/scenes/scenes.txt, its source and
# its checks file, and nothing else: in a scratch copy of the tree, test9's
# source is copied as test11 and its checks file renamed, one line is added
# to the list, and then, with no other edit,
#   - CTest has a test11 counterpart of every check test9 has (its program's
#     claims, the browser check where test9 has one, the per-program checks
#     of every other file: knobs, fuzz, hardening, copy line, launcher ...);
#   - the launcher lists it, and its program runs as test11 (its --help and
#     its copied command line name it);
#   - scripts/odelab.sh run, Makefile.win, the web build's list and the lab
#     (its scenes, its first screen's rows) have it.
# Usage: twelfth_scene.sh SOURCE_ROOT WORK_DIR   (builds two targets in WORK_DIR)
set -euo pipefail
root=$(cd "$1" && pwd)
work=$2
fail() { echo "twelfth_scene: FAIL: $*" >&2; exit 1; }

rm -rf "$work"
mkdir -p "$work/tree"
tree=$work/tree
# The tree as a developer has it: its files, edits and new files included,
# not what git ignores (build output).
(cd "$root" && git ls-files -z --cached --others --exclude-standard |
  while IFS= read -r -d '' file; do [ -f "$file" ] && printf '%s\0' "$file"; done |
  xargs -0 cp --parents -t "$tree")

cp "$tree/tests/scenes/test9_restitution.cpp" "$tree/tests/scenes/test11_restitution_copy.cpp"
sed -E 's/test9([^0-9]|$)/test11\1/g' "$tree/checks/programs/test9.cmake" >"$tree/checks/programs/test11.cmake"
printf 'test11  test11_restitution_copy.cpp  Restitution copy\n' >>"$tree/tests/scenes/scenes.txt"

cmake -S "$tree" -B "$work/build" -DCMAKE_BUILD_TYPE=Release -DODELAB_BUILD_PEERS=OFF \
  ${ODELAB_WEB_SITE:+-DODELAB_WEB_SITE=$ODELAB_WEB_SITE} >"$work/configure.log" 2>&1 ||
  { tail -20 "$work/configure.log" >&2; fail "the tree with test11 does not configure"; }

# Every check named after test9 has its test11 counterpart.
ctest --test-dir "$work/build" -N | sed -n 's/^ *Test *#[0-9]*: //p' >"$work/tests.txt"
missing=0
samples=0
while read -r name; do
  twin=$(printf '%s' "$name" | sed -E 's/test9([^0-9]|$)/test11\1/g')
  if ! grep -qxF "$twin" "$work/tests.txt"; then
    # A framework check that takes test9 as its sample names it in a shared
    # checks file (checks/*.cmake); every other is the scene's own or walks
    # the list, and must be there for test11 too.
    if grep -qwF "$name" "$tree"/checks/*.cmake; then
      samples=$((samples + 1))
      continue
    fi
    echo "twelfth_scene: test9 has $name, test11 has no $twin" >&2
    missing=$((missing + 1))
  fi
done < <(grep -E '(^|[^0-9a-z])test9([^0-9]|$)' "$work/tests.txt")
nine=$(grep -cE '(^|[^0-9a-z])test9([^0-9]|$)' "$work/tests.txt" || true)
[ "$nine" -gt 0 ] || fail "no check of test9 found to compare with"
[ "$missing" -eq 0 ] || fail "$missing of test9's $nine checks have no test11 counterpart"
echo "twelfth_scene: CTest: test11 has a counterpart of each of test9's $nine checks" \
  "but the $samples framework checks that take test9 as their sample"

# The launcher and the program.
cmake --build "$work/build" --target odelab test11 -j "${ODELAB_JOBS:-2}" >"$work/build.log" 2>&1 ||
  { tail -20 "$work/build.log" >&2; fail "odelab and test11 do not build"; }
listed=$("$work/build/tests/odelab" --list)
grep -qP '^test11\t' <<<"$listed" || fail "odelab --list has no test11"
helped=$("$work/build/tests/test11" --help)
[ "$(head -1 <<<"$helped")" = 'test11 - Restitution copy' ] ||
  fail "test11 --help does not name it 'test11 - Restitution copy'"
out=$work/run
mkdir -p "$out"
"$work/build/tests/test11" --headless --seconds 0.5 --out-dir "$out" --print-command-line >"$out/stdout.txt" ||
  fail "test11 --headless --seconds 0.5 failed"
grep -q '^command line: test11 ' "$out/stdout.txt" || fail "test11's copied command line does not start with test11"
echo "twelfth_scene: odelab --list has test11; test11 runs as itself"

# The others that list scenes.
# (Each output is kept whole before it is searched: odelab.sh refuses the
# name with status 2, which a pipe under pipefail would take for a failure.)
refused=$(bash "$tree/scripts/odelab.sh" run no-such-scene 2>&1 || true)
grep -q ' test10 test11 (' <<<"$refused" || fail "scripts/odelab.sh run does not list test11: $refused"
planned=$(make -C "$tree" -n -f Makefile.win 2>&1 || true)
grep -q 'build-win/test11\.exe' <<<"$planned" || fail "Makefile.win builds no test11.exe"
cat >"$work/scene_list.cmake" <<EOF
cmake_minimum_required(VERSION 3.19)
include("$tree/cmake/Scenes.cmake")
odelab_read_scenes("$tree")
odelab_write_scene_list("$work/scenes.json")
EOF
cmake -P "$work/scene_list.cmake"
/usr/bin/python3 - "$work/scenes.json" "$tree/lab" <<'EOF' || fail "the web list or the lab has no test11"
import json, sys
listed = json.load(open(sys.argv[1]))
assert {"name": "test11", "title": "Restitution copy"} in listed, listed
sys.path.insert(0, sys.argv[2])
from odelab_report import first_screen, scenes
assert scenes.names()[-1] == "test11", scenes.names()
assert [row[0] for row in first_screen.rows()][-1] == "test11"
EOF
echo "twelfth_scene: scripts/odelab.sh, Makefile.win, the web page's list and the lab have test11"
