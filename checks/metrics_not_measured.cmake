# ---- metrics not measured and not finite, one rule (doc/manual.md, "Outputs"). Labels: hardening, lab.
# The programs' side: short runs of the scenes whose figures need time
# (test1's rebounds, test2's period, test9's later apexes) write exactly
# those as null, not measured, and every other metric as a finite number.
add_test(NAME metrics_not_measured_are_null_and_nothing_else
         COMMAND ${Python3_EXECUTABLE} ${ODELAB_CHECK_SCRIPTS}/metrics_not_measured.py $<TARGET_FILE_DIR:test2>)
set_tests_properties(metrics_not_measured_are_null_and_nothing_else PROPERTIES LABELS hardening TIMEOUT 120)
# The lab's side: null gives no figure; "nan", "inf", "-inf" are refused, named.
add_test(NAME lab_metrics_not_measured_or_not_finite
         COMMAND ${Python3_EXECUTABLE} -m unittest discover -s ${CMAKE_SOURCE_DIR}/lab/tests
                 -p test_metrics_not_measured.py)
set_tests_properties(lab_metrics_not_measured_or_not_finite PROPERTIES LABELS "lab;hardening" TIMEOUT 60)
