"""ODE Lab's speed-accuracy report (lab/odelab-report)."""
