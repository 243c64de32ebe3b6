# ---- windowed checks: a real window under Xvfb with Mesa's software OpenGL ----
add_executable(screenshot_check screenshot_check.cpp)
target_link_libraries(screenshot_check PRIVATE PkgConfig::STB)

find_program(XVFB_RUN xvfb-run)
if(NOT XVFB_RUN)
  message(WARNING "xvfb-run not found: the windowed checks are left out (install xvfb and xauth)")
  return()
endif()

# test0 renders in a window and saves a screenshot; the image must not be
# blank and must show a shadow cast onto a lit surface (the rule is in
# screenshot_check.cpp). Objects spawn every 0.05 s so that something casts
# a shadow onto the platform within the 30 frames.
add_test(NAME test0_window_renders_lit_and_shadowed_scene
         COMMAND sh -c "\"${XVFB_RUN}\" -a -s '-screen 0 1280x800x24' \"$<TARGET_FILE:test0>\" --screenshot test0_window.png --frames 30 --spawn-interval 0.05 && \"$<TARGET_FILE:screenshot_check>\" test0_window.png"
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})

# With no display at all the program says so and exits with status 6.
add_test(NAME test0_window_without_display_exits_6
         COMMAND sh -c "env -u DISPLAY -u WAYLAND_DISPLAY \"$<TARGET_FILE:test0>\" --frames 1 --screenshot none.png; test $? -eq 6")
# Shaders that cannot be found: status 5, naming the path tried.
add_test(NAME test0_window_missing_shaders_exits_5
         COMMAND sh -c "\"${XVFB_RUN}\" -a \"$<TARGET_FILE:test0>\" --shader-dir /nonexistent-shaders --frames 1 --screenshot none.png 2>err.txt; s=$?; grep -q /nonexistent-shaders err.txt && test $s -eq 5"
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
