# ---- the accuracy atlas on every engine (lab/odelab-report --atlas) ----
# The quick form (step 1/240 s, each cell's one run timed itself) of every
# case of doc/atlas/ on every engine here, default and best; then
# lab/check_atlas_report.py makes its ATLAS.md again from its CSVs, as it
# does for the committed atlas (doc/atlas-report/).
set(ODELAB_LAB_ATLAS_DIR ${CMAKE_BINARY_DIR}/lab-atlas-quick)
add_test(NAME lab_atlas_quick
         COMMAND ${CMAKE_SOURCE_DIR}/lab/odelab-report --atlas --quick --out ${ODELAB_LAB_ATLAS_DIR}
                 --build-dir $<TARGET_FILE_DIR:test2>)
# (measured here: 3:10 on 2 cores with seven engines, most of it Node's four)
set_tests_properties(lab_atlas_quick PROPERTIES FIXTURES_SETUP lab_atlas PROCESSORS 2 TIMEOUT 1200 LABELS lab)
add_test(NAME lab_atlas_report_made_from_its_csvs
         COMMAND ${Python3_EXECUTABLE} ${CMAKE_SOURCE_DIR}/lab/check_atlas_report.py ${ODELAB_LAB_ATLAS_DIR})
set_tests_properties(lab_atlas_report_made_from_its_csvs PROPERTIES FIXTURES_REQUIRED lab_atlas LABELS lab)
add_test(NAME lab_atlas_committed_report_made_from_its_csvs
         COMMAND ${Python3_EXECUTABLE} ${CMAKE_SOURCE_DIR}/lab/check_atlas_report.py
                 ${CMAKE_SOURCE_DIR}/doc/atlas-report)
set_tests_properties(lab_atlas_committed_report_made_from_its_csvs PROPERTIES LABELS lab)
# What the programs and the docs say of each engine is what the atlas measured:
# --list-engines prints the committed atlas-notes.csv (compiled in), and every
# [atlas: ...] tag in a hand-written note holds to atlas.csv.
add_test(NAME list_engines_prints_the_committed_atlas_notes
         COMMAND ${Python3_EXECUTABLE} ${ODELAB_CHECK_SCRIPTS}/list_engines_atlas_notes.py $<TARGET_FILE:odelab>
                 ${CMAKE_SOURCE_DIR}/doc/atlas-report/atlas-notes.csv)
set_tests_properties(list_engines_prints_the_committed_atlas_notes PROPERTIES LABELS lab)
add_test(NAME engine_notes_hold_to_the_atlas
         COMMAND ${Python3_EXECUTABLE} ${CMAKE_SOURCE_DIR}/lab/check_engine_claims.py ${CMAKE_SOURCE_DIR})
set_tests_properties(engine_notes_hold_to_the_atlas PROPERTIES LABELS lab)
