# The options every program shares (utils/CommandLine.cpp: addCommonOptions,
# rejectEmptyValues, validateRunOptions, called by runScene for every
# program) refused once, end to end through one program: each bad value must
# end the run with status 2, a message that says "error" and names the
# option, and nothing written (scripts/refusals.sh). The parser itself is
# unit-tested with the same values (checks/unit/test_command_line.cpp), and
# every program's refuses_bad_options check gives it one of them, which
# shows that the program reads its options through the shared parser.
set(ODELAB_COMMON_OPTIONS_PROGRAM test0)

# Numbers: empty, out of range, NaN, infinities, 1e400 (beyond a double),
# text; integers also a fraction and 20 digits (beyond any integer type).
set(_bad--seconds "<empty>" 0 -1 nan inf -inf 1e400 abc 1e8)
set(_bad--step "<empty>" 0 -1 nan inf 1e400 abc 1 1e-7)
set(_bad--erp "<empty>" -0.1 1.5 2 nan inf 1e400 abc)
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

set(_program ${ODELAB_COMMON_OPTIONS_PROGRAM})
foreach(_option --seconds --step --erp --cfm --sor --iterations --solver --seed --frames --width --height
                --out-dir --metrics-json --screenshot --record --events --shader-dir --font)
  set(_cases)
  foreach(_value IN LISTS _bad${_option})
    list(APPEND _cases "${_option}=${_value}")
  endforeach()
  string(REGEX REPLACE "^--" "" _name "${_option}")
  string(MAKE_C_IDENTIFIER "${_name}" _name)
  odelab_refusals(${_program} refuses_bad_${_name} headless 2 ${_cases})
endforeach()
# A flag given a value; window-only options with --headless.
odelab_refusals(${_program} refuses_bad_headless_flag no-display 2 --headless=maybe)
odelab_refusals(${_program} refuses_window_options_when_headless headless 2 --screenshot=shot.png --record=.)
# Unknown options, a stray word, a misspelt option, a missing value.
odelab_refusals(${_program} refuses_unknown_arguments headless 2 --no-such-option -x extra --Step=0.01 --step)
# An option given twice.
odelab_refusals(${_program} refuses_an_option_twice headless 2 "--seconds=1 --seconds=2" "--seconds=2 --seconds")
# An output folder that exists but cannot be written (skipped as root).
odelab_refusals(${_program} refuses_unwritable_out_dir headless 2 --out-dir=<unwritable-dir>)
# Window-only paths that cannot be written are refused before any window is
# needed (so without a display too).
odelab_refusals(${_program} window_refuses_unwritable_paths no-display 2
                --screenshot=/nonexistent-folder/shot.png --record=/nonexistent-folder)
