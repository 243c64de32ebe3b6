"""test2's pendulum: the energy of its swing, m g d, that its relative energy
errors are given against.

Every program reports the total energy E = m g y + kinetic with the
potential's zero on the ground, 7 m below the hinge: released horizontal at
rest, E0 = m g H (H the hinge's height), of which only m g d ever turns into
motion (d: the hinge to the composite centre of mass, the height the centre
falls to the bottom of the swing). An error divided by E0 is diluted by
H / d = 2.4x; this module divides by m g d.

m = rod + bob, d = (rod L / 2 + bob D) / m, from the scene's own constants
(tests/shared/SceneConstants.h namespace test2, utils/WorldSettings.h;
lab/tests/test_physics_scores.py holds them equal)."""

from .runner import LabError

HINGE_HEIGHT_M = 7.0       # ANCHOR_HEIGHT
ROD_LENGTH_M = 3.0         # ROD_LENGTH: from the hinge along the rod
ROD_MASS_KG = 0.1          # ROD_MASS
BOB_MASS_KG = 0.33         # BOB_MASS
BOB_DISTANCE_M = 3.3       # BOB_DISTANCE: hinge to the bob's centre
GRAVITY_M_S2 = 9.823       # SURFACE_GRAVITY, the thesis's g


def mass():
    return ROD_MASS_KG + BOB_MASS_KG


def centre_distance():
    """d: the hinge to the composite centre of mass (m)."""
    return (ROD_MASS_KG * ROD_LENGTH_M / 2 + BOB_MASS_KG * BOB_DISTANCE_M) / mass()


def swing_joules():
    """m g d: the energy of the swing from horizontal (J)."""
    return mass() * GRAVITY_M_S2 * centre_distance()


def start_joules():
    """E0 = m g H: released horizontal at rest, the potential's zero on the ground (J)."""
    return mass() * GRAVITY_M_S2 * HINGE_HEIGHT_M


def largest_error(start, low, high):
    """max |E - E0| / (m g d) from a run's start, least and largest total
    energy (J). The run's start must be this module's E0: otherwise the scene
    is not the one these constants describe."""
    if abs(start - start_joules()) > 1e-6 * start_joules():
        raise LabError(f"test2's start energy {start:.9g} J is not m g H = {start_joules():.9g} J of "
                       "lab/odelab_report/swing_energy.py: the pendulum's constants changed")
    return max(high - start, start - low) / swing_joules()


def per_swing(relative_to_start):
    """|E - E0| / E0 as |E - E0| / (m g d), for a reading given against E0
    (the peers' energy_max_deviation, in float32 on the web peers: their E0
    is m g H to rounding, not to 1e-6); None stays None."""
    return None if relative_to_start is None else relative_to_start * start_joules() / swing_joules()


def of_run(r):
    """A test2 run's (any engine's) largest |E - E0| / (m g d), from its
    energy_start_J, energy_min_J and energy_max_J; None where it gave none."""
    start, low, high = (r.m(name) for name in ("energy_start_J", "energy_min_J", "energy_max_J"))
    return None if None in (start, low, high) else largest_error(start, low, high)


def drift_of_run(r):
    """A test2 run's (last - first) / (m g d): the energy it gained (lost: below 0) by its end."""
    start, last = r.m("energy_start_J"), r.m("energy_last_J")
    if None in (start, last):
        return None
    largest_error(start, start, start)  # the same rig check
    return (last - start) / swing_joules()


def header():
    """The definition and its inputs, for a CSV header and a definition cell."""
    return (f"energy errors relative to the swing's energy m g d = {swing_joules():.6g} J, not to E0 = m g H = "
            f"{start_joules():.6g} J (potential zero on the ground, H = {HINGE_HEIGHT_M:g} m the hinge's height; "
            f"E0 / (m g d) = {start_joules() / swing_joules():.4g}): m = {mass():.4g} kg the rod ({ROD_MASS_KG:g} kg, "
            f"{ROD_LENGTH_M:g} m) and the bob ({BOB_MASS_KG:g} kg at {BOB_DISTANCE_M:g} m), "
            f"g = {GRAVITY_M_S2:g} m/s^2, "
            f"d = {centre_distance():.6g} m the hinge to their centre of mass (how far it falls from horizontal)")
