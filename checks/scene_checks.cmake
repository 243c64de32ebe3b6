# Scene checks: each runs a program headless and asserts a physical fact with
# a stated tolerance. Per-scene sections live in their own files.

# ---- test0 - Box & Sphere ----
# Six boxes dropped one per 0.5 s onto the platform all come to rest on it
# within 10 s: finite state, nothing removed, every spawned body resting
# (speed below 0.05 m/s, centre above the platform's top face and inside it).
# (Spheres are left out: with no rolling resistance they may roll off.)
odelab_check(test0_boxes_come_to_rest_on_platform test0
  EXPECT spawned==6 bodies_resting_on_platform==6 removed_bodies==0 non_finite==0
  ARGS --headless --seconds 10 --spawn-interval 0.5 --spawn-count 6 --spawn-shapes box)
# The lifetime rule: after 40 s, every object spawned in the first 10 s is gone.
odelab_check(test0_lifetime_removes_old_objects test0
  EXPECT spawned==10 removed_bodies==10 bodies==0
  ARGS --headless --seconds 40 --spawn-interval 1 --spawn-count 10)
# The lifetime and boundary rules bound the count: an object every 0.1 s,
# each living at most 30 s, leaves at most 301 alive at any moment
# (max_bodies counts them after every step's spawn).
odelab_check(test0_count_bounded_by_lifetime test0
  EXPECT spawned==600 max_bodies<=301 max_bodies>0 non_finite==0
  ARGS --headless --seconds 60 --spawn-interval 0.1)

# ---- every program: bad options are refused with status 2 and nothing written
set(ODELAB_BAD_OPTIONS
  "--step=0" "--step=-1" "--step=nan" "--erp=2" "--cfm=-1" "--cfm=inf" "--iterations=0"
  "--solver=fast" "--seconds=abc" "--out-dir=/nonexistent-folder" "--no-such-option")
foreach(_bad IN LISTS ODELAB_BAD_OPTIONS)
  string(MAKE_C_IDENTIFIER "${_bad}" _id)
  odelab_check(test0_refuses${_id} test0 STATUS 2 ARGS --headless ${_bad})
endforeach()

foreach(_section scenes_1_to_5.cmake scenes_6_to_10.cmake windowed.cmake fuzz_window.cmake)
  if(EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/${_section})
    include(${CMAKE_CURRENT_SOURCE_DIR}/${_section})
  endif()
endforeach()
include(${CMAKE_CURRENT_SOURCE_DIR}/hardening.cmake)  # issue 7: extreme settings, bad input, determinism, interrupted runs
