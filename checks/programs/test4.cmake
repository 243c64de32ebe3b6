# test4 - Different Weights (doc/tests/test4.md): physical claims and bad values.

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

# Friction decides it as much as the step (issue 12): the thesis never gives
# test4's mu; with its "usual" mu = 1.0 (thesis 5.4) the 5000 kg cube slides
# off within a second at step 0.001 (measured: lost at 0.576 s, seed 1),
# where the default dInfinity holds it for the whole 20 s (the check above).
odelab_check(test4_5000kg_falls_with_mu_1 test4
  EXPECT held==0 seconds_held<2 mu==1 mu_infinite==0 non_finite==0
  ARGS --headless --seconds 20 --step 0.001 --big-mass 5000 --mu 1)
odelab_check(test4_5000kg_holds_with_mu_inf test4
  EXPECT held==1 seconds_held==20 mu_infinite==1 non_finite==0
  ARGS --headless --seconds 20 --step 0.001 --big-mass 5000 --mu inf)
# --max-contacts caps dCollide per pair: with 1, the three pairs (small cube
# on the ground, big cube on the small one, big cube on the ground after a
# fall) give at most 3 contacts in a step; and one point per pair cannot
# hold the 5000 kg cube level (measured: lost at 14.3 s; 2 or more hold it).
odelab_check(test4_one_contact_per_pair test4
  EXPECT contacts<=3 max_contacts==1 held==0 non_finite==0
  ARGS --headless --seconds 20 --step 0.001 --big-mass 5000 --max-contacts 1)

# A mass must be a positive finite number; then one common option and an
# unknown one (the shared options: common_options.cmake).
odelab_refusals(test4 refuses_bad_options headless 2
  --big-mass=<empty> --big-mass=0 --big-mass=-1 --big-mass=nan --big-mass=inf --big-mass=1e400 --big-mass=heavy
  --step=nan --no-such-option)
odelab_determinism(test4 --seconds 2)

# --mu and --max-contacts (the contact choices every scene with contacts takes).
odelab_contact_choice_refusals(test4)

# In headless Chromium, against this build's headless run (checks/web.cmake,
# label web): 1e-4 degree against the scene's 2 degrees.
odelab_web_check(test4 max_tilt_degrees 1e-4 SECONDS 5 ARGS --big-mass 5000)
