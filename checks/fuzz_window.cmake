# ---- window fuzzing (issue 7): 10,000 random input events per program ---------
# Each program's window, under Xvfb, takes a seeded random script of keys
# with modifiers, mouse motion, clicks, wheel turns and resizes
# (fuzz_events.cpp) and must take every event and exit cleanly on Esc
# (fuzz_window.sh says how it is checked and how to replay a seed). The
# seeds are fixed, so CI is repeatable; ODELAB_FUZZ_SEED=random, or a number,
# tries others.
add_executable(fuzz_events fuzz_events.cpp)
target_link_libraries(fuzz_events PRIVATE PkgConfig::SDL2 CLI11::CLI11)

find_program(XVFB_RUN xvfb-run)
if(NOT XVFB_RUN)
  return()  # windowed.cmake has warned already
endif()

list(LENGTH ODELAB_PROGRAMS _fuzz_count)
math(EXPR _fuzz_last "${_fuzz_count} - 1")
foreach(_i RANGE 0 ${_fuzz_last} 2)
  list(GET ODELAB_PROGRAMS ${_i} _program)
  if(NOT TARGET ${_program})
    continue()
  endif()
  string(REGEX REPLACE "^test" "" _number ${_program})
  math(EXPR _seed "7000 + ${_number}")
  add_test(NAME fuzz_window_${_program}
           COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/fuzz_window.sh ${XVFB_RUN} $<TARGET_FILE:fuzz_events>
                   $<TARGET_FILE:expect_metrics> $<TARGET_FILE:${_program}>
                   ${CMAKE_CURRENT_BINARY_DIR}/fuzz_runs/${_program} ${_seed})
  set_tests_properties(fuzz_window_${_program} PROPERTIES TIMEOUT 330)
endforeach()
