# ---- a malformed world file is refused (issue 38). CTest label: engines.

# 200 world files, each a valid world (test1, 2, 4, 8 and 9 exported, and
# checks/worlds/fuzz_seed.json with joints, pair surfaces, measures and
# events) broken in one way the format forbids: a required field deleted, a
# value of the wrong type or out of its range, an index past its list, a
# field misspelt, a quaternion not of length 1, an inertia not positive
# definite, a joint on one body twice, the text cut short or a byte put in.
# Each must end with status 2 and one line naming the field (a parse error:
# its line), never a crash, a hang, a metrics file or an output file. The
# seeds pass doc/world.schema.json and the schema refuses every file broken
# in a way a schema can see (the rest only the reader can). The
# seed fixes the files, so a failure names a file that stays under runs/.
add_test(NAME world_file_fuzz_200_mutations
         COMMAND /usr/bin/python3 ${ODELAB_CHECK_SCRIPTS}/world_fuzz.py --odelab $<TARGET_FILE:odelab>
                 --program-dir $<TARGET_FILE_DIR:test1> --seed 38 --count 200 --require-line
                 --schema ${CMAKE_SOURCE_DIR}/doc/world.schema.json
                 --work ${CMAKE_CURRENT_BINARY_DIR}/runs/world_fuzz)
set_tests_properties(world_file_fuzz_200_mutations PROPERTIES LABELS engines TIMEOUT 600)
