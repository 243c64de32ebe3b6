# test1 - Jumping Balls (doc/tests/test1.md): physical claims and bad values.

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

# No scene options: one common option and an unknown one show that the
# program takes the shared options (checked in full in common_options.cmake).
odelab_refusals(test1 refuses_bad_options headless 2 --step=nan --no-such-option)
odelab_determinism(test1 --seconds 3)

# --mu and --max-contacts (the contact choices every scene with contacts takes).
odelab_contact_choice_refusals(test1)

# --bounce-velocity (issue 12): the thesis's 0.01 m/s is the default; 2 m/s
# stops the slow late bounces, so fewer balls give two apexes (measured 33
# of 45) but those measured keep e^2 (max error 0.0012).
odelab_check(test1_bounce_velocity_2_measures_fewer_balls test1
  EXPECT bounce_velocity==2 balls_measured<45 max_rebound_error<0.01 non_finite==0
  ARGS --headless --erp 0 --cfm 0 --seconds 15 --bounce-velocity 2)
odelab_refusals(test1 refuses_bad_bounce_velocity headless 2
  --bounce-velocity=-1 --bounce-velocity=nan --bounce-velocity=inf --bounce-velocity=fast --bounce-velocity=<empty>)

# In headless Chromium, against this build's headless run (checks/web.cmake,
# label web): a count, compared exactly.
odelab_web_check(test1 balls_bounced 0 SECONDS 15 ARGS --erp 0 --cfm 0)
