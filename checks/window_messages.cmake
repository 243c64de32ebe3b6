# ---- what a window run says before and as it starts (label window) ----------
# With DISPLAY set empty (and no Wayland display), the program's own message
# comes first and alone: SDL, left to try its drivers, printed Wayland's
# "XDG_RUNTIME_DIR is invalid or not set" before it.
add_test(NAME test0_window_without_display_says_only_its_own_message
         COMMAND sh -c "env -u WAYLAND_DISPLAY -u SDL_VIDEODRIVER DISPLAY= XDG_RUNTIME_DIR= \"$<TARGET_FILE:test0>\" --seconds 1 2>err.txt; s=$?; cat err.txt; test $s -eq 6 && head -n 1 err.txt | grep -q '^error: cannot open a window' && ! grep -q XDG_RUNTIME_DIR err.txt"
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties(test0_window_without_display_says_only_its_own_message PROPERTIES LABELS window)

# The launcher's window says which files a scene it visits writes, and in
# which folder (the current one unless --out-dir): test2's energies went
# into the folder the launcher was started in, unannounced.
if(XVFB_RUN)
  file(MAKE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/window_runs/launcher_says_files)
  add_test(NAME odelab_window_visit_says_where_files_go
           COMMAND sh -c "\"${XVFB_RUN}\" -a -s '-screen 0 1280x800x24' \"$<TARGET_FILE:odelab>\" --scene test2 --events \"${ODELAB_CHECK_SCRIPTS}/quit_at_once.events\" 2>err.txt; s=$?; cat err.txt; test $s -eq 0 && grep -q \"^test2 writes .*Test2_output.txt in $(pwd -P) \" err.txt"
           WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/window_runs/launcher_says_files)
  set_tests_properties(odelab_window_visit_says_where_files_go PROPERTIES LABELS window TIMEOUT 120)
endif()
