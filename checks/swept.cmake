# ---- test10: the swept collision (--ccd) for any orientation, and launches
# that fly out of the scene (issue 15) ----

# A cube at 200,000 m/s moves 200 m a step: at step 0.001 it jumps the 0.05 m
# wall whole, and flies past the 100 m the scene keeps cubes within in the
# very step that decides it. Every launch passes (exact counts). Before the
# fix the outcome was read from the removed launch's record (a heap overflow
# under AddressSanitizer, a garbage outcome in a release build). The scene's
# sizes are reported for the lab: half-size 0.2 m, wall 0.05 m (exact).
odelab_check(test10_launch_that_leaves_the_scene_in_one_step_is_counted test10
  EXPECT passed_through==3 stopped==0 launches==3 cube_half_size_m==0.2 wall_thickness_m==0.05 non_finite==0
  ARGS --headless --velocity 200000 --launches 3)
# The same at step 0.1: 2000 m/s is 200 m a step, far past (h + t)/step = 2.5 m/s.
odelab_check(test10_launch_at_step_0_1_passes_and_is_counted test10
  EXPECT passed_through==1 stopped==0 launches==1 non_finite==0
  ARGS --headless --step 0.1 --velocity 2000 --launches 1)

# Issue 17: with --ccd, cubes turned at random (corner or edge first) are
# stopped at every velocity of the scan up to 10,000 m/s, 5 launches each
# (16,520 launches): the time of impact accounts for the turn and the
# corners on their way in get contacts. Without it, turned cubes passed
# from 523 m/s. max_velocity is the last tested velocity below the limit
# (9992.6 m/s at 0.1% resolution), no launch passed.
odelab_check(test10_ccd_stops_turned_cubes_up_to_10000 test10
  EXPECT max_velocity>=9990 first_failure_velocity==0 passed_through==0 ccd_speculative_contacts>0 non_finite==0
  ARGS --headless --ccd --random-orientation --find-max-velocity --launches 5 --scan-limit 10000 --band-factor 1)
# ... at a random phase of the step too, and with another seed.
odelab_check(test10_ccd_stops_turned_cubes_at_random_phase_up_to_10000 test10
  EXPECT max_velocity>=9990 first_failure_velocity==0 passed_through==0 non_finite==0
  ARGS --headless --ccd --random-orientation --phase-jitter --find-max-velocity --launches 5 --scan-limit 10000
       --band-factor 1)
odelab_check(test10_ccd_stops_turned_cubes_up_to_10000_seed_2 test10
  EXPECT max_velocity>=9990 first_failure_velocity==0 passed_through==0 non_finite==0
  ARGS --headless --ccd --random-orientation --phase-jitter --seed 2 --find-max-velocity --launches 5
       --scan-limit 10000 --band-factor 1)

# --spin (rad/s at launch, to measure the sweep's limit with fast-turning
# cubes): a finite rate from 0 to 1e6, else status 2 and nothing written.
odelab_check(test10_refuses_negative_spin test10 STATUS 2 LABEL hardening ARGS --headless --spin=-1)
odelab_check(test10_refuses_nan_spin test10 STATUS 2 LABEL hardening ARGS --headless --spin=nan)
odelab_check(test10_refuses_huge_spin test10 STATUS 2 LABEL hardening ARGS --headless --spin=1e7)
# A cube turning at 1000 rad/s (one radian a step) toward the wall at
# 10,000 m/s, corner or edge first, at a random phase: every one of 200 is
# stopped with --ccd (measured: none of 1000 passed; at 30,000 rad/s, 5 of 1000).
odelab_check(test10_ccd_stops_spinning_cubes_at_10000 test10
  EXPECT passed_through==0 stopped==200 launch_spin==1000 non_finite==0
  ARGS --headless --ccd --random-orientation --phase-jitter --spin 1000 --velocity 10000 --launches 200)
