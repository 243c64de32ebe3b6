# A twelfth scene is one line of tests/scenes/scenes.txt, its source and its
# checks file: in a scratch copy of the tree, a copy of test9 listed as
# test11 gets every check test9 has, the launcher's list, its name in its
# files, and its place in scripts/odelab.sh, Makefile.win, the web page's
# list and the lab (checks/scripts/twelfth_scene.sh; builds the launcher and
# one program).
add_test(NAME a_twelfth_scene_is_one_line_of_the_list
         COMMAND bash ${ODELAB_CHECK_SCRIPTS}/twelfth_scene.sh ${CMAKE_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/twelfth_scene)
set_tests_properties(a_twelfth_scene_is_one_line_of_the_list PROPERTIES LABELS unit TIMEOUT 1800 PROCESSORS 2)
