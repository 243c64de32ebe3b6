# Size targets of the framework: the scene base's header and every test
# program (checks/scripts/size_targets.sh).
add_test(NAME framework_files_within_size_targets
         COMMAND sh ${ODELAB_CHECK_SCRIPTS}/size_targets.sh ${CMAKE_SOURCE_DIR})
set_tests_properties(framework_files_within_size_targets PROPERTIES LABELS unit)
