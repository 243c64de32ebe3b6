# ---- the lab on a world file (issue 38: lab/odelab-report --world) ----
# `odelab-report --world checks/worlds/bouncing-ball.json --quick` sweeps the
# step, the solver, ERP and CFM on ODE, searches the step's stability limit and
# runs every engine --list-engines has (a missing one is listed, never fatal);
# lab/check_world_report.py then checks its files (CSVs with the run header and
# rows, one reference row deviating 0 from itself, valid PNG and SVG plots) and
# recomputes every sentence of its first screen from the CSVs (claims.csv).
# A world odelab refuses ends the report before any run with status 2 and
# odelab's message naming the field; --world with --only is refused (status 2).
set(ODELAB_LAB_WORLD_DIR ${CMAKE_BINARY_DIR}/lab-world-quick)
add_test(NAME lab_world_report_quick
         COMMAND ${CMAKE_SOURCE_DIR}/lab/odelab-report --world ${CMAKE_SOURCE_DIR}/checks/worlds/bouncing-ball.json
                 --quick --out ${ODELAB_LAB_WORLD_DIR} --build-dir $<TARGET_FILE_DIR:test2>)
# (measured here: 1:30 on 2 cores with all six engines, most of it Node's three)
set_tests_properties(lab_world_report_quick PROPERTIES
                     FIXTURES_SETUP lab_world_report PROCESSORS 2 TIMEOUT 900 LABELS lab)
add_test(NAME lab_world_report_files_valid
         COMMAND ${Python3_EXECUTABLE} ${CMAKE_SOURCE_DIR}/lab/check_world_report.py ${ODELAB_LAB_WORLD_DIR})
set_tests_properties(lab_world_report_files_valid PROPERTIES FIXTURES_REQUIRED lab_world_report LABELS lab)

add_test(NAME lab_world_refusals
         COMMAND sh ${CMAKE_SOURCE_DIR}/checks/scripts/lab_world_refusals.sh ${CMAKE_SOURCE_DIR}/lab/odelab-report
                 ${CMAKE_SOURCE_DIR}/checks/worlds/refused-mass.json ${CMAKE_SOURCE_DIR}/checks/worlds/bouncing-ball.json
                 $<TARGET_FILE_DIR:test2> ${CMAKE_BINARY_DIR}/lab-world-refusals)
set_tests_properties(lab_world_refusals PROPERTIES LABELS lab TIMEOUT 120)

# The committed reports of the example worlds (doc/worlds/NAME/RESULTS.md,
# doc/worlds.md links them): each holds the rules check_world_report.py
# recomputes, as the fresh one above does.
file(GLOB ODELAB_WORLD_EXAMPLES ${CMAKE_SOURCE_DIR}/doc/worlds/*.json)
# An example whose report is not committed (one taken out because the lab's
# rules changed after it was made, until it is made again) is named here.
foreach(world ${ODELAB_WORLD_EXAMPLES})
  get_filename_component(name ${world} NAME_WE)
  if(NOT EXISTS ${CMAKE_SOURCE_DIR}/doc/worlds/${name}/RESULTS.md)
    message(STATUS "doc/worlds/${name}.json has no committed report: make it with lab/odelab-report --world doc/worlds/${name}.json --quick --out doc/worlds/${name}")
    continue()
  endif()
  add_test(NAME lab_world_report_committed_${name}
           COMMAND ${Python3_EXECUTABLE} ${CMAKE_SOURCE_DIR}/lab/check_world_report.py ${CMAKE_SOURCE_DIR}/doc/worlds/${name})
  set_tests_properties(lab_world_report_committed_${name} PROPERTIES LABELS lab)
endforeach()
