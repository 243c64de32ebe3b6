# ---- SDF in (doc/world-format.md, "SDF"): the examples of doc/worlds/sdf/
# read by SDFormat's parser, exported with the SDF's own figures (1e-9), run
# on ODE to their physics (the ball's bounce to 0.2 m within 5 mm and its
# rest at its radius within 1 mm, the cube's slide by the pair's smaller
# friction within 3%, the pendulum's period within 1% and its <limit> on the
# side SDF puts it), a model's links kept apart without <self_collide>
# (checks/worlds/sdf/stacked_links.sdf), every joint kind and shape in a
# turned model exported to the SDF's figures (joints_and_shapes.sdf), each
# example run on every engine here or refused with status 2 saying why,
# --export-world ending on the SDF's own state_hash (but the slope's, whose
# turned static box ODE holds as a matrix: printed, not compared), and the
# refusals (a file SDFormat refuses, a mesh, a negative mass, a damped
# hinge) each status 2 naming what was wrong.
# Without SDFormat an SDF file is refused, saying the build has none.
if(ODELAB_SDF)
  add_test(NAME world_sdf_examples_engines_and_refusals
           COMMAND ${Python3_EXECUTABLE} ${ODELAB_CHECK_SCRIPTS}/world_sdf.py $<TARGET_FILE:odelab>
                   ${CMAKE_SOURCE_DIR}/doc/worlds/sdf ${CMAKE_CURRENT_SOURCE_DIR}/worlds/sdf
                   "${ODELAB_CHECK_ENGINES}" "${ODELAB_CHECK_ENGINES_SKIPPED}")
  set_tests_properties(world_sdf_examples_engines_and_refusals PROPERTIES TIMEOUT 600 LABELS peers)
else()
  odelab_refusals(odelab refuses_sdf_without_sdformat headless 2 NEEDLE "SDF needs SDFormat (libsdformat-dev)"
                  --world=${CMAKE_SOURCE_DIR}/doc/worlds/sdf/ball_on_plane.sdf)
endif()
