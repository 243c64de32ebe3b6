#!/bin/sh
# windows_makefile.sh SOURCE_DIR OUT
#
# Makefile.win as a cross makefile: `make -f Makefile.win
# CROSS=x86_64-w64-mingw32-` builds all eleven programs into OUT from the
# prefix scripts/windows/deps.sh built (skipped, status 77, when it was not
# built), and the test2.exe it makes runs under Wine. -O0 and ccache (where
# there is one) keep it cheap: what is checked is that the makefile builds,
# not the optimised code, which the CMake build makes.
source_dir=$1 out=$2
prefix=$("$source_dir/scripts/windows/deps.sh" --built 2>/dev/null) || {
  echo "SKIP: the Windows libraries are not built (scripts/odelab.sh windows builds them)"
  exit 77
}
compiler=x86_64-w64-mingw32-g++-posix
command -v ccache >/dev/null && compiler="ccache $compiler"
start=$(date +%s)
if ! make -C "$source_dir" -f Makefile.win -j2 CROSS=x86_64-w64-mingw32- WINDOWS_PREFIX="$prefix" \
  OUT="$out" OPTIMIZE=-O0 CXX="$compiler" >"$out.log" 2>&1; then
  tail -n 30 "$out.log"
  echo "FAIL: make -f Makefile.win CROSS=x86_64-w64-mingw32- failed (log: $out.log)"
  exit 1
fi
built=$(ls "$out"/test*.exe | wc -l)
echo "ok:   Makefile.win made $built programs in $(($(date +%s) - start)) s: $(cd "$out" && ls test*.exe | tr '\n' ' ')"
[ "$built" = 11 ] || { echo "FAIL: 11 programs expected"; exit 1; }
status=0
wine "$out/test2.exe" --headless --seconds 1 --out-dir "$out" >"$out/run.txt" 2>&1 || status=$?
if [ "$status" = 0 ] && grep -q '^# complete' "$out/Test2_output.txt"; then
  echo "ok:   its test2.exe ran under Wine: $(tail -n 1 "$out/Test2_output.txt")"
else
  echo "FAIL: its test2.exe ended with status $status"
  tail -n 5 "$out/run.txt"
  exit 1
fi
