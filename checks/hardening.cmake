# Hardening (issue 7): the suite survives what a user can set or do. The
# per-program parts live in checks/programs/ (each program's bad values,
# determinism, interrupted output files, window refusals) and
# common_options.cmake (the shared options); here are the two that take
# every program at once or need fixtures. doc/hardening.md has the figures;
# checks/long_runs.sh and checks/sanitize.sh are run by hand (or from
# scripts/odelab.sh).

# ---- extreme settings -------------------------------------------------------
# Every program, headless, across step 1e-5 ... 0.1, ERP 0/0.5/1, CFM
# 0/1e-3/1, iterations 1/20/1000, solver quick/step: a pairwise covering set
# (15 settings in which every value of every parameter meets every value of
# every other parameter) plus 6 extreme corners, 21 settings x 11 programs =
# 231 runs of min(3 s, 10000 steps) simulated time each (checks/extreme_grid.h).
# No run may crash (a signal) or hang; a blow-up must end with status 3 and a
# message naming the run's very settings, an ODE error with status 4 and
# ODE's message naming them too; any other end fails.
#
# One CTest row per program and setting, extreme_settings_grid_<test>_<K>:
# `ctest -j` runs them side by side, and a row with no end within its
# TIMEOUT is a hang. The runner takes setting K of _grid_batches round
# robin (--batch K --batches B), so a grid that grows still runs every
# setting (a row then holds two), and one that shrinks below B fails the
# empty row instead of checking less unnoticed.
add_executable(extreme_settings extreme_settings.cpp)
target_link_libraries(extreme_settings PRIVATE odelab_physics nlohmann_json::nlohmann_json odelab_warnings)
set(_grid_batches 21)
math(EXPR _grid_last "${_grid_batches} - 1")
set(_grid_dir ${CMAKE_CURRENT_BINARY_DIR}/hardening/extreme_settings)
file(MAKE_DIRECTORY ${_grid_dir})
foreach(_program IN LISTS ODELAB_PROGRAMS)
  foreach(_batch RANGE ${_grid_last})
    set(_row extreme_settings_grid_${_program}_${_batch})
    add_test(NAME ${_row}
             COMMAND extreme_settings --batch ${_batch} --batches ${_grid_batches} --step-budget 10000
                     --max-seconds 3 --strict-ode-errors --work-dir ${_grid_dir} $<TARGET_FILE:${_program}>)
    set_tests_properties(${_row} PROPERTIES TIMEOUT 120 LABELS hardening)
  endforeach()
endforeach()

# ---- shader folders and fonts that are wrong inside ------------------------------
# Framework code, so test0 stands for all: one shader missing, one that does
# not compile, a folder where a shader belongs, one unreadable (skipped as
# root); a font that is not a font, a folder as the font. Each is a resource
# problem: status 5, and the message names the file. (Missing ones, and no
# display: odelab_window_refusals in the program files.)
if(XVFB_RUN)
  set(_fixtures ${CMAKE_CURRENT_BINARY_DIR}/hardening/shader_fixtures)
  file(REMOVE_RECURSE ${_fixtures})
  file(GLOB _shader_files ${CMAKE_SOURCE_DIR}/shaders/*)
  foreach(_fixture missing_depth broken_scene folder_scene)
    file(COPY ${_shader_files} DESTINATION ${_fixtures}/${_fixture})
  endforeach()
  file(REMOVE ${_fixtures}/missing_depth/depth.vert)
  file(WRITE ${_fixtures}/broken_scene/scene.frag "#version 330 core\nthis is not GLSL(\n")
  file(REMOVE ${_fixtures}/folder_scene/scene.frag)
  file(MAKE_DIRECTORY ${_fixtures}/folder_scene/scene.frag)
  odelab_refusals(test0 window_unusable_shaders_exit_5 window 5 --shader-dir=${_fixtures}/missing_depth
                  --shader-dir=${_fixtures}/broken_scene --shader-dir=${_fixtures}/folder_scene)
  odelab_refusals(test0 window_unreadable_shader_exits_5 window 5 --shader-dir=<unreadable-shaders>)
  odelab_refusals(test0 window_unusable_font_exits_5 window 5 --font=/etc/passwd --font=${_fixtures})
endif()

# ---- the promises hold ------------------------------------------------------
# doc/hardening.md's "What you can rely on": every promise names checks,
# and each is a test this build lists (scripts/promises_name_their_checks.py
# reads the test2/test8_rest and BlowUp.* shorthands). The promises name
# checks of the optional parts (Bullet, MuJoCo, the web peers, windows under
# Xvfb), so a build without one of them cannot list them all: there the
# check is left out and said, never failed.
set(_promise_parts_missing)
foreach(_part ODELAB_HAVE_BULLET ODELAB_HAVE_MUJOCO ODELAB_WEB_PEERS_READY XVFB_RUN)
  if(NOT ${_part})
    list(APPEND _promise_parts_missing ${_part})
  endif()
endforeach()
if(_promise_parts_missing)
  message(STATUS "Check hardening_promises_name_listed_checks left out: the build lacks ${_promise_parts_missing}")
else()
  add_test(NAME hardening_promises_name_listed_checks
           COMMAND ${Python3_EXECUTABLE} ${ODELAB_CHECK_SCRIPTS}/promises_name_their_checks.py
                   ${PROJECT_SOURCE_DIR}/doc/hardening.md ${CMAKE_CTEST_COMMAND} ${CMAKE_BINARY_DIR})
  set_tests_properties(hardening_promises_name_listed_checks PROPERTIES LABELS hardening TIMEOUT 120)
endif()
