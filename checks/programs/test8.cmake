# test8 - Hinge stability (doc/tests/test8.md): physical claims, its output file and bad values.

# ERP 0.4, CFM 0, step 0.001, 60 s, 5000 kg bob: the hinge keeps the
# anchor-to-centre-of-mass length to 1e-4 (the issue's bound; measured
# 3.5e-5), and the output file gets one row per 0.01 s: 6001 rows.
file(MAKE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/out_test8_cfm_0)
odelab_check(test8_hinge_keeps_length_at_cfm_0 test8
  EXPECT max_relative_elongation<1e-4 output_rows==6001 non_finite==0
  ARGS --headless --seconds 60 --erp 0.4 --cfm 0 --step 0.001 --out-dir ${CMAKE_CURRENT_BINARY_DIR}/out_test8_cfm_0)
set_tests_properties(test8_hinge_keeps_length_at_cfm_0 PROPERTIES FIXTURES_SETUP test8_output)
# The file that run wrote, read by an independent parser: header with every
# setting, the three columns, 6001 rows on the 0.01 s grid, then "# complete: ...".
add_test(NAME test8_output_file_parses
  COMMAND $<TARGET_FILE:check_output_file> ${CMAKE_CURRENT_BINARY_DIR}/out_test8_cfm_0/Test8_output.txt
          --columns time_s,relative_elongation,deflection_rad --interval 0.01 --rows 6001 --complete)
set_tests_properties(test8_output_file_parses PROPERTIES FIXTURES_REQUIRED test8_output LABELS scene)
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
# ERP 0.4, CFM 1e-2 over 60 s: the soft hinge damps the swing, but it does not
# stop. Peak to peak over the last 10 s (swing_last_10s_deg): measured 141
# degrees, against 180 at CFM 0 (a swing from horizontal to horizontal; the
# thesis says it settles and stops). Asserted: below 170 (damped) and above
# 10 (still swinging), far from both measured figures.
file(MAKE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/out_test8_swing)
odelab_check(test8_cfm_1e-2_damps_but_keeps_swinging test8
  EXPECT swing_last_10s_deg<170 swing_last_10s_deg>10 non_finite==0
  ARGS --headless --seconds 60 --erp 0.4 --cfm 1e-2 --step 0.001 --out-dir ${CMAKE_CURRENT_BINARY_DIR}/out_test8_swing)

# The bob's mass and the sampling interval positive and finite; then one
# common option and an unknown one (the shared options: common_options.cmake).
odelab_refusals(test8 refuses_bad_options headless 2
  --bob-mass=<empty> --bob-mass=0 --bob-mass=-1 --bob-mass=nan --bob-mass=inf --bob-mass=abc
  --sample-interval=<empty> --sample-interval=0 --sample-interval=-1 --sample-interval=nan
  --sample-interval=inf --sample-interval=abc
  --step=nan --no-such-option)
odelab_determinism(test8 --seconds 3)
# The output file survives a kill and a full disk (see test2.cmake).
odelab_interrupted_output(test8 kill Test8_output.txt time_s,relative_elongation,deflection_rad)
odelab_interrupted_output(test8 file-limit Test8_output.txt time_s,relative_elongation,deflection_rad)
# A window that cannot start leaves no Test8_output.txt.
odelab_window_refusals(test8)

# In headless Chromium, against this build's headless run (checks/web.cmake,
# label web): 1e-9 against the scene's 1e-4.
odelab_web_check(test8 max_relative_elongation 1e-9 SECONDS 10 ARGS --erp 0.4 --cfm 0)
