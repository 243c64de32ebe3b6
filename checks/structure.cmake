# Size target of every test program, each read as its thesis chapter
# (checks/scripts/size_targets.sh).
add_test(NAME framework_files_within_size_targets
         COMMAND sh ${ODELAB_CHECK_SCRIPTS}/size_targets.sh ${CMAKE_SOURCE_DIR})
set_tests_properties(framework_files_within_size_targets PROPERTIES LABELS unit)
