# test3 - Domino (doc/tests/test3.md): physical claims and bad values.

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
# At ODE's own auto-disable thresholds (0.01, not the scene's 0.1) the thesis
# saw fallen plates stay active though they no longer moved: every domino
# falls and bodies are still active 20 s in (measured: 59 of 60; at 0.1, none).
odelab_check(test3_ode_thresholds_leave_fallen_dominoes_active test3
  EXPECT fallen_fraction==1 active_bodies>0 auto_disable_threshold==0.01 non_finite==0
  ARGS --headless --seconds 20 --auto-disable-threshold 0.01)
# mu = dInfinity: the contact between a falling plate's top and the next plate
# cannot slide, so the two plates and the ground form a rigid triangle and
# the chain stops at once (at most 2 of 60 fall; measured 1).
odelab_check(test3_infinite_friction_locks_the_first_pair test3
  EXPECT fallen_fraction<0.05 non_finite==0
  ARGS --headless --seconds 10 --mu inf --no-auto-disable)

# At least 2 and at most 1000 dominoes (an integer); mu a number >= 0 or inf;
# the flag takes no value but true/false; the auto-disable threshold a
# number in [0, 1e6]. Then one common option and an
# unknown one (the shared options: common_options.cmake).
odelab_refusals(test3 refuses_bad_options headless 2
  --dominoes=<empty> --dominoes=0 --dominoes=1 --dominoes=-1 --dominoes=1001 --dominoes=1.5 --dominoes=ten
  --dominoes=99999999999999999999
  --mu=<empty> --mu= --mu=-1 --mu=-inf --mu=nan --mu=abc
  --no-auto-disable=maybe
  --auto-disable-threshold=<empty> --auto-disable-threshold=-1 --auto-disable-threshold=nan
  --auto-disable-threshold=abc --auto-disable-threshold=1e7
  --step=nan --no-such-option)
odelab_determinism(test3 --seconds 4)

# --mu and --max-contacts (the contact choices every scene with contacts takes).
odelab_contact_choice_refusals(test3)

# In headless Chromium, against this build's headless run (checks/web.cmake,
# label web): a count, compared exactly.
odelab_web_check(test3 fallen_fraction 0 SECONDS 20)
