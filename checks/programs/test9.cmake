# test9 - Restitution accuracy (doc/tests/test9.md): physical claims and bad values.

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

# No scene options: one common option and an unknown one show that the
# program takes the shared options (checked in full in common_options.cmake).
odelab_refusals(test9 refuses_bad_options headless 2 --step=nan --no-such-option)
odelab_determinism(test9 --seconds 3)

# --mu and --max-contacts (the contact choices every scene with contacts takes).
odelab_contact_choice_refusals(test9)

# --bounce-velocity (issue 12, proposed 0.01 m/s): refused when not a finite number >= 0.
odelab_refusals(test9 refuses_bad_bounce_velocity headless 2
  --bounce-velocity=-1 --bounce-velocity=nan --bounce-velocity=inf --bounce-velocity=fast)

# In headless Chromium, against this build's headless run (checks/web.cmake,
# label web): 1e-10 against the scene's 1e-4.
odelab_web_check(test9 apex_error_20 1e-10 ARGS --erp 0.2 --cfm 0)
