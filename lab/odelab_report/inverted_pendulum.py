"""test6's big cube as an inverted pendulum: the analytic fall time that a
run's "seconds upright" is scored against.

The 5000 kg cube (side a) stands on a ball joint at the centre of its bottom
face; its centre of mass is d = a / 2 above the anchor and its moment of
inertia about a horizontal axis through the anchor is I = m a^2 / 6 + m d^2.
Linearised, a tilt theta grows as theta'' = lambda^2 theta with
lambda = sqrt(m g d / I) = sqrt(6 g / (5 a)) (the mass cancels); from rest at
theta_0 it is theta_0 cosh(lambda t), so it passes theta_f at
t = acosh(theta_f / theta_0) / lambda. The anchor is taken as fixed: it sits
on a 1 kg cube that the 5000 kg load presses onto ground with infinite
friction.

The inputs are the scene's own constants (tests/shared/SceneConstants.h,
utils/WorldSettings.h; lab/tests/test_inverted_pendulum.py holds them equal)."""

import math

BIG_SIDE_M = 5.0            # scene::test6::BIG_SIDE
GRAVITY_M_S2 = 9.823        # SURFACE_GRAVITY, the thesis's g (WorldSettings.h)
FALL_TILT_DEGREES = 1.0     # scene::test6::UPRIGHT_TILT_DEGREES: "upright" ends past it


def growth_rate(side=BIG_SIDE_M, gravity=GRAVITY_M_S2):
    """lambda (1/s): sqrt(m g d / I) with d = a / 2, I = m a^2 / 6 + m d^2."""
    d = side / 2
    return math.sqrt(gravity * d / (side * side / 6 + d * d))


def fall_seconds(start_tilt_degrees, fall_tilt_degrees=FALL_TILT_DEGREES):
    """The analytic time from rest at `start_tilt_degrees` to `fall_tilt_degrees`."""
    if not 0 < start_tilt_degrees < fall_tilt_degrees:
        raise ValueError(f"a start tilt must be above 0 and below {fall_tilt_degrees} degrees, "
                         f"not {start_tilt_degrees}")
    return math.acosh(fall_tilt_degrees / start_tilt_degrees) / growth_rate()


def equivalent_start_tilt(fall_time_s, fall_tilt_degrees=FALL_TILT_DEGREES):
    """The start tilt (degrees) from which the analytic pendulum falls at
    `fall_time_s`: for a build with no tilt, the size of the asymmetry the
    solver injected, read as a tilt at the start."""
    return fall_tilt_degrees / math.cosh(growth_rate() * fall_time_s)


def header():
    """The formula and its inputs, for a CSV header and a definition cell."""
    lam = growth_rate()
    return (f"analytic fall time t = acosh(theta_f / theta_0) / lambda, lambda = sqrt(m g d / I) = "
            f"sqrt(6 g / (5 a)) = {lam:.6g} 1/s (e-fold {1 / lam:.4g} s) for the big cube as an inverted "
            f"pendulum on a fixed anchor: a = {BIG_SIDE_M:g} m its side, d = a/2 its centre above the anchor, "
            f"I = m a^2/6 + m d^2 about the anchor, g = {GRAVITY_M_S2:g} m/s^2, theta_f = {FALL_TILT_DEGREES:g} "
            "degree (test6's upright rule), theta_0 the start tilt (--tilt-degrees), from rest")
