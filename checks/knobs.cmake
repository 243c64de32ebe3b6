# Every knob of every program, from one declaration (utils/Knob.h): the
# range --list-settings gives is the range the command line takes. For each
# program, each option at its min and max is taken and shown as the value,
# and the values just past them end with status 2 naming the option
# (scripts/knob_bounds.py). Parsing only: cheap.
foreach(_program IN LISTS ODELAB_PROGRAMS)
  add_test(NAME ${_program}_knob_bounds
           COMMAND ${Python3_EXECUTABLE} ${ODELAB_CHECK_SCRIPTS}/knob_bounds.py $<TARGET_FILE:${_program}>)
  set_tests_properties(${_program}_knob_bounds PROPERTIES TIMEOUT 300 LABELS hardening)
endforeach()

# What --list-settings says is what the options do, for every program at
# once: each setting names its option (mu and max_contacts too), its kind,
# a range holding its default (max "inf" where the option takes inf), and
# the option takes that default and refuses a value just outside with
# status 2 (scripts/settings_listing.py). Parsing only.
set(_listing_programs)
foreach(_program IN LISTS ODELAB_PROGRAMS)
  list(APPEND _listing_programs $<TARGET_FILE:${_program}>)
endforeach()
add_test(NAME every_program_lists_its_settings_as_its_options_take_them
         COMMAND ${Python3_EXECUTABLE} ${ODELAB_CHECK_SCRIPTS}/settings_listing.py ${_listing_programs})
set_tests_properties(every_program_lists_its_settings_as_its_options_take_them PROPERTIES TIMEOUT 300 LABELS hardening)

# An interval knob holds at least one step, whichever scene declares it:
# spawning, sampling and throwing all refuse an interval below the step,
# and test0 an interval so short its objects pile up at the spawn point.
odelab_refusals(test0 refuses_spawn_interval_below_step headless 2
  --spawn-interval=1e-300 "--spawn-interval=0.02 --step=0.05"
  "--spawn-interval=1e-6 --step=1e-6 --seconds=0.05")
odelab_refusals(test5 refuses_spawn_interval_below_step headless 2
  --spawn-interval=1e-300 "--spawn-interval=1e-4 --step=1e-3")

# A shape or mass so small that ODE's mass check fails is a bad option
# value (status 2 naming it), not an ODE error in the run (status 4); the
# smallest accepted values build a valid pendulum and run.
odelab_refusals(test2 refuses_bob_radius_that_breaks_ode_mass headless 2 --bob-radius=1e-300 --bob-radius=5e-324)
odelab_refusals(test8 refuses_bob_mass_that_breaks_ode_mass headless 2 --bob-mass=4.9e-324 --bob-mass=1e-300)
odelab_check(test2_smallest_bob_radius_runs test2 LABEL hardening
  EXPECT non_finite==0
  ARGS --headless --seconds 1 --bob-radius 0.001 --rod-length 0.01 --rod-thickness 0.001 --rod-mass 0.001)
odelab_check(test8_smallest_bob_mass_runs test8 LABEL hardening
  EXPECT non_finite==0
  ARGS --headless --seconds 1 --bob-mass 0.01)
