# The programs cross-built for Windows (scripts/odelab.sh windows, into
# ODELAB_WINDOWS_BUILD_DIR), run under Wine beside their Linux builds.
# Label: windows. Each check is skipped (status 77) with a message where the
# cross-build was not made or Wine is missing; scripts/odelab.sh test makes
# both. Included after checks/programs/, whose short runs and bad values
# (check_functions.cmake records them) are the ones used here.
set(ODELAB_WINDOWS_BUILD_DIR ${CMAKE_SOURCE_DIR}/build-windows CACHE PATH
    "The cross-build of the programs for Windows that the windows checks run under Wine")
# Without Wine none of them can run: they are left out, said once here
# (where Wine is there but the cross-build is not, each is skipped at run time).
find_program(ODELAB_WINE wine)
if(NOT ODELAB_WINE)
  message(STATUS "Windows checks left out (label windows): wine not found; Debian's wine and wine64 bring it")
  return()
endif()
set(_windows_dir ${CMAKE_CURRENT_BINARY_DIR}/windows)
set(_skip sh ${ODELAB_CHECK_SCRIPTS}/windows_skip_unless_built.sh)
# A private Wine prefix, quiet, without the .NET and HTML installers' prompts.
set(_wine_env "WINEPREFIX=${_windows_dir}/wine" "WINEDEBUG=-all" "WINEDLLOVERRIDES=mscoree,mshtml=")
find_package(Python3 COMPONENTS Interpreter QUIET)

add_test(NAME windows_wine_prefix
         COMMAND ${_skip} ${ODELAB_WINDOWS_BUILD_DIR}/tests/test0.exe sh ${ODELAB_CHECK_SCRIPTS}/windows_wine_prefix.sh)
set_tests_properties(windows_wine_prefix PROPERTIES FIXTURES_SETUP windows_wine ENVIRONMENT "${_wine_env}"
                     SKIP_RETURN_CODE 77 TIMEOUT 300 LABELS windows)

foreach(program IN LISTS ODELAB_PROGRAMS)
  set(_exe ${ODELAB_WINDOWS_BUILD_DIR}/tests/${program}.exe)
  # The determinism check's short run: same metrics, same state_hash, same
  # output files as the Linux build (checks/scripts/windows_same_metrics.py).
  get_property(_run GLOBAL PROPERTY ODELAB_SHORT_RUN_${program})
  # test5's state parts from Linux's once plates land on plates: ODE culls
  # box-box contact points by angle (atan2 in box.cpp's cullPoints), and the
  # C library's atan2 under Windows differs from glibc's in the last bit for
  # some inputs (doc/building-on-windows.md). Compared bit for bit over its
  # first 1.4 s, in which two plates land, the second on the first; by 1.6 s
  # (five landed) the two builds' states differ.
  if(program STREQUAL "test5")
    set(_run --seconds 1.4 --spawn-interval 0.1)
  endif()
  add_test(NAME windows_${program}_same_metrics_as_linux
           COMMAND ${_skip} ${_exe} ${Python3_EXECUTABLE} ${ODELAB_CHECK_SCRIPTS}/windows_same_metrics.py
                   $<TARGET_FILE:${program}> ${_exe} ${_run})
  # The program's own bad values, refused with status 2 as on Linux, through
  # the same checks/scripts/refusals.sh, which starts wine by a wrapper.
  set(_wrapper ${_windows_dir}/${program}.sh)
  file(GENERATE OUTPUT ${_wrapper} CONTENT "#!/bin/sh\nexec wine '${_exe}' \"$@\"\n"
       FILE_PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE WORLD_READ WORLD_EXECUTE)
  get_property(_bad GLOBAL PROPERTY ODELAB_BAD_OPTIONS_${program})
  add_test(NAME windows_${program}_refuses_bad_options
           COMMAND ${_skip} ${_exe} sh ${ODELAB_CHECK_SCRIPTS}/refusals.sh headless ${_wrapper} 2 ${_bad})
  set_tests_properties(windows_${program}_same_metrics_as_linux windows_${program}_refuses_bad_options
                       PROPERTIES FIXTURES_REQUIRED windows_wine ENVIRONMENT "${_wine_env}" SKIP_RETURN_CODE 77
                                  TIMEOUT 600 LABELS windows)
endforeach()

# Whole files, one writer at a time, atomic replace: on Windows by other means
# (checks/scripts/windows_files.sh says which).
add_test(NAME windows_test2_files_whole_held_and_replaced
         COMMAND ${_skip} ${ODELAB_WINDOWS_BUILD_DIR}/tests/test2.exe
                 sh ${ODELAB_CHECK_SCRIPTS}/windows_files.sh ${ODELAB_WINDOWS_BUILD_DIR}/tests/test2.exe)
set_tests_properties(windows_test2_files_whole_held_and_replaced PROPERTIES FIXTURES_REQUIRED windows_wine
                     ENVIRONMENT "${_wine_env}" SKIP_RETURN_CODE 77 TIMEOUT 300 LABELS windows)

# Windows' own kinds of file that are not regular files: devices by reserved
# name in any folder (NUL, CON, COM1, with or without an extension) and a
# folder; refused with status 2 before the run, as /dev/null is on Linux.
# And the program's own output file named in other letter case, which on
# Windows is the same file.
add_test(NAME windows_test2_refuses_metrics_json_devices_and_folders
         COMMAND ${_skip} ${ODELAB_WINDOWS_BUILD_DIR}/tests/test2.exe sh ${ODELAB_CHECK_SCRIPTS}/refusals.sh headless
                 ${_windows_dir}/test2.sh 2 --metrics-json=NUL --metrics-json=CON --metrics-json=com1.json
                 --metrics-json=C:/windows --metrics-json=test2_OUTPUT.txt)
set_tests_properties(windows_test2_refuses_metrics_json_devices_and_folders PROPERTIES FIXTURES_REQUIRED windows_wine
                     ENVIRONMENT "${_wine_env}" SKIP_RETURN_CODE 77 TIMEOUT 300 LABELS windows)

# test0.exe in a window under Xvfb and Wine (Mesa's llvmpipe through Wine's
# OpenGL): the screenshot passes the Linux build's screenshot check. A prefix
# of its own, made under the X server: a wineserver started without DISPLAY
# would be reused and give "no display".
if(XVFB_RUN)
  add_test(NAME windows_test0_window_screenshot_not_blank
           COMMAND ${_skip} ${ODELAB_WINDOWS_BUILD_DIR}/tests/test0.exe
                   sh ${ODELAB_CHECK_SCRIPTS}/windows_window.sh ${XVFB_RUN} ${ODELAB_WINDOWS_BUILD_DIR}/tests/test0.exe
                   $<TARGET_FILE:screenshot_check> ${_windows_dir}/window)
  set_tests_properties(windows_test0_window_screenshot_not_blank PROPERTIES
                       ENVIRONMENT "WINEPREFIX=${_windows_dir}/wine-x11;WINEDEBUG=-all;WINEDLLOVERRIDES=mscoree,mshtml="
                       SKIP_RETURN_CODE 77 TIMEOUT 600 RUN_SERIAL TRUE LABELS windows)
endif()

# Makefile.win, the thesis's build, as a cross makefile from the same prefix
# (checks/scripts/windows_makefile.sh).
add_test(NAME windows_makefile_builds_the_programs
         COMMAND ${_skip} ${ODELAB_WINDOWS_BUILD_DIR}/tests/test0.exe
                 sh ${ODELAB_CHECK_SCRIPTS}/windows_makefile.sh ${CMAKE_SOURCE_DIR} ${_windows_dir}/makefile)
set_tests_properties(windows_makefile_builds_the_programs PROPERTIES FIXTURES_REQUIRED windows_wine
                     ENVIRONMENT "${_wine_env}" SKIP_RETURN_CODE 77 TIMEOUT 1200 LABELS windows)
