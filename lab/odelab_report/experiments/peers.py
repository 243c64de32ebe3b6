"""Live peers: the thesis's measurement scenes on ODE, Bullet, MuJoCo and,
through their WebAssembly builds in Node.js, Havok, Jolt and Rapier, at the
same steps, each engine at its defaults and at its best (doc/peers.md).

ODE runs its own program (build/tests/testN); the peers run
build/peers/<engine>_lab, found in the folder `peers/` beside the
--build-dir folder (the web peers' are launchers CMake writes where node and
peers/wasm/node_modules are there; without them those three are skipped and
the report says so). Every program writes the same metric names, so one
reading serves every engine. The thesis's Havok figures come from
lab/reference/thesis-figures.csv, quoted, never measured here."""

import json
import re
from pathlib import Path

from .. import markdown as md
from .. import peers_headline
from .. import swing_energy
from .. import timing
from ..plots import peers as plots
from ..header import first_line
from ..peer_compare import BY_CONSTRUCTION, like_surface, ode_friction, peer_friction, standings, surface_text
from ..runner import LabError, RunSpec
from ..search import highest_passing
from .base import Experiment, Outcome
from .limit_test4 import judge as judge_test4
from .limit_test5 import SETTLE as SETTLE_TEST5, SPAWN_INTERVAL as SPAWN_INTERVAL_TEST5, judge as judge_test5
from .thesis import reference_rows

ENGINES = ("ode", "bullet", "mujoco", "havok", "jolt", "rapier")
PEER_PROGRAMS = {"bullet": "bullet_lab", "mujoco": "mujoco_lab", "havok": "havok_lab", "jolt": "jolt_lab",
                 "rapier": "rapier_lab"}
# The web peers and their npm packages (versions read from the lockfile).
WEB_PEERS = {"havok": "@babylonjs/havok", "jolt": "jolt-physics", "rapier": "@dimforge/rapier3d-compat"}
LOCKFILE = Path(__file__).resolve().parents[3] / "peers" / "wasm" / "package-lock.json"
# Below this an error is rounding, not physics: such settings tie, and the
# cheapest wins. The web peers hold their state in float32: there an error
# below 1e-7 is rounding.
ROUNDING = 1e-12
FLOAT32_ROUNDING = 1e-7
COMPARE_STEP = 0.001  # the step of the thesis's figures and of the matrix
# The steps each scene's verdicts compare at: the thesis's step for the
# scene (test3's program runs at 0.005) and the matrix's.
VERDICT_STEPS = {"test3": [0.005, 0.001]}
# Scenes whose figure is an event of the scene as built (a chain that falls
# and sleeps, a stack searched at its run length, a velocity scan): their
# timed runs repeat the figure's run; every other scene's timed runs are
# stretched to last timing.MIN_RUN_CPU_SECONDS.
FIXED_LENGTH = ("test3", "test5", "test10")  # (test10: the scan; the peers have no repeated launches)

# Each engine's settings per scene: (name, program arguments). A peer's
# "default" and "best" are defined in its program (peers/*_lab.cpp, printed
# on its first line); ODE's best is the ODE program's own remedy for the scene.
PEER_SETTINGS = [("default", ["--setting", "default"]), ("best", ["--setting", "best"])]
ODE_SETTINGS = {
    "test1": [("default", [])],  # ERP 0, CFM 0: the thesis's accurate setting
    "test6": [("default", []), ("best", ["--solver", "step"])],
    "test2": [("default", []), ("best", ["--solver", "step"])],
    "test8": [("default", []), ("best", ["--erp", 1.0, "--cfm", 0, "--solver", "step"])],
    "test9": [("default", [])],  # ERP 0.2, CFM 0 is already the exact bounce
    "test4": [("default", []), ("best", ["--solver", "step"])],
    "test10": [("default", []), ("best", ["--ccd"])],
    "test3": [("default", []), ("best", ["--solver", "step"])],
    "test5": [("default", []), ("best", ["--space", "hash"])],  # the thesis's remedy: a hash space
    # No peer caps the angular speed: ODE runs without its cap too.
    "test7": [("default", ["--max-angular-speed", 0]), ("best", ["--max-angular-speed", 0, "--solver", "step"])],
}
ODE_SETTING_TEXT = {
    "test1": "the program's (ERP 0, CFM 0, bounce velocity 0.01 m/s), one setting",
    "test6": "default: the program's (QuickStep 20); best: dWorldStep (its remedy)",
    "test2": "default: the program's (ERP 0.4, CFM 0, QuickStep 20); best: dWorldStep",
    "test8": "default: the program's (ERP 0.4, CFM 1e-4, QuickStep 20); best: ERP 1.0, CFM 0, dWorldStep (the thesis's most rigid hinge)",
    "test9": "default: the program's (ERP 0.2, CFM 0, bounce 1.0), already exact",
    "test4": "default: the program's (ERP 0.2, CFM 1e-6, QuickStep 20); best: dWorldStep",
    "test10": "default: the program's (ERP 0.3, CFM 0, surface layer 0); best: its --ccd sweep",
    "test3": "default: the program's (QuickStep 8, auto-disable on); best: dWorldStep",
    "test5": "default: the program's (QuickStep 20, ERP 0.2, CFM 0, simple space); best: a hash space (the thesis's remedy)",
    "test7": "default: the program's (QuickStep 20) without its angular speed cap, as every peer; best: dWorldStep",
}


class Scene:
    """One measurement scene: what is read, how it is run, which way is better."""

    def __init__(self, name, quantity, metric, label, lower_is_better, quick_steps, full_steps, args, in_quick=True,
                 not_reached="not reached", missing=None, voided_by=None, unranked=None, convert=None):
        self.name, self.quantity, self.metric, self.label = name, quantity, metric, label
        self.not_reached = not_reached  # what an empty value means
        self.missing = missing or {}  # engine -> why it does not run this scene
        self.lower_is_better = lower_is_better
        self.quick_steps, self.full_steps = quick_steps, full_steps
        self.args = args  # quick -> arguments every engine's run of this scene gets
        self.in_quick = in_quick
        # (rule, why): a run the rule picks has no figure: the scene did not happen as built
        self.voided_by = voided_by
        self.unranked = unranked  # why no engine is "best" on this figure; None: ranked
        self.convert = convert  # the metric's value -> the figure, where they differ

    def steps(self, quick, engine="ode"):
        if quick or engine not in WEB_PEERS:
            return self.quick_steps if quick else self.full_steps
        return [step for step in self.full_steps if step in WEB_STEPS[self.name]]


STEPS = [0.01, 0.003, 0.001, 0.0003, 0.0001]
# test6: a small cube sunk deeper than its own side has gone through the ground.
SANK_THROUGH = 1.0
# The web peers cost ten to a hundred times ODE's CPU per simulated second:
# in the full report they run at fewer steps (always the thesis's 0.001).
WEB_STEPS = {"test1": [0.001], "test6": [0.001], "test2": [0.01, 0.001, 0.0001], "test8": [0.01, 0.001],
             "test9": [0.01, 0.001, 0.0001], "test4": [0.001], "test10": [0.01, 0.001], "test7": [0.001],
             "test3": [0.005, 0.001], "test5": [0.001]}
SCENES = [
    Scene("test1", "max_rebound_error", "max_rebound_error",
          "largest |apex2 / apex1 - e^2| over the balls with e >= 0.1", True, [], [0.01, 0.001],
          lambda q: [], in_quick=False, not_reached="no ball bounced twice"),
    # The build is symmetric and no peer has a start tilt: how long it stands
    # is the asymmetry an engine injects, not accuracy (an inverted pendulum in
    # exact arithmetic never falls); remedy-test6 scores ODE against the
    # analytic fall from a tilt.
    Scene("test6", "seconds_upright", "seconds_upright",
          "seconds the 5000 kg cube, built untilted, stays upright on its ball joint (of 60)", False, [], [0.001],
          lambda q: [], in_quick=False, not_reached="fell at once",
          voided_by=(lambda r: (r.m("sink_while_upright_metres") or 0) > SANK_THROUGH,
                     "the pair sank through the ground"),
          unranked="standing longer is not better physics: the untilted build is an inverted pendulum in "
                   "equilibrium, so the time measures the asymmetry each engine injects; no other engine has a "
                   "start tilt to score against the analytic fall (remedy-test6 scores ODE)"),
    # Every engine reports |E - E0| / E0 with the potential's zero on the ground,
    # 7 m below the hinge: given against the swing's energy m g d instead.
    Scene("test2", "energy_swing_error", "energy_max_deviation", "largest energy error |E - E0| / (m g d)", True,
          [0.01, 0.001], STEPS, lambda q: ["--seconds", 5 if q else 20], convert=swing_energy.per_swing),
    Scene("test8", "max_relative_elongation", "max_relative_elongation",
          "largest relative elongation |l - l0| / l0 (5000 kg bob)", True, [], STEPS,
          lambda q: ["--seconds", 20], in_quick=False),
    Scene("test3", "fallen_fraction", "fallen_fraction",
          "fraction of the sixty dominoes fallen in 20 s (1: the chain completes; cost: sleeping on where the engine has it)",
          False, [], [0.005, 0.001], lambda q: [], in_quick=False, not_reached="no domino fell"),
    Scene("test5", "tallest_aligned_plates", None,
          "tallest aligned stack of plates still stepped in real time (limit-test5's search and rule)", False,
          [], [0.001], lambda q: [], in_quick=False, not_reached="not even 5 plates"),
    Scene("test7", "max_joint_error", "max_joint_error",
          "largest ball-joint error (m), hanging pair hit 3 times at 30 m/s, no angular speed cap", True,
          [0.001], STEPS, lambda q: [],
          voided_by=(lambda r: bool(r.m("cube_passed_pivot")), "the test cube passed through the pivot")),
    Scene("test9", "apex_error_20", "apex_error_20", "apex error after 20 bounces", True,
          [0.01, 0.001], STEPS, lambda q: ["--seconds", 21], not_reached="fewer than 20 bounces"),
    Scene("test4", "heaviest_held_kg", None, "heaviest big cube held on the 5 kg cube (kg)", False,
          [], [0.001, 0.0005], lambda q: ["--seconds", 20], in_quick=False, not_reached="not even 50 kg"),
    Scene("test10", "max_velocity_stopped", "max_velocity", "highest velocity with every launch stopped (m/s)", False,
          [0.001], [0.01, 0.001, 0.0001], lambda q: ["--find-max-velocity"]),
]
# Scenes no peer program builds yet, though every engine here has the parts.
NOT_BUILT = {}
ODE_ONLY_ARGS = {  # what only the ODE program needs: no output file rows; test10's scan stops at its first failure
    "test2": ["--sample-interval", 3600], "test8": ["--sample-interval", 3600], "test10": ["--band-factor", 1.0]}


def rounding_of(engine):
    return FLOAT32_ROUNDING if engine in WEB_PEERS else ROUNDING


def web_versions():
    """{engine: "package version"} from peers/wasm/package-lock.json."""
    try:
        packages = json.loads(LOCKFILE.read_text())["packages"]
    except (OSError, ValueError, KeyError):
        return {}
    return {e: f"`{p}` {packages.get('node_modules/' + p, {}).get('version', '?')}" for e, p in WEB_PEERS.items()}


def native_version(peers_dir, engine):
    """"Bullet 3.24": the engine and the version of the library its peer
    program links, as `<engine>_lab --version` prints them."""
    line = first_line([str(peers_dir / PEER_PROGRAMS[engine]), "--version"])
    words = (line or "").split()
    name = {"bullet": "Bullet", "mujoco": "MuJoCo"}[engine]
    return f"{name} {words[1] if len(words) == 2 and words[0] == engine else '(version unknown)'}"


def program_of(engine, scene):
    return scene.name if engine == "ode" else "../peers/" + PEER_PROGRAMS[engine]


def settings_of(engine, scene):
    return ODE_SETTINGS[scene.name] if engine == "ode" else PEER_SETTINGS


def base_args(engine, scene, quick):
    own = ODE_ONLY_ARGS.get(scene.name, []) if engine == "ode" else ["--scene", scene.name]
    return [*own, *scene.args(quick)]


def first_line_of(r):
    """The settings line a peer program prints first ("" for no run)."""
    return (r.stdout.splitlines() or [""])[0] if r is not None else ""


def timed_args(runner, scene, r, minimum):
    """The arguments of a cell's timed runs: its figure run's, stretched to
    last `minimum` CPU seconds (timing.stretched) unless the scene's
    length is its figure (FIXED_LENGTH)."""
    if scene.name in FIXED_LENGTH:
        return list(r.spec.args)
    return timing.stretched(runner, r.spec.program, r.spec.args, minimum)


def costs(results):
    """A cell's cost columns from its timed runs (those that ended with status 0)."""
    ok = [r for r in results if r.rc == 0 and r.m("sim_seconds")]
    cpu = timing.spread([per_sim_second(r, r.cpu_seconds) for r in ok])
    wall = timing.spread([per_sim_second(r, r.m("wall_seconds")) for r in ok])
    return dict(timed_sim_seconds=ok[0].m("sim_seconds") if ok else None, repeats=len(ok),
                shortest_run_cpu_seconds=min((r.cpu_seconds for r in ok), default=None),
                cpu_s_per_sim_s=cpu[0], cpu_s_per_sim_s_min=cpu[1], cpu_s_per_sim_s_max=cpu[2],
                wall_s_per_sim_s=wall[0], wall_s_per_sim_s_min=wall[1], wall_s_per_sim_s_max=wall[2])


def cost_text(row):
    """"0.031 [0.030-0.033]": a cell's CPU seconds per simulated second, median [range]."""
    if row.get("cpu_s_per_sim_s") is None:
        return "not timed"
    return (f"{md.num(row['cpu_s_per_sim_s'], 2)} [{md.num(row['cpu_s_per_sim_s_min'], 2)}-"
            f"{md.num(row['cpu_s_per_sim_s_max'], 2)}]")


def as_standing(row):
    """A peers row as peer_compare.standings reads it."""
    return dict(row, cpu_median=row["cpu_s_per_sim_s"], cpu_min=row["cpu_s_per_sim_s_min"],
                cpu_max=row["cpu_s_per_sim_s_max"])


def per_sim_second(r, seconds):
    sim = r.m("sim_seconds")
    return seconds / sim if seconds is not None and sim else None


def havok_quote(scene_name):
    """(text, number or None, conditions) of the thesis's quoted Havok figure for a scene."""
    for row in reference_rows():
        if row["test"] == scene_name and row["havok_6_5_quoted_by_thesis"]:
            text = row["havok_6_5_quoted_by_thesis"]
            found = re.search(r"([\d.]+)\s*(%|kg|m/s)", text)
            number = None
            if found:
                number = float(found.group(1)) / (100 if found.group(2) == "%" else 1)
            return text, number, row["conditions"]
    return None, None, None


def thesis_ode(scene_name):
    rows = [r for r in reference_rows() if r["test"] == scene_name]
    return "; ".join(f"{r['ode_0_11_1_thesis']} ({r['conditions']})" for r in rows)


class Peers(Experiment):
    name = "peers"
    title = "ODE, Bullet, MuJoCo, Havok, Jolt and Rapier on the same scenes"
    section = 5
    programs = tuple(scene.name for scene in SCENES)
    cost = (1200.0, 40.0)

    def run(self, ctx):
        peers_dir = ctx.runner.build_dir.parent / "peers"
        missing = [p for e, p in PEER_PROGRAMS.items() if e not in WEB_PEERS and not (peers_dir / p).exists()]
        if missing:
            raise LabError(f"no {', '.join(missing)} in {peers_dir}: the peers are built with the rest "
                           "(`cmake --build build`, needs libbullet-dev and libmujoco-dev); the lab looks for "
                           "them in peers/ beside the --build-dir folder")
        skipped = [e for e in WEB_PEERS if not (peers_dir / PEER_PROGRAMS[e]).exists()]
        engines = [e for e in ENGINES if e not in skipped]
        scenes = [s for s in SCENES if s.in_quick or not ctx.quick]
        plan = [(scene, engine, setting, args, step) for scene in scenes for engine in engines
                if engine not in scene.missing
                for setting, args in settings_of(engine, scene) for step in scene.steps(ctx.quick, engine)]
        ctx.expect(len(plan) * (1 + timing.repeats(ctx.quick)))

        def one(point):
            scene, engine, setting, args, step = point
            search = {"test4": self.heaviest, "test5": self.tallest}.get(scene.name, self.measure)
            value, r = search(ctx, scene, engine, args, step)
            ctx.advance()
            voided = bool(r) and scene.voided_by is not None and scene.voided_by[0](r)
            if voided:
                value = None
            friction = ode_friction(scene.name) if engine == "ode" else peer_friction(first_line_of(r))
            return dict(voided=voided, scene=scene.name, engine=engine, setting=setting, step=step,
                        quantity=scene.quantity, value=value, friction=friction,
                        like_ode_surface=int(like_surface(scene.name, friction)),
                        by_construction=BY_CONSTRUCTION.get((engine, scene.name), ""),
                        capped=bool(r) and scene.name == "test10" and r.m("first_failure_velocity") == 0,
                        exit_status=r.rc if r else None), r

        measured = ctx.runner.parallel([lambda p=p: one(p) for p in plan])
        rows = [row for row, _ in measured]
        self.time_cells(ctx, plan, measured)
        columns = ["scene", "engine", "setting", "step", "quantity", "value", "friction", "like_ode_surface",
                   "by_construction", "timed_sim_seconds", "repeats", "shortest_run_cpu_seconds",
                   "cpu_s_per_sim_s", "cpu_s_per_sim_s_min", "cpu_s_per_sim_s_max",
                   "wall_s_per_sim_s", "wall_s_per_sim_s_min", "wall_s_per_sim_s_max", "capped"]
        csv = ctx.write_csv("peers", columns, rows, notes=[
            "engines at the same step; settings: doc/peers.md; value: the quantity named (empty: not reached, "
            "e.g. no 20th bounce), from one run of the scene's length",
            "friction: the coefficient the run used (ODE's from its scene, a peer's from the settings line it "
            "prints; 'engine default' where it sets none); like_ode_surface: 1 where it stands on ODE's surface "
            "(friction 100 is the peers' never-sliding contact, ODE's infinite) or friction does not act; "
            "by_construction: why the figure cannot be wrong on that engine (it takes no part in a comparison)",
            f"costs: the median, min and max over `repeats` interleaved timed runs of timed_sim_seconds each (at "
            f"least {timing.min_run_cpu(ctx.quick):g} CPU s where the scene can be lengthened; "
            f"{', '.join(FIXED_LENGTH)} and test4's search repeat the figure's own run or mass); "
            "wall_s_per_sim_s: the program's own run-loop wall_seconds / sim_seconds; cpu_s_per_sim_s: the "
            "process's user + system time (start-up included) / sim_seconds",
            "max_velocity_stopped: the ODE program's and the peers' max_velocity metric (test10's scan, stopped at "
            "the first failure); heaviest_held_kg: the search of limit-test4 on each engine",
            "capped: 1 when test10's scan reached its limit with no launch through (the figure is the scan's limit)",
            "energy_swing_error (test2): each engine's energy_max_deviation, |E - E0| / E0, times E0 / (m g d); "
            + swing_energy.header()])
        parts, headline, claims = [], [], {}
        for scene in scenes:
            mine = [r for r in rows if r["scene"] == scene.name]
            text, line, said = self.scene_part(ctx, scene, mine)
            parts.append(text)
            headline += line
            claims.update(said)
        versions = web_versions()
        web = [f"{e.capitalize()} ({versions.get(e, WEB_PEERS[e])})" for e in WEB_PEERS if e not in skipped]
        web_text = (f"""Havok, Jolt and Rapier run through their WebAssembly builds in Node.js
({", ".join(web)}; `peers/wasm`). This Havok is today's Havok for the web, not
the Havok 6.5 whose figures the thesis quotes; the three hold their state in
float32, so an error below {FLOAT32_ROUNDING:g} is rounding, not physics.""" if web else "")
        if skipped:
            web_text += (f"\n\n**Skipped: {', '.join(skipped)}** (no {', '.join(PEER_PROGRAMS[e] for e in skipped)} "
                         f"in {peers_dir}: install Node.js, run `npm ci` in peers/wasm and configure again).")
        not_built = ("\n\nNot yet on any peer (the peer programs do not build these scenes; every engine here has "
                     f"the parts): {'; '.join(f'{k}, {v}' for k, v in NOT_BUILT.items())}." if NOT_BUILT else "")
        intro = f"""Each scene runs on ODE (its own program), {native_version(peers_dir, "bullet")} and
{native_version(peers_dir, "mujoco")} (the
programs in `peers/`, doc/peers.md) with the same geometry, masses, gravity,
step and run length, and each engine at its defaults and at its best for the
scene. Cost is wall (and CPU) seconds per simulated second on this machine.
{web_text}
The column "Havok 6.5 (thesis)" is quoted from the thesis, not measured. ODE's settings:
{"; ".join(f"{k}: {v}" for k, v in ODE_SETTING_TEXT.items() if any(s.name == k for s in scenes))}.

{md.files_line([csv])}

{self.matrix(scenes, engines, rows)}{not_built}"""
        return Outcome(intro + "\n\n" + "\n\n".join(parts), headline, claims=claims)

    # ---- the matrix: scene by engine, at COMPARE_STEP ----------------------------------
    def matrix(self, scenes, engines, rows):
        columns = [(e, s) for e in engines for s in ("default", "best")]
        header = ["scene"]
        for e, s in columns:
            header.append(f"{e} {s}")
            if (e, s) == ("havok", "best"):
                header.append("Havok 6.5 (thesis)")
        if "havok" not in engines:
            header.append("Havok 6.5 (thesis)")
        figures, costs = [], []
        for scene in scenes:
            figure_row, cost_row = [scene.name], [scene.name]
            for e, s in columns:
                found = [r for r in rows if r["scene"] == scene.name and r["engine"] == e and r["setting"] == s
                         and r["step"] == COMPARE_STEP]
                figure_row.append(self.value_text(scene, found[0]) if found
                                  else "cannot run it (below)" if e in scene.missing else "(one setting)")
                cost_row.append(cost_text(found[0]) if found else "-")
                if (e, s) == ("havok", "best") or (e, s) == columns[-1] and "havok" not in engines:
                    figure_row.append(havok_quote(scene.name)[0] or "-")
                    cost_row.append("-")
            figures.append(figure_row)
            costs.append(cost_row)
        quantities = "; ".join(f"{s.name}: {s.label}" for s in scenes)
        return f"""#### The matrix at step {COMPARE_STEP} s

The figure each engine reaches ({quantities}):

{md.table(header, figures)}

Its cost, CPU seconds per simulated second, the median [min-max] of the timed runs (the whole process, start-up
included; peers.csv has the program's own wall times too):

{md.table(header, costs)}"""

    # ---- the cells' timings ------------------------------------------------------------
    def time_cells(self, ctx, plan, measured):
        """timing.repeats timed runs of every cell that ran, interleaved (every
        cell's first, then every cell's second...: a busy spell of the machine
        falls on many cells, not on the repeats of one); their costs into the rows."""
        ran = [(point, row, r) for point, (row, r) in zip(plan, measured) if r is not None and r.rc == 0]
        minimum = timing.min_run_cpu(ctx.quick)
        lengths = ctx.runner.parallel([lambda p=p, r=r: timed_args(ctx.runner, p[0], r, minimum) for p, _, r in ran])
        cells = [(point, row, args) for (point, row, _), args in zip(ran, lengths)]
        done = {id(row): [] for _, row, _ in cells}
        for repeat in range(timing.repeats(ctx.quick)):
            specs = [RunSpec(program_of(point[1], point[0]), args, timed=True, repeat=repeat,
                             measures_blow_ups=True) for point, _, args in cells]
            for (_, row, _), result in zip(cells, ctx.runner.map(specs)):
                done[id(row)].append(result)
            ctx.advance(len(cells))
        ctx.advance((len(plan) - len(cells)) * timing.repeats(ctx.quick))
        for row, _ in measured:
            row.update(costs(done.get(id(row), [])))

    # ---- one point ---------------------------------------------------------------
    def measure(self, ctx, scene, engine, args, step):
        r = ctx.runner.run(RunSpec(program_of(engine, scene),
                                   [*base_args(engine, scene, ctx.quick), *args, "--step", step],
                                   measures_blow_ups=True))
        value = r.m(scene.metric) if r.rc == 0 else None
        return (scene.convert(value) if scene.convert and value is not None else value), r

    def heaviest(self, ctx, scene, engine, args, step):
        """limit-test4's search and failure rule on any engine: (heaviest held kg, its run)."""
        def probe(mass):
            r = ctx.runner.run(RunSpec(program_of(engine, scene),
                                       [*base_args(engine, scene, ctx.quick), *args, "--big-mass", mass,
                                        "--step", step], priority=0, measures_blow_ups=True))
            passed, reason = judge_test4(r)
            return passed, r

        result = highest_passing(probe, start=5000.0, factor=4.0, ratio=1.1, low=50.0, high=1e9)
        held = next((info for value, passed, info in result.probes if value == result.highest_pass), None)
        return result.highest_pass, held

    def tallest(self, ctx, scene, engine, args, step):
        """limit-test5's search and rule on any engine: (tallest aligned stack in real time, its run)."""
        def probe(plates):
            extra = ["--plates", plates, "--spawn-interval", SPAWN_INTERVAL_TEST5,
                     "--seconds", round(plates * SPAWN_INTERVAL_TEST5 + SETTLE_TEST5, 3)]
            r = ctx.runner.run(RunSpec(program_of(engine, scene),
                                       [*base_args(engine, scene, ctx.quick), *args, *extra, "--step", step],
                                       timed=True, timeout=900, priority=0, measures_blow_ups=True))
            passed, reason = judge_test5(r, plates, step)
            return passed, r

        result = highest_passing(probe, start=40, factor=1.5, ratio=1.2, low=5, high=600, integer=True)
        held = next((info for value, passed, info in result.probes if value == result.highest_pass), None)
        return result.highest_pass, held

    # ---- one scene's part of the report ----------------------------------------------
    def scene_part(self, ctx, scene, rows):
        havok_text, havok_number, havok_conditions = havok_quote(scene.name)
        ctx.register_files(plots.peers_speed_accuracy(ctx.out_dir, f"peers-{scene.name}", rows, scene.label,
                                                      scene.lower_is_better, havok_number, ROUNDING))
        table = [[r["engine"], r["setting"], md.num(r["step"]), self.value_text(scene, r),
                  surface_text(scene.name, r["friction"]) + ("" if r["like_ode_surface"] else " (not ODE's)"),
                  cost_text(r), md.num(r["repeats"])] for r in rows]
        verdicts, headline = [], []
        if scene.unranked:
            # No engine is "best" on a figure that is not better physics (Scene.unranked says why).
            verdicts.append(f"Not ranked: {scene.unranked}.")
        else:
            for step in VERDICT_STEPS.get(scene.name, [COMPARE_STEP]):
                for kind in ("default", "best"):
                    verdicts.append(self.verdict(scene, rows, step, kind))
            # The headline is a claim on peers.csv (peers_headline.py), the
            # sections' first sentence recomputed by check_report.py.
            rounding = (tuple(WEB_PEERS), ROUNDING, FLOAT32_ROUNDING)
            headline = [peers_headline.headline(scene.name, scene.label, scene.lower_is_better,
                                                VERDICT_STEPS.get(scene.name, [COMPARE_STEP])[0], *rounding)]
        havok = (f"Havok 6.5, quoted by the thesis ({havok_conditions}): **{havok_text}**."
                 if havok_text else "The thesis quotes no Havok figure for this scene.")
        missing = "".join(f" Not run on {e}: {why}." for e, why in scene.missing.items())
        text = f"""#### {scene.name}: {scene.label}

{" ".join(verdicts)} {havok}{missing} The thesis's ODE 0.11.1: {thesis_ode(scene.name) or "-"}.

{md.table(["engine", "setting", "step (s)", scene.quantity, "surface", "CPU s / sim s, median [range]", "timed runs"],
          table)}

{md.figure(f"peers-{scene.name}", f"{scene.name}: {scene.label} against CPU seconds per simulated second, "
           "one curve per engine and setting (steps large to small), bars the range of the timed runs" +
           (", Havok's quoted figure as a line" if havok_number is not None else ""))}"""
        return text, headline, {}

    def verdict(self, scene, rows, step, kind):
        """One sentence: who is best at `step` among the engines' `kind`
        settings (defaults with defaults, best with best; ODE's one setting
        counts as both), like with like (peer_compare.standings)."""
        mine = [r for r in rows if r["step"] == step and (
            r["setting"] == kind or r["engine"] == "ode" and len(ODE_SETTINGS[scene.name]) == 1)]
        winners, excluded = standings([as_standing(r) for r in mine], scene.lower_is_better,
                                      lambda r: rounding_of(r["engine"]))
        where = f"At step {md.num(step)}, {'defaults' if kind == 'default' else 'each engine at its best'}"
        left = "".join(f" Not compared: {r['engine']} ({why})." for r, why in excluded)
        if not winners:
            return f"{where}: no engine that compares reached a figure.{left}"
        first = winners[0]
        how = "exact to rounding" if self.exact(scene, first) else "best"
        figure = self.value_text(scene, first)
        if len(winners) == 1:
            text = (f"{where}: {first['engine']} ({first['setting']}) is {how} with {figure} at "
                    f"{cost_text(first)} CPU s per simulated s")
        else:
            names = ", ".join(f"{r['engine']} ({r['setting']}, {cost_text(r)})" for r in winners)
            text = (f"{where}: a tie within the timing's scatter at {figure}: {names} CPU s per simulated s")
        return text + "." + left

    @staticmethod
    def exact(scene, r):
        return scene.lower_is_better and r["value"] is not None and r["value"] < rounding_of(r["engine"])

    def value_text(self, scene, r):
        if r.get("voided"):
            return scene.voided_by[1]
        if r["value"] is None:
            return scene.not_reached if r["exit_status"] in (0, None) else f"blew up (exit {r['exit_status']})"
        text = md.num(r["value"], 3)
        if r.get("by_construction"):
            return f"{text}: {r['by_construction']}"
        return text + " (scan limit)" if r.get("capped") else text
