# Issue 15, the programs' side: files that are whole or say they are not,
# no file replaced that should not be, two runs never mixed, signals that
# end a run as cut short, numbers read as written (doc/hardening.md,
# "What you can rely on"). Label: hardening.

# Refused before running, status 2, nothing left behind (scripts/refusals.sh).
odelab_refusals(test2 refuses_metrics_json_that_is_not_a_regular_file headless 2
                --metrics-json=/dev/null --metrics-json=/dev/stdout --metrics-json=Test2_output.txt)
odelab_refusals(test8 refuses_metrics_json_naming_its_output headless 2 --metrics-json=Test8_output.txt
                --metrics-json=./Test8_output.txt)
# Names that collide, refused by the options' checks before any window
# opens (so without a display too): a frame --record saves, and, in the
# launcher's window that may switch to any scene, any scene's output file.
odelab_refusals(test0 refuses_files_naming_a_recorded_frame no-display 2
                "--metrics-json=test0_frame_000002.png --record=." "--screenshot=test0_frame_000001.png --record=.")
odelab_refusals(odelab refuses_files_naming_any_scenes_output no-display 2
                "--metrics-json=Test2_output.txt --scene=test3" --metrics-json=Test8_output.txt
                "--screenshot=Test2_output.txt --scene=test0" "--metrics-json=test2_frame_000001.png --record=.")
# ...and a hard link at another scene's output file is refused before the
# launcher's window opens on test1, not once Page Down reaches test8.
set(_dir ${CMAKE_CURRENT_BINARY_DIR}/runs/odelab_hard_link)
file(MAKE_DIRECTORY ${_dir})
add_test(NAME odelab_refuses_a_hard_link_at_any_scenes_output
         COMMAND sh -c "rm -f victim Test8_output.txt err.txt && echo precious > victim && ln victim Test8_output.txt &&
                        env -u DISPLAY -u WAYLAND_DISPLAY timeout 60 \"$1\" --seconds 0.1 >/dev/null 2>err.txt; s=$?;
                        cat err.txt; [ $s = 2 ] && grep -q \"^error: cannot write 'Test8_output.txt': has more than one link\" err.txt &&
                        [ \"$(cat victim)\" = precious ]" sh $<TARGET_FILE:odelab>
         WORKING_DIRECTORY ${_dir})
set_tests_properties(odelab_refuses_a_hard_link_at_any_scenes_output PROPERTIES TIMEOUT 120 LABELS hardening)
odelab_refusals(test2 refuses_runs_and_intervals_below_one_step headless 2
                --seconds=1e-7 "--seconds=0.009 --step=0.01" --sample-interval=1e-300 "--sample-interval=0.001 --step=0.002")
odelab_refusals(test8 refuses_sample_interval_below_the_step headless 2 --sample-interval=1e-300)
odelab_refusals(test7 refuses_throw_interval_below_one_step headless 2 --throw-interval=1e-320)
odelab_refusals(test0 refuses_integers_that_are_not_decimal headless 2 --iterations=0x10 --iterations=1e1
                --seed=0x10 --frames=0x10)

# Complete marker, planted link, a second run into one folder, SIGTERM
# headless and in a window (scripts/output_files.sh).
foreach(_program_file test2:Test2_output.txt test8:Test8_output.txt)
  string(REPLACE ":" ";" _pair ${_program_file})
  list(GET _pair 0 _program)
  list(GET _pair 1 _file)
  set(_window)
  if(XVFB_RUN)
    set(_window window)
  endif()
  add_test(NAME ${_program}_output_file_whole_unshared_and_marked
           COMMAND sh ${ODELAB_CHECK_SCRIPTS}/output_files.sh $<TARGET_FILE:${_program}> ${_file} ${_window})
  set_tests_properties(${_program}_output_file_whole_unshared_and_marked PROPERTIES TIMEOUT 300 LABELS hardening)
  # The one file rule's refusals that came late or never: a hard-linked
  # output or metrics file, a metrics name too long for its temporary file,
  # a missing folder; status 2 before the run, nothing written.
  add_test(NAME ${_program}_refuses_hard_links_and_late_failures_before_the_run
           COMMAND sh ${ODELAB_CHECK_SCRIPTS}/late_failures_refused.sh $<TARGET_FILE:${_program}> ${_file})
  set_tests_properties(${_program}_refuses_hard_links_and_late_failures_before_the_run PROPERTIES TIMEOUT 120
                       LABELS hardening)
  # Every way a run ends leaves the file marked: SIGHUP and SIGINT, and in a
  # window --record on a full disk and the display going away (Xlib's
  # exit()). They ended with a plain row, though the program knew why it
  # stopped. Framework code: one program in a window is enough.
  if(NOT _program STREQUAL "test2")
    set(_window)
  endif()
  add_test(NAME ${_program}_every_ending_marks_the_output_file
           COMMAND sh ${ODELAB_CHECK_SCRIPTS}/every_ending_marked.sh $<TARGET_FILE:${_program}> ${_file} ${_window})
  set_tests_properties(${_program}_every_ending_marks_the_output_file PROPERTIES TIMEOUT 300 LABELS hardening)
endforeach()

# Screenshots and --record frames on a full disk (ulimit -f): status 1 and no
# PNG, whole or cut short (stb's own writer ignored write errors).
if(XVFB_RUN)
  add_test(NAME test0_png_on_a_full_disk_is_refused_not_truncated
           COMMAND sh ${ODELAB_CHECK_SCRIPTS}/full_disk_screenshot.sh $<TARGET_FILE:test0>)
  set_tests_properties(test0_png_on_a_full_disk_is_refused_not_truncated PROPERTIES TIMEOUT 300 LABELS hardening)
endif()

# test5 --threads: an ODE error in a pool thread ends the run with status 4
# and a message naming the threads (it aborted with status 134 and no
# message); a threaded run says in its metrics that it is not reproducible.
add_test(NAME test5_ode_error_in_a_pool_thread_exits_4
         COMMAND sh -c "\"$1\" --headless --threads 2 --solver step >/dev/null 2>err.txt; s=$?; cat err.txt;
                        [ $s = 4 ] && grep -q \"error: .*island-stepping threads\" err.txt" sh $<TARGET_FILE:test5>
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties(test5_ode_error_in_a_pool_thread_exits_4 PROPERTIES TIMEOUT 300 LABELS hardening)
odelab_check(test5_threaded_run_says_not_reproducible test5 LABEL hardening
  EXPECT threads==2 reproducible==0 ARGS --headless --seconds 0.5 --threads 2)
odelab_check(test5_single_thread_run_says_reproducible test5 LABEL hardening
  EXPECT threads==1 reproducible==1 ARGS --headless --seconds 0.5)

# The lab's inputs and endings: a CMakeCache.txt that is a FIFO, huge,
# binary or no cache at all; SIGTERM while a program hangs; SIGHUP while the
# runs go on; a run leaving a FIFO or gigabytes. Each ends at once with its
# status and a message, leaving no staging folder, runs' folder or program.
add_test(NAME lab_inputs_checked_and_every_ending_clean
         COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/scripts/lab_inputs_and_endings_check.sh $<TARGET_FILE_DIR:test2>
                 ${CMAKE_CURRENT_BINARY_DIR}/lab-inputs)
set_tests_properties(lab_inputs_checked_and_every_ending_clean PROPERTIES TIMEOUT 600 LABELS lab)

# The lab trusts no run blindly: a run that blew up, or wrote a NaN metric or
# a NaN in its output file, fails the report with a message naming it (no
# traceback, no rule that "holds"); a dask port out of range and an srun
# allocation without a CPU are refused with status 2 at once; SIGTERM ends
# the children of a wrapper that does not exec. About 30 s.
add_test(NAME lab_refuses_untrusted_runs_and_executors
         COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/scripts/lab_trusts_check.sh $<TARGET_FILE_DIR:test2>
                 ${CMAKE_CURRENT_BINARY_DIR}/lab-trusts)
set_tests_properties(lab_refuses_untrusted_runs_and_executors PROPERTIES TIMEOUT 300 LABELS lab)

# An ODE error in a pool thread names the moment and the settings, as on the
# main thread ("... at t=1.104 s (step 0.001, ERP 0.2, CFM 0, solver step,
# 20 iterations, SOR w 1.3)"); it said only which kind of thread failed.
add_test(NAME test5_pool_thread_error_names_time_and_settings
         COMMAND sh -c "\"$1\" --headless --threads 2 --solver step --plates 20 --seconds 3 >/dev/null 2>err.txt;
                        s=$?; cat err.txt; [ $s = 4 ] &&
                        grep -q 'error: .* at t=[0-9.e+-]* s (step 0.001, ERP 0.2, CFM 0, solver step, 20 iterations, SOR w [0-9.]*) (in one of ODE.s island-stepping threads' err.txt"
                        sh $<TARGET_FILE:test5>
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties(test5_pool_thread_error_names_time_and_settings PROPERTIES TIMEOUT 300 LABELS hardening)
