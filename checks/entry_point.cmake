# The README's entry point: `scripts/odelab.sh run NAME` with a name that is
# not a program says which programs exist and exits 2, before installing or
# building anything.
# The names it gives are CMake's list.
string(REPLACE ";" " " ODELAB_PROGRAMS_TEXT "${ODELAB_PROGRAMS}")
add_test(NAME odelab_sh_run_unknown_program_exits_2
         COMMAND sh -c "bash \"${CMAKE_SOURCE_DIR}/scripts/odelab.sh\" run no-such-test 2>err.txt; s=$?; cat err.txt; test $s -eq 2 && grep -q 'the programs are ${ODELAB_PROGRAMS_TEXT}' err.txt"
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties(odelab_sh_run_unknown_program_exits_2 PROPERTIES LABELS hardening)
