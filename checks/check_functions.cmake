# The kinds of check, as functions the per-program files and the framework
# files call. Each gives its tests their label (checks/CMakeLists.txt).
set(ODELAB_CHECK_SCRIPTS ${CMAKE_CURRENT_SOURCE_DIR}/scripts)

# odelab_check(NAME PROGRAM EXPECT <name<op>value>... [STATUS n] [LABEL l] ARGS <program args>...)
# Runs PROGRAM headless (given --headless in ARGS) and checks its metrics
# against the stated bounds (expect_metrics.cpp). Label: scene, unless LABEL.
function(odelab_check name program)
  cmake_parse_arguments(C "" "STATUS;LABEL" "EXPECT;ARGS" ${ARGN})
  set(status_args)
  if(DEFINED C_STATUS)
    set(status_args --status ${C_STATUS})
  endif()
  if(NOT DEFINED C_LABEL)
    set(C_LABEL scene)
  endif()
  # A folder of its own: the programs write their output files into the
  # working folder, and two runs into one folder refuse each other (a lock),
  # so checks that run at the same time (ctest -j) must not share one.
  set(dir ${CMAKE_CURRENT_BINARY_DIR}/runs/${name})
  file(MAKE_DIRECTORY ${dir})
  add_test(NAME ${name}
           COMMAND expect_metrics ${status_args} ${C_EXPECT} -- $<TARGET_FILE:${program}> ${C_ARGS}
           WORKING_DIRECTORY ${dir})
  set_tests_properties(${name} PROPERTIES LABELS ${C_LABEL})
endfunction()

# odelab_refusals(PROGRAM NAME MODE STATUS [NEEDLE text] CASE...)
# Test PROGRAM_NAME runs PROGRAM once per CASE (scripts/refusals.sh says how
# a case is written): each run must end with STATUS, print a message that
# says "error" and names the bad argument (or NEEDLE), and leave its folder
# (its --out-dir and the home of its --metrics-json) empty. Status 2: a
# refused option; 5: shaders or font missing or unusable; 6: no display.
# MODE: headless, window (under Xvfb; left out without xvfb-run), no-display
# or bad-display. Label: hardening.
function(odelab_refusals program name mode status)
  cmake_parse_arguments(R "" "NEEDLE" "" ${ARGN})
  if(mode STREQUAL "window" AND NOT XVFB_RUN)
    return()
  endif()
  add_test(NAME ${program}_${name}
           COMMAND sh ${ODELAB_CHECK_SCRIPTS}/refusals.sh ${mode} $<TARGET_FILE:${program}> ${status}
                   ${R_UNPARSED_ARGUMENTS})
  set(environment "ODELAB_SHADERS=${CMAKE_SOURCE_DIR}/shaders")
  if(DEFINED R_NEEDLE)
    list(APPEND environment "NEEDLE=${R_NEEDLE}")
  endif()
  set_tests_properties(${program}_${name} PROPERTIES TIMEOUT 600 SKIP_RETURN_CODE 77 ENVIRONMENT "${environment}"
                       LABELS hardening)
  # Each program's own bad values, run again on its Windows build (windows.cmake).
  if(name STREQUAL "refuses_bad_options")
    set_property(GLOBAL PROPERTY ODELAB_BAD_OPTIONS_${program} "${R_UNPARSED_ARGUMENTS}")
  endif()
endfunction()

# odelab_window_refusals(PROGRAM): a window run that cannot start is refused
# before the scene is built, so it writes nothing: missing shaders and a
# missing font end with status 5 naming the path, no display or one that is
# not there with status 6. Framework code, checked through test0 and through
# the programs that write output files (test2, test8), which would otherwise
# leave one behind.
function(odelab_window_refusals program)
  odelab_refusals(${program} window_missing_shaders_exits_5 window 5 --shader-dir=/nonexistent-shaders)
  odelab_refusals(${program} window_missing_font_exits_5 window 5 --font=/nonexistent-font.ttf)
  odelab_refusals(${program} window_without_display_exits_6 no-display 6 NEEDLE "cannot open a window"
                  --seconds=1)
  odelab_refusals(${program} window_with_absent_display_exits_6 bad-display 6 NEEDLE "cannot open a window"
                  --seconds=1)
endfunction()

# odelab_determinism(PROGRAM [OTHER_SEED n] ARGS...): PROGRAM run twice
# headless with ARGS, each in its own folder, gives the same state_hash (a
# hash of every body's exact state, in the metrics) and byte-identical output
# files; with OTHER_SEED, a run with --seed n gives another hash (for scenes
# that draw from --seed). scripts/determinism.sh. Label: hardening.
function(odelab_determinism program)
  cmake_parse_arguments(D "" "OTHER_SEED" "" ${ARGN})
  if(NOT DEFINED D_OTHER_SEED)
    set(D_OTHER_SEED none)
  endif()
  set(name ${program}_same_seed_same_state_and_files)
  add_test(NAME ${name}
           COMMAND sh ${ODELAB_CHECK_SCRIPTS}/determinism.sh $<TARGET_FILE:${program}> ${D_OTHER_SEED}
                   ${D_UNPARSED_ARGUMENTS})
  set_tests_properties(${name} PROPERTIES TIMEOUT 600 LABELS hardening)
  # The same short run, compared with the program's Windows build (windows.cmake).
  set_property(GLOBAL PROPERTY ODELAB_SHORT_RUN_${program} "${D_UNPARSED_ARGUMENTS}")
endfunction()

# odelab_interrupted_output(PROGRAM HOW FILE COLUMNS): PROGRAM's output FILE
# survives a run that does not end normally (HOW: kill, file-limit): it
# parses up to its last complete row, and no metrics JSON is left
# (scripts/interrupted_output.sh). Label: hardening.
function(odelab_interrupted_output program how file columns)
  string(MAKE_C_IDENTIFIER "${how}" id)
  set(name ${program}_output_file_parses_after_${id})
  add_test(NAME ${name}
           COMMAND sh ${ODELAB_CHECK_SCRIPTS}/interrupted_output.sh ${how} $<TARGET_FILE:${program}>
                   $<TARGET_FILE:check_output_file> ${file} ${columns} 0.01)
  set_tests_properties(${name} PROPERTIES TIMEOUT 300 LABELS hardening)
endfunction()

# odelab_window_check(NAME PROGRAM EVENTS <file in scripts/> EXPECT <name<op>bound>... ARGS <program args>...)
# PROGRAM's window under Xvfb plays the scripted input, then its metrics are
# checked (expect_metrics.cpp). Every run gets its own folder for output
# files. Left out without xvfb-run. Label: window.
function(odelab_window_check name program)
  if(NOT XVFB_RUN)
    return()
  endif()
  cmake_parse_arguments(C "" "EVENTS" "EXPECT;ARGS" ${ARGN})
  set(dir ${CMAKE_CURRENT_BINARY_DIR}/window_runs/${name})
  file(MAKE_DIRECTORY ${dir})
  add_test(NAME ${name}
           COMMAND ${XVFB_RUN} -a -s "-screen 0 1280x800x24" $<TARGET_FILE:expect_metrics> ${C_EXPECT}
                   -- $<TARGET_FILE:${program}> --events ${ODELAB_CHECK_SCRIPTS}/${C_EVENTS}
                   --out-dir ${dir} ${C_ARGS}
           WORKING_DIRECTORY ${dir})
  set_tests_properties(${name} PROPERTIES TIMEOUT 180 LABELS window)
endfunction()

# Stops the configuration when a test of this folder has no label, naming it.
function(odelab_require_labels)
  get_directory_property(tests TESTS)
  set(unlabelled)
  foreach(test IN LISTS tests)
    get_test_property(${test} LABELS labels)
    if(NOT labels)
      list(APPEND unlabelled ${test})
    endif()
  endforeach()
  if(unlabelled)
    list(JOIN unlabelled ", " names)
    message(FATAL_ERROR "checks: tests without LABELS (give each one of unit, scene, window, hardening, fuzz, "
                        "lab, install, peers, cluster; see checks/CMakeLists.txt): ${names}")
  endif()
endfunction()

# odelab_contact_choice_refusals(PROGRAM): a scene with contacts refuses a
# friction coefficient that is not a number >= 0 or inf, and a contact limit
# per pair outside 1 ... 64 or not whole (utils/ContactChoices.cpp).
function(odelab_contact_choice_refusals program)
  odelab_refusals(${program} refuses_bad_contact_choices headless 2
    --mu=<empty> --mu=-1 --mu=-inf --mu=nan --mu=abc
    --max-contacts=<empty> --max-contacts=0 --max-contacts=65 --max-contacts=2.5 --max-contacts=many)
endfunction()

# odelab_web_check(SCENE METRIC TOLERANCE [SECONDS S] [DOWNLOAD FILE] [ARGS ...]):
# the scene's run in headless Chromium against this build's headless run,
# asked in its checks file; checks/web.cmake registers it where the browser
# checks are not left out.
function(odelab_web_check scene)
  set_property(GLOBAL APPEND PROPERTY ODELAB_WEB_CHECK_SCENES ${scene})
  set_property(GLOBAL PROPERTY ODELAB_WEB_CHECK_${scene} ${ARGN})
endfunction()
