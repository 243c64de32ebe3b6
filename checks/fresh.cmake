# ---- the first ten minutes (issue 32; label fresh) -------------------------------
# A new user's machine has only what `scripts/odelab.sh run` installs: the
# window's packages. The project must configure there, name once each part
# it leaves out with the Debian package that brings it, and build and run
# test0. Checked two ways:
#
# On every CI, in a scratch build on this machine with everything but the
# window's packages hidden (checks/scripts/window_packages_only.sh): two
# configures and test0 built from scratch (about 40 s on 2 cores with a
# warm compiler cache; a few minutes without one).
add_test(NAME fresh_window_packages_only_configure_build_run
         COMMAND ${ODELAB_CHECK_SCRIPTS}/window_packages_only.sh ${CMAKE_SOURCE_DIR}
                 ${CMAKE_BINARY_DIR}/fresh-window-only)
set_tests_properties(fresh_window_packages_only_configure_build_run PROPERTIES
                     LABELS fresh PROCESSORS 2 TIMEOUT 900)

# For real: the README's first command in a fresh Debian 12 root made by
# debootstrap (checks/scripts/fresh_root.sh), which installs the window's
# packages from the archive, builds test0 with no compiler cache and runs it
# headless; it prints the time that took. Skipped (77, saying why) without
# root, debootstrap or chroot.
# A CTest rather than a step of `scripts/odelab.sh test` before ctest: its
# verdict then sits in the one summary with every other check, a skip shows
# as one, and `ctest -L fresh` runs it alone. RUN_SERIAL so that its build,
# the longest single job of the suite (several minutes on 2 cores), runs
# alone: the time it prints is then that of a machine doing nothing else,
# and the checks beside it are not starved. TIMEOUT: 30 minutes, well over
# the measured runs (doc/measurements/first_ten_minutes.csv), for a slow archive.
add_test(NAME fresh_root_first_command_runs_test0
         COMMAND ${ODELAB_CHECK_SCRIPTS}/fresh_root.sh ${CMAKE_SOURCE_DIR})
set_tests_properties(fresh_root_first_command_runs_test0 PROPERTIES
                     LABELS fresh RUN_SERIAL ON TIMEOUT 1800 SKIP_RETURN_CODE 77)
