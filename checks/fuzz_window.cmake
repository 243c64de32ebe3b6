# ---- window fuzzing (issue 7): 10,000 random input events per program ---------
# Each program's window, under Xvfb, takes a seeded random script of keys
# with modifiers, mouse motion, clicks, wheel turns and resizes
# (fuzz_events.cpp) and must take every event and exit cleanly on Esc
# (scripts/fuzz_window.sh says how it is checked and how to replay a seed).
# The seeds are fixed, so CI is repeatable; ODELAB_FUZZ_SEED=random, or a
# number, tries others.
add_executable(fuzz_events fuzz_events.cpp)
target_link_libraries(fuzz_events PRIVATE PkgConfig::SDL2 CLI11::CLI11 odelab_warnings)

if(NOT XVFB_RUN)
  return()  # CMakeLists.txt has warned already
endif()

foreach(_program IN LISTS ODELAB_PROGRAMS)
  string(REGEX REPLACE "^test" "" _number ${_program})
  math(EXPR _seed "7000 + ${_number}")
  add_test(NAME fuzz_window_${_program}
           COMMAND sh ${ODELAB_CHECK_SCRIPTS}/fuzz_window.sh ${XVFB_RUN} $<TARGET_FILE:fuzz_events>
                   $<TARGET_FILE:expect_metrics> $<TARGET_FILE:${_program}>
                   ${CMAKE_CURRENT_BINARY_DIR}/fuzz_runs/${_program} ${_seed})
  set_tests_properties(fuzz_window_${_program} PROPERTIES TIMEOUT 330 LABELS fuzz)
endforeach()
