"""The rules of the world report (lab/odelab-report --world) on its rows,
apart from running anything, so that they can be tested on made-up rows:
which settings are within a tolerance, the cheapest of them (ties within
the timing's scatter), the stability limit along the step, and the limit
the claims of the first screen compute from world-limit.csv."""

from .claims import cheapest_set

LEVELS = (1e-2, 1e-3)  # "within 1%" and "within 0.1%" of the reference
# A run whose measurements depart from the reference by more than this has
# broken down even if it did not blow up (the step limit's second rule).
BOUND = 0.1


def cheapest_within(rows, level, error="max_dev", cost="engine_s_per_sim_s"):
    """Indices of `rows` that are the cheapest within `level` (deviation
    <= level): the cheapest by its median cost, then every other whose
    fastest timed run is not slower than the cheapest's slowest (a tie);
    [] when none is within it. A row has `error`, `cost`, `cost`_min and
    `cost`_max (None: not reached / not timed)."""
    return cheapest_set([r.get(error) for r in rows], [r.get(cost) for r in rows],
                        [r.get(cost + "_min") for r in rows], [r.get(cost + "_max") for r in rows], level)


def step_limit(probes):
    """From [(step, passed)]: (largest passing step below the smallest
    failing one or None, smallest failing step or None). Failing is taken as
    monotone in the step: a pass above the first failure is not the limit."""
    failed = [s for s, ok in probes if not ok]
    first_fail = min(failed) if failed else None
    passed = [s for s, ok in probes if ok and (first_fail is None or s < first_fail)]
    return (max(passed) if passed else None), first_fail


def passes_bound(exit_status, max_dev, bound=BOUND):
    """A step probe passes the bound when it ran (status 0) and every
    measurement stayed within `bound` of the reference."""
    return exit_status == 0 and max_dev is not None and max_dev <= bound


# The same limit, written for the claims (an expression over the lookups
# `steps` and `passed` of world-limit.csv): check_report-style recomputation
# reads it from claims.csv.
FIRST_FAIL = "min([s for s, x in zip(steps, passed) if not x])"
LAST_PASS_BELOW = "max([s for s, x in zip(steps, passed) if x and s < f])"
