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
