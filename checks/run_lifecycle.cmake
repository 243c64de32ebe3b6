# ---- a run's life from its refusal to its end (doc/hardening.md, "Fourth round"). Labels: hardening, engines.
# A refused run, or one whose engine fails before its first step, keeps the
# previous run's files; no run writes a file it reads.
set(_node_here "")
if("jolt" IN_LIST ODELAB_CHECK_ENGINES)
  set(_node_here node)
endif()
add_test(NAME refused_runs_keep_previous_files_and_inputs
         COMMAND sh ${ODELAB_CHECK_SCRIPTS}/refused_runs_keep_files.sh $<TARGET_FILE_DIR:test2> ${_node_here})
set_tests_properties(refused_runs_keep_previous_files_and_inputs PROPERTIES LABELS hardening TIMEOUT 180)

# An engine that fails ends with status 7, never read as a blow-up, and the
# relative energy figures of a world have a defined denominator.
add_test(NAME engine_failure_is_not_physics
         COMMAND sh ${ODELAB_CHECK_SCRIPTS}/engine_failure_not_physics.sh ${CMAKE_SOURCE_DIR} $<TARGET_FILE_DIR:test2>
                 ${_node_here})
set_tests_properties(engine_failure_is_not_physics PROPERTIES LABELS "hardening;engines" TIMEOUT 240)
add_test(NAME lab_engine_failure_not_physics
         COMMAND ${Python3_EXECUTABLE} -m unittest discover -s ${CMAKE_SOURCE_DIR}/lab/tests -p test_engine_failure_status.py)
set_tests_properties(lab_engine_failure_not_physics PROPERTIES LABELS "lab;hardening" TIMEOUT 60)
# The lab's own writer: no world file inside the --out it replaces, no --out through a link.
add_test(NAME lab_run_inputs_kept
         COMMAND /usr/bin/python3 -m unittest discover -s ${CMAKE_SOURCE_DIR}/lab/tests -p test_run_inputs_kept.py)
set_tests_properties(lab_run_inputs_kept PROPERTIES LABELS "lab;hardening" TIMEOUT 120)

# An engine that stops answering: the deadline, a stop signal while waiting.
if(_node_here)
  add_test(NAME engine_that_stops_answering_never_holds_the_run
           COMMAND sh ${ODELAB_CHECK_SCRIPTS}/engine_that_stops_answering.sh $<TARGET_FILE:test2>)
  set_tests_properties(engine_that_stops_answering_never_holds_the_run PROPERTIES LABELS "hardening;engines" TIMEOUT 300)
endif()

# Signals and limits that used to kill a run unmarked, a reader that goes
# away, a TMPDIR that is not there, a name every JavaScript object has.
set(_server_js "")
if(_node_here)
  set(_server_js ${CMAKE_SOURCE_DIR}/peers/wasm/engine_server.js)
endif()
add_test(NAME signals_and_limits_leave_runs_marked_and_nothing_behind
         COMMAND sh ${ODELAB_CHECK_SCRIPTS}/signals_leave_nothing_behind.sh $<TARGET_FILE:test2> ${_server_js})
set_tests_properties(signals_and_limits_leave_runs_marked_and_nothing_behind PROPERTIES LABELS hardening TIMEOUT 240)
