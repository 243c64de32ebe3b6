# ---- a world file's own joint ERP and CFM (doc/world-format.md): applied where
# ODE has them, refused where it has none; and what another engine is handed
# of a world file. CTest label: engines.
set(_joint_worlds ${CMAKE_CURRENT_SOURCE_DIR}/worlds)

# A 1 kg box held to the world by a fixed joint under g = 9.81, dWorldStep at
# 1 ms: the joint is a spring of stiffness ERP / (h CFM) and damping
# (1 - ERP) / CFM, so released at zero stretch it sags to m g h CFM / ERP and
# peaks between that (overdamped) and twice it (undamped). At the world's ERP
# 0.2 and CFM 1e-5 (no joint values): sag 4.905e-7 m, heavily overdamped;
# measured 4.905e-7; bound 1% either side. Its own CFM 0.01: sag 4.905e-4 m;
# measured 6.45e-4; bound [sag, 2 sag]. ERP 0.9, CFM 0.01: sag 1.09e-4 m;
# measured 1.74e-4; bound [sag, 2 sag]. Before ODE applied a fixed joint's own
# values, all three gave 4.905e-7 and the same state hash.
odelab_check(world_fixed_joint_takes_the_worlds_erp_cfm odelab LABEL engines
             EXPECT joint_error_max_m>4.856e-7 joint_error_max_m<4.954e-7
             ARGS --world ${_joint_worlds}/fixed-joint-world-erp-cfm.json --headless --seconds 2)
odelab_check(world_fixed_joint_applies_its_own_cfm odelab LABEL engines
             EXPECT joint_error_max_m>4.905e-4 joint_error_max_m<9.81e-4
             ARGS --world ${_joint_worlds}/fixed-joint-cfm-0.01.json --headless --seconds 2)
odelab_check(world_fixed_joint_applies_its_own_erp odelab LABEL engines
             EXPECT joint_error_max_m>1.09e-4 joint_error_max_m<2.18e-4
             ARGS --world ${_joint_worlds}/fixed-joint-erp-0.9-cfm-0.01.json --headless --seconds 2)
# A hinge's or slider's own erp or cfm would change nothing in ODE: refused
# (status 2) naming the field, before anything runs.
odelab_refusals(odelab refuses_a_hinges_own_erp headless 2 NEEDLE "joints[0].erp"
                --world=${_joint_worlds}/hinge-with-erp.json)

# Each engine here is handed the file's joints and surfaces: on every example
# world no note names a value the file does not set (scripts/
# world_notes_name_file_values.py; ODE's read-back gave tumbling_brick.json
# "infinite friction" on Bullet and MuJoCo and MuJoCo's elliptic cones).
set(_other_engines ${ODELAB_CHECK_ENGINES})
list(REMOVE_ITEM _other_engines ode)
if(_other_engines)
  string(REPLACE ";" "," _engine_list "${_other_engines}")
  file(GLOB _example_worlds ${CMAKE_SOURCE_DIR}/doc/worlds/*.json)
  add_test(NAME world_notes_name_only_file_values
           COMMAND ${Python3_EXECUTABLE} ${ODELAB_CHECK_SCRIPTS}/world_notes_name_file_values.py
                   $<TARGET_FILE:odelab> ${_engine_list} ${_example_worlds})
  set_tests_properties(world_notes_name_only_file_values PROPERTIES LABELS engines TIMEOUT 600)
endif()
