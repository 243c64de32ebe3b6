# ---- install: the installed programs find their shaders from any folder ----------
# `cmake --install` of this build into a fresh prefix outside it, then the
# installed test0 run from / renders a lit, shadowed frame with the installed
# shaders, and without them is refused having tried only the install's own
# places (scripts/check_install.sh). Needs the whole build, as CTest runs it.
if(XVFB_RUN)
  add_test(NAME install_programs_find_their_shaders_from_any_folder
           COMMAND sh ${ODELAB_CHECK_SCRIPTS}/check_install.sh ${CMAKE_COMMAND} ${CMAKE_BINARY_DIR}
                   ${CMAKE_INSTALL_BINDIR} ${CMAKE_INSTALL_DATADIR} ${CMAKE_INSTALL_DOCDIR} ${XVFB_RUN}
                   $<TARGET_FILE:screenshot_check> ${ODELAB_PROGRAMS})
  set_tests_properties(install_programs_find_their_shaders_from_any_folder PROPERTIES TIMEOUT 300 LABELS install)
endif()

# ---- the window module: only a window run needs it --------------------------------
# A program copied away from odelab_window.so runs headless with the same
# state_hash, and refuses a window run with status 5 naming the module and
# the paths it tried (scripts/check_window_module.sh). No display needed.
if(ODELAB_WINDOW_MODULE)
  add_test(NAME headless_runs_without_the_window_module
           COMMAND sh ${ODELAB_CHECK_SCRIPTS}/check_window_module.sh $<TARGET_FILE:test9>)
  set_tests_properties(headless_runs_without_the_window_module PROPERTIES TIMEOUT 60 LABELS install)
endif()
