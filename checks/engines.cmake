# ---- every scene on every engine (doc/peers.md, doc/world-format.md). CTest label: engines.

# The world file leaves nothing out: a program's world, exported and run by
# odelab --world, ends on the program's own state hash. For every program
# whose world changes only by stepping; those whose headless run adds bodies
# as it goes (test0's spawns, test5's plates, test10's launches) are left out,
# and test3, whose dominoes are turned by rotation matrix: the file holds
# quaternions, the matrix ODE makes from one differs in the last bits, and
# the chain of sixty falls magnifies that (the runs part after the first
# contacts, the same fall to the eye). test7 throws once and runs past the throw.
set(_not_round_trip test0 test3 test5 test10)
foreach(_program IN LISTS ODELAB_PROGRAMS)
  if(_program IN_LIST _not_round_trip)
    continue()
  endif()
  set(_args)
  set(_seconds 3)
  if(_program STREQUAL "test7")
    set(_args --throws 1)
    set(_seconds 8)
  endif()
  add_test(NAME ${_program}_world_file_round_trip
           COMMAND sh ${ODELAB_CHECK_SCRIPTS}/world_round_trip.sh $<TARGET_FILE:${_program}> $<TARGET_FILE:odelab>
                   ${_seconds} ${_args})
  set_tests_properties(${_program}_world_file_round_trip PROPERTIES LABELS engines TIMEOUT 300)
endforeach()

# A world file that cannot be read or run is refused before anything runs,
# naming the path: absent, a folder, not JSON. --world is read by the
# launcher, so the message names the file given.
odelab_refusals(odelab refuses_unusable_world_files headless 2 NEEDLE "--world"
                --world=/nonexistent-world.json --world=/ --world=/etc/hostname)
# An engine that is not one, or --export-world with one: refused naming the option.
foreach(_program IN LISTS ODELAB_PROGRAMS)
  odelab_refusals(${_program} refuses_unknown_engines headless 2 --engine=odd "--export-world=w.json --engine=bullet"
                  --engine-setting=better)
endforeach()

# Without Node.js: the engines it runs are named as missing, refused
# cleanly, and skipped (and said) by the lab (scripts/without_node.sh).
if(ODELAB_ENGINE_NODE)
  add_test(NAME engines_without_node_named_refused_and_skipped
           COMMAND bash ${ODELAB_CHECK_SCRIPTS}/without_node.sh ${CMAKE_SOURCE_DIR} $<TARGET_FILE_DIR:test9>
                   ${CMAKE_CURRENT_BINARY_DIR}/runs/without_node)
  set_tests_properties(engines_without_node_named_refused_and_skipped PROPERTIES LABELS engines TIMEOUT 900)
endif()

# The engines' side of the protocol (peers/wasm/src/session.js), which the
# Node.js server and the page share: replies, an error told in the next
# reply, a number that is not finite sent as null, quit (node's test runner);
# 100 sessions per engine on one module, each freeing its world at quit; and
# an engine's step time that holds none of the clock's own CPU reading.
if("rapier" IN_LIST ODELAB_CHECK_ENGINES)
  add_test(NAME engine_protocol_session
           COMMAND ${ODELAB_NODE} --test ${CMAKE_SOURCE_DIR}/peers/wasm/test/session.test.js
                   ${CMAKE_SOURCE_DIR}/peers/wasm/test/sessions_free_their_worlds.test.js
                   ${CMAKE_SOURCE_DIR}/peers/wasm/test/step_clock.test.js)
  set_tests_properties(engine_protocol_session PROPERTIES LABELS engines TIMEOUT 300)
  # The bare harness (peers/wasm/bench/bare.js, the floor of
  # bench_engine_overhead.py) builds the adapter's world: its bodies end
  # where the Rapier adapter's do; what it cannot build it refuses, named.
  add_test(NAME engine_bare_harness_same_world
           COMMAND ${ODELAB_NODE} --test ${CMAKE_SOURCE_DIR}/peers/wasm/test/bare_harness.test.js)
  set_tests_properties(engine_bare_harness_same_world PROPERTIES LABELS engines TIMEOUT 300)
endif()
# The PhysX adapter on cases with a known answer (peers/wasm/test/physx.test.js):
# a dropped ball's fall against 1/2 g t^2, a hinged pendulum's energy, a
# slider along a tilted axis and its stop, fixed joints (no scene has a
# slider or a fixed joint), a cylinder refused, the notes.
if("physx" IN_LIST ODELAB_CHECK_ENGINES)
  add_test(NAME engine_physx_adapter_analytic
           COMMAND ${ODELAB_NODE} --test ${CMAKE_SOURCE_DIR}/peers/wasm/test/physx.test.js)
  set_tests_properties(engine_physx_adapter_analytic PROPERTIES LABELS engines TIMEOUT 300)
endif()
