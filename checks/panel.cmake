# ---- the control panel and the window's keys under real-input timing ----
# Windowed checks (label window) with scripted input; each script in
# checks/scripts/ says what it does and why.
if(NOT XVFB_RUN)
  return()  # CMakeLists.txt has warned already
endif()

# A key tapped within one frame (the script's "key" presses and releases in
# one) is one press in a panel field: "0.55" and one BackSpace is "0.5",
# however many frames pass before Enter.
odelab_window_check(test2_window_panel_key_tap_is_one_press test2 EVENTS panel_tap_backspace.events
  EXPECT world_erp==0.5)

# The panel's CFM field takes 0, as --cfm 0 does (the slider, logarithmic,
# stops short of it), and a field clicked and left is no change.
add_test(NAME test2_window_panel_takes_cfm_zero
         COMMAND sh ${ODELAB_CHECK_SCRIPTS}/check_panel_cfm_zero.sh ${XVFB_RUN} $<TARGET_FILE:test2>
                 $<TARGET_FILE:expect_metrics> ${ODELAB_CHECK_SCRIPTS}/panel_cfm_zero.events
                 ${CMAKE_CURRENT_BINARY_DIR}/window_runs/panel_cfm_zero)

# Esc closes the help before it quits; with the settings changed since the
# start, the first Esc asks and the second quits.
add_test(NAME test2_window_escape_closes_help_first
         COMMAND sh ${ODELAB_CHECK_SCRIPTS}/check_escape.sh ${XVFB_RUN} $<TARGET_FILE:test2>
                 ${ODELAB_CHECK_SCRIPTS}/escape_closes_help.events
                 ${CMAKE_CURRENT_BINARY_DIR}/window_runs/escape_help after_help)
add_test(NAME test2_window_escape_asks_when_settings_changed
         COMMAND sh ${ODELAB_CHECK_SCRIPTS}/check_escape.sh ${XVFB_RUN} $<TARGET_FILE:test2>
                 ${ODELAB_CHECK_SCRIPTS}/escape_asks_when_changed.events
                 ${CMAKE_CURRENT_BINARY_DIR}/window_runs/escape_changed asked "settings changed since the start")

# After ',' from a pause between snapshots, '.' comes back to the paused
# step, bit for bit.
odelab_window_check(test2_window_rewind_then_forward_returns_to_paused_step test2 EVENTS forward_to_paused_step.events
  EXPECT mark_a_steps==200 mark_b_steps==128 mark_c_steps==@mark_a_steps mark_c_hash==@mark_a_hash
  ARGS --step 0.001953125)

# The timeline slider rebuilds the run at the handle's step while it is
# dragged, not only when released.
odelab_window_check(test2_window_panel_timeline_scrubs_while_dragged test2 EVENTS panel_timeline_scrub.events
  EXPECT mark_start_steps==300 mark_held_steps<@mark_start_steps mark_held_steps>0
         mark_released_steps==@mark_held_steps
  ARGS --step 0.001953125)

# "Copy as command line" leaves the rows under it in place: the timeline is
# dragged where it was before the click.
odelab_window_check(test2_window_panel_copy_keeps_timeline_in_place test2 EVENTS panel_copy_keeps_rows.events
  EXPECT --stdout-contains "command line: test2 " mark_start_steps==300 mark_released_steps<@mark_start_steps
         mark_released_steps>0
  ARGS --step 0.001953125)

# A double click on a body follows it without dragging it.
add_test(NAME test2_window_double_click_follows_without_drag
         COMMAND sh ${ODELAB_CHECK_SCRIPTS}/check_double_click.sh ${XVFB_RUN} $<TARGET_FILE:test2>
                 ${ODELAB_CHECK_SCRIPTS}/double_click_follows.events
                 ${CMAKE_CURRENT_BINARY_DIR}/window_runs/double_click)

set_tests_properties(test2_window_panel_takes_cfm_zero test2_window_escape_closes_help_first
                     test2_window_escape_asks_when_settings_changed test2_window_double_click_follows_without_drag
                     PROPERTIES TIMEOUT 180 LABELS window)
