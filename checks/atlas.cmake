# ---- the accuracy atlas's cases (doc/atlas/*.json) on ODE, in one process:
# each probe's expect within the case's stated tolerance, or ODE's recorded
# miss (doc/atlas/ode-known.csv) as recorded. CTest label: unit.
# With them, each probe reading against the integrator's exact figure (probe_readings.cpp).
add_executable(atlas_cases_on_ode atlas_cases_on_ode.cpp probe_readings.cpp unit/test_ode_environment.cpp)  # ODE initialised once
target_link_libraries(atlas_cases_on_ode PRIVATE odelab_physics odelab_warnings GTest::gtest GTest::gtest_main)
target_compile_definitions(atlas_cases_on_ode PRIVATE "ODELAB_ATLAS_DIR=\"${PROJECT_SOURCE_DIR}/doc/atlas\"")
add_test(NAME atlas_cases_on_ode COMMAND atlas_cases_on_ode)
set_tests_properties(atlas_cases_on_ode PROPERTIES LABELS unit TIMEOUT 600)
