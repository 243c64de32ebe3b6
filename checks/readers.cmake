# ---- readers and writers of given text (doc/hardening.md, "Readers with a
# bound" and "Given text stays text").

# A world's title and file name enter the lab's RESULTS.md escaped (one
# Markdown escaping function), and lab/check_world_report.py refuses a
# report whose title made a second heading or an HTML element.
add_test(NAME lab_forged_text
         COMMAND /usr/bin/python3 -m unittest discover -s ${CMAKE_SOURCE_DIR}/lab/tests -p test_forged_text.py)
set_tests_properties(lab_forged_text PROPERTIES LABELS lab TIMEOUT 60)
