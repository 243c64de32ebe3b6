# ---- test10 - Maximum velocity ----
# At step 0.001 every cube launched at 200 m/s is stopped: one step's travel,
# 0.2 m, is below cube half-size + half the wall (0.225 m), so the first step
# that overlaps the wall always finds the cube short of its mid-plane. Exact
# count, no tolerance: the outcome is geometric. Continuous collision is off
# by default (the thesis's behaviour): no sweep ran.
odelab_check(test10_every_launch_at_200_is_stopped test10
  EXPECT passed_through==0 stopped==5 launches==5 ccd==0 ccd_sweeps==0 ccd_clamps==0 non_finite==0
  ARGS --headless --velocity 200 --launches 5)
# The scan at step 0.001 finds a limit between 200 and 1000 m/s, at the
# stated 1 m/s resolution, printed as well as written (the issue's bounds;
# measured: 250 m/s, the thesis's figure).
odelab_check(test10_max_velocity_between_200_and_1000 test10
  EXPECT max_velocity>200 max_velocity<1000 max_velocity_resolution==1 non_finite==0
         --stdout-contains "(resolution 1 m/s)"
  ARGS --headless --find-max-velocity)
# At step 0.0001 the limit scales with 1/step: at least (h + t/2)/step = 2250
# m/s (every arrival phase stopped below it) and below (2h + t)/step = 4500
# m/s (a cube can skip the wall whole above it). Measured: 2352.7 m/s.
odelab_check(test10_max_velocity_scales_with_step test10
  EXPECT max_velocity>=2250 max_velocity<4500 non_finite==0
  ARGS --headless --find-max-velocity --step 0.0001)
# With a random arrival phase (20 launches per velocity) the limit is still at
# least (h + t/2)/step = 225 m/s: below it no phase lets a cube through. It is
# also below the fixed launch point's 250 m/s: at v in 226..249 a fraction
# 1 - 0.225/(v*step) of phases passes, and the chance that 20 random phases at
# every one of those velocities all miss it is 7e-12, whatever the seed.
odelab_check(test10_random_phase_never_passes_below_guaranteed_limit test10
  EXPECT max_velocity>=225 max_velocity<250 non_finite==0
  ARGS --headless --find-max-velocity --phase-jitter --launches 20)
# The remedy, --ccd: at 10,000 m/s (10 m per step, 40 times past the no-CCD
# limit) every cube is stopped, each by a sweep that moved it to the wall
# (one clamp per launch, exact counts). The wall stops it through contacts
# (mode 0, no bounce): what energy is left is the potential energy at 3 m
# (29.5 J) plus what QuickStep's 20 iterations leave unsolved of the stop
# with the far corners' speculative contacts in it: below 1e-4 of the 5e7 J
# launch energy, i.e. thrown back at under 1% of the launch speed (measured
# 1.6e-5; 5.9e-7 before the corner contacts, which turned cubes need).
odelab_check(test10_ccd_stops_every_launch_at_10000 test10
  EXPECT passed_through==0 stopped==5 ccd==1 ccd_clamps==5 max_stop_energy_ratio<1e-4 non_finite==0
  ARGS --headless --ccd --velocity 10000 --launches 5)
# With --ccd the whole scan, 1 m/s to the scan limit 100,000 m/s (5607
# velocities, 0.2 s), finds no velocity at which a cube passes: max_velocity
# is the last tested one (99,952.8 m/s), so at least the issue's 10,000 m/s.
# No stopped cube has more mechanical energy than at its launch (ratio < 1:
# a stop that created energy would be unphysical; measured at most 0.315, a
# cube of about 8 m/s, below the sweep's threshold, that fell on its way).
odelab_check(test10_ccd_scan_finds_no_pass_up_to_100000 test10
  EXPECT max_velocity>=10000 first_failure_velocity==0 passed_through==0 max_stop_energy_ratio<1 non_finite==0
         --stdout-contains "no launch passed up to the scan limit 100000 m/s"
  ARGS --headless --ccd --find-max-velocity)
# The same with a random arrival phase (5 launches per velocity, any seed):
# the sweep does not depend on where in the step the cube meets the wall.
odelab_check(test10_ccd_scan_random_phase_finds_no_pass test10
  EXPECT max_velocity>=10000 first_failure_velocity==0 passed_through==0 non_finite==0
  ARGS --headless --ccd --find-max-velocity --phase-jitter --launches 5)
# Bad scene options are refused with status 2 and nothing written.
odelab_check(test10_refuses_ccd_with_a_value test10 STATUS 2 ARGS --headless --ccd=maybe)
odelab_check(test10_refuses_negative_velocity test10 STATUS 2 ARGS --headless --velocity=-1)
odelab_check(test10_refuses_nan_velocity test10 STATUS 2 ARGS --headless --velocity=nan)
odelab_check(test10_refuses_zero_launches test10 STATUS 2 ARGS --headless --launches=0)
odelab_check(test10_refuses_zero_scan_limit test10 STATUS 2 ARGS --headless --find-max-velocity --scan-limit=0)
odelab_check(test10_refuses_band_factor_below_one test10 STATUS 2 ARGS --headless --find-max-velocity --band-factor=0.5)
odelab_check(test10_refuses_scan_option_without_scan test10 STATUS 2 ARGS --headless --scan-limit=500)
# ---- test6 - Axis system ----
# As measured at the defaults (QuickStep, step 0.001): the symmetric build
# does not stay upright; the big cube passes 1 degree of tilt after 1.052 s
# (deterministic). Asserted as "falls within a few seconds", the thesis's
# outcome: between 0.5 s and 3 s, i.e. within about 1.5 e-folding times of
# the tilt's growth (0.65 s) either side of the measured value.
odelab_check(test6_symmetric_build_falls_within_seconds test6
  EXPECT fell==1 seconds_upright>0.5 seconds_upright<3 non_finite==0
  ARGS --headless --seconds 10)
# The fall is the inverted pendulum's: with dWorldStep and a 0.1 degree start
# tilt, a rigid cube on a fixed pivot reaches 1 degree when cosh(lambda t) =
# 10, lambda = sqrt(m g l / I_anchor) = 1.535 /s, so t = 1.95 s. Within 0.1 s
# (5%): the pivot is not quite fixed (it rides on the 1 kg cube).
odelab_check(test6_fall_follows_inverted_pendulum test6
  EXPECT fell==1 seconds_upright>1.85 seconds_upright<2.05 non_finite==0
  ARGS --headless --seconds 4 --solver step --tilt-degrees 0.1)
# dWorldSetMaxAngularSpeed(world, 0.01) only slows the fall: the big cube
# turns at most 0.01 rad/s, so in 10 s it tilts at most 0.573 deg/s x 10 s =
# 5.73 degrees (a hard cap, no tolerance), yet it still leaves the upright band.
odelab_check(test6_max_angular_speed_caps_tilt_rate test6
  EXPECT fell==1 max_tilt_degrees<=5.73 non_finite==0
  ARGS --headless --seconds 10 --max-angular-speed 0.01)
# Bad scene options are refused with status 2 and nothing written.
odelab_check(test6_refuses_zero_max_angular_speed test6 STATUS 2 ARGS --headless --max-angular-speed=0)
odelab_check(test6_refuses_nan_max_angular_speed test6 STATUS 2 ARGS --headless --max-angular-speed=nan)
odelab_check(test6_refuses_negative_tilt test6 STATUS 2 ARGS --headless --tilt-degrees=-0.1)
odelab_check(test6_refuses_tilt_outside_upright_band test6 STATUS 2 ARGS --headless --tilt-degrees=1)

# ---- test8 - Hinge stability ----
# ERP 0.4, CFM 0, step 0.001, 60 s, 5000 kg bob: the hinge keeps the
# anchor-to-centre-of-mass length to 1e-4 (the issue's bound; measured
# 3.5e-5), and the output file gets one row per 0.01 s: 6001 rows.
file(MAKE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/out_test8_cfm_0)
odelab_check(test8_hinge_keeps_length_at_cfm_0 test8
  EXPECT max_relative_elongation<1e-4 output_rows==6001 non_finite==0
  ARGS --headless --seconds 60 --erp 0.4 --cfm 0 --step 0.001 --out-dir ${CMAKE_CURRENT_BINARY_DIR}/out_test8_cfm_0)
set_tests_properties(test8_hinge_keeps_length_at_cfm_0 PROPERTIES FIXTURES_SETUP test8_output)
# The file that run wrote, read by an independent parser: header with every
# setting, the two columns, 6001 rows on the 0.01 s grid.
add_test(NAME test8_output_file_parses
  COMMAND $<TARGET_FILE:check_output_file> ${CMAKE_CURRENT_BINARY_DIR}/out_test8_cfm_0/Test8_output.txt
          --columns time_s,relative_elongation,deflection_rad --interval 0.01 --rows 6001)
set_tests_properties(test8_output_file_parses PROPERTIES FIXTURES_REQUIRED test8_output)
# At the scene's default CFM 1e-4 the hinge behaves as a spring of stiffness
# k = ERP / (step * CFM) = 4e6 N/m (ODE manual's ERP/CFM-to-spring relation):
# the peak tension at the bottom of a swing from horizontal, m g (1 + 2 m d^2 / I)
# = 2.993 m g = 1.47e5 N, stretches it by 0.0368 m, a relative 0.01114 of
# l0 = 3.2999 m. Asserted within 5% (the spring model ignores the damping
# and the stretch's own effect on the swing; measured 0.01111, 0.2% off).
# The thesis reported about 1e-3 here (see doc/tests/test8.md).
file(MAKE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/out_test8_cfm_1e-4)
odelab_check(test8_cfm_1e-4_stretches_like_a_spring test8
  EXPECT max_relative_elongation>0.01058 max_relative_elongation<0.01170 non_finite==0
  ARGS --headless --seconds 60 --erp 0.4 --cfm 1e-4 --step 0.001 --out-dir ${CMAKE_CURRENT_BINARY_DIR}/out_test8_cfm_1e-4)
# ERP 0.4, CFM 1e-2: the pendulum visibly stretches (above 1e-2, the issue's
# bound; measured 1.09, the length doubles) and, as the thesis saw, the bob
# passes through the ground (its lowest point below y = 0; measured -0.20 m).
file(MAKE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/out_test8_cfm_1e-2)
odelab_check(test8_cfm_1e-2_stretches_through_the_ground test8
  EXPECT max_relative_elongation>1e-2 lowest_bob_height_m<0 non_finite==0
  ARGS --headless --seconds 60 --erp 0.4 --cfm 1e-2 --step 0.001 --out-dir ${CMAKE_CURRENT_BINARY_DIR}/out_test8_cfm_1e-2)
# Bad scene options are refused with status 2 and nothing written.
foreach(_bad "--bob-mass=0" "--bob-mass=-1" "--bob-mass=nan" "--bob-mass=inf" "--sample-interval=0"
             "--sample-interval=nan")
  string(MAKE_C_IDENTIFIER "${_bad}" _id)
  odelab_check(test8_refuses${_id} test8 STATUS 2 ARGS --headless ${_bad})
endforeach()

# ---- test9 - Restitution accuracy ----
# ERP 0.2, CFM 0 (the thesis's ideal setting), bounce 1.0 under 4 g: after 20
# bounces the apex is back at the start height to 1e-4 of the 4.5 m drop (the
# issue's bound; measured 2.8e-9, apexes and the start both taken as the
# vertex of the parabola through three steps), with no horizontal drift (a
# vertical drop onto a plane has no horizontal force: below 1e-9 m, measured
# 0). Every apex is printed as a deviation vector on standard output.
odelab_check(test9_perfect_bounce_at_cfm_0 test9
  EXPECT apex_error_20<1e-4 max_horizontal_drift<1e-9 bounces>=20 non_finite==0
  --stdout-contains "apex 20 at t=" --stdout-contains "s: deviation"
  ARGS --headless --erp 0.2 --cfm 0)
# The thesis: ERP does not matter for a perfect bounce. ERP 1.0, CFM 0: the
# same bound (measured 2.8e-9, identical to ERP 0.2).
odelab_check(test9_perfect_bounce_at_erp_1 test9
  EXPECT apex_error_20<1e-4 bounces>=20 non_finite==0
  ARGS --headless --erp 1.0 --cfm 0)
# CFM 1e-6 damps the bounce: after 20 bounces the apex is more than 1% low
# (the issue's bound; the thesis saw over 5%, measured here 7.7%).
odelab_check(test9_cfm_1e-6_damps_bounce test9
  EXPECT apex_error_20>0.01 non_finite==0
  ARGS --headless --erp 0.2 --cfm 1e-6)
# ---- test7 - Axis system 2 ----
# The issue's claim: with the thesis's dWorldSetMaxAngularSpeed(world, 10) and
# three throws 5 s apart, both ball joints hold to within 0.02 m (measured
# 0.0156 m, at the hits) and the state stays finite. The pivot never turns
# faster than the cap (10 rad/s, plus 1e-6 for the rescaling's rounding).
odelab_check(test7_joints_hold_three_throws_with_cap test7
  EXPECT max_joint_error<0.02 max_angular_speed<=10.000001 throws==3 non_finite==0
  ARGS --headless --max-angular-speed 10 --throws 3 --throw-interval 5)
# Energy is not created: after k throws of a 100 kg cube at 30 m/s (45 kJ
# each) the pair's swing energy is below k x 45 kJ; and the first hit does put
# energy in (above zero; measured 98 J, 1 s mean).
odelab_check(test7_throws_do_not_create_energy test7
  EXPECT energy_after_throw_1>0 energy_after_throw_1<45000 energy_after_throw_2<90000 energy_after_throw_3<135000
         non_finite==0
  ARGS --headless --throws 3 --throw-interval 5)
# Without the cap the glancing hits spin the pivot well past 10 rad/s (as
# measured: 31.6 rad/s), the effect the thesis tamed; the state stays finite.
odelab_check(test7_uncapped_pivot_spins_past_ten test7
  EXPECT max_angular_speed>10 max_angular_speed_limit==0 non_finite==0
  ARGS --headless --max-angular-speed 0 --throws 3 --throw-interval 5)
# Bad scene options are refused with status 2 and nothing written.
odelab_check(test7_refuses_negative_max_angular_speed test7 STATUS 2 ARGS --headless --max-angular-speed=-1)
odelab_check(test7_refuses_nan_max_angular_speed test7 STATUS 2 ARGS --headless --max-angular-speed=nan)
odelab_check(test7_refuses_zero_throws test7 STATUS 2 ARGS --headless --throws=0)
odelab_check(test7_refuses_zero_throw_interval test7 STATUS 2 ARGS --headless --throw-interval=0)
odelab_check(test7_refuses_infinite_throw_interval test7 STATUS 2 ARGS --headless --throw-interval=inf)
