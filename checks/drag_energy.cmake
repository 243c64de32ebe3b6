# ---- a released drag gives back no more energy than it put in (label window) ----
# test2's pendulum dragged round and released (checks/scripts/
# drag_release_energy.events), on ODE and on every engine here (--engine),
# one window each. The program keeps the drag's energy books
# (utils/DragEnergy.h): the bodies' kinetic and potential energy when the
# drag began, the drag spring's work (each step's force times how far the
# grabbed point moved in it), and the most energy at any step after the
# release. The excess, most-after - (before + work), must stay below 2% of
# the energy before the drag (0.5 J of test2's 25 J): the integrators' own
# error over a few seconds of a swinging pendulum, while an engine that kept
# the drag's torque after its step (Rapier's resetForces keeps torques) made
# thousands of joules.
foreach(_engine IN ITEMS ode ${ODELAB_CHECK_ENGINES})
  odelab_window_check(test2_window_drag_release_keeps_energy_${_engine} test2 EVENTS drag_release_energy.events
    EXPECT drag_work_J>0 drag_energy_excess_J<@drag_energy_before_J*0.02
    ARGS --no-panel --hud off --engine ${_engine})
endforeach()
