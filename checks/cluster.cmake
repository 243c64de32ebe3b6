# ---- the lab beyond one machine (doc/cluster.md) and the lab's own safety ------
# Dask and Slurm are optional: a check whose tools are missing is left out,
# said once here with the Debian packages that bring them (scripts/odelab.sh
# test installs them). The cache variables can be set to NOTFOUND to hide one.
find_program(ODELAB_DASK dask)
set(_slurm_tools)
foreach(_tool munged slurmctld slurmd salloc)
  string(TOUPPER ${_tool} _var)
  find_program(ODELAB_${_var} ${_tool} PATHS /usr/sbin /sbin)
  if(NOT ODELAB_${_var})
    list(APPEND _slurm_tools ${_tool})
  endif()
endforeach()
if(NOT ODELAB_DASK)
  message(STATUS "Dask left out (check lab_dask_cluster_same_results): dask not found; "
                 "Debian's python3-distributed brings it")
endif()
if(_slurm_tools)
  string(REPLACE ";" ", " _slurm_tools "${_slurm_tools}")
  message(STATUS "Slurm left out (check lab_slurm_single_node_same_results): ${_slurm_tools} not found; "
                 "Debian's munge slurmctld slurmd slurm-client bring them")
endif()
# cluster: a real Dask scheduler and two workers on 127.0.0.1, started and
# stopped by the check itself (python3-distributed, scripts/odelab.sh).
if(ODELAB_DASK)
  add_test(NAME lab_dask_cluster_same_results
           COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/scripts/dask_cluster_check.sh
                   $<TARGET_FILE_DIR:test2> ${CMAKE_BINARY_DIR}/lab-dask-check)
  set_tests_properties(lab_dask_cluster_same_results PROPERTIES
                       LABELS cluster PROCESSORS 2 TIMEOUT 300 RUN_SERIAL ON)
endif()
# RUN_SERIAL: it asserts that no test4 of this build runs after an interrupt,
# which another lab check running beside it would contradict.

# The lab's --out, --only and interrupts (issue 15, items 3 and 8): refusals
# with status 2 and nothing touched, SIGINT at ten moments of a report.
add_test(NAME lab_out_only_interrupt_safety
         COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/scripts/lab_safety_check.sh
                 $<TARGET_FILE_DIR:test2> ${CMAKE_BINARY_DIR}/lab-safety-check)
set_tests_properties(lab_out_only_interrupt_safety PROPERTIES LABELS lab PROCESSORS 2 TIMEOUT 300)

# cluster: a single-node Slurm (munged, slurmctld, slurmd started by hand with a
# configuration in a temporary folder, stopped by process id); srun steps give
# the local run's non-timing columns; SIGINT and scancel end the lab cleanly.
# About 30 s; needs root (slurmd), else skipped.
if(NOT _slurm_tools)
  add_test(NAME lab_slurm_single_node_same_results
           COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/scripts/slurm_lab_check.sh
                   $<TARGET_FILE_DIR:test2> ${CMAKE_BINARY_DIR}/lab-slurm-check)
  set_tests_properties(lab_slurm_single_node_same_results PROPERTIES
                       LABELS cluster PROCESSORS 2 TIMEOUT 300 RUN_SERIAL ON SKIP_RETURN_CODE 77)
endif()

# The executor plumbing without a cluster: --executor values, Slurm's CPU
# count, the one-timing-host rule, a run's files packed and unpacked, --out rules.
add_test(NAME lab_executor_units
         COMMAND /usr/bin/python3 -m unittest discover -s ${CMAKE_SOURCE_DIR}/lab/tests)
set_tests_properties(lab_executor_units PROPERTIES LABELS lab TIMEOUT 60)
