#!/usr/bin/python3
"""Runs every example world of doc/worlds.md at the settings and on the
engines the page quotes, and writes what the page quotes as a CSV with the
run header every CSV here starts with:

  /usr/bin/python3 doc/measurements/measure_worlds.py [--csv CSV] [--build BUILD]

CSV defaults to doc/measurements/worlds.csv: one row per figure (world,
engine, setting, options, seconds, metric, value, note). engine is an engine
odelab steps the world with (ode, bullet, ...: the metric as odelab's
--metrics-json prints it), `analytic` (the page's closed-form answer,
computed here from its formula, which the note gives), or `file` (a number
the world file states, echoed so the page can cite it). Three runs use an
edited copy of a world (the cradle with its balls touching, the incline
without friction_pyramid): the note says what was changed. Each run is made
once (a second run gave the page's figures again: the runs are deterministic).
Uses build/tests/odelab of BUILD (default: BUILD_DIR, else build/). Two to four
minutes on two shared cores, most of it the cradle's 100000 steps on the
engines run through Node."""

import argparse
import json
import math
import os
import platform
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
WORLDS = ROOT / "doc" / "worlds"
G = 9.81

# Metrics of the measures (and the run's size and cost); odelab's other
# metrics are the settings it ran with, which the options column states.
KEPT = ("energy_", "linear_momentum_", "angular_momentum_", "joint_", "penetration_max_m", "tunnelled_bodies",
        "tunnelling_crossings", "_error_max_m", "_period_", "time_to_rest_s", "steps", "sim_seconds",
        "engine_wall_seconds", "blew_up")

# (world, engine, setting label, odelab options, seconds, edit): every run the page quotes.
RUNS = [
    ("newtons_cradle", "ode", "file", [], 10, None),
    ("newtons_cradle", "ode", "cfm_1e-5", ["--cfm", "1e-5"], 10, None),
    ("newtons_cradle", "ode", "touching", [], 10, "touching"),
    ("newtons_cradle", "ode", "touching_solver_step", ["--solver", "step"], 10, "touching"),
    ("newtons_cradle", "bullet", "default", [], 10, None),
    ("newtons_cradle", "bullet", "best", [], 10, None),
    ("newtons_cradle", "mujoco", "default", [], 10, None),
    ("newtons_cradle", "mujoco", "best", [], 10, None),
    ("newtons_cradle", "havok", "best", [], 10, None),
    ("newtons_cradle", "jolt", "best", [], 10, None),
    ("newtons_cradle", "rapier", "default", [], 10, None),
    ("hinged_chain", "ode", "file", [], 10, None),
    ("hinged_chain", "ode", "iterations_100", ["--iterations", "100"], 10, None),
    ("hinged_chain", "ode", "solver_step", ["--solver", "step"], 10, None),
    ("hinged_chain", "ode", "step_0.0001", ["--step", "0.0001"], 10, None),
    ("hinged_chain", "ode", "solver_step_step_0.0001", ["--solver", "step", "--step", "0.0001"], 10, None),
    ("incline_slide", "ode", "file", [], 10, None),
    ("incline_slide", "ode", "no_friction_pyramid", [], 10, "no_friction_pyramid"),
    ("tumbling_brick", "ode", "file", [], 10, None),
    ("tumbling_brick", "ode", "file", [], 30, None),
    ("tumbling_brick", "ode", "step_0.0001", ["--step", "0.0001"], 10, None),
    ("tumbling_brick", "ode", "step_0.00001", ["--step", "0.00001"], 10, None),
    ("projectile", "ode", "file", [], 10, None),
    ("projectile", "ode", "step_0.0001", ["--step", "0.0001"], 10, None),
    ("thin_wall", "ode", "file", [], 10, None),
    ("thin_wall", "ode", "step_0.0005", ["--step", "0.0005"], 10, None),
    ("thin_wall", "ode", "step_0.0001", ["--step", "0.0001"], 10, None),
]
# The 1 ms worlds on every engine at both settings (cheap: 10000 steps each).
for _world in ("hinged_chain", "incline_slide", "tumbling_brick", "projectile", "thin_wall"):
    for _engine in ("bullet", "mujoco", "havok", "jolt", "rapier"):
        for _setting in ("default", "best"):
            RUNS.append((_world, _engine, _setting, [], 10, None))

EDITS = {
    "touching": "world edited: the gaps closed (balls 1 to 4 and their hinges at x = 0.05 i), "
                "period measured about x = 0.25 against T(30 deg) without the gaps' term",
    "no_friction_pyramid": "world edited: friction_pyramid false (mu a force limit per contact point)",
}


def edited(world, edit):
    """The world file's text with `edit` applied (see EDITS)."""
    data = json.loads((WORLDS / f"{world}.json").read_text())
    if edit == "touching":
        for i in range(1, 5):
            data["bodies"][i]["position"][0] = 0.05 * i
            data["joints"][i]["anchor"][0] = 0.05 * i
        period = next(m for m in data["measures"] if m["kind"] == "period")
        period["about"] = 0.25
        period["expected"] = cradle()["period_30deg_s"]
    elif edit == "no_friction_pyramid":
        for surface in data["surfaces"]:
            surface["friction_pyramid"] = False
    return json.dumps(data, indent=1)


def run(odelab, work, world, engine, setting, options, seconds, edit):
    """The metrics (name: value as printed) of one headless run."""
    path = WORLDS / f"{world}.json"
    if edit:
        path = work / f"{world}-{edit}.json"
        path.write_text(edited(world, edit))
    out = work / "m.json"
    command = [str(odelab), "--world", str(path), "--headless", "--seconds", str(seconds), "--metrics-json", str(out)]
    if engine != "ode":
        command += ["--engine", engine, "--engine-setting", setting]
    command += options
    done = subprocess.run(command, cwd=work, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                          stderr=subprocess.PIPE, text=True)
    if done.returncode not in (0, 3) or not out.exists():
        raise SystemExit(f"measure_worlds: {' '.join(command)} ended with status {done.returncode}: "
                         f"{done.stderr.strip()[-400:]}")
    # Keep the numbers as odelab printed them (not re-rounded through a float).
    metrics = json.loads(out.read_text(), parse_float=str, parse_int=str)
    out.unlink()
    # A measure with no answer (a period never timed) prints null.
    return {name: "null" if value is None else value for name, value in metrics.items() if any(k in name for k in KEPT)}


def elliptic_k(k):
    """The complete elliptic integral of the first kind K(k), by the
    arithmetic-geometric mean (exact to rounding even for k near 1)."""
    a, b = 1.0, math.sqrt((1.0 - k) * (1.0 + k))
    while abs(a - b) > 1e-16 * a:
        a, b = (a + b) / 2, math.sqrt(a * b)
    return math.pi / (2 * a)


def cradle():
    r, density, length, gap, release = 0.025, 7850.0, 0.4, 0.001, math.radians(30)
    m = density * 4 / 3 * math.pi * r ** 3
    omega0 = math.sqrt(G * length / (length ** 2 + 2 * r ** 2 / 5))
    height = length * (1 - math.cos(release))
    period = 4 * elliptic_k(math.sin(release / 2)) / omega0
    # The bottom speed of a physical pendulum: m g h = (m L^2 + I) w^2 / 2, v = w L.
    v = math.sqrt(2 * G * height * m * length ** 2 / (m * length ** 2 + 2 / 5 * m * r ** 2))
    gaps = 8 * gap / v
    return {"steel_density_kg_m3": density, "ball_mass_kg": m, "release_height_m": height, "omega0_rad_s": omega0,
            "period_30deg_s": period, "period_small_swing_s": 2 * math.pi / omega0, "bottom_speed_m_s": v,
            "gaps_time_per_cycle_s": gaps, "cycle_period_s": period + gaps, "gaps_share": gaps / period,
            "energy_scale_J": m * G * height}


CRADLE_NOTES = {
    "steel_density_kg_m3": "steel's density: gives the file's mass 7850 x 4/3 pi r^3, r = 0.025 m",
    "ball_mass_kg": "7850 x 4/3 pi r^3", "release_height_m": "L (1 - cos 30 deg), L = 0.4 m",
    "omega0_rad_s": "sqrt(g L / (L^2 + 2 r^2 / 5))", "period_30deg_s": "4 K(sin 15 deg) / omega0",
    "period_small_swing_s": "2 pi / omega0", "bottom_speed_m_s": "L sqrt(2 m g h / (m L^2 + 2/5 m r^2))",
    "gaps_time_per_cycle_s": "8 x 1 mm / v", "cycle_period_s": "4 K(sin 15 deg) / omega0 + 8 x 1 mm / v",
    "gaps_share": "(8 x 1 mm / v) / T(30 deg)", "energy_scale_J": "m g L (1 - cos 30 deg)"}


def chain():
    return [("energy_scale_J", 6 * 0.5 * G * 0.9, "6 x 0.5 kg x g x 0.9 m (the centre of mass falls 0.9 m)")]


def incline():
    theta, mu, v0, m, corners, limit = math.radians(20), 0.5, 2.0, 2.0, 4, 0.5
    a = G * (mu * math.cos(theta) - math.sin(theta))
    return [("tan_theta", math.tan(theta), "tan 20 deg"),
            ("deceleration_m_s2", a, "g (mu cos 20 deg - sin 20 deg)"),
            ("stop_time_s", v0 / a, "v0 / a"), ("stop_distance_m", v0 ** 2 / (2 * a), "v0^2 / (2 a)"),
            ("time_to_rest_s", (v0 - 0.01) / a, "(v0 - 0.01 m/s) / a"),
            ("pull_down_slope_N", m * G * math.sin(theta), "m g sin 20 deg"),
            ("friction_limit_N", corners * limit, "4 corners x 0.5 N"),
            ("acceleration_force_limit_m_s2", G * math.sin(theta) - corners * limit / m,
             "g sin 20 deg - 4 x 0.5 N / m")]


def brick_rates(w, inertia):
    i1, i2, i3 = inertia
    return ((i2 - i3) / i1 * w[1] * w[2], (i3 - i1) / i2 * w[2] * w[0], (i1 - i2) / i3 * w[0] * w[1])


def brick():
    m, (a, b, c) = 1.0, (0.3, 0.2, 0.1)
    inertia = (m * (b * b + c * c) / 12, m * (a * a + c * c) / 12, m * (a * a + b * b) / 12)
    w0 = (0.01, 6.0, 0.01)
    energy = sum(i * w * w for i, w in zip(inertia, w0)) / 2
    momentum2 = sum((i * w) ** 2 for i, w in zip(inertia, w0))
    i1, i2, i3 = inertia
    # Torque-free motion in Jacobi elliptic functions (I1 < I2 < I3): the
    # intermediate component goes as sn(lambda t, k), changing sign every 2K/lambda.
    if momentum2 > 2 * energy * i2:
        lam = math.sqrt((i3 - i2) * (momentum2 - 2 * energy * i1) / (i1 * i2 * i3))
        k2 = (i2 - i1) * (2 * energy * i3 - momentum2) / ((i3 - i2) * (momentum2 - 2 * energy * i1))
    else:
        lam = math.sqrt((i2 - i1) * (2 * energy * i3 - momentum2) / (i1 * i2 * i3))
        k2 = (i3 - i2) * (momentum2 - 2 * energy * i1) / ((i2 - i1) * (2 * energy * i3 - momentum2))
    rows = [("inertia_xx", inertia[0], "m (b^2 + c^2) / 12"), ("inertia_yy", inertia[1], "m (a^2 + c^2) / 12"),
            ("inertia_zz", inertia[2], "m (a^2 + b^2) / 12"), ("energy_J", energy, "sum I w^2 / 2"),
            ("angular_momentum", math.sqrt(momentum2), "|I w|"), ("one_minus_k2", 1 - k2, "1 - k^2"),
            ("lambda_per_s", lam, "Jacobi elliptic solution's rate"),
            ("flip_interval_s", 2 * elliptic_k(math.sqrt(k2)) / lam, "2 K(k) / lambda")]
    # Euler's equations by RK4 at 0.1 ms: the times the y spin changes sign.
    h, t, w, flips = 1e-4, 0.0, w0, []
    while t < 26.0:
        k1 = brick_rates(w, inertia)
        k2_ = brick_rates([x + h / 2 * d for x, d in zip(w, k1)], inertia)
        k3 = brick_rates([x + h / 2 * d for x, d in zip(w, k2_)], inertia)
        k4 = brick_rates([x + h * d for x, d in zip(w, k3)], inertia)
        n = tuple(x + h / 6 * (p + 2 * q + 2 * r + s) for x, p, q, r, s in zip(w, k1, k2_, k3, k4))
        if (n[1] < 0) != (w[1] < 0):
            flips.append(t + h * w[1] / (w[1] - n[1]))
        w, t = n, t + h
    rows += [(f"flip_{i + 1}_s", f, "Euler's equations, RK4 at 0.1 ms") for i, f in enumerate(flips)]
    return rows


def projectile():
    y0, vx, vy, r, until = 1.0, 4.0, 6.0, 0.1, 1.3
    impact = math.sqrt(vy * vy + 2 * G * (y0 - r))
    return [("speed_m_s", math.hypot(vx, vy), "|v0|"), ("angle_deg", math.degrees(math.atan2(vy, vx)), "atan(6/4)"),
            ("landing_s", (vy + impact) / G, "centre at y = r"), ("apex_m", y0 + vy * vy / (2 * G), "y0 + vy^2/(2g)"),
            ("apex_time_s", vy / G, "vy / g"),
            ("arc_error_step_0.001_m", G * 0.001 * until / 2, "g h t / 2, h = 1 ms, t = 1.3 s"),
            ("arc_error_step_0.0001_m", G * 0.0001 * until / 2, "g h t / 2, h = 0.1 ms, t = 1.3 s"),
            ("impact_speed_m_s", impact, "sqrt(vy^2 + 2 g (y0 - r))"),
            ("impact_depth_one_step_m", impact * 0.001, "vertical impact speed x 1 ms")]


def flat(prefix, value, rows):
    """(name, number) of every number in a JSON value, named by its path."""
    if isinstance(value, dict):
        for key, item in value.items():
            flat(f"{prefix}.{key}" if prefix else key, item, rows)
    elif isinstance(value, list):
        for i, item in enumerate(value):
            flat(f"{prefix}[{i}]", item, rows)
    elif isinstance(value, (int, float)) and not isinstance(value, bool):
        rows.append((prefix, value))
    return rows


def header(command):
    cpu = next((line.split(":", 1)[1].strip() for line in Path("/proc/cpuinfo").read_text().splitlines()
                if line.startswith("model name")), platform.processor() or "unknown")
    commit = subprocess.run(["git", "-C", str(ROOT), "rev-parse", "HEAD"], capture_output=True, text=True)
    return [f"# measured by: {command}", f"# CPU: {cpu}, {os.cpu_count()} cores, shared with other work",
            f"# load average at the start: {' '.join(Path('/proc/loadavg').read_text().split()[:3])}",
            f"# date: {time.strftime('%Y-%m-%d %H:%M:%S +0000', time.gmtime())}",
            f"# commit: {commit.stdout.strip() if commit.returncode == 0 else 'unknown'}"]


def cell(value):
    text = str(value)
    return f'"{text}"' if any(c in text for c in ',"') else text


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    parser.add_argument("--csv", type=Path, default=ROOT / "doc" / "measurements" / "worlds.csv",
                        help="the CSV to write (default: doc/measurements/worlds.csv)")
    parser.add_argument("--build", type=Path, default=Path(os.environ.get("BUILD_DIR", ROOT / "build")),
                        help="the build folder holding tests/odelab (default: BUILD_DIR, else build/)")
    args = parser.parse_args(argv)
    odelab = args.build / "tests" / "odelab"
    if not os.access(odelab, os.X_OK):
        parser.error(f"no program {odelab}")
    lines = header("/usr/bin/python3 doc/measurements/measure_worlds.py")
    rows = []
    for world in sorted(p.stem for p in WORLDS.glob("*.json")):
        data = json.loads((WORLDS / f"{world}.json").read_text())
        for part in ("settings", "measures", "bodies", "geoms"):
            for name, value in flat(part, data.get(part, []), []):
                rows.append((world, "file", "file", "", "", name, value, "stated by the world file"))
    analytic = {"newtons_cradle": [(k, v, CRADLE_NOTES[k]) for k, v in cradle().items()], "hinged_chain": chain(),
                "incline_slide": incline(), "tumbling_brick": brick(), "projectile": projectile()}
    for world, figures in analytic.items():
        rows += [(world, "analytic", "formula", "", "", name, f"{value:.10g}", note) for name, value, note in figures]
    with tempfile.TemporaryDirectory(prefix="measure-worlds-") as folder:
        for world, engine, setting, options, seconds, edit in RUNS:
            started = time.monotonic()
            metrics = run(odelab, Path(folder), world, engine, setting, options, seconds, edit)
            shown = " ".join((["--engine", engine, "--engine-setting", setting] if engine != "ode" else []) + options)
            note = EDITS.get(edit, "")
            rows += [(world, engine, setting, shown, seconds, name, value, note) for name, value in metrics.items()]
            print(f"measure_worlds: {world} {engine} {setting} {seconds} s: {time.monotonic() - started:.1f} s wall",
                  file=sys.stderr)
            if world == "incline_slide" and engine == "ode" and setting == "file":
                rest = float(metrics["time_to_rest_s"])
                rows.append((world, engine, setting, shown, seconds, "time_to_rest_error_s",
                             f"{rest - incline()[4][1]:.3g}", "derived: time_to_rest_s - (v0 - 0.01) / a"))
            if world == "thin_wall" and engine == "ode":
                step = float(options[1]) if options else 0.001
                depth = float(metrics["penetration_max_m"])
                rows.append((world, engine, setting, shown, seconds, "erp_push_out_speed_m_s",
                             f"{0.2 * depth / step:.4g}", "derived: ERP 0.2 x penetration_max_m / step"))
    lines.append("world,engine,setting,options,seconds,metric,value,note")
    lines += [",".join(cell(c) for c in row) for row in rows]
    # Atomically: a reader never sees half a CSV, and a failed run leaves the old one.
    handle, temporary = tempfile.mkstemp(prefix=f".{args.csv.name}.", dir=args.csv.parent)
    with os.fdopen(handle, "w") as stream:
        stream.write("\n".join(lines) + "\n")
    os.chmod(temporary, 0o644)
    os.replace(temporary, args.csv)
    print(f"measure_worlds: wrote {args.csv} ({len(rows)} rows)", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
