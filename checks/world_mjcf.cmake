# ---- MJCF in (doc/world-format.md, "MJCF"): the examples of doc/worlds/mjcf/
# read by MuJoCo's loader, exported with the MJCF's own figures (1e-9), run
# on ODE to their physics (the pendulum's period within 1%, the cube held by
# the pair's larger friction), a body's principal inertia turned into its
# own frame with a jointless child welded to it (checks/worlds/mjcf/
# tilted_inertia.xml), and the refusals (an ellipsoid, a damped
# hinge, a file MuJoCo refuses) each status 2 naming what was wrong.
# Without MuJoCo an MJCF file is refused, saying the build has none.
if(ODELAB_MJCF)
  add_test(NAME world_mjcf_examples_and_refusals
           COMMAND ${Python3_EXECUTABLE} ${ODELAB_CHECK_SCRIPTS}/world_mjcf.py $<TARGET_FILE:odelab>
                   ${CMAKE_SOURCE_DIR}/doc/worlds/mjcf ${CMAKE_CURRENT_SOURCE_DIR}/worlds/mjcf)
  set_tests_properties(world_mjcf_examples_and_refusals PROPERTIES TIMEOUT 300 LABELS peers)
else()
  odelab_refusals(odelab refuses_mjcf_without_mujoco headless 2 NEEDLE "MJCF needs MuJoCo (libmujoco-dev)"
                  --world=${CMAKE_SOURCE_DIR}/doc/worlds/mjcf/ball_on_plane.xml)
endif()
