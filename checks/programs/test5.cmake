# test5 - Lots of same collisions (doc/tests/test5.md): physical claims and bad values.

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
# --max-contacts 3 caps every colliding pair at 3 contacts: 50 plates make 50
# pairs (49 plate on plate, 1 on the platform), so at most 150 contacts
# (measured 150; about 4.3 per pair uncapped), and three contacts a pair still
# hold the column straight (measured 0.014 m off the axis, 2.4945 m).
odelab_check(test5_max_contacts_3_caps_each_pair test5
  EXPECT plates==50 landed_plates==50 max_contacts==3 contacts<=150 max_axis_offset<0.05 stack_height>2.45 stack_height<=2.5 non_finite==0
  ARGS --headless --seconds 20 --plates 50 --spawn-interval 0.3 --cfm 0 --max-contacts 3)

# Dropped 6x faster (every 0.05 s, the lab's stack searches), a plate can come
# to rest on one still rocking below it; every plate is counted as landed once
# both are still (the count used to stop at the newer one: 26 of 40 here).
# 40 x 0.05 = 2 m less the overlap (measured 1.9976 m, 0.009 m off the axis).
odelab_check(test5_fast_drops_count_every_plate_landed test5
  EXPECT plates==40 landed_plates==40 stack_height>1.96 stack_height<=2.0 max_axis_offset<0.05 non_finite==0
  ARGS --headless --seconds 4 --plates 40 --spawn-interval 0.05 --cfm 0)

# Plate count a positive integer up to 100000, interval positive and finite,
# space one of four names; auto-disable thresholds finite and >= 0 (given
# with --auto-disable: without it a threshold is refused for that alone, the
# last case); threads 1 ... 64, an integer; contacts per pair 1 ... 64;
# surface layer in [0, 0.1] m; max correcting velocity positive (inf, ODE's unlimited, is its default). Then one common option and an
# unknown one (the shared options: common_options.cmake).
odelab_refusals(test5 refuses_bad_options headless 2
  --plates=<empty> --plates=0 --plates=-5 --plates=100001 --plates=1.5 --plates=many --plates=99999999999999999999
  --spawn-interval=<empty> --spawn-interval=0 --spawn-interval=-1 --spawn-interval=nan --spawn-interval=inf
  --spawn-interval=abc
  --space=<empty> --space= --space=octree --space=SIMPLE
  "--auto-disable-linear=-0.1 --auto-disable" "--auto-disable-linear=nan --auto-disable"
  "--auto-disable-linear=inf --auto-disable" "--auto-disable-angular=-1 --auto-disable"
  "--auto-disable-angular=nan --auto-disable" "--auto-disable-angular= --auto-disable"
  --threads=0 --threads=65 --threads=-2 --threads=two --threads=1.5
  --max-contacts=0 --max-contacts=65 --max-contacts=2.5 --max-contacts=<empty>
  --contact-surface-layer=-0.001 --contact-surface-layer=nan --contact-surface-layer=0.2
  --contact-max-correcting-vel=0 --contact-max-correcting-vel=-1 --contact-max-correcting-vel=-inf
  --contact-max-correcting-vel=nan
  --auto-disable-linear=0.3
  --step=nan --no-such-option)
odelab_determinism(test5 --seconds 3 --spawn-interval 0.1)

# --mu and --max-contacts (the contact choices every scene with contacts takes).
odelab_contact_choice_refusals(test5)

# In headless Chromium, against this build's headless run (checks/web.cmake,
# label web): 1 micrometre against the scene's 5 cm window on the stack's height.
odelab_web_check(test5 stack_height 1e-6 SECONDS 5 ARGS --plates 10 --spawn-interval 0.3 --cfm 0)
