# test2 - Pendulum (doc/tests/test2.md): physical claims, its output file and bad values.

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
# setting, the four columns, 6001 rows on the 0.01 s grid, then "# complete: ...".
add_test(NAME test2_output_file_parses
  COMMAND $<TARGET_FILE:check_output_file> ${CMAKE_CURRENT_BINARY_DIR}/out_test2_energy_kept/Test2_output.txt
          --columns time_s,potential_J,kinetic_J,total_J --interval 0.01 --rows 6001 --complete)
set_tests_properties(test2_output_file_parses PROPERTIES FIXTURES_REQUIRED test2_output LABELS scene)
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

# The sampling interval must be a positive finite number; then one common
# option and an unknown one (the shared options: common_options.cmake).
odelab_refusals(test2 refuses_bad_options headless 2
  --sample-interval=<empty> --sample-interval=0 --sample-interval=-0.01 --sample-interval=nan
  --sample-interval=inf --sample-interval=1e400 --sample-interval=abc
  --step=nan --no-such-option)
odelab_determinism(test2 --seconds 3)
# The output file survives a kill (SIGKILL mid-run) and a full disk (a 2 KiB
# file size limit: status 1, "cannot write"): it parses up to its last
# complete row, and no metrics JSON exists.
odelab_interrupted_output(test2 kill Test2_output.txt time_s,potential_J,kinetic_J,total_J)
odelab_interrupted_output(test2 file-limit Test2_output.txt time_s,potential_J,kinetic_J,total_J)
# A window that cannot start leaves no Test2_output.txt.
odelab_window_refusals(test2)

# Issue 12: how the energy is computed. Without the rotational kinetic energy
# the total dips at the bottom of every swing by the spin's share of it: the
# variation equals rotational_energy_max_fraction to 2% (measured 0.035383
# against 0.035371 with the default rig), far above the 0.064% with it.
odelab_check(test2_energy_without_rotation_dips_by_the_spin test2
  EXPECT rotational_energy_included==0 energy_rel_variation>@rotational_energy_max_fraction*0.98
         energy_rel_variation<@rotational_energy_max_fraction*1.02 energy_rel_variation>0.03
  ARGS --headless --erp 0.4 --cfm 0 --step 0.001 --seconds 60 --sample-interval 3600 --no-rotational-energy)
# A light rod (0.015 kg, shape not in the thesis) makes that dip near the
# thesis's 0.75%: within a factor 1.5 of it (measured 0.88%), while the
# period still matches the exact one for the new shape (error below 1e-4).
odelab_check(test2_light_rod_without_rotation_dips_like_the_thesis test2
  EXPECT energy_rel_variation>0.005 energy_rel_variation<0.01125 period_error<1e-4 period_error>-1e-4
  ARGS --headless --erp 0.4 --cfm 0 --step 0.001 --seconds 60 --sample-interval 3600 --no-rotational-energy
       --rod-mass 0.015)
odelab_refusals(test2 refuses_bad_shape headless 2
  --rod-length=0 --rod-length=-1 --rod-length=nan --rod-length=7 --rod-thickness=0 --rod-thickness=inf
  --rod-mass=0 --rod-mass=abc --bob-radius=0 --bob-radius=-0.3 "--bob-radius=0.9 --rod-length=6")

# In headless Chromium, against this build's headless run (checks/web.cmake,
# label web): 1e-6 against the scene's 1% bound; the window run's output file comes
# through the page's download link whole.
odelab_web_check(test2 energy_rel_variation 1e-6 SECONDS 10 DOWNLOAD Test2_output.txt ARGS --erp 0.4 --cfm 0)
