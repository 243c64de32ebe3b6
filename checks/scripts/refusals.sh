#!/bin/sh
# refusals.sh MODE PROGRAM STATUS CASE...
#
# Runs PROGRAM once per CASE and checks that each run is refused cleanly: it
# ends with exactly STATUS (within 60 s), prints a message on standard error
# that says "error" and names the bad argument, and leaves nothing behind in
# its folder.
#   MODE    headless (adds --headless), window (under xvfb-run; the program's
#           own status is taken, not xvfb-run's, whose cleanup can fail with
#           5), no-display (DISPLAY and WAYLAND_DISPLAY unset) or bad-display
#           (DISPLAY names a server that does not exist).
#   CASE    one argument holding the bad argument, then, after spaces, any
#           fixed arguments that run needs ("--scan-limit=0 --find-max-velocity").
#           The bad argument is OPTION=VALUE, or a whole word (an unknown
#           option, a stray word, an option without its value). The message
#           must name OPTION (the word up to its "="); for a path given to
#           --shader-dir or --font, the path.
#   VALUE   <empty>: OPTION "" (an empty argument, which CMake cannot pass as
#           such; "OPTION=" with nothing after it is given as it is);
#           <unwritable-dir>: a fresh folder with mode 555;
#           <unreadable-shaders>: a copy of $ODELAB_SHADERS whose scene.frag
#           has mode 000. As root, where permissions stop nothing, the last
#           two run as the unprivileged user nobody (uid 65534) through
#           setpriv (or runuser); without either they are skipped with a
#           message (status 77, CTest's skip, when nothing else ran).
# $NEEDLE, when set, replaces what the message must name.
# Each run's working directory is a fresh empty folder: its --out-dir (the
# default ".") and the home of its --metrics-json, so any file it leaves
# behind is seen.
mode=$1 program=$2 status=$3
shift 3
root=$(mktemp -d "${TMPDIR:-/tmp}/odelab_refusals.XXXXXX") || exit 2
trap 'chmod -R u+rwx "$root" 2>/dev/null; rm -rf "$root"' EXIT
failures=0 ran=0 skipped=0 n=0
exe=$program  # what a run as nobody starts (see below)
# As root, permissions stop nothing: runs that test them drop to nobody.
as_nobody=
if [ "$(id -u)" = 0 ]; then
  if command -v setpriv >/dev/null 2>&1; then
    as_nobody="setpriv --reuid=65534 --regid=65534 --clear-groups"
  elif command -v runuser >/dev/null 2>&1; then
    as_nobody="runuser -u nobody --"
  fi
fi
for case in "$@"; do
  n=$((n + 1))
  dropped=
  run="$root/run$n"
  mkdir "$run"
  bad=${case%% *}
  fixed=
  [ "$bad" = "$case" ] || fixed=${case#* }
  option=${bad%%=*}
  value=
  has_value=no
  case $bad in *=*) value=${bad#*=} has_value=yes ;; esac
  case $value in
    "<empty>") value= ;;
    "<unwritable-dir>" | "<unreadable-shaders>")
      if [ "$(id -u)" = 0 ] && [ -z "$as_nobody" ]; then
        echo "skipped: $case: running as root without setpriv or runuser, where file permissions stop nothing"
        skipped=$((skipped + 1))
        continue
      fi
      if [ "$value" = "<unwritable-dir>" ]; then
        value="$root/unwritable$n"
        mkdir "$value" && chmod 555 "$value"
      else
        value="$root/unreadable$n"
        cp -r "$ODELAB_SHADERS" "$value" && chmod 000 "$value/scene.frag"
      fi
      # nobody must reach the program, the folders and the files it may use.
      # A checkout in a private folder (mktemp -d makes them mode 700) is out
      # of its reach: then nobody runs a copy of the program from $root (its
      # font and shaders are found without the build folder).
      if [ -n "$as_nobody" ]; then
        chmod 755 "$root" && chown 65534:65534 "$run"
        # shellcheck disable=SC2086 # $as_nobody is a command and its arguments
        if [ "$exe" = "$program" ] && ! $as_nobody sh -c 'test -x "$1"' sh "$program"; then
          exe="$root/program"
          cp "$program" "$exe" && chmod 755 "$exe"
          # The window side is a module the program loads from beside itself.
          module=$(dirname "$program")/odelab_window.so
          if [ -f "$module" ]; then cp "$module" "$root/" && chmod 755 "$root/odelab_window.so"; fi
        fi
        [ -d "$value" ] && [ "$value" != "$root/unwritable$n" ] && chmod -R a+rX "$value" && chmod 000 "$value/scene.frag"
        dropped=yes
      fi ;;
  esac
  # The arguments: mode, the bad one, the fixed ones, a metrics file.
  set --
  [ "$mode" = headless ] && set -- --headless
  # A window run that is wrongly let through still ends, and leaves its metrics.
  [ "$mode" = window ] && set -- --seconds 0.5
  needle=$option
  if [ "$has_value" = no ] || [ "$bad" = "$option=" ]; then
    set -- "$@" "$bad"
  elif [ -z "$value" ]; then
    set -- "$@" "$option" ""
  else
    set -- "$@" "$option=$value"
    case $option in --shader-dir | --font) needle=$value ;; esac
  fi
  [ -n "${NEEDLE:-}" ] && needle=$NEEDLE
  # shellcheck disable=SC2086 # the fixed arguments are split at spaces on purpose
  set -- "$@" $fixed
  [ "$option" = --metrics-json ] || set -- "$@" --metrics-json metrics.json
  rm -f "$root/status"
  start=$program
  [ -n "$dropped" ] && start=$exe
  case $mode in
    window)
      # The status file is written by the program's user (nobody, when dropped).
      : > "$root/status" && chmod 666 "$root/status"
      # shellcheck disable=SC2086 # $as_nobody is a command and its arguments
      (cd "$run" && STATUS_FILE="$root/status" timeout 60 ${dropped:+$as_nobody} xvfb-run -a \
        -s "-screen 0 1280x800x24" sh -c '"$@"; echo $? > "$STATUS_FILE"' sh "$start" "$@") >"$root/out" 2>"$root/err"
      wrapper=$?
      got=$(cat "$root/status" 2>/dev/null)
      [ -n "$got" ] || got="none (xvfb-run or timeout ended with $wrapper)" ;;
    no-display)
      (cd "$run" && timeout 60 env -u DISPLAY -u WAYLAND_DISPLAY "$program" "$@") >"$root/out" 2>"$root/err"
      got=$? ;;
    bad-display)
      (cd "$run" && timeout 60 env -u WAYLAND_DISPLAY DISPLAY=:4242 "$program" "$@") >"$root/out" 2>"$root/err"
      got=$? ;;
    *)
      # shellcheck disable=SC2086 # $as_nobody is a command and its arguments
      (cd "$run" && timeout 60 ${dropped:+$as_nobody} "$start" "$@") >"$root/out" 2>"$root/err"
      got=$? ;;
  esac
  ran=$((ran + 1))
  message=$(grep -m1 -F -- "$needle" "$root/err")
  left=$(ls -A "$run")
  problems=
  [ "$got" = "$status" ] || problems="$problems; exit status $got, expected $status"
  [ "$got" = 124 ] && problems="$problems (timed out: a hang)"
  grep -q 'error' "$root/err" || problems="$problems; no error message on standard error"
  grep -qF -- "$needle" "$root/err" || problems="$problems; the message does not name '$needle'"
  [ -z "$left" ] || problems="$problems; left behind: $(echo $left)"
  if [ -z "$problems" ]; then
    echo "ok:   $case -> exit $got: $message"
  else
    echo "FAIL: $case -> exit $got${problems}"
    sed 's/^/      stderr: /' "$root/err" | head -5
    failures=$((failures + 1))
  fi
done
[ "$failures" -gt 0 ] && exit 1
[ "$ran" = 0 ] && [ "$skipped" -gt 0 ] && exit 77
exit 0
