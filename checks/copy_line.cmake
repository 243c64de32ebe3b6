# The copied command line (the panel's "Copy as command line", and
# --print-command-line at a run's end; utils/CopyLine.h) starts the run it
# was copied from (scripts/copy_line.py).

# Every program's line names every setting and knob --list-settings lists,
# with the value in force read back exactly. test5 and test10 again with the
# flags their companion knobs only work with. Short headless runs: cheap.
foreach(_program IN LISTS ODELAB_PROGRAMS)
  add_test(NAME ${_program}_copy_line_names_every_knob
           COMMAND ${Python3_EXECUTABLE} ${ODELAB_CHECK_SCRIPTS}/copy_line.py names $<TARGET_FILE:${_program}>)
  set_tests_properties(${_program}_copy_line_names_every_knob PROPERTIES TIMEOUT 120 LABELS hardening)
endforeach()
add_test(NAME test5_copy_line_names_auto_disable_knobs
         COMMAND ${Python3_EXECUTABLE} ${ODELAB_CHECK_SCRIPTS}/copy_line.py names $<TARGET_FILE:test5> --auto-disable)
set_tests_properties(test5_copy_line_names_auto_disable_knobs PROPERTIES TIMEOUT 120 LABELS hardening)

# Headless: a line given values off every default prints itself again and
# ends in the same state, to the bit (round-trip doubles, mu's inf, flags).
add_test(NAME test4_copy_line_reproduces_itself
         COMMAND ${Python3_EXECUTABLE} ${ODELAB_CHECK_SCRIPTS}/copy_line.py headless $<TARGET_FILE:test4> 0.5
                 --big-mass 12345.678901234567 --mu inf --max-contacts 5 --erp 0.123456789012345 --cfm 3e-7
                 --iterations 33 --sor 1.2345678901 --step 0.0015 --solver step --seed 7)
add_test(NAME test2_copy_line_reproduces_itself
         COMMAND ${Python3_EXECUTABLE} ${ODELAB_CHECK_SCRIPTS}/copy_line.py headless $<TARGET_FILE:test2> 0.5
                 --rod-length 2.718281828459045 --bob-radius 0.3 --rod-mass 1.1 --rod-thickness 0.07
                 --sample-interval 0.003 --no-rotational-energy --erp 0.3)
add_test(NAME test10_copy_line_reproduces_itself
         COMMAND ${Python3_EXECUTABLE} ${ODELAB_CHECK_SCRIPTS}/copy_line.py headless $<TARGET_FILE:test10> 0.2
                 --velocity 333.3 --spin 2.5 --surface-layer 0.001 --ccd --random-orientation --mu 0.7 --seed 3)
set_tests_properties(test4_copy_line_reproduces_itself test2_copy_line_reproduces_itself
                     test10_copy_line_reproduces_itself PROPERTIES TIMEOUT 120 LABELS hardening)

# Window: keys change settings and knobs while paused at step 0; the line
# printed at the window's end, run headless, ends in the window's state.
if(XVFB_RUN)
  foreach(_program test4 test2)
    add_test(NAME ${_program}_window_copy_line_same_state
             COMMAND ${XVFB_RUN} -a -s "-screen 0 1280x800x24" ${Python3_EXECUTABLE}
                     ${ODELAB_CHECK_SCRIPTS}/copy_line.py window $<TARGET_FILE:${_program}>
                     ${ODELAB_CHECK_SCRIPTS}/copy_line_${_program}.events 0.5)
    set_tests_properties(${_program}_window_copy_line_same_state PROPERTIES TIMEOUT 180 LABELS window)
  endforeach()
  # The world-setting keys (F3, F7, F6, Shift+F8, G) on every program whose
  # headless run is its window's run (a new scene too): not test5, whose
  # window drops its first plate at once, nor test7 and test10, whose
  # headless runs are their throw and launch experiments, scene defaults the
  # copied line leaves to the scene. test6 holds a ball joint, which keeps
  # the ERP and CFM it was made with unless the change is carried to it
  # (WorldRun::carryWorldErpCfmToBallJoints).
  set(_headless_run_differs test5 test7 test10)
  foreach(_program IN LISTS ODELAB_PROGRAMS)
    if(_program IN_LIST _headless_run_differs)
      continue()
    endif()
    add_test(NAME ${_program}_window_copy_line_after_setting_keys_same_state
             COMMAND ${XVFB_RUN} -a -s "-screen 0 1280x800x24" ${Python3_EXECUTABLE}
                     ${ODELAB_CHECK_SCRIPTS}/copy_line.py window $<TARGET_FILE:${_program}>
                     ${ODELAB_CHECK_SCRIPTS}/copy_line_keys.events 0.5)
    set_tests_properties(${_program}_window_copy_line_after_setting_keys_same_state PROPERTIES TIMEOUT 180
                         LABELS window)
  endforeach()
endif()
