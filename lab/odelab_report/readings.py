"""What quantity, at which scene setting, a lookup into a report CSV reads.

The first table promises that each row's cells read one quantity at one
setting, the one its definition cell states. A CSV says part of that in its
own columns (peers.csv's `quantity`, limit-test8.csv's `erp` and `cfm`); the
rest is fixed by the experiment that wrote it (speed-test8.csv runs at CFM 0)
and is written down here, once, for first_screen.py (which puts "n/a: ..."
where a source reads something else) and for check_report.py (which compares
every lookup of claims.csv against its row's definition).

The solver and the step are not compared: the cheapest cell searches over
them by design, and the definition cell states the ones the figure uses."""

from .claims import _matches

# The scene settings a definition may fix; each is compared where a source says it.
SETTING_KEYS = ("erp", "cfm", "seconds", "bob_mass_kg", "angular_speed_cap")
SAID = {"erp": "ERP {}", "cfm": "CFM {}", "seconds": "{} s", "bob_mass_kg": "{} kg bob",
        "angular_speed_cap": "speed cap {}"}

# Columns that give a figure (a quantity); other columns a lookup reads
# (costs, solvers, steps, counts) are only compared for their setting.
QUANTITY_COLUMNS = {"value", "error", "heaviest_held_kg", "tallest_plates", "seconds_upright", "max_velocity",
                    "fall_time_error"}

# The quantity a column, a peers.csv `quantity` or a thesis-values.csv `name` stands for.
QUANTITIES = {
    "max_rebound_error": "rebound error", "rebound_error": "rebound error",
    "variation": "energy (max-min)/max", "energy_max_deviation": "energy |E-E0|/E0",
    "max_deviation": "energy |E-E0|/E0", "energy_swing_error": "energy |ΔE|/mgd",
    "max_swing_error": "energy |ΔE|/mgd",
    "real_time_factor": "real-time factor", "fallen_fraction": "dominoes fallen",
    "heaviest_held_kg": "heaviest cube held", "tallest_plates": "tallest stack",
    "tallest_aligned_plates": "tallest stack", "seconds_upright": "seconds upright",
    "fall_time_error": "fall-time error",
    "joint_error": "joint error", "max_joint_error": "joint error",
    "elongation": "relative elongation", "max_relative_elongation": "relative elongation",
    "apex_error_20": "apex error after 20 bounces", "max_velocity": "velocity stopped",
    "max_velocity_stopped": "velocity stopped", "resting": "bodies at rest",
}

# Settings fixed by the experiment that wrote a file (file -> facts), or one
# scene's / thesis row's part of it ((file, key) -> facts).
FIXED = {
    "speed-test2.csv": dict(quantity="energy |ΔE|/mgd", erp=0.4, cfm=0, seconds=20),
    "speed-test8.csv": dict(quantity="relative elongation", erp=0.4, cfm=0, seconds=20, bob_mass_kg=5000),
    "speed-test9.csv": dict(quantity="apex error after 20 bounces", erp=0.2, cfm=0),
    ("thesis-values.csv", "test2"): dict(erp=0.4, cfm=0, seconds=60),
    ("thesis-values.csv", "test7"): dict(angular_speed_cap="on"),
    # (test8_a runs 60 s, 10 s in --quick: its length is left to the row's text.)
    ("thesis-values.csv", "test8_a"): dict(erp=0.4, cfm=0.0001, bob_mass_kg=5000),
    ("thesis-values.csv", "test9_a"): dict(erp=0.2, cfm=0),
    # peers.csv (experiments/peers.py): the scenes' defaults, test8 and test2
    # for 20 s; test7 without the angular speed cap, which no other engine
    # has (doc/peers.md).
    ("peers.csv", "test2"): dict(seconds=20),
    ("peers.csv", "test8"): dict(erp=0.4, cfm=0.0001, seconds=20, bob_mass_kg=5000),
    ("peers.csv", "test9"): dict(erp=0.2, cfm=0),
    ("peers.csv", "test7"): dict(angular_speed_cap="off"),
}

# Files whose lookups read no measured quantity: the thesis's own words, and
# the runs' CPU times (chosen by a row of a file compared here).
NOT_READINGS = {"thesis.csv", "runs.csv"}


def facts(spec, rows):
    """What the lookup `spec` reads, from the `rows` it matches: a dict with
    `quantity` (None for a cost or a description) and the settings known."""
    file, column, where = spec["file"], spec["column"], spec.get("where", {})
    known = dict(FIXED.get(file, {}))
    scene = where.get("key", where.get("scene"))
    known.update(FIXED.get((file, scene), {}))
    for key in SETTING_KEYS:
        values = {row.get(key) for row in rows if row.get(key) not in (None, "")}
        if len(values) == 1:
            known[key] = values.pop()
        if key in where:
            known[key] = where[key]
    quantity = known.pop("quantity", None)
    if column in QUANTITY_COLUMNS and rows:  # no row: no figure, nothing read
        if file == "peers.csv":
            names = {row.get("quantity") for row in rows}
            quantity = QUANTITIES.get(names.pop()) if len(names) == 1 else None
        elif file == "thesis-values.csv":
            quantity = QUANTITIES.get(where.get("name"))
        elif quantity is None:
            quantity = QUANTITIES.get(column)
        known["quantity"] = quantity or f"unknown ({file} {column})"
    return known


def differences(definition, read):
    """How `read` (facts) departs from a row's `definition`: a list of
    'CFM 0, not CFM 0.0001' phrases; empty when it reads the row's quantity at
    the row's setting."""
    found = []
    if "quantity" in read and read["quantity"] != definition["quantity"]:
        found.append(f"{read['quantity']}, not {definition['quantity']}")
    for key in SETTING_KEYS:
        if key in definition and key in read and not _matches(str(read[key]), definition[key]):
            found.append(f"{SAID[key].format(read[key])}, not {SAID[key].format(definition[key])}")
    return found
