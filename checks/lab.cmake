# ---- lab report (quick) ----
# The speed-accuracy lab (lab/, doc/lab.md): `odelab-report --quick` runs every
# experiment on these programs (a few minutes on 2 cores: its timings are
# repeated and stretched, doc/lab.md), then
# lab/check_report.py checks that every CSV has its run header and rows, and that
# every plot exists and is a valid image (PNG signature and size, SVG parses as XML).
# The report's peers section runs the scenes on Bullet and MuJoCo (--engine): where either
# was left out (peers/engines/CMakeLists.txt names it once) the quick report is too.
if(ODELAB_ENGINE_BULLET AND ODELAB_ENGINE_MUJOCO)
  set(ODELAB_LAB_QUICK_DIR ${CMAKE_BINARY_DIR}/lab-quick)
  add_test(NAME lab_report_quick
           COMMAND ${CMAKE_SOURCE_DIR}/lab/odelab-report --quick --out ${ODELAB_LAB_QUICK_DIR}
                   --build-dir $<TARGET_FILE_DIR:test2>)
  # (odelab-report picks its own Python, Debian's, for python3-matplotlib and python3-tqdm;
  # check_report.py needs only the standard library: the Python CMake found.)
  # Its peers experiment runs Havok, Jolt and Rapier through the engines' pipe
  # to Node.js, every step: alone it took 9:26 here (`--quick --only peers`,
  # 251 runs, load average 8), hence the room.
  set_tests_properties(lab_report_quick PROPERTIES
                       FIXTURES_SETUP lab_report PROCESSORS 2 TIMEOUT 1800 LABELS lab)
  add_test(NAME lab_report_files_valid
           COMMAND ${Python3_EXECUTABLE} ${CMAKE_SOURCE_DIR}/lab/check_report.py ${ODELAB_LAB_QUICK_DIR})
  set_tests_properties(lab_report_files_valid PROPERTIES FIXTURES_REQUIRED lab_report LABELS lab)
endif()

# ---- the committed report and the docs ----
# Every sentence of the committed doc/results/RESULTS.md (first table,
# headline findings, the engines' included, sections' conclusions),
# recomputed from the committed CSVs by its rule (claims.csv), each rule
# reading its data; every measured figure in README.md and doc/ cited to the
# committed CSV cell it equals or inside a block the lab generates (and
# regenerated to compare), a setting written as code; the pages not yet
# converted counted exactly in lab/reference/docs-uncited.txt
# (lab/check_docs.py says which numbers count).
add_test(NAME lab_committed_report_claims
         COMMAND ${Python3_EXECUTABLE} ${CMAKE_SOURCE_DIR}/lab/check_report.py ${CMAKE_SOURCE_DIR}/doc/results)
set_tests_properties(lab_committed_report_claims PROPERTIES LABELS lab)
add_test(NAME lab_docs_figures_in_csvs
         COMMAND ${Python3_EXECUTABLE} ${CMAKE_SOURCE_DIR}/lab/check_docs.py ${CMAKE_SOURCE_DIR})
set_tests_properties(lab_docs_figures_in_csvs PROPERTIES LABELS lab)
# (lab/tests/test_claims.py runs under lab_executor_units, which discovers lab/tests.)

# ---- the file rule (checks/file_rules.json) in the lab ----
# Every writer case through the lab's writers (files.py, csvout.write_csv) and
# every reader case through its bounded reader, and a link planted at the
# writer's temporary name left alone. (lab_executor_units runs it too, among
# all of lab/tests; this names the rule's check on its own.)
add_test(NAME lab_file_rules
         COMMAND ${Python3_EXECUTABLE} -m unittest discover -s ${CMAKE_SOURCE_DIR}/lab/tests -p test_file_rules.py)
set_tests_properties(lab_file_rules PROPERTIES LABELS lab TIMEOUT 60)

# Every sentence a rule on its own data: the engines' headline findings are
# claims on peers.csv, a typed one or a rule that reads none of its values is
# refused. The docs cite the cell they quote: a figure not in the cell its
# citation names is refused, and a fabricated figure and a changed cited cell
# planted in a copy of the docs fail. (Both also part of lab_executor_units.)
add_test(NAME lab_sentence_rules
         COMMAND ${Python3_EXECUTABLE} -m unittest discover -s ${CMAKE_SOURCE_DIR}/lab/tests -p test_sentence_rules.py)
set_tests_properties(lab_sentence_rules PROPERTIES LABELS lab TIMEOUT 60)
add_test(NAME lab_doc_citations
         COMMAND ${Python3_EXECUTABLE} -m unittest discover -s ${CMAKE_SOURCE_DIR}/lab/tests -p test_doc_citations.py)
set_tests_properties(lab_doc_citations PROPERTIES LABELS lab TIMEOUT 60)

# The first screen's rules on their own (also part of lab_executor_units):
# a row whose cell reads another quantity or setting than its definition is
# refused, n/a says why, costs are CPU time over the timed runs, the screen fits.
add_test(NAME lab_first_screen_rules
         COMMAND ${Python3_EXECUTABLE} -m unittest discover -s ${CMAKE_SOURCE_DIR}/lab/tests -p test_first_screen.py)
set_tests_properties(lab_first_screen_rules PROPERTIES LABELS lab TIMEOUT 60)

# The report's physics scores on their own (also part of lab_executor_units):
# test6's fall time against the analytic inverted pendulum from the scene's own
# constants, its first-screen row, the engines' untilted test6 left unranked;
# test2's energy errors per swing energy m g d.
# (Debian's Python, as lab_executor_units: the experiments import matplotlib.)
add_test(NAME lab_physics_scores
         COMMAND /usr/bin/python3 -m unittest discover -s ${CMAKE_SOURCE_DIR}/lab/tests -p test_physics_scores.py)
set_tests_properties(lab_physics_scores PROPERTIES LABELS lab TIMEOUT 60)

# Like with like across engines and timing with spread on their own (also
# part of lab_executor_units): another surface or a figure zero by
# construction takes no part, defaults beside defaults, an equal figure
# inside the cheapest's timing range is a tie, timed runs last 0.5 s of CPU,
# the tuning's and the remedies' choices inside the scatter are ties; the
# peers experiment's runs per engine (Debian's Python: it imports matplotlib).
add_test(NAME lab_like_with_like
         COMMAND /usr/bin/python3 -m unittest discover -s ${CMAKE_SOURCE_DIR}/lab/tests -p test_like_with_like.py)
set_tests_properties(lab_like_with_like PROPERTIES LABELS lab TIMEOUT 60)
