# ---- the example worlds of doc/worlds.md against their analytic answers, and
# on every engine here (doc/worlds/*.json). CTest label: engines.
#
# Each bound was measured first ("measured X; bound Y because ..."): a run
# of build/tests/odelab --world doc/worlds/X.json --headless, 10 simulated
# seconds (the default) unless said. On ODELAB_CHECK_ENGINES, the engines
# here (engines_here.cmake).
set(_worlds ${CMAKE_SOURCE_DIR}/doc/worlds)

# odelab_world_check(NAME WORLD EXPECT ... [ARGS ...]): odelab --world
# doc/worlds/WORLD.json --headless ARGS, its metrics against the bounds.
function(odelab_world_check name world)
  cmake_parse_arguments(W "" "" "EXPECT;ARGS" ${ARGN})
  odelab_check(${name} odelab LABEL engines EXPECT ${W_EXPECT}
               ARGS --world ${_worlds}/${world}.json --headless ${W_ARGS})
  set_tests_properties(${name} PROPERTIES TIMEOUT 300)
endfunction()

# ---- 1. each world's physical fact on ODE ---------------------------------------

# Newton's cradle: the momentum passes through the row, and one cycle (the
# first ball's half swing and the last ball's) lasts T(30 deg) = 4 K(sin 15 deg) / w0
# = 1.291843 s, plus the 1 mm gaps crossed at the bottom speed, 8 gap / v =
# 7.81 ms: 1.299651 s, the file's expected. Measured 1.299899 s (error
# 1.91e-4); bound 1e-3, a sixth of the gaps' share (6.0e-3), so the gaps'
# correction is part of what is checked. Energy: restitution 1, no friction:
# kept; measured 2.62e-4 of the released ball's 0.270 J; bound 1e-3. The
# hinges: measured 3.6 um apart at most; bound 10 um.
odelab_world_check(world_newtons_cradle_passes_momentum_through newtons_cradle
                   EXPECT cycle_period_error>-1e-3 cycle_period_error<1e-3 energy_max_deviation<1e-3
                          joint_error_max_m<1e-5)

# The hinged chain keeps its energy exactly in nature. ODE keeps it at a
# tenth of a millisecond with the exact solver: measured 9.41e-4 of the
# 26.5 J the chain can give up, the joints 31 um apart at most; bounds 2e-3
# and 0.1 mm. At the file's settings (1 ms, QuickStep) the whip loses energy
# through the joints' correction: measured -38.0% in 10 s; bound: more than
# 20% lost (doc/worlds.md says so).
odelab_world_check(world_hinged_chain_keeps_energy_small_step hinged_chain
                   EXPECT energy_max_deviation<2e-3 joint_error_max_m<1e-4 ARGS --solver step --step 0.0001)
odelab_world_check(world_hinged_chain_loses_energy_at_file_settings hinged_chain EXPECT energy_drift<-0.2)

# The box on the 20 deg incline, mu 0.5 > tan 20 deg = 0.364, launched down
# it at 2 m/s: decelerates at g (mu cos - sin) = 1.2540 m/s^2, so its speed
# falls under the rest measure's 0.01 m/s at (2 - 0.01) / 1.2540 = 1.58695 s
# and it stays. Measured 1.587 s (the first step under it); bound 5 steps
# either side (0.3%). Contact depth: measured 9.2 um; bound 0.1 mm.
odelab_world_check(world_incline_slide_stops_on_time incline_slide
                   EXPECT time_to_rest_s>1.582 time_to_rest_s<1.592 penetration_max_m<1e-4)

# The tumbling brick, no gravity and no contact: energy and angular momentum
# kept, and linear momentum zero. At 0.1 ms: measured 1.73e-3 of the energy
# and 8.7e-4 of |L| (first order in the step: 1.48e-4 and 7.8e-5 at 10 us);
# bounds 5e-3 and 2e-3; linear momentum measured 0 (no force: exact). At the
# file's 1 ms ODE's implicit gyroscopic term loses energy: measured -2.48% in
# 10 s (-8.47% in 30 s); bound: more than 1% lost.
odelab_world_check(world_tumbling_brick_keeps_energy_and_momentum tumbling_brick
                   EXPECT energy_max_deviation<5e-3 angular_momentum_drift<2e-3 linear_momentum_drift==0
                   ARGS --step 0.0001)
odelab_world_check(world_tumbling_brick_gyroscopic_loss tumbling_brick EXPECT energy_drift<-0.01)

# The thrown ball: ODE's semi-implicit Euler puts the ball g h t / 2 above
# the exact arc, so up to 1.3 s the largest error is 9.81 * 0.001 * 1.3 / 2
# = 6.3765 mm, and a tenth of it at a tenth of the step. Measured 6.3765e-3
# and 6.3765000e-4; bounds: the formula to 1e-7 m and 1e-8 m (rounding). The
# landing cannot sink deeper than one step at the impact speed, 7.325 m/s:
# 7.33 mm; measured 4.29 mm.
odelab_world_check(world_projectile_arc_error_is_the_integrators projectile
                   EXPECT arc_error_max_m>0.0063764 arc_error_max_m<0.0063766 penetration_max_m<0.00733)
odelab_world_check(world_projectile_arc_error_tenth_step projectile
                   EXPECT arc_error_max_m>0.00063764 arc_error_max_m<0.00063766 ARGS --step 0.0001 --seconds 1.5)

# The thin wall: a ball is caught only when a step lands its centre within
# 2 cm (half the wall plus the radius) of the wall's middle. At 1 ms the
# 400 m/s ball steps 0.4 m (0.8, 1.2: none within) and passes; the 40 m/s
# ball steps 4 cm and cannot skip the 4 cm band. Measured 1 passed; at
# 0.1 ms (4 cm and 4 mm a step) 0. Bounds: exactly those counts.
odelab_world_check(world_thin_wall_fast_ball_passes thin_wall EXPECT tunnelled_bodies==1 ARGS --seconds 0.1)
odelab_world_check(world_thin_wall_small_step_stops_both thin_wall EXPECT tunnelled_bodies==0
                   ARGS --step 0.0001 --seconds 0.1)

# ---- 2. each world on every other engine --------------------------------------------
# world_<world>_on_<engine>: scripts/engine_metrics.py: the engine's run (its
# default setting) ends with status 0, writes every metric the ODE run
# writes (the world's measurements among them) plus its translation_notes
# (a non-empty list) and steps the world itself (another state hash). Short
# runs, each past the first contact or collision: Bullet's double-precision
# free flight is ODE's to the bit (measured: the 400 m/s ball alone gave
# ODE's hash), and a Node engine takes about 0.3 ms a step through its pipe
# (the cradle's 10 s at 0.1 ms: 31 s on Rapier).
set(_engine_seconds_newtons_cradle 1)
set(_engine_seconds_hinged_chain 2)
set(_engine_seconds_incline_slide 2)
set(_engine_seconds_tumbling_brick 2)
set(_engine_seconds_projectile 2)
set(_engine_seconds_thin_wall 0.1)
foreach(_world newtons_cradle hinged_chain incline_slide tumbling_brick projectile thin_wall)
  foreach(_engine IN LISTS ODELAB_CHECK_ENGINES)
    set(_name world_${_world}_on_${_engine})
    set(_dir ${CMAKE_CURRENT_BINARY_DIR}/runs/${_name})
    file(MAKE_DIRECTORY ${_dir})
    add_test(NAME ${_name}
             COMMAND ${Python3_EXECUTABLE} ${ODELAB_CHECK_SCRIPTS}/engine_metrics.py ${_engine} $<TARGET_FILE:odelab>
                     --world ${_worlds}/${_world}.json --seconds ${_engine_seconds_${_world}}
             WORKING_DIRECTORY ${_dir})
    set_tests_properties(${_name} PROPERTIES LABELS engines TIMEOUT 300)
  endforeach()
endforeach()

# ---- 3. the energy measure is test2's own ------------------------------------------
# test2's pendulum exported, given "measures": [{"kind": "energy"}] and run
# by odelab --world for 20 s: its six energy figures equal test2's as printed
# (scripts/world_energy_matches_test2.py). Measured: equal, energy_max_deviation
# 0.0003209647103 both.
add_test(NAME world_energy_measure_equals_test2s
         COMMAND ${Python3_EXECUTABLE} ${ODELAB_CHECK_SCRIPTS}/world_energy_matches_test2.py $<TARGET_FILE:test2>
                 $<TARGET_FILE:odelab> 20)
set_tests_properties(world_energy_measure_equals_test2s PROPERTIES LABELS engines TIMEOUT 300)
