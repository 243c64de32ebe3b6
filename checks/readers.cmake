# ---- readers and writers of given text (doc/hardening.md, "Readers with a
# bound" and "Given text stays text").

# A world's title and file name enter the lab's RESULTS.md escaped (one
# Markdown escaping function), and lab/check_world_report.py refuses a
# report whose title made a second heading or an HTML element.
add_test(NAME lab_forged_text
         COMMAND /usr/bin/python3 -m unittest discover -s ${CMAKE_SOURCE_DIR}/lab/tests -p test_forged_text.py)
set_tests_properties(lab_forged_text PROPERTIES LABELS lab TIMEOUT 60)

# The world reader's figures and its ranges as JSON (checks/world_read_tool.cpp).
add_executable(world_read_tool world_read_tool.cpp)
target_include_directories(world_read_tool PRIVATE ${CMAKE_SOURCE_DIR}/utils/world)
target_link_libraries(world_read_tool PRIVATE odelab_physics odelab_warnings)

# doc/world.schema.json states the ranges the reader enforces
# (utils/world/FormatRanges.h and the knobs' ranges, utils/WorldSettings.cpp):
# the schema's numbers are written from them (world_schema_ranges.py --write)
# and this check fails when the two differ.
add_test(NAME world_schema_ranges_agree
         COMMAND /usr/bin/python3 ${ODELAB_CHECK_SCRIPTS}/world_schema_ranges.py
                 --tool $<TARGET_FILE:world_read_tool> --schema ${CMAKE_SOURCE_DIR}/doc/world.schema.json)
set_tests_properties(world_schema_ranges_agree PROPERTIES LABELS engines TIMEOUT 60)

# The engine server's bounds: a step message of more than 1000 steps is
# refused without stepping (a count of 1e9 held it for hours), and a message
# line past 128 MiB ends the reading (a 256 MiB line was read whole).
# Needs Node.js only, not the engines' packages.
if(ODELAB_NODE)
  add_test(NAME engine_server_bounds COMMAND ${ODELAB_NODE} --test ${CMAKE_SOURCE_DIR}/peers/wasm/test/bounds.test.js)
  set_tests_properties(engine_server_bounds PROPERTIES LABELS engines TIMEOUT 120)
endif()
