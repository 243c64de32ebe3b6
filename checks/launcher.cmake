# The launcher (utils/Launcher.cpp): odelab --list names every program of
# CMake's list, in its order, and odelab --scene NAME --headless runs NAME
# exactly as its program does: every metric but the clock's (state_hash
# included) and every output file the same (scripts/launcher_same_run.py).
# Each program's default run, or 3 s where that is long.
string(REPLACE ";" "\\n" _expected_list "${ODELAB_PROGRAMS}")
add_test(NAME odelab_list_names_every_program
         COMMAND sh -c "$<TARGET_FILE:odelab> --list | cut -f1 > list.txt && printf '${_expected_list}\\n' | cmp - list.txt"
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties(odelab_list_names_every_program PROPERTIES LABELS scene)
odelab_refusals(odelab refuses_unknown_scene headless 2 --scene=test99 --scene=)
foreach(_program IN LISTS ODELAB_PROGRAMS)
  add_test(NAME ${_program}_same_run_from_odelab
           COMMAND ${Python3_EXECUTABLE} ${ODELAB_CHECK_SCRIPTS}/launcher_same_run.py $<TARGET_FILE:odelab>
                   $<TARGET_FILE:${_program}> --seconds 3)
  set_tests_properties(${_program}_same_run_from_odelab PROPERTIES TIMEOUT 600 LABELS scene)
endforeach()

# The launcher's window switches scenes without leaving the window: each
# scene shown reports its own metrics, visit<N>.<scene>.NAME (test2's
# energies after two Page Downs from test0; test10's launch velocity after
# one Page Up).
# --scene test0 opens the window on the registry's first scene.
odelab_window_check(odelab_window_page_down_switches_scenes odelab EVENTS switch_scenes.events
  EXPECT visits==3 visit3.test2.energy_start_J>0 visit3.test2.non_finite==0 ARGS --scene test0)
odelab_window_check(odelab_window_page_up_wraps_to_the_last_scene odelab EVENTS switch_back.events
  EXPECT visits==2 visit2.test10.launch_velocity>0 visit2.test10.non_finite==0 ARGS --scene test0)

# The launcher's control panel lists the scenes of the registry; a click on
# one (test4's entry, from test0) switches to it as Page Down does: the scene
# on screen at the end, the second visit, is test4, which reports its big cube's mass.
odelab_window_check(odelab_window_scene_list_click_switches odelab EVENTS scene_list_click.events
  EXPECT visits==2 visit2.test4.big_mass>0 visit2.test4.held==1 visit2.test4.non_finite==0 ARGS --scene test0)

# Each scene the window opens owns its files, locks and hooks and lets them
# go, destroyed, before the next is made (utils/OpenScene.h). Away and back:
# the scene opened again reopens its output file (Test2_output.txt,
# Test8_output.txt; the first visit kept the file's lock: status 1), and
# each visit reports its own metrics, named visit<N>.<scene>.NAME.
foreach(_program IN ITEMS test2 test8)
  odelab_window_check(odelab_window_${_program}_switched_away_and_back_reopens_its_output_file odelab
    EVENTS switch_away_and_back.events
    EXPECT visits==3 visit1.${_program}.output_rows>0 visit3.${_program}.output_rows>0 ARGS --scene ${_program})
endforeach()
# Marks made before a switch stay, under the visit they were made in.
odelab_window_check(odelab_window_metrics_name_every_visit_and_keep_its_marks odelab
  EVENTS marks_across_switches.events
  EXPECT visits==3 visit1.test3.mark_before_steps>=0 visit2.test2.mark_between_steps>=0
         visit3.test3.mark_after_steps>=0 visit3.test3.steps>0 ARGS --scene test3)
# Two Page Ups in one frame are two switches: test0 to test9, not test10.
odelab_window_check(odelab_window_two_page_ups_in_one_frame_switch_twice odelab
  EVENTS two_page_ups_in_one_frame.events
  EXPECT visits==2 visit1.test0.steps>=0 visit2.test9.steps>0 ARGS --scene test0)
# --record numbers frames over the whole window: a scene shown twice keeps
# its first visit's frames.
if(XVFB_RUN)
  add_test(NAME odelab_window_record_numbers_frames_across_switches
           COMMAND sh ${ODELAB_CHECK_SCRIPTS}/launcher_record_across_switches.sh $<TARGET_FILE:odelab>)
  set_tests_properties(odelab_window_record_numbers_frames_across_switches PROPERTIES TIMEOUT 180 LABELS window)
  # The display goes away after a switch: the exit hook marks the scene on
  # screen (test8's Test8_output.txt), not the one the window opened on.
  add_test(NAME odelab_display_lost_after_a_switch_marks_the_scene_on_screen
           COMMAND sh ${ODELAB_CHECK_SCRIPTS}/launcher_display_lost_after_switch.sh $<TARGET_FILE:odelab>)
  set_tests_properties(odelab_display_lost_after_a_switch_marks_the_scene_on_screen PROPERTIES TIMEOUT 180
                       LABELS hardening)
  # A window's options hold for every scene it can switch to: --seconds
  # 0.003 is three steps of test2 but less than one step of test3 (0.005 s):
  # refused at start, status 2, naming --seconds and test3.
  add_test(NAME odelab_refuses_seconds_below_a_step_of_any_scene
           COMMAND sh ${ODELAB_CHECK_SCRIPTS}/launcher_refuses_short_seconds.sh $<TARGET_FILE:odelab>)
  set_tests_properties(odelab_refuses_seconds_below_a_step_of_any_scene PROPERTIES TIMEOUT 120 LABELS hardening)
endif()
