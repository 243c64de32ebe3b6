#!/bin/sh
# peers_hold_no_scene_code.sh SOURCE_DIR: the engine adapters know no scene.
# Every C++ and JavaScript file git tracks under peers/ (*.cpp, *.h, *.js)
# must not name a test program (test0 ... test10): the scenes describe their
# worlds as data and measure them with their own code; an adapter builds and
# steps whatever world it is given (checks/engine_claims.cmake).
# Status 77 (skipped) without git or outside a git checkout.
cd "$1" || exit 1
command -v git >/dev/null 2>&1 || { echo "skipped: git is not installed"; exit 77; }
git rev-parse --is-inside-work-tree >/dev/null 2>&1 || { echo "skipped: $1 is not a git checkout"; exit 77; }
files=$(git ls-files -- peers | grep -E '\.(cpp|h|js)$')
found=0
for f in $files; do
  [ -f "$f" ] || continue  # removed from the work tree, not yet from the index
  if grep -nHE 'test([0-9]|10)' "$f"; then
    found=1
  fi
done
if [ "$found" -ne 0 ]; then
  echo "FAIL: the lines above name a scene's program in peers/ (adapters must hold no scene code)"
  exit 1
fi
echo "$(echo "$files" | grep -c .) tracked .cpp/.h/.js files under peers/ name no scene"
