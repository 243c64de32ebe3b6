#!/bin/sh
# compare_window_refusal_keeps_files.sh TESTS_DIR EVENTS [bullet]
#
# The compare window builds every engine's scene before it writes a file,
# as the headless compare run does (doc/hardening.md, "Fourth round"): when
# an engine refuses the scene (here Jolt, whose process dies at once with
# ODELAB_NODE=/bin/false), the window run ends with status 7 and the
# previous run's streamed outputs are byte for byte as they were: ODE's
# Test2_output.txt / Test8_output.txt, built first, and with "bullet" also
# Bullet's in bullet/, built before Jolt; and a window compare run that
# starts writes ODE's file to its end. Must run under a display (xvfb-run).
tests=$(cd "$1" && pwd) events=$(cd "$(dirname "$2")" && pwd)/$(basename "$2") bullet=${3:-}
root=$(mktemp -d "${TMPDIR:-/tmp}/odelab_compare_window_refusal.XXXXXX") || exit 2
trap 'rm -rf "$root"' EXIT
cd "$root" || exit 2
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
ok() { echo "ok:   $*"; }

# same NAME FILE COPY: FILE is byte for byte COPY
same() {
  if cmp -s "$2" "$3"; then ok "$1: $2 kept"; else fail "$1: $2 changed (now $(wc -l < "$2") lines, was $(wc -l < "$3"))"; fi
}

for pair in test2:Test2_output.txt test8:Test8_output.txt; do
  program=${pair%%:*} file=${pair#*:}
  others=jolt
  # A complete run's files, kept to compare with: ODE's here, Bullet's in bullet/.
  "$tests/$program" --headless --seconds 0.2 >/dev/null 2>&1 || fail "the first $program run failed"
  cp "$file" before.txt
  if [ "$bullet" = bullet ]; then
    mkdir -p bullet
    "$tests/$program" --headless --seconds 0.2 --engine bullet --out-dir bullet >/dev/null 2>&1 ||
      fail "the first $program --engine bullet run failed"
    cp "bullet/$file" bullet-before.txt
    others=bullet,jolt
  fi

  ODELAB_NODE=/bin/false timeout 120 "$tests/$program" --compare "$others" --seconds 0.5 --events "$events" \
    >/dev/null 2>err.txt
  status=$?
  if [ "$status" = 7 ]; then
    ok "$program --compare $others in a window, Jolt dead at once: status 7"
  else
    fail "$program --compare $others in a window: status $status, expected 7: $(head -n 3 err.txt)"
  fi
  grep -q jolt err.txt || fail "$program --compare $others: the error does not name the engine: $(cat err.txt)"
  same "$program --compare $others in a window" "$file" before.txt
  [ "$bullet" = bullet ] && same "$program --compare $others in a window" "bullet/$file" bullet-before.txt
  # The hold is released when every engine builds: a window compare run
  # that starts writes ODE's file afresh, to its end.
  if [ "$bullet" = bullet ]; then
    timeout 120 "$tests/$program" --compare bullet --seconds 0.5 --events "$events" >/dev/null 2>err.txt ||
      fail "$program --compare bullet in a window failed: $(head -n 3 err.txt)"
    case $(tail -n 1 "$file") in
      "# complete: t=0.5 s"*) ok "$program --compare bullet in a window: $file written to its end" ;;
      *) fail "$program --compare bullet in a window: $file ends '$(tail -n 1 "$file")'" ;;
    esac
  fi
  rm -rf bullet jolt
done
[ "$failures" = 0 ]
