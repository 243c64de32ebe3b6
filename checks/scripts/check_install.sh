#!/bin/sh
# check_install.sh CMAKE BUILD_DIR BINDIR DATADIR DOCDIR XVFB_RUN SCREENSHOT_CHECK PROGRAM...
#
# `cmake --install BUILD_DIR --prefix P` into a fresh folder P outside the
# build tree (a program inside the build tree may fall back on the source
# tree's shaders; an installed one may not), then, from / as working folder:
#   0. every PROGRAM (their names) is in P/BINDIR;
#   1. P/BINDIR/test0 renders a frame under Xvfb with the installed shaders
#      and the PNG passes SCREENSHOT_CHECK (lit and shadowed surfaces: every
#      shader ran);
#   2. with P/DATADIR/odelab/shaders moved away the same program ends with
#      status 5, and the places it says it tried are the install's own
#      (P/BINDIR/shaders, P/DATADIR/odelab/shaders) and nothing else: so the
#      first run took its shaders from the install, not from the source tree.
# BINDIR, DATADIR and DOCDIR are GNUInstallDirs' relative paths (bin, share,
# share/doc/odelab); the programs, the shaders and the manual must be there.
set -u
cmake=$1 build=$2 bindir=$3 datadir=$4 docdir=$5 xvfb=$6 check=$7
shift 7
prefix=$(mktemp -d "${TMPDIR:-/tmp}/odelab_install.XXXXXX") || exit 2
trap 'rm -rf "$prefix"' EXIT
work="$prefix/work"
mkdir "$work" || exit 2
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

"$cmake" --install "$build" --prefix "$prefix" >"$work/install.txt" 2>&1 ||
  { cat "$work/install.txt"; echo "FAIL: cmake --install ended with an error"; exit 1; }
echo "installed into $prefix: $(grep -c 'Installing:' "$work/install.txt") files"
for program in "$@"; do
  [ -x "$prefix/$bindir/$program" ] || fail "$bindir/$program is missing"
done
shaders="$prefix/$datadir/odelab/shaders"
[ -f "$shaders/scene.vert" ] || fail "$datadir/odelab/shaders/scene.vert is missing"
[ -f "$prefix/$docdir/manual.md" ] || fail "$docdir/manual.md is missing"
[ -f "$prefix/$docdir/README.md" ] || fail "$docdir/README.md is missing"
[ "$failures" = 0 ] || exit 1

# 1. A frame rendered with the installed shaders.
(cd / && "$xvfb" -a -s "-screen 0 1280x800x24" "$prefix/$bindir/test0" --screenshot "$work/shot.png" \
  --frames 30 --spawn-interval 0.05 --out-dir "$work") >"$work/out.txt" 2>&1
status=$?
cat "$work/out.txt"
if [ "$status" = 0 ]; then
  "$check" "$work/shot.png" || fail "the installed test0's frame does not pass screenshot_check"
else
  fail "the installed test0 ended with status $status (5: shaders or font not found)"
fi

# 2. Without the installed shaders: refused, having tried only the install's places.
mv "$shaders" "$shaders.away"
(cd / && env -u DISPLAY -u WAYLAND_DISPLAY "$prefix/$bindir/test0" --frames 1 --screenshot "$work/none.png" \
  --out-dir "$work") >"$work/out2.txt" 2>&1
status=$?
mv "$shaders.away" "$shaders"
cat "$work/out2.txt"
expected="error: shaders not found; tried: $prefix/$bindir/shaders, $shaders"
[ "$status" = 5 ] || fail "without the installed shaders: status $status, expected 5"
grep -qxF "$expected" "$work/out2.txt" || fail "expected exactly: $expected"
[ "$failures" = 0 ] && echo "ok:   the installed programs find their shaders in $datadir/odelab/shaders from /"
[ "$failures" = 0 ]
