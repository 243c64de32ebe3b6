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

# The launcher's window switches scenes without leaving the window: the
# scene on screen at the end reports its own metrics (test2's energies after
# two Page Downs from test0; test10's launch velocity after one Page Up).
# --scene test0 opens the window on the registry's first scene.
odelab_window_check(odelab_window_page_down_switches_scenes odelab EVENTS switch_scenes.events
  EXPECT energy_start_J>0 non_finite==0 ARGS --scene test0)
odelab_window_check(odelab_window_page_up_wraps_to_the_last_scene odelab EVENTS switch_back.events
  EXPECT launch_velocity>0 non_finite==0 ARGS --scene test0)

# The launcher's control panel lists the scenes of the registry; a click on
# one (test4's entry, from test0) switches to it as Page Down does: the scene
# on screen at the end is test4, which reports its big cube's mass.
odelab_window_check(odelab_window_scene_list_click_switches odelab EVENTS scene_list_click.events
  EXPECT big_mass>0 held==1 non_finite==0 ARGS --scene test0)
