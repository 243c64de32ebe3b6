# ---- a world's analytic ghost (doc/world-format.md, "ghost") -----------------
# The laws against their closed forms and the reader's refusals are unit
# tests (unit/test_ghost_law.cpp, unit/test_world_ghost.cpp); here, the
# program: a ghost its law cannot follow is refused before anything runs,
# status 2 naming the field, and a ghost changes no run (it is only drawn).
odelab_refusals(odelab refuses_a_ghost_its_law_cannot_follow headless 2 NEEDLE "ghost.law"
                --world=${CMAKE_SOURCE_DIR}/checks/worlds/refused-ghost.json)
foreach(_case bounce-v5-e0p5 projectile-arc pendulum-small-amplitude)
  add_test(NAME world_ghost_changes_no_run_${_case}
           COMMAND sh ${ODELAB_CHECK_SCRIPTS}/ghost_changes_nothing.sh $<TARGET_FILE:odelab>
                   ${CMAKE_SOURCE_DIR}/doc/atlas/${_case}.json ${CMAKE_CURRENT_BINARY_DIR}/runs/ghost_${_case})
  set_tests_properties(world_ghost_changes_no_run_${_case} PROPERTIES LABELS engines TIMEOUT 120)
endforeach()
