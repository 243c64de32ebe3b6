
# ---- test4 - Different Weights ----
# 5000 kg on 5 kg at the thesis's step 0.001 (QuickStep, ERP 0.2, CFM 1e-6),
# 20 s. Asserted as measured: ODE 0.16.2 HOLDS it (the thesis's ODE 0.11.1 let
# it collapse; see doc/tests/test4.md). The centre stays within 0.5 m of the
# axis and above 2.9 m; tilt below 2 degrees (measured 0.54-0.79 over seeds 1-6);
# deepest penetration below 0.01 m (measured 0.0049-0.0068).
odelab_check(test4_5000kg_holds_at_step_0_001 test4
  EXPECT held==1 seconds_held==20 max_tilt_degrees<2 max_penetration<0.01 non_finite==0
  ARGS --headless --seconds 20 --step 0.001 --big-mass 5000)
# The same at step 0.0001 (the thesis's fix): it holds, and tenfold smaller
# steps make the overlap a hundredfold smaller (measured 4.8e-5 m against
# 5.2e-3 m; ERP corrects the sag of g*step^2 per step): below 1e-4 m; tilt
# below 0.1 degree (measured 0.004).
odelab_check(test4_5000kg_holds_at_step_0_0001 test4
  EXPECT held==1 seconds_held==20 max_tilt_degrees<0.1 max_penetration<0.0001 non_finite==0
  ARGS --headless --seconds 20 --step 0.0001 --big-mass 5000)
# The thesis's claim that the step decides it, shown at 20 t, where this build
# does collapse at step 0.001 (measured 4.5-7.1 s over seeds 1-3) and holds
# at step 0.0001 for 20 s (tilt 0.017 degrees).
odelab_check(test4_20t_collapses_at_step_0_001 test4
  EXPECT held==0 seconds_held<15 non_finite==0
  ARGS --headless --seconds 20 --step 0.001 --big-mass 20000)
odelab_check(test4_20t_holds_at_step_0_0001 test4
  EXPECT held==1 max_tilt_degrees<0.1 non_finite==0
  ARGS --headless --seconds 20 --step 0.0001 --big-mass 20000)
# A mass must be a positive finite number.
foreach(_bad "--big-mass=-1" "--big-mass=0" "--big-mass=nan" "--big-mass=inf" "--big-mass=heavy")
  string(MAKE_C_IDENTIFIER "${_bad}" _id)
  odelab_check(test4_refuses${_id} test4 STATUS 2 ARGS --headless ${_bad})
endforeach()

# ---- test2 - Pendulum ----
# The thesis's setting (ERP 0.4, CFM 0, step 0.001, 60 s): the total energy
# stays within 1% of its maximum (the issue's bound; the thesis saw 0.75%,
# measured here 0.064%), the swing's period matches the exact physical-
# pendulum period 4 sqrt(I/(m g d)) K(sin 45 deg) to 1e-4 (timing by
# interpolated bottom crossings over 14 periods; measured 2.9e-6), and the
# output file gets one row per 0.01 s, t = 0 to 60 inclusive: 6001 rows.
file(MAKE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/out_test2_energy_kept)
odelab_check(test2_energy_kept_at_thesis_settings test2
  EXPECT energy_rel_variation<0.01 period_error<1e-4 period_error>-1e-4 output_rows==6001 non_finite==0
  ARGS --headless --seconds 60 --erp 0.4 --cfm 0 --step 0.001
       --out-dir ${CMAKE_CURRENT_BINARY_DIR}/out_test2_energy_kept)
set_tests_properties(test2_energy_kept_at_thesis_settings PROPERTIES FIXTURES_SETUP test2_output)
# The file that run wrote, read by an independent parser: header with every
# setting, the four columns, 6001 rows on the 0.01 s grid.
add_test(NAME test2_output_file_parses
  COMMAND $<TARGET_FILE:check_output_file> ${CMAKE_CURRENT_BINARY_DIR}/out_test2_energy_kept/Test2_output.txt
          --columns time_s,potential_J,kinetic_J,total_J --interval 0.01 --rows 6001)
set_tests_properties(test2_output_file_parses PROPERTIES FIXTURES_REQUIRED test2_output)
# The thesis: "any CFM above 0 drains the energy". Searched by decades from
# 1e-6 to 1 (60 s, ERP 0.4, step 0.001), the smallest CFM whose energy_drift
# is below -1% is, as measured, 1 (drift -1.04%); at 0.1 the drift is -0.09%,
# and from 1e-6 to 1e-2 it is within 0.02% of CFM 0's (see doc/tests/test2.md).
file(MAKE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/out_test2_cfm_1)
odelab_check(test2_cfm_1_drains_energy test2
  EXPECT energy_drift<-0.01 non_finite==0
  ARGS --headless --seconds 60 --erp 0.4 --cfm 1 --step 0.001 --out-dir ${CMAKE_CURRENT_BINARY_DIR}/out_test2_cfm_1)
file(MAKE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/out_test2_cfm_0_1)
odelab_check(test2_cfm_0_1_keeps_energy test2
  EXPECT energy_drift>=-0.01 non_finite==0
  ARGS --headless --seconds 60 --erp 0.4 --cfm 0.1 --step 0.001 --out-dir ${CMAKE_CURRENT_BINARY_DIR}/out_test2_cfm_0_1)
# The sampling interval must be a positive finite number.
foreach(_bad "--sample-interval=0" "--sample-interval=-0.01" "--sample-interval=nan" "--sample-interval=inf")
  string(MAKE_C_IDENTIFIER "${_bad}" _id)
  odelab_check(test2_refuses${_id} test2 STATUS 2 ARGS --headless ${_bad})
endforeach()

# ---- test5 - Lots of same collisions ----
# 50 plates [5, 0.05, 5] of 1 kg dropped every 0.3 s (the last at 14.7 s) at
# ERP 0.2, CFM 0, plain contacts; after 20 s all have landed and the column is
# straight: no plate centre more than 0.05 m off the axis (one hundredth of the
# plate's width; measured 0.008 m, up to 0.019 m over seeds 1-3). The stack is
# 50 x 0.05 = 2.5 m tall less the contact overlap: between 2.45 and 2.5 m
# (measured 2.4966).
odelab_check(test5_50_plates_stack_straight_at_cfm_0 test5
  EXPECT plates==50 landed_plates==50 max_axis_offset<0.05 stack_height>2.45 stack_height<=2.5 non_finite==0
  ARGS --headless --seconds 20 --plates 50 --spawn-interval 0.3 --cfm 0)
# The same claim with a hash space (the thesis's faster space): geometry is
# independent of the space kind, so the column is as straight.
odelab_check(test5_50_plates_stack_straight_in_hash_space test5
  EXPECT plates==50 landed_plates==50 max_axis_offset<0.05 stack_height>2.45 stack_height<=2.5 non_finite==0
  ARGS --headless --seconds 20 --plates 50 --spawn-interval 0.3 --cfm 0 --space hash)
# Options: plate count a positive integer, interval positive and finite, space one of four names.
# Thresholds finite and >= 0, threads 1 ... 64, an integer.
foreach(_bad "--plates=0" "--plates=-5" "--plates=many" "--spawn-interval=0" "--spawn-interval=-1"
        "--spawn-interval=nan" "--space=octree" "--space=" "--auto-disable-linear=-0.1"
        "--auto-disable-linear=nan" "--auto-disable-linear=inf" "--auto-disable-angular=-1"
        "--auto-disable-angular=nan" "--auto-disable-angular=" "--threads=0" "--threads=65" "--threads=-2"
        "--threads=two" "--threads=1.5")
  string(MAKE_C_IDENTIFIER "${_bad}" _id)
  odelab_check(test5_refuses${_id} test5 STATUS 2 ARGS --headless --auto-disable ${_bad})
endforeach()
# A threshold without --auto-disable would do nothing: refused.
odelab_check(test5_refuses_threshold_without_auto_disable test5 STATUS 2
  ARGS --headless --auto-disable-linear 0.3)
# Threaded island stepping (2 threads) builds the same straight 50-plate
# stack (measured 0.0081 m off the axis, 2.4965 m), and the pool survives the
# world being rebuilt and torn down.
odelab_check(test5_50_plates_stack_straight_with_2_threads test5
  EXPECT plates==50 landed_plates==50 threads==2 max_axis_offset<0.05 stack_height>2.45 stack_height<=2.5 non_finite==0
  ARGS --headless --seconds 20 --plates 50 --spawn-interval 0.3 --cfm 0 --threads 2)
# Auto-disable with the thesis's linear threshold 0.3 (and 0.05 angular): no
# plate is frozen in the air in this build and the column stands (measured
# 0.008 m off the axis, 2.4924 m).
odelab_check(test5_50_plates_stack_with_auto_disable_0_3 test5
  EXPECT plates==50 landed_plates==50 auto_disable==1 plates_frozen_in_air==0 max_axis_offset<0.05 stack_height>2.45 stack_height<=2.5 non_finite==0
  ARGS --headless --seconds 20 --plates 50 --spawn-interval 0.3 --cfm 0 --auto-disable --auto-disable-linear 0.3 --auto-disable-angular 0.05)

# ---- test3 - Domino ----
# The chain at the scene's defaults (60 dominoes [0.2, 2, 1] of 1 kg, 1 m
# apart on a spiral, mu 1.0, auto-disable with thresholds 0.1, 8 iterations,
# step 0.005): every domino falls (leans more than 30 degrees; the fallen
# ones lie at 76 degrees or more, so the threshold is far from both states)
# and 20 s later auto-disable has put every body to rest (measured: the chain
# ends at 8.53 s; the last bodies are disabled by 15 s).
odelab_check(test3_chain_runs_to_the_end test3
  EXPECT dominoes==60 fallen_fraction==1 min_fallen_tilt_degrees>50 active_bodies==0 non_finite==0
  ARGS --headless --seconds 20)
# Without auto-disable the chain is the same (every domino falls) but every
# body stays active to the end: the cost the thesis describes.
odelab_check(test3_without_auto_disable_every_body_stays_active test3
  EXPECT fallen_fraction==1 active_bodies==60 non_finite==0
  ARGS --headless --seconds 20 --no-auto-disable)
# mu = dInfinity: the contact between a falling plate's top and the next plate
# cannot slide, so the two plates and the ground form a rigid triangle and
# the chain stops at once (at most 2 of 60 fall; measured 1).
odelab_check(test3_infinite_friction_locks_the_first_pair test3
  EXPECT fallen_fraction<0.05 non_finite==0
  ARGS --headless --seconds 10 --mu inf --no-auto-disable)
# Options: at least 2 dominoes (an integer), mu a number >= 0 or inf.
foreach(_bad "--dominoes=1" "--dominoes=0" "--dominoes=ten" "--mu=-1" "--mu=nan" "--mu=abc" "--mu=")
  string(MAKE_C_IDENTIFIER "${_bad}" _id)
  odelab_check(test3_refuses${_id} test3 STATUS 2 ARGS --headless ${_bad})
endforeach()

# ---- test1 - Jumping Balls ----
# ERP 0, CFM 0, gravity 0.25 g (the thesis's settings), 15 s: for each of the
# 45 balls with e >= 0.1 the second rebound apex over the first, both above
# the contact height, is e^2 to within 0.01 (the issue's bound; measured
# 0.0041, worst at e = 0.10, where the 0.43 mm second apex is comparable
# with the up to 0.58 mm one step's travel lets the ball sink before it
# bounces; e = 1 is exact to 1e-10). Every ball but the e = 0 one rebounds.
odelab_check(test1_rebound_ratio_matches_e_squared test1
  EXPECT max_rebound_error<0.01 balls_measured==45 balls_bounced==49 non_finite==0
  ARGS --headless --seconds 15 --erp 0 --cfm 0)
# The thesis: CFM ~0.001 damps every ball whatever its bounce. At ERP 0 the
# contact then yields like a damper: no ball rebounds at all within 10 s
# (every ball has hit the ground by 2.4 s; an e = 1 rebound would peak by
# 4.8 s).
odelab_check(test1_cfm_1e-3_damps_every_ball test1
  EXPECT balls_bounced==0 non_finite==0
  ARGS --headless --seconds 10 --erp 0 --cfm 1e-3)
# The thesis: ERP above 0 spoils the bounce. The contact's push-out speed
# ERP * depth / step reaches up to ERP times the impact speed and replaces
# the bounce when larger, so at ERP 0.8 balls with e below 0.8 rebound too
# high: the ratio error exceeds the 0.01 bound (measured 0.26).
odelab_check(test1_erp_0_8_spoils_rebounds test1
  EXPECT max_rebound_error>0.01 non_finite==0
  ARGS --headless --seconds 15 --erp 0.8 --cfm 0)
