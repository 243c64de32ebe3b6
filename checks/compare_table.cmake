# ---- what a compare run prints at its end (label compare) --------------------
# A short table, an engine a row, and no metric lines: every metric goes to
# --metrics-json (some 240 lines with six engines buried the figures).
if(ODELAB_ENGINE_BULLET)
  add_test(NAME compare_test2_prints_a_table_not_every_metric
           COMMAND sh -c "\"$<TARGET_FILE:test2>\" --compare bullet --headless --seconds 0.2 --out-dir . --metrics-json m.json > out.txt; s=$?; cat out.txt; test $s -eq 0 && grep -q '^engine  *status  *sim s  *engine ms/step  *link ms/step  *headline' out.txt && grep -q '^ode  *0  *0.2 ' out.txt && grep -q '^bullet  *0  *0.2 ' out.txt && ! grep -q ' = ' out.txt && grep -q 'bullet.sim_seconds' m.json"
           WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  set_tests_properties(compare_test2_prints_a_table_not_every_metric PROPERTIES LABELS compare TIMEOUT 120)
endif()
