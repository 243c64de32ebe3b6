# ---- first screens: what a window shows before any key is pressed, and a
# HUD and a panel that keep their places (label window) ------------------------
# Window-only choices: the headless runs, and so every measured check, are
# the scenes' own and unchanged.

# The compact HUD's lines without a window (compact_hud.cpp): test7's must
# name the joint error, the scene's headline measurement.
add_executable(compact_hud compact_hud.cpp)
target_link_libraries(compact_hud PRIVATE odelab_scenes odelab_warnings)
add_test(NAME test7_compact_hud_names_the_joint_error
         COMMAND sh -c "\"$<TARGET_FILE:compact_hud>\" test7 0.5 > hud.txt && cat hud.txt && grep -q '^joint error [0-9.e+-]* m (max ' hud.txt"
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties(test7_compact_hud_names_the_joint_error PROPERTIES LABELS window)

# mu's infinity is "infinite" wherever people read it: the --help (the --mu
# option and the F / G keys) ...
add_test(NAME test0_help_says_infinite_not_dInfinity
         COMMAND sh -c "\"$<TARGET_FILE:test0>\" --help > help.txt && grep -q 'ladder 0 ... 5, infinite' help.txt && ! grep -n dInfinity help.txt")
set_tests_properties(test0_help_says_infinite_not_dInfinity PROPERTIES LABELS window)

# The --help and doc/manual.md say the same of the metrics' temporary file
# (the name SafeFile.cpp gives it: .FILE.XXXXXX beside FILE) and of what
# --text-size sizes (HudText and the panel: the HUD, the help and the panel).
add_test(NAME test0_help_agrees_with_manual
         COMMAND sh ${ODELAB_CHECK_SCRIPTS}/help_agrees_with_manual.sh $<TARGET_FILE:test0>
                 ${CMAKE_SOURCE_DIR}/doc/manual.md)
set_tests_properties(test0_help_agrees_with_manual PROPERTIES LABELS window)

if(NOT XVFB_RUN)
  return()
endif()

# ... and the notice of G at the ladder's top says that nothing changed.
set(_dir ${CMAKE_CURRENT_BINARY_DIR}/window_runs/mu_top)
file(MAKE_DIRECTORY ${_dir})
add_test(NAME test0_window_mu_notice_says_infinite
         COMMAND sh -c "\"${XVFB_RUN}\" -a -s '-screen 0 1280x800x24' \"$<TARGET_FILE:test0>\" --events \"${ODELAB_CHECK_SCRIPTS}/mu_top.events\" --out-dir . 2>err.txt; s=$?; cat err.txt; test $s -eq 0 && grep -q 'mu stays infinite (the ladder.s top)' err.txt && ! grep -q dInfinity err.txt"
         WORKING_DIRECTORY ${_dir})
set_tests_properties(test0_window_mu_notice_says_infinite PROPERTIES TIMEOUT 180 LABELS window)

# A window's first seconds show the scene's subject with no key pressed.
# test0: a box at once and a sphere at 1 s fall onto the platform.
odelab_window_check(test0_window_first_seconds_drop_a_box_and_a_sphere test0 EVENTS no_input.events
  EXPECT spawned==2 ARGS --seconds 1.5)
# test5: the first plate falls at once.
odelab_window_check(test5_window_first_plate_at_once test5 EVENTS no_input.events
  EXPECT plates==1 ARGS --seconds 0.5)
# test10: the first cube is launched at once.
odelab_window_check(test10_window_first_launch_at_once test10 EVENTS no_input.events
  EXPECT launches==1 ARGS --seconds 0.5)
# test6 runs from the first frame (it stands, then falls) ...
odelab_window_check(test6_window_runs_at_once test6 EVENTS first_seconds.events EXPECT steps>0)
# ... unless --paused, which opens it paused on the upright system.
odelab_window_check(test6_window_paused_on_request test6 EVENTS first_seconds.events EXPECT steps==0 ARGS --paused)
# The launcher opens on test1's bouncing balls (test1 reports bounce_velocity).
odelab_window_check(odelab_window_opens_on_a_scene_in_motion odelab EVENTS first_seconds.events
  EXPECT bounce_velocity>0 steps>0)

# The launcher's panel at 1280x720 and 1024x768: the scene list is one row,
# so the scene's own buttons below the timeline stay in view; a click on
# test0's B button spawns a box (--spawn-interval 0: nothing else does).
odelab_window_check(odelab_window_scene_buttons_in_view_1280x720 odelab EVENTS scene_button_1280x720.events
  EXPECT spawned==1 ARGS --scene test0 --spawn-interval 0)
odelab_window_check(odelab_window_scene_buttons_in_view_1024x768 odelab EVENTS scene_button_1024x768.events
  EXPECT spawned==1 ARGS --scene test0 --spawn-interval 0 --width 1024 --height 768)

# A notice joining the HUD moves neither the view below it nor, in the full
# HUD's columns, the lines at the top of the columns after the first (the
# notice joins the last column's end; check_hud_notice.sh). The first
# column holds the frame rate, which changes from frame to frame (and
# widens when the frame's profile is first measured, a second into the run:
# under load after frame 11). The view is what lies below the strip: from a
# quarter of the height down, and for the full HUD at 1024x768, whose strip
# of wrapped lines is 202 px tall (26%), from 27% down.
set(_view 0,0.25,1,1)
set(_view_below_tall_strip 0,0.27,1,1)
foreach(_case IN ITEMS "test2;compact;1280;720;${_view}" "test2;compact;1024;768;${_view}"
                       "test2;full;1280;720;${_view} 0.51,0,1,0.1"
                       "test2;full;1024;768;${_view_below_tall_strip} 0.34,0,1,0.12"
                       "test0;full;1280;720;${_view} 0.51,0,1,0.1")
  list(GET _case 0 _program)
  list(GET _case 1 _hud)
  list(GET _case 2 _width)
  list(GET _case 3 _height)
  list(GET _case 4 _regions)
  set(_name ${_program}_window_${_hud}_hud_notice_moves_nothing_${_width}x${_height})
  add_test(NAME ${_name}
           COMMAND sh ${ODELAB_CHECK_SCRIPTS}/check_hud_notice.sh ${XVFB_RUN} $<TARGET_FILE:${_program}>
                   $<TARGET_FILE:png_compare> ${ODELAB_CHECK_SCRIPTS}/hud_notice.events
                   ${CMAKE_CURRENT_BINARY_DIR}/window_runs/${_name} ${_width} ${_height} "${_regions}" --hud ${_hud})
  set_tests_properties(${_name} PROPERTIES TIMEOUT 180 LABELS window)
endforeach()
