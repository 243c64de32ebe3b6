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

# A world the format accepts runs, or is refused with status 2 naming its
# field (checks/scripts/world_reader_cases.py --group valid): tilted gravity,
# a jointed body without a geom, "infinity" in a vector, an inertia of
# 1e300, settings past the knobs' ranges, a key given twice, a byte-order
# mark, a missing comma, a misspelt field.
add_test(NAME world_reader_valid_worlds_run_or_name_the_field
         COMMAND /usr/bin/python3 ${ODELAB_CHECK_SCRIPTS}/world_reader_cases.py --odelab $<TARGET_FILE:odelab>
                 --group valid --work ${CMAKE_CURRENT_BINARY_DIR}/runs/world_reader_valid)
set_tests_properties(world_reader_valid_worlds_run_or_name_the_field PROPERTIES LABELS engines TIMEOUT 120)

# The reader's bounds: 100,000 bodies read within 10 CPU seconds, 100,000
# nested arrays refused within 1 GiB (--group bounds).
add_test(NAME world_reader_bounds
         COMMAND /usr/bin/python3 ${ODELAB_CHECK_SCRIPTS}/world_reader_cases.py --odelab $<TARGET_FILE:odelab>
                 --group bounds --work ${CMAKE_CURRENT_BINARY_DIR}/runs/world_reader_bounds)
set_tests_properties(world_reader_bounds PROPERTIES LABELS engines TIMEOUT 120)

# A world's title and an engine's error text with line breaks make no line
# of their own in the outputs or on stdout (--group text; the engine is a
# stand-in for the Node.js server that fails its first step).
add_test(NAME world_given_text_stays_one_line
         COMMAND /usr/bin/python3 ${ODELAB_CHECK_SCRIPTS}/world_reader_cases.py --odelab $<TARGET_FILE:odelab>
                 --group text --work ${CMAKE_CURRENT_BINARY_DIR}/runs/world_given_text)
set_tests_properties(world_given_text_stays_one_line PROPERTIES LABELS engines TIMEOUT 120)

# Random worlds the schema accepts, made from nothing within the reader's
# ranges (checks/scripts/world_generate.py): each is exported, its export
# read back and run, every 100th run on each engine here; each runs or is
# refused naming its field, never a signal, an ODE error or an export that
# does not read back. CI's quick form: 2,000 worlds.
string(REPLACE ";" "," _generated_engines "${ODELAB_CHECK_ENGINES}")
add_test(NAME world_generated_2000_random_worlds
         COMMAND /usr/bin/python3 ${ODELAB_CHECK_SCRIPTS}/world_generate.py --odelab $<TARGET_FILE:odelab>
                 --tool $<TARGET_FILE:world_read_tool> --schema ${CMAKE_SOURCE_DIR}/doc/world.schema.json
                 --count 2000 --seed 51 --engines "${_generated_engines}" --engine-every 100
                 --work ${CMAKE_CURRENT_BINARY_DIR}/runs/world_generated)
set_tests_properties(world_generated_2000_random_worlds PROPERTIES LABELS engines TIMEOUT 1800)
