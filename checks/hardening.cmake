# Hardening (issue 7): the suite survives what a user can set or do.
#
#   extreme settings  every program across a covering grid of step, ERP, CFM,
#                     iterations and solver (checks/extreme_settings.cpp)
#   bad input         every option of every program given malformed values;
#                     missing or broken shaders and font; no display
#   determinism       the same run twice: the same state_hash, the same files
#   interrupted runs  an output file killed mid-run or cut short by a full
#                     disk still parses up to its last complete row, and no
#                     metrics JSON, whole or partial, is left
#
# The three shell helpers are kept at the end of this file and written into
# the build folder, so this file is the whole of it. doc/hardening.md has
# the figures; checks/long_runs.sh and checks/sanitize.sh are run by hand
# (or from scripts/odelab.sh).

set(_hardening_dir ${CMAKE_CURRENT_BINARY_DIR}/hardening)
file(MAKE_DIRECTORY ${_hardening_dir})

# The programs that exist (the table in the top-level CMakeLists.txt).
set(_hardening_programs)
list(LENGTH ODELAB_PROGRAMS _hardening_count)
math(EXPR _hardening_last "${_hardening_count} - 1")
foreach(_i RANGE 0 ${_hardening_last} 2)
  list(GET ODELAB_PROGRAMS ${_i} _program)
  if(TARGET ${_program})
    list(APPEND _hardening_programs ${_program})
  endif()
endforeach()

# ---- extreme settings -------------------------------------------------------
# Every program, headless, across step 1e-5 ... 0.1, ERP 0/0.5/1, CFM
# 0/1e-3/1, iterations 1/20/1000, solver quick/step: a pairwise covering set
# (15 settings in which every value of every parameter meets every value of
# every other parameter) plus 6 extreme corners, 21 settings x 11 programs =
# 231 runs of min(3 s, 10000 steps) simulated time each. No run may crash
# (a signal) or hang (no end within 120 s); a blow-up must end with status 3
# and a message naming the run's very settings, an ODE error with status 4
# and ODE's message; any other end fails. The table lists every run.
add_executable(extreme_settings extreme_settings.cpp)
target_link_libraries(extreme_settings PRIVATE odelab_physics)
set(_grid_programs)
foreach(_program IN LISTS _hardening_programs)
  list(APPEND _grid_programs $<TARGET_FILE:${_program}>)
endforeach()
file(MAKE_DIRECTORY ${_hardening_dir}/extreme_settings)
add_test(NAME extreme_settings_grid
         COMMAND extreme_settings --jobs 2 --timeout 120 --step-budget 10000 --max-seconds 3 --strict-ode-errors
                 --work-dir ${_hardening_dir}/extreme_settings ${_grid_programs})
# It runs two programs at a time, so CTest counts it as two.
set_tests_properties(extreme_settings_grid PROPERTIES PROCESSORS 2 TIMEOUT 1200)

# ---- bad input --------------------------------------------------------------
# Each check runs a program once per bad value (refusals.sh, written into
# the build folder from the end of this file): the run must end with the stated status, print a message that says
# "error" and names the option, and leave its folder (its --out-dir and the
# home of its --metrics-json) empty. Status 2: a refused option; 5: shaders or
# font missing or unusable; 6: no display. "<empty>" stands for an empty
# argument (--step ""), which CMake cannot pass as such.
set(_refusals ${_hardening_dir}/refusals.sh)

# Values already checked by a test of the same meaning elsewhere (the
# <program>_refuses<option=value> tests of the scene files are found by name).
set(_hardening_checked_elsewhere
  "test6 --max-angular-speed=0" "test6 --max-angular-speed=nan" "test6 --tilt-degrees=-0.1" "test6 --tilt-degrees=1"
  "test7 --max-angular-speed=-1" "test7 --max-angular-speed=nan" "test7 --throws=0" "test7 --throw-interval=0"
  "test7 --throw-interval=inf" "test10 --velocity=-1" "test10 --velocity=nan" "test10 --launches=0"
  "test10 --scan-limit=0" "test10 --band-factor=0.5" "test10 --ccd=maybe")

# odelab_refusals(PROGRAM NAME MODE STATUS OPTION [EXTRA "args"] [NEEDLE text] VALUES...)
# MODE: headless, window (under Xvfb), no-display or bad-display. OPTION "-":
# each value is a whole argument. NEEDLE: what the message must contain
# instead of the option's name.
function(odelab_refusals program name mode status option)
  cmake_parse_arguments(R "" "EXTRA;NEEDLE" "" ${ARGN})
  set(extra none)
  if(DEFINED R_EXTRA)
    set(extra "${R_EXTRA}")
  endif()
  set(values)
  foreach(_value IN LISTS R_UNPARSED_ARGUMENTS)
    if(option STREQUAL "-")
      set(_given "${_value}")
    else()
      set(_given "${option}=${_value}")
    endif()
    string(MAKE_C_IDENTIFIER "${_given}" _id)
    if(TEST ${program}_refuses${_id} OR "${program} ${_given}" IN_LIST _hardening_checked_elsewhere)
      continue()
    endif()
    list(APPEND values "${_value}")
  endforeach()
  if(NOT values)
    return()
  endif()
  add_test(NAME ${program}_${name}
           COMMAND sh ${_refusals} ${mode} $<TARGET_FILE:${program}> ${status} ${option} "${extra}" ${values})
  set(environment "ODELAB_SHADERS=${CMAKE_SOURCE_DIR}/shaders")
  if(DEFINED R_NEEDLE)
    list(APPEND environment "NEEDLE=${R_NEEDLE}")
  endif()
  set_tests_properties(${program}_${name} PROPERTIES TIMEOUT 600 SKIP_RETURN_CODE 77 ENVIRONMENT "${environment}")
endfunction()

# The common options, in every program. Numbers: empty, out of range, NaN,
# infinities, 1e400 (beyond a double), text; integers also a fraction and
# 20 digits (beyond any integer type).
set(_bad--seconds "<empty>" 0 -1 nan inf -inf 1e400 abc 1e8)
set(_bad--step "<empty>" 0 -1 nan inf 1e400 abc 1 1e-7)
set(_bad--erp "<empty>" -0.1 1.5 nan inf 1e400 abc)
set(_bad--cfm "<empty>" -1 2 nan inf 1e400 abc)
set(_bad--sor "<empty>" 0 -1 2 nan inf abc)
set(_bad--iterations "<empty>" 0 -1 10001 1.5 abc 99999999999999999999)
set(_bad--solver "<empty>" fast QUICK 1)
set(_bad--seed "<empty>" -1 1.5 abc 4294967296 99999999999999999999)
set(_bad--frames "<empty>" 0 -1 1.5 abc 99999999999999999999)
set(_bad--width "<empty>" 0 63 16385 -1 abc 99999999999999999999)
set(_bad--height "<empty>" 0 63 16385 -1 abc 99999999999999999999)
# Folders and files: empty, missing, a regular file where a folder belongs,
# a path under a regular file (unwritable even for root), a folder where a
# file belongs.
set(_bad--out-dir "<empty>" /nonexistent-folder /etc/passwd /etc/passwd/x)
set(_bad--metrics-json "<empty>" /nonexistent-folder/m.json /etc/passwd/m.json .)
set(_bad--record "<empty>" /nonexistent-folder /etc/passwd)
set(_bad--events "<empty>" /nonexistent-file.events)
# An explicit empty path is an error, not "search as usual" or "none".
set(_bad--screenshot "<empty>")
set(_bad--shader-dir "<empty>")
set(_bad--font "<empty>")
# A flag takes no value but true/false.
set(_bad--headless maybe)
set(_hardening_common_options --seconds --step --erp --cfm --sor --iterations --solver --seed --frames --width
    --height --out-dir --metrics-json --screenshot --record --events --shader-dir --font)

# The scene options (each program's --help).
set(_bad_test0--spawn-interval "<empty>" 0 -1 nan inf 1e400 abc)
set(_bad_test0--spawn-count "<empty>" -1 1.5 abc 99999999999999999999)
set(_bad_test0--spawn-shapes "<empty>" cube BOX 1)
set(_bad_test2--sample-interval "<empty>" 0 -0.01 nan inf 1e400 abc)
set(_bad_test3--dominoes "<empty>" 0 1 -1 1001 1.5 ten 99999999999999999999)
set(_bad_test3--mu "<empty>" -1 -inf nan abc)
set(_bad_test3--no-auto-disable maybe)
set(_bad_test4--big-mass "<empty>" 0 -1 nan inf 1e400 heavy)
set(_bad_test5--plates "<empty>" 0 -5 100001 1.5 many 99999999999999999999)
set(_bad_test5--spawn-interval "<empty>" 0 -1 nan inf abc)
set(_bad_test5--space "<empty>" octree SIMPLE)
set(_bad_test6--max-angular-speed "<empty>" 0 -1 nan inf abc)
set(_bad_test6--tilt-degrees "<empty>" -0.1 1 nan inf abc)
set(_bad_test7--max-angular-speed "<empty>" -1 nan inf 1e7 abc)
set(_bad_test7--throws "<empty>" 0 -1 1001 1.5 abc)
set(_bad_test7--throw-interval "<empty>" 0 -1 nan inf abc)
set(_bad_test8--bob-mass "<empty>" 0 -1 nan inf abc)
set(_bad_test8--sample-interval "<empty>" 0 -1 nan inf abc)
set(_bad_test10--velocity "<empty>" 0 -1 nan inf 1e400 abc)
set(_bad_test10--launches "<empty>" 0 -1 100001 1.5 abc)
set(_bad_test10--find-max-velocity maybe)
set(_bad_test10--phase-jitter maybe)
set(_bad_test10--random-orientation maybe)
set(_bad_test10--ccd maybe)
# The scan's own options are checked with the scan on (without it they are
# refused for that alone: test10_refuses_scan_option_without_scan).
set(_bad_test10--scan-limit "<empty>" 0 -1 nan inf abc)
set(_bad_test10--band-factor "<empty>" 0.5 101 nan inf abc)
set(_extra_test10--scan-limit --find-max-velocity)
set(_extra_test10--band-factor --find-max-velocity)

foreach(_program IN LISTS _hardening_programs)
  foreach(_option IN LISTS _hardening_common_options)
    string(REGEX REPLACE "^--" "" _name "${_option}")
    string(MAKE_C_IDENTIFIER "${_name}" _name)
    odelab_refusals(${_program} refuses_bad_${_name} headless 2 ${_option} ${_bad${_option}})
  endforeach()
  # A flag given a value; a window-only option with --headless.
  odelab_refusals(${_program} refuses_bad_headless_flag no-display 2 --headless ${_bad--headless})
  odelab_refusals(${_program} refuses_window_options_when_headless headless 2 - --screenshot=shot.png --record=.)
  # Unknown options, a stray word, an option twice, a missing value.
  odelab_refusals(${_program} refuses_unknown_arguments headless 2 -
                  --no-such-option -x extra --Step=0.01 --step)
  odelab_refusals(${_program} refuses_an_option_twice headless 2 --seconds EXTRA --seconds=1 2)
  # An output folder that exists but cannot be written (skipped as root).
  odelab_refusals(${_program} refuses_unwritable_out_dir headless 2 --out-dir "<unwritable-dir>")
  # The scene's own options.
  get_cmake_property(_variables VARIABLES)
  foreach(_variable IN LISTS _variables)
    if(_variable MATCHES "^_bad_${_program}(--.*)$")
      set(_option ${CMAKE_MATCH_1})
      string(REGEX REPLACE "^--" "" _name "${_option}")
      string(MAKE_C_IDENTIFIER "${_name}" _name)
      set(_extra)
      if(DEFINED _extra_${_program}${_option})
        set(_extra EXTRA "${_extra_${_program}${_option}}")
      endif()
      odelab_refusals(${_program} refuses_bad_${_name} headless 2 ${_option} ${_extra} ${${_variable}})
    endif()
  endforeach()
  # Window-only paths that cannot be written are refused before any window
  # is needed (so without a display too).
  odelab_refusals(${_program} window_refuses_unwritable_paths no-display 2 -
                  --screenshot=/nonexistent-folder/shot.png --record=/nonexistent-folder)
endforeach()

# ---- shaders, font and display ----------------------------------------------
# In every program: missing shaders and a missing font end with status 5 and
# a message naming the path; no display, or a display that is not there,
# with status 6. A refused window run writes nothing (test2 and test8 would
# otherwise leave an output file). test0's missing-shaders and no-display
# checks are in windowed.cmake.
find_program(XVFB_RUN xvfb-run)
foreach(_program IN LISTS _hardening_programs)
  if(XVFB_RUN)
    if(NOT _program STREQUAL "test0")
      odelab_refusals(${_program} window_missing_shaders_exits_5 window 5 --shader-dir /nonexistent-shaders)
    endif()
    odelab_refusals(${_program} window_missing_font_exits_5 window 5 --font /nonexistent-font.ttf)
  endif()
  if(NOT _program STREQUAL "test0")
    odelab_refusals(${_program} window_without_display_exits_6 no-display 6 - NEEDLE "cannot open a window"
                    --seconds=1)
  endif()
  odelab_refusals(${_program} window_with_absent_display_exits_6 bad-display 6 - NEEDLE "cannot open a window"
                  --seconds=1)
endforeach()

# Shader folders that are wrong inside (framework code, so test0 stands for
# all): one shader missing, one that does not compile, a folder where a
# shader belongs, one unreadable (skipped as root); a font that is not a
# font, a folder as the font. Each is a resource problem: status 5, and the
# message names the file.
if(XVFB_RUN AND TARGET test0)
  set(_fixtures ${_hardening_dir}/shader_fixtures)
  file(REMOVE_RECURSE ${_fixtures})
  file(GLOB _shader_files ${CMAKE_SOURCE_DIR}/shaders/*)
  foreach(_fixture missing_depth broken_scene folder_scene)
    file(COPY ${_shader_files} DESTINATION ${_fixtures}/${_fixture})
  endforeach()
  file(REMOVE ${_fixtures}/missing_depth/depth.vert)
  file(WRITE ${_fixtures}/broken_scene/scene.frag "#version 330 core\nthis is not GLSL(\n")
  file(REMOVE ${_fixtures}/folder_scene/scene.frag)
  file(MAKE_DIRECTORY ${_fixtures}/folder_scene/scene.frag)
  odelab_refusals(test0 window_unusable_shaders_exit_5 window 5 --shader-dir
                  ${_fixtures}/missing_depth ${_fixtures}/broken_scene ${_fixtures}/folder_scene)
  odelab_refusals(test0 window_unreadable_shader_exits_5 window 5 --shader-dir "<unreadable-shaders>")
  odelab_refusals(test0 window_unusable_font_exits_5 window 5 --font /etc/passwd ${_fixtures})
endif()

# ---- determinism ------------------------------------------------------------
# Every program, run twice headless with the same settings and seed, each in
# its own folder: the same state_hash (a hash of every body's exact state,
# in the metrics) and byte-identical output files (cmp). Where the scene
# draws from --seed (test0's sizes, test10's launch phase and orientation),
# another seed must give another hash.
set(_deterministic_test0 2 --seconds 5 --spawn-interval 0.2)
set(_deterministic_test1 none --seconds 3)
set(_deterministic_test2 none --seconds 3)
set(_deterministic_test3 none --seconds 4)
set(_deterministic_test4 none --seconds 2)
set(_deterministic_test5 none --seconds 3 --spawn-interval 0.1)
set(_deterministic_test6 none --seconds 2)
set(_deterministic_test7 none --throws 2 --throw-interval 1)
set(_deterministic_test8 none --seconds 3)
set(_deterministic_test9 none --seconds 3)
set(_deterministic_test10 2 --launches 3 --phase-jitter --random-orientation)
foreach(_program IN LISTS _hardening_programs)
  if(NOT DEFINED _deterministic_${_program})
    set(_deterministic_${_program} none --seconds 2)
  endif()
  add_test(NAME ${_program}_same_seed_same_state_and_files
           COMMAND sh ${_hardening_dir}/determinism.sh $<TARGET_FILE:${_program}> ${_deterministic_${_program}})
  set_tests_properties(${_program}_same_seed_same_state_and_files PROPERTIES TIMEOUT 600)
endforeach()

# ---- interrupted runs ---------------------------------------------------------
# test2 killed with SIGKILL mid-run; test2 and test8 stopped by a 2 KiB file
# size limit (status 1, "cannot write"): the output file parses up to its last
# complete row (check_output_file on the part before the last newline), and
# no metrics JSON exists.
foreach(_case "test2;kill;Test2_output.txt;time_s,potential_J,kinetic_J,total_J"
              "test2;file-limit;Test2_output.txt;time_s,potential_J,kinetic_J,total_J"
              "test8;kill;Test8_output.txt;time_s,relative_elongation,deflection_rad"
              "test8;file-limit;Test8_output.txt;time_s,relative_elongation,deflection_rad")
  list(GET _case 0 _program)
  list(GET _case 1 _how)
  list(GET _case 2 _file)
  list(GET _case 3 _columns)
  if(TARGET ${_program})
    string(MAKE_C_IDENTIFIER "${_how}" _id)
    add_test(NAME ${_program}_output_file_parses_after_${_id}
             COMMAND sh ${_hardening_dir}/interrupted_output.sh ${_how} $<TARGET_FILE:${_program}>
                     $<TARGET_FILE:check_output_file> ${_file} ${_columns} 0.01)
    set_tests_properties(${_program}_output_file_parses_after_${_id} PROPERTIES TIMEOUT 300)
  endif()
endforeach()

# ---- the helpers ---------------------------------------------------------------
file(WRITE ${_hardening_dir}/refusals.sh [==[
#!/bin/sh
# refusals.sh MODE PROGRAM STATUS OPTION EXTRA VALUE...
#
# Runs PROGRAM once per VALUE and checks that each run is refused cleanly:
# it ends with exactly STATUS (within 60 s), prints a message on standard
# error that says "error" and names OPTION (for a path given to --shader-dir
# or --font: the path), and leaves nothing behind in its folder.
#   MODE    headless (adds --headless), window (under xvfb-run; the program's
#           own status is taken, not xvfb-run's, whose cleanup can fail with
#           5), no-display (DISPLAY and WAYLAND_DISPLAY unset) or bad-display
#           (DISPLAY names a server that does not exist).
#   OPTION  each VALUE is given as OPTION=VALUE, or as OPTION "" for the value
#           <empty>; with OPTION "-" each VALUE is one whole argument (an
#           unknown option, a stray word), and the message must name it (up
#           to its "=").
#   EXTRA   fixed arguments for every run, split at spaces; "none" for none.
#   VALUE   <unwritable-dir>: a fresh folder with mode 555; <unreadable-shaders>:
#           a copy of $ODELAB_SHADERS whose scene.frag has mode 000. As root,
#           where permissions stop nothing, such a value is skipped with a
#           message (status 77, CTest's skip, when nothing else ran).
# $NEEDLE, when set, replaces what the message must name.
# Each run's working directory is a fresh empty folder: its --out-dir (the
# default ".") and the home of its --metrics-json, so any file it leaves
# behind is seen.
mode=$1 program=$2 status=$3 option=$4 extra=$5
shift 5
[ "$extra" = none ] && extra=
root=$(mktemp -d "${TMPDIR:-/tmp}/odelab_refusals.XXXXXX") || exit 2
trap 'chmod -R u+rwx "$root" 2>/dev/null; rm -rf "$root"' EXIT
failures=0 ran=0 skipped=0 n=0
for value; do
  n=$((n + 1))
  run="$root/run$n"
  mkdir "$run"
  shown=$value
  case $value in
    "<empty>") value= ;;
    "<unwritable-dir>" | "<unreadable-shaders>")
      if [ "$(id -u)" = 0 ]; then
        echo "skipped: $option $value: running as root, where file permissions do not stop reading or writing"
        skipped=$((skipped + 1))
        continue
      fi
      if [ "$value" = "<unwritable-dir>" ]; then
        value="$root/unwritable$n"
        mkdir "$value" && chmod 555 "$value"
      else
        value="$root/unreadable$n"
        cp -r "$ODELAB_SHADERS" "$value" && chmod 000 "$value/scene.frag"
      fi ;;
  esac
  # The arguments: mode, the bad one, the fixed ones, a metrics file.
  set --
  [ "$mode" = headless ] && set -- --headless
  # A window run that is wrongly let through still ends, and leaves its metrics.
  [ "$mode" = window ] && set -- --seconds 0.5
  if [ "$option" = - ]; then
    set -- "$@" "$value"
    needle=${value%%=*}
  elif [ -z "$value" ]; then
    set -- "$@" "$option" ""
    needle=$option
  else
    set -- "$@" "$option=$value"
    needle=$option
    case $option in --shader-dir | --font) needle=$value ;; esac
  fi
  [ -n "$NEEDLE" ] && needle=$NEEDLE
  # shellcheck disable=SC2086 # EXTRA is split at spaces on purpose
  set -- "$@" $extra
  [ "$option" = --metrics-json ] || set -- "$@" --metrics-json metrics.json
  rm -f "$root/status"
  case $mode in
    window)
      (cd "$run" && STATUS_FILE="$root/status" timeout 60 xvfb-run -a -s "-screen 0 1280x800x24" \
        sh -c '"$@"; echo $? > "$STATUS_FILE"' sh "$program" "$@") >"$root/out" 2>"$root/err"
      wrapper=$?
      got=$(cat "$root/status" 2>/dev/null) || got="none (xvfb-run or timeout ended with $wrapper)" ;;
    no-display)
      (cd "$run" && timeout 60 env -u DISPLAY -u WAYLAND_DISPLAY "$program" "$@") >"$root/out" 2>"$root/err"
      got=$? ;;
    bad-display)
      (cd "$run" && timeout 60 env -u WAYLAND_DISPLAY DISPLAY=:4242 "$program" "$@") >"$root/out" 2>"$root/err"
      got=$? ;;
    *)
      (cd "$run" && timeout 60 "$program" "$@") >"$root/out" 2>"$root/err"
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
    echo "ok:   $option $shown -> exit $got: $message"
  else
    echo "FAIL: $option $shown -> exit $got${problems}"
    sed 's/^/      stderr: /' "$root/err" | head -5
    failures=$((failures + 1))
  fi
done
[ "$failures" -gt 0 ] && exit 1
[ "$ran" = 0 ] && [ "$skipped" -gt 0 ] && exit 77
exit 0
]==])

file(WRITE ${_hardening_dir}/determinism.sh [==[
#!/bin/sh
# determinism.sh PROGRAM OTHER_SEED ARGS...
#
# Runs PROGRAM --headless ARGS twice, each in a fresh folder (its --out-dir),
# and checks that both end with status 0, report the same state_hash in
# their metrics JSON and write the same set of output files, byte for byte
# (cmp). The metrics JSON itself is not compared: wall_seconds and
# real_time_factor differ from run to run by nature. With OTHER_SEED (not
# "none"), a third run with --seed OTHER_SEED must report a different hash,
# so the hash is shown to depend on the seeded choices.
program=$1 other_seed=$2
shift 2
root=$(mktemp -d "${TMPDIR:-/tmp}/odelab_determinism.XXXXXX") || exit 2
trap 'rm -rf "$root"' EXIT
hash_of() {
  sed -n 's/^ *"state_hash": *\([0-9][0-9]*\).*/\1/p' "$1/metrics.json"
}
run() {  # run NAME ARGS...
  name=$1
  shift
  mkdir "$root/$name"
  (cd "$root/$name" && timeout 300 "$program" --headless "$@" --metrics-json metrics.json >/dev/null 2>"$root/$name.err")
  status=$?
  if [ "$status" != 0 ]; then
    echo "FAIL: run $name ended with status $status"
    sed 's/^/      stderr: /' "$root/$name.err" | head -5
    exit 1
  fi
}
run a "$@"
run b "$@"
a=$(hash_of "$root/a") b=$(hash_of "$root/b")
failures=0
if [ -z "$a" ]; then
  echo "FAIL: no state_hash in the metrics"
  exit 1
fi
if [ "$a" = "$b" ]; then echo "ok:   state_hash $a in both runs"
else echo "FAIL: state_hash $a, then $b"; failures=$((failures + 1)); fi
files_a=$(cd "$root/a" && ls | grep -v '^metrics\.json$')
files_b=$(cd "$root/b" && ls | grep -v '^metrics\.json$')
if [ "$files_a" != "$files_b" ]; then
  echo "FAIL: the runs wrote different files: [$files_a] and [$files_b]"
  failures=$((failures + 1))
fi
for f in $files_a; do
  if cmp "$root/a/$f" "$root/b/$f"; then echo "ok:   $f identical ($(wc -c < "$root/a/$f") bytes)"
  else failures=$((failures + 1)); fi
done
if [ "$other_seed" != none ]; then
  run c "$@" --seed "$other_seed"
  c=$(hash_of "$root/c")
  if [ "$c" != "$a" ]; then echo "ok:   --seed $other_seed gives another state_hash ($c)"
  else echo "FAIL: --seed $other_seed gives the same state_hash"; failures=$((failures + 1)); fi
fi
[ "$failures" = 0 ]
]==])

file(WRITE ${_hardening_dir}/interrupted_output.sh [==[
#!/bin/sh
# interrupted_output.sh HOW PROGRAM CHECKER FILE COLUMNS INTERVAL ARGS...
#
# An output file must survive a run that does not end normally: it parses
# (CHECKER: check_output_file) up to its last complete row, and no metrics
# JSON, whole or partial, exists. HOW:
#   kill        the run (--seconds 100000, far beyond its end) is killed with
#               SIGKILL once FILE holds 200 lines;
#   file-limit  the run (--seconds 60) may write 2 KiB per file (ulimit -f 4,
#               SIGXFSZ ignored): it must stop with status 1 and a message
#               naming FILE.
how=$1 program=$2 checker=$3 file=$4 columns=$5 interval=$6
shift 6
root=$(mktemp -d "${TMPDIR:-/tmp}/odelab_interrupted.XXXXXX") || exit 2
pid=
trap '[ -n "$pid" ] && kill -KILL "$pid" 2>/dev/null; rm -rf "$root"' EXIT
cd "$root" || exit 2
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
case $how in
  kill)
    "$program" --headless --seconds 100000 --metrics-json metrics.json "$@" >/dev/null 2>err.txt &
    pid=$!
    waited=0
    while [ "$(cat "$file" 2>/dev/null | wc -l)" -lt 200 ]; do
      kill -0 "$pid" 2>/dev/null || { fail "the run ended before it was killed"; cat err.txt; exit 1; }
      [ "$waited" -ge 600 ] && { fail "$file did not reach 200 lines within 60 s"; exit 1; }
      sleep 0.1
      waited=$((waited + 1))
    done
    kill -KILL "$pid"
    wait "$pid" 2>/dev/null
    status=$?
    pid=
    [ "$status" = 137 ] || fail "status $status after SIGKILL, expected 137"
    ;;
  file-limit)
    (ulimit -f 4; trap '' XFSZ; exec "$program" --headless --seconds 60 --metrics-json metrics.json "$@") >/dev/null 2>err.txt
    status=$?
    [ "$status" = 1 ] || fail "status $status, expected 1 (an output file could not be written)"
    grep -q "error: cannot write.*$file" err.txt || fail "no 'error: cannot write ... $file' message"
    sed 's/^/      stderr: /' err.txt | head -3
    ;;
  *) echo "usage: interrupted_output.sh kill|file-limit PROGRAM CHECKER FILE COLUMNS INTERVAL ARGS..."; exit 2 ;;
esac
[ -e metrics.json ] && fail "a metrics JSON exists after the interrupted run"
[ -e metrics.json.tmp ] && fail "a partial metrics JSON (metrics.json.tmp) exists"
[ -s "$file" ] || { fail "$file is missing or empty"; exit 1; }
# The complete part: everything up to the last newline.
bytes=$(wc -c < "$file")
complete=$(tr -cd '\n' < "$file" | wc -c)
head -n "$complete" "$file" > complete.txt
tail_bytes=$((bytes - $(wc -c < complete.txt)))
# Every line that is not a comment is a row, but the first: the column names.
rows=$(($(grep -vc '^#' complete.txt) - 1))
echo "$file: $bytes bytes, $complete complete lines ($rows rows), $tail_bytes bytes of an unfinished line after them"
"$checker" complete.txt --columns "$columns" --interval "$interval" --rows "$rows" || failures=$((failures + 1))
[ "$failures" = 0 ]
]==])

