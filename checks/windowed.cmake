# ---- windowed checks: a real window under Xvfb with Mesa's software OpenGL ----
# Framework behaviour, each through one program (label: window).

# A script with a mistake stops the run with status 2 and a message naming
# the file and the line, before any window opens (so no display is needed).
add_test(NAME test0_window_events_script_error_exits_2
         COMMAND sh -c "\"$<TARGET_FILE:test0>\" --events \"${ODELAB_CHECK_SCRIPTS}/bad.events\" 2>err.txt; s=$?; cat err.txt; test $s -eq 2 && grep -q 'bad.events:3: key: unknown key name' err.txt"
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties(test0_window_events_script_error_exits_2 PROPERTIES LABELS window)

if(NOT XVFB_RUN)
  return()  # CMakeLists.txt has warned already
endif()

# test0 renders in a window and saves a screenshot; the image must not be
# blank and must show a shadow cast onto a lit surface (the rule is in
# screenshot_check.cpp). Objects spawn every 0.05 s so that something casts
# a shadow onto the platform within the 30 frames.
add_test(NAME test0_window_renders_lit_and_shadowed_scene
         COMMAND sh -c "\"${XVFB_RUN}\" -a -s '-screen 0 1280x800x24' \"$<TARGET_FILE:test0>\" --screenshot test0_window.png --frames 30 --spawn-interval 0.05 && \"$<TARGET_FILE:screenshot_check>\" test0_window.png"
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties(test0_window_renders_lit_and_shadowed_scene PROPERTIES LABELS window)
# (No display, missing shaders and font: odelab_window_refusals in programs/test0.cmake.)

# ---- the interactive lab, driven by scripted input (--events) ----------------
# Each check plays a script from checks/scripts/ (the script says what it
# does and why) through SDL's event queue, the path real input takes, and
# checks the metrics the window run writes at exit (odelab_window_check,
# check_functions.cmake).

# --seconds in a window ends on the step a headless run ends on (round(1.5 s /
# 0.001 s) = 1500), not at the end of the frame that crossed it, so the last
# picture and the files are of that moment on any machine.
odelab_window_check(test9_window_run_ends_on_the_headless_step test9 EVENTS no_input.events
  EXPECT steps==1500 sim_seconds==1.5 ARGS --seconds 1.5)
# P stops simulated time: two marks 30 frames apart while paused see the same step.
odelab_window_check(test2_window_pause_stops_time test2 EVENTS pause.events
  EXPECT mark_b_steps==@mark_a_steps mark_b_sim_seconds==@mark_a_sim_seconds mark_a_steps>0)
# One O press while paused advances exactly one step, over the following frames too.
odelab_window_check(test2_window_one_step_per_o test2 EVENTS single_step.events
  EXPECT mark_d_steps==@mark_c_steps+1)
# Rewind then replay: ',' twice back to the start, '.' twice forward to the
# snapshot where the first pass stopped; the state hash there equals the
# first pass's bit for bit (so positions agree far better than 1e-9).
odelab_window_check(test2_window_rewind_replay_reaches_same_state test2 EVENTS rewind_replay.events
  EXPECT mark_e_steps==256 mark_g_steps==128 mark_h_steps==0 mark_f_steps==@mark_e_steps
         mark_f_hash==@mark_e_hash
  ARGS --step 0.001953125)
# A drag pulls the picked body toward the cursor: the gap opened by moving
# the cursor is at most half as wide when the button is released. (The
# script's pixels are the bob's with the whole window as the view: no
# panel, no HUD strip.)
odelab_window_check(test2_window_drag_pulls_body_to_cursor test2 EVENTS drag.events
  EXPECT drag_start_distance>1 drag_end_distance<@drag_start_distance*0.5
  ARGS --no-panel --hud off)

# An ODE error in a window pauses at the last good state, as a blow-up
# does, and the session goes on (headless it ends the run with status 4).
odelab_window_check(test4_window_ode_error_pauses_and_goes_on test4 EVENTS ode_error_recovery.events
  EXPECT mark_a_steps==0 mark_b_steps>0 window_failures>=1
  ARGS --solver step --cfm 0)

# F12 saves the frame shown as test0_t<simulated seconds>.png in --out-dir and
# prints its path; the PNG passes the screenshot check above.
add_test(NAME test0_window_f12_saves_png
         COMMAND sh ${ODELAB_CHECK_SCRIPTS}/check_f12.sh ${XVFB_RUN} $<TARGET_FILE:test0>
                 $<TARGET_FILE:screenshot_check> ${ODELAB_CHECK_SCRIPTS}/f12.events
                 ${CMAKE_CURRENT_BINARY_DIR}/window_runs/f12 --spawn-interval 0.05)
# --record writes every frame as test0_frame_000001.png ...; the help overlay
# (H) shows over the paused scene. (That the help lists every bound key is
# checked by the unit test HelpLines.ListEveryBinding.)
add_test(NAME test0_window_record_frames_and_help_overlay
         COMMAND sh ${ODELAB_CHECK_SCRIPTS}/check_help_record.sh ${XVFB_RUN} $<TARGET_FILE:test0>
                 $<TARGET_FILE:png_compare> ${ODELAB_CHECK_SCRIPTS}/help_record.events
                 ${CMAKE_CURRENT_BINARY_DIR}/window_runs/help_record)
set_tests_properties(test0_window_f12_saves_png test0_window_record_frames_and_help_overlay PROPERTIES TIMEOUT 180
                     LABELS window)

# Benchmark (not a test): frame rate of test5 with 100 plates with the debug
# drawing and the live plot on against off. Prints figures; see the script.
if(TARGET test5)
  add_custom_target(bench_debug_drawing
                    COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/bench_debug_drawing.sh $<TARGET_FILE:test5>
                    DEPENDS test5
                    USES_TERMINAL)
endif()

# The control panel drives the world through the settings table: a CFM typed
# into its field reaches dWorldSetCFM, Test2_output.txt and the run log.
add_test(NAME test2_window_panel_sets_cfm
         COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/scripts/check_panel_cfm.sh ${XVFB_RUN} $<TARGET_FILE:test2>
                 $<TARGET_FILE:expect_metrics> ${CMAKE_CURRENT_SOURCE_DIR}/scripts/panel_cfm.events
                 ${CMAKE_CURRENT_BINARY_DIR}/window_runs/panel_cfm)
set_tests_properties(test2_window_panel_sets_cfm PROPERTIES LABELS window)

# Home brings back the scene's start view after the wheel and W moved the
# camera: a paused scene with the HUD off, compared pixel by pixel.
add_test(NAME test0_window_home_restores_start_view
         COMMAND sh ${ODELAB_CHECK_SCRIPTS}/check_home_view.sh ${XVFB_RUN} $<TARGET_FILE:test0>
                 $<TARGET_FILE:png_compare> ${ODELAB_CHECK_SCRIPTS}/home_view.events
                 ${CMAKE_CURRENT_BINARY_DIR}/window_runs/home_view)
set_tests_properties(test0_window_home_restores_start_view PROPERTIES TIMEOUT 180 LABELS window)

# A number typed into the panel is read as the command line reads it:
# "0,002" in the step field is refused (never read as 0.002 or 2) with a
# message naming the text, and the step stays 0.001 s, so one O advances
# the paused run by exactly 0.001 s.
if(XVFB_RUN)
  add_test(NAME test2_window_panel_refuses_decimal_comma
           COMMAND sh -c "\"${XVFB_RUN}\" -a -s '-screen 0 1280x800x24' \"$<TARGET_FILE:expect_metrics>\" mark_stepped_steps==1 mark_stepped_sim_seconds==0.001 -- \"$<TARGET_FILE:test2>\" --events \"${ODELAB_CHECK_SCRIPTS}/panel_refuses_comma.events\" --out-dir . 2>err.txt; s=$?; cat err.txt; test $s -eq 0 && grep -q \"step (s).*'0,002' is not a number; unchanged\" err.txt"
           WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/window_runs)
  set_tests_properties(test2_window_panel_refuses_decimal_comma PROPERTIES TIMEOUT 180 LABELS window)
endif()
