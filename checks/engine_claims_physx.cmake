# ---- what PhysX 5 (physx-js-webidl 2.7.3) does with the scenes' own worlds --------
# (doc/peers.md). Included by engine_claims.cmake, whose odelab_engine_claim
# registers each only where PhysX is here. Each bound was measured first
# (`build/tests/testN --headless --engine physx [--engine-setting best] ...
# --metrics-json F`, this machine, float32, deterministic from run to run);
# "measured X; bound Y because ..." beside it. Default: PGS, 4 position and
# 1 velocity iterations per body, angular damping 0.05, no bounce below
# 2 m/s, no CCD. Best: TGS, 32 and 4 iterations, no damping, the world's
# bounce velocity, swept CCD (peers/wasm/src/engines/physx.js).

# test2, the pendulum (20 s). PhysX damps rotation by 0.05 by default:
# measured -4.53% of the energy in 20 s; bound -2%. Without damping, on TGS
# (best): measured a worst deviation of 3.46e-4 (ODE's own: 3.21e-4) and a
# period 1.2e-5 off; bounds 1e-3 (the double-precision engines' bound) and
# 1e-3 on the period.
odelab_engine_claim(engine_physx_default_damping_drains physx test2 EXPECT energy_drift<-0.02 ARGS --seconds 20)
odelab_engine_claim(engine_physx_pendulum_energy physx test2
                    EXPECT energy_max_deviation<1e-3 period_error>-1e-3 period_error<1e-3
                    ARGS --engine-setting best --seconds 20)

# test8, test2's pendulum with a 5000 kg bob (20 s): a revolute joint between
# free bodies stretches a little. Measured 3.24e-6 (default) and 1.48e-6
# (best); bounds 1e-5 and 1e-9 (it is not rigid).
odelab_engine_claim(engine_physx_hinge_stretch physx test8 EXPECT max_relative_elongation<1e-5
                    max_relative_elongation>1e-9 ARGS --seconds 20)

# test9, the ball of bounce 1 under 4 g (21 s). TGS with the world's bounce
# velocity (best): measured 1.33e-4 at the 20th apex; bound 1e-3. PGS at its
# defaults loses about 0.4% a bounce: measured 0.0853; bound 0.05. (PGS with
# best's other settings loses the same 0.0853: the solver is what keeps it.)
odelab_engine_claim(engine_physx_tgs_bounce physx test9 EXPECT apex_error_20<1e-3 bounces>=20
                    ARGS --engine-setting best --seconds 21)
odelab_engine_claim(engine_physx_default_bounce_decays physx test9 EXPECT apex_error_20>0.05 ARGS --seconds 21)

# test1, fifty balls of restitution 0 to 1 (15 s). At its defaults PhysX
# bounces only above 2 m/s, so 33 of the 45 balls with e >= 0.1 are
# measured; those within 0.225% of e^2 (measured 2.25e-3, ball 19); bound
# 5e-3. At best (TGS) every one is measured, but ball 48 (e = 0.98) rebounds
# 21.4% short of e^2 (measured 0.214); PGS with best's other settings
# measures 0.61%, so TGS is the cause. Bound: more than 10% short, a finding
# held as it stands (doc/peers.md, "PhysX").
odelab_engine_claim(engine_physx_default_rebound_ratio physx test1 EXPECT max_rebound_error<5e-3 balls_measured==33)
odelab_engine_claim(engine_physx_tgs_rebound_short physx test1 EXPECT max_rebound_error>0.1 balls_measured==45
                    ARGS --engine-setting best)

# test4, the 5000 kg cube on the 5 kg cube (20 s): held at both settings.
# Overlap measured 7.17 mm (default, tilt 0.45 degrees) and 0.064 mm (best,
# tilt 0.003 degrees); bounds 1 cm and 1 mm.
odelab_engine_claim(engine_physx_stack_holds_default physx test4 EXPECT held==1 max_penetration<0.01)
odelab_engine_claim(engine_physx_stack_holds physx test4 EXPECT held==1 max_penetration<1e-3
                    ARGS --engine-setting best)

# test6, the 5000 kg cube on a ball joint above the 1 kg cube (first 5 s):
# measured 6.65 mm (default) and 0.051 mm (best) while upright; bounds 1 cm
# and 1 mm.
odelab_engine_claim(engine_physx_axis_holds_default physx test6 EXPECT sink_while_upright_metres<0.01 ARGS --seconds 5)
odelab_engine_claim(engine_physx_axis_holds_load physx test6 EXPECT sink_while_upright_metres<1e-3
                    ARGS --engine-setting best --seconds 5)

# test10, five cubes at the thin wall at 5000 m/s. PhysX's default linear
# speed cap is 1e16 m/s and it sweeps nothing by default: all 5 pass
# (measured). Swept CCD on every moving body (best): all 5 stopped.
odelab_engine_claim(engine_physx_wall_passed physx test10 EXPECT passed_through==5 ARGS --velocity 5000)
odelab_engine_claim(engine_physx_ccd_stops physx test10 EXPECT stopped==5 ARGS --engine-setting best --velocity 5000)

# test7, the hanging pair hit at 30 m/s three times (the scene's 10 rad/s
# cap applied). Measured joint error 61.7 mm at the defaults and 6.51 mm at
# best; bound 1 cm at best. The cube passes the pivot on neither.
odelab_engine_claim(engine_physx_test7_joints_hold physx test7 EXPECT max_joint_error<0.01 cube_passed_pivot==0
                    throws==3 ARGS --engine-setting best)

# test5, ten plates dropped 0.3 s apart (5 s), the lab's rule for an aligned
# stack. Default: 0.49972 m, 25.4 mm off the axis, 0.072 degrees; best:
# 0.499999 m, 11.7 mm, 0.062 degrees.
odelab_engine_claim(engine_physx_plate_stack_aligned physx test5
                    EXPECT landed_plates==10 stack_height>0.475 max_axis_offset<0.1 max_twist_degrees<2
                    ARGS --plates 10 --seconds 5)

# test3, the spiral of sixty dominoes (20 s at 0.005): the chain completes
# and every domino is asleep at the end, at the defaults (measured: all
# fallen, 0 active; the same at best).
odelab_engine_claim(engine_physx_domino_chain_completes physx test3 EXPECT fallen_fraction==1 active_bodies==0)
