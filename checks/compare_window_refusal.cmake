# ---- the compare window refused by an engine keeps the previous run's files (doc/hardening.md, "Fourth round").
# Every engine's scene is built before any streamed output is opened, as in
# the headless compare run: Jolt's process dead at once (ODELAB_NODE=/bin/false)
# ends the window with status 7, ODE's and Bullet's files byte for byte as
# they were. Needs a display (Xvfb) and Jolt; Bullet where it was built.
if(XVFB_RUN AND "jolt" IN_LIST ODELAB_CHECK_ENGINES)
  set(_bullet_here "")
  if("bullet" IN_LIST ODELAB_CHECK_ENGINES)
    set(_bullet_here bullet)
  endif()
  add_test(NAME compare_window_refused_by_an_engine_keeps_previous_files
           COMMAND ${XVFB_RUN} -a -s "-screen 0 1280x800x24"
                   sh ${ODELAB_CHECK_SCRIPTS}/compare_window_refusal_keeps_files.sh $<TARGET_FILE_DIR:test2>
                   ${ODELAB_CHECK_SCRIPTS}/no_input.events ${_bullet_here})
  set_tests_properties(compare_window_refused_by_an_engine_keeps_previous_files
                       PROPERTIES LABELS "hardening;window;engines" TIMEOUT 300)
endif()
