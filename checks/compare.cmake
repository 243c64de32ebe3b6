# ---- several engines in one run: --compare (doc/peers.md, "Several engines
# in one run"). CTest label: compare.
#
# `testN --compare bullet,mujoco --headless` runs the scene on ODE and on each
# engine named, in lockstep, each from its own parse of the same command
# line. Each engine's block of the metrics (ode.NAME, bullet.NAME, ...) must
# equal the separate run's (testN --headless, testN --engine E --headless,
# same options and seconds) to the digits written, but for the metrics read
# from a clock (launcher_same_run.py's list); its exit_status the separate
# run's status; its output files the separate run's byte for byte (ODE's in
# the folder, the others' in <folder>/<engine>/). Then the refusals: status 2,
# nothing written.
#
# The engines here (engines_here.cmake); a missing one is named as skipped.
set(_compare_engines ${ODELAB_CHECK_ENGINES})
set(_compare_skipped ${ODELAB_CHECK_ENGINES_SKIPPED})
string(REPLACE ";" "," _compare_engine_list "${_compare_engines}")
string(REPLACE ";" "," _compare_skipped_list "${_compare_skipped}")

if(_compare_engines)
  foreach(_program IN ITEMS test2 test9)
    add_test(NAME compare_${_program}_equals_separate_runs
             COMMAND ${Python3_EXECUTABLE} ${ODELAB_CHECK_SCRIPTS}/compare_same_runs.py
                     --program $<TARGET_FILE:${_program}> --engines ${_compare_engine_list}
                     --skipped "${_compare_skipped_list}" -- --seconds 2)
    set_tests_properties(compare_${_program}_equals_separate_runs PROPERTIES LABELS compare TIMEOUT 600)
  endforeach()
  # The launcher's --scene runs the same compare run as the program.
  add_test(NAME compare_odelab_scene_test9_equals_separate_runs
           COMMAND ${Python3_EXECUTABLE} ${ODELAB_CHECK_SCRIPTS}/compare_same_runs.py
                   --program $<TARGET_FILE:test9> --launcher $<TARGET_FILE:odelab> --engines ${_compare_engine_list}
                   --skipped "${_compare_skipped_list}" -- --seconds 2)
  set_tests_properties(compare_odelab_scene_test9_equals_separate_runs PROPERTIES LABELS compare TIMEOUT 600)
endif()

# The compare window (doc/manual.md, "Engines side by side"): test2 on ODE
# and the three engines the issue names that are here, under Xvfb, its last
# frame (--seconds 3) saved; the same figures as the separate headless runs,
# and every engine's view shows the pendulum where ODE's does (view_bodies).
set(_compare_window_engines)
foreach(_engine IN ITEMS bullet jolt rapier)
  if(_engine IN_LIST _compare_engines)
    list(APPEND _compare_window_engines ${_engine})
  endif()
endforeach()
if(_compare_window_engines AND XVFB_RUN)
  string(REPLACE ";" "," _compare_window_list "${_compare_window_engines}")
  add_test(NAME compare_window_test2_views_and_figures
           COMMAND ${XVFB_RUN} -a -s "-screen 0 1280x800x24" ${Python3_EXECUTABLE}
                   ${ODELAB_CHECK_SCRIPTS}/compare_same_runs.py --window --view-bodies $<TARGET_FILE:view_bodies>
                   --program $<TARGET_FILE:test2> --engines ${_compare_window_list}
                   --skipped "${_compare_skipped_list}" -- --seconds 3)
  set_tests_properties(compare_window_test2_views_and_figures PROPERTIES LABELS compare TIMEOUT 600)
endif()
# The panel's tick of an engine hides its view (checks/scripts/
# compare_panel_hides.events clicks Jolt's off): the others fill the window,
# each still showing the pendulum, and Jolt steps on unseen.
if(_compare_window_list STREQUAL "bullet,jolt,rapier" AND XVFB_RUN)
  add_test(NAME compare_window_panel_hides_an_engine
           COMMAND ${XVFB_RUN} -a -s "-screen 0 1280x800x24" ${Python3_EXECUTABLE}
                   ${ODELAB_CHECK_SCRIPTS}/compare_same_runs.py
                   --panel-hides ${ODELAB_CHECK_SCRIPTS}/compare_panel_hides.events --hidden jolt
                   --view-bodies $<TARGET_FILE:view_bodies> --program $<TARGET_FILE:test2>
                   --engines bullet,jolt,rapier -- --seconds 2)
  set_tests_properties(compare_window_panel_hides_an_engine PROPERTIES LABELS compare TIMEOUT 300)
endif()
# Keys, a drag, R and the panel's typed field reach every engine at ODE's step.
if(ODELAB_ENGINE_BULLET AND XVFB_RUN)
  add_test(NAME compare_window_inputs_reach_every_engine
           COMMAND ${XVFB_RUN} -a -s "-screen 0 1280x800x24" ${Python3_EXECUTABLE}
                   ${ODELAB_CHECK_SCRIPTS}/compare_same_runs.py --inputs ${ODELAB_CHECK_SCRIPTS}/compare_inputs.events
                   --program $<TARGET_FILE:test2> --engines bullet)
  set_tests_properties(compare_window_inputs_reach_every_engine PROPERTIES LABELS compare TIMEOUT 300)
endif()

# The refusals name Bullet as the engine that is here.
if(ODELAB_ENGINE_BULLET)
  add_test(NAME compare_refusals_test2
           COMMAND ${Python3_EXECUTABLE} ${ODELAB_CHECK_SCRIPTS}/compare_same_runs.py
                   --program $<TARGET_FILE:test2> --refusals)
  set_tests_properties(compare_refusals_test2 PROPERTIES LABELS compare TIMEOUT 120)
endif()
