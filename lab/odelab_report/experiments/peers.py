"""Live peers: the thesis's measurement scenes on ODE, Bullet, MuJoCo and,
through their WebAssembly builds in Node.js, Havok, Jolt, Rapier and PhysX, at the
same steps, each engine at its defaults and at its best (doc/peers.md).

Every engine runs the scene's own program: `build/tests/testN --engine E
--engine-setting default|best` describes the scene's ODE world as data,
the engine's adapter (peers/engines/) builds and steps it, and the scene's
own code measures it, so every engine writes the scene's own metric names
on the scene's own world (its surface, masses, step and length). ODE runs
the program as it is, at ODE_SETTINGS. Which engines this build has, and
their versions, come from `testN --list-engines`; one not available is
skipped and the report says why. What an adapter could not express exactly
it lists in its run's `translation_notes`: they go beside the figures and
into peers-notes.csv. The thesis's Havok figures come from
lab/reference/thesis-figures.csv, quoted, never measured here."""

import re

from .. import markdown as md
from .. import peers_headline
from .. import peers_notes
from .. import swing_energy
from .. import timing
from ..costs import columns as cost_columns
from ..plots import peers as plots
from ..peer_compare import by_construction, default_surface, mu_text, standings, surface_short, \
    surface_words
from ..runner import RunSpec
from ..search import highest_passing
from .base import Experiment, Outcome
from .limit_test4 import judge as judge_test4
from .limit_test5 import SETTLE as SETTLE_TEST5, SPAWN_INTERVAL as SPAWN_INTERVAL_TEST5, engine_step_cost, \
    judge as judge_test5
from .thesis import reference_rows

ENGINES = ("ode", "bullet", "mujoco", "havok", "jolt", "rapier", "physx")
# The engines that run through Node.js (WebAssembly): ten to a hundred times
# ODE's cost, so fewer steps in the full report (WEB_STEPS).
NODE_ENGINES = ("havok", "jolt", "rapier", "physx")
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

# Each engine's settings per scene: (name, program arguments). Another
# engine's "default" and "best" are its adapter's (peers/engines/; `testN
# --list-engines` prints what best sets); ODE's best is the ODE program's own
# remedy for the scene.
ENGINE_SETTINGS = ("default", "best")
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
    # (test7 runs without its angular speed cap on every engine: RUN_ARGS.)
    "test7": [("default", []), ("best", ["--solver", "step"])],
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
    "test7": "default: the program's (QuickStep 20) without its angular speed cap, as every engine; best: dWorldStep",
}


PHASE_LAUNCHES = (2, 5)  # test10: launches per velocity at random phases (quick, full)


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
        if quick or engine not in NODE_ENGINES:
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
SPEED_CAP_VOIDS = "the engine's speed cap slowed the cubes before the wall: no wall limit measured"


def scan_ended_at_speed_cap(r):
    """An engine's speed cap (Havok's 200 m/s at its defaults) slows a cube
    before the wall: test10's scan then ends there (first_slowed_velocity),
    and a scan that ended so with every launch stopped measured the cap, not
    the wall."""
    return bool(r.m("first_slowed_velocity")) and not r.m("first_failure_velocity")


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
          "tallest aligned stack of plates whose engine's own collision and step calls keep up with real time "
          "(limit-test5's search and rule, the one cost for every engine: the engine's own calls' ms per step over "
          "the last second at most the step; the link and a Node.js engine's process not counted)", False,
          [], [0.001], lambda q: [], in_quick=False, not_reached="not even 5 plates"),
    Scene("test7", "max_joint_error", "max_joint_error",
          "largest ball-joint error (m), hanging pair hit 3 times at 30 m/s, no angular speed cap", True,
          [0.001], STEPS, lambda q: [],
          voided_by=(lambda r: bool(r.m("cube_passed_pivot")), "the test cube passed through the pivot")),
    Scene("test9", "apex_error_20", "apex_error_20", "apex error after 20 bounces", True,
          [0.01, 0.001], STEPS, lambda q: ["--seconds", 21], not_reached="fewer than 20 bounces"),
    Scene("test4", "heaviest_held_kg", None, "heaviest big cube held on the 5 kg cube (kg)", False,
          [], [0.001, 0.0005], lambda q: ["--seconds", 20], in_quick=False, not_reached="not even 50 kg"),
    # One launch phase decides a limit by luck (ODE: 250 m/s at the fixed
    # launch point, 227 m/s over random phases at step 0.001): every engine's
    # limit is a scan over random phases of the step, the same launches each.
    Scene("test10", "max_velocity_stopped", "max_velocity",
          "highest velocity with every launch stopped (m/s), each velocity launched at random phases of the step "
          f"({PHASE_LAUNCHES[1]} launches; --quick: {PHASE_LAUNCHES[0]})", False,
          [0.001], [0.01, 0.001, 0.0001],
          lambda q: ["--find-max-velocity", "--phase-jitter", "--launches", PHASE_LAUNCHES[0 if q else 1]],
          voided_by=(scan_ended_at_speed_cap, SPEED_CAP_VOIDS)),
]
# Arguments every engine's run of a scene gets (the same program for all):
# no output file rows; test10's scan stops at its first failure; test7 without
# the angular speed cap, which Bullet, MuJoCo and Rapier do not have.
RUN_ARGS = {"test2": ["--sample-interval", 3600], "test8": ["--sample-interval", 3600],
            "test10": ["--band-factor", 1.0], "test7": ["--max-angular-speed", 0]}


def rounding_of(engine, float32=NODE_ENGINES):
    """Below this an error of `engine` is rounding (`float32`: the engines
    whose --list-engines precision is float32)."""
    return FLOAT32_ROUNDING if engine in float32 else ROUNDING


def list_engines(text):
    """`testN --list-engines`, parsed: {name: dict(available, version,
    precision, missing, best)} in the order printed. A line "name:
    available|not available[, version X][, precision]" opens an engine; its
    indented "missing: ..." and "best settings: ..." lines follow."""
    engines, current = {}, None
    for line in text.splitlines():
        found = re.match(r"^([A-Za-z0-9_]+):\s*(available|not available)\s*(?:,(.*))?$", line)
        if found:
            current = dict(available=found.group(2) == "available", version="", precision="", missing="", best="")
            for part in (found.group(3) or "").split(","):
                part = part.strip()
                if part.startswith("version "):
                    current["version"] = part[len("version "):].strip()
                elif part:
                    current["precision"] = part
            engines[found.group(1)] = current
            continue
        detail = re.match(r"^\s+(missing|best settings):\s*(.*)$", line)
        if detail and current is not None:
            current["missing" if detail.group(1) == "missing" else "best"] = detail.group(2).strip()
    return engines


def available_engines(listed):
    """From {scene: list_engines(...)}: ({engine: its entry, where some
    scene's program has it available}, {engine: why it is skipped (its
    "missing:" line), where none has it}), engines in ENGINES' order."""
    infos, skipped = {}, {}
    for engines in listed.values():
        for engine in ENGINES:
            info = engines.get(engine)
            if info and info["available"]:
                infos.setdefault(engine, info)
            else:
                skipped.setdefault(engine, info["missing"] if info and info["missing"] else
                                   "not listed by the program's --list-engines" if not info else "no reason given")
    return infos, {e: why for e, why in skipped.items() if e not in infos}


def engine_name(engine, info=None):
    """"Bullet 3.24": the engine and its version as --list-engines gives it."""
    name = {"ode": "ODE", "mujoco": "MuJoCo", "physx": "PhysX"}.get(engine, engine.capitalize())
    version = (info or {}).get("version")
    return f"{name} {version}" if version else name


def program_of(engine, scene):
    """Every engine runs the scene's own program (build/tests/testN)."""
    return scene.name


def settings_of(engine, scene):
    """(name, arguments) of each setting `engine` runs `scene` at: ODE's own
    per scene (ODE_SETTINGS); another engine's adapter's default and best."""
    if engine == "ode":
        return ODE_SETTINGS[scene.name]
    return [(s, ["--engine", engine, "--engine-setting", s]) for s in ENGINE_SETTINGS]


def base_args(engine, scene, quick):
    """The arguments every engine's run of `scene` gets (RUN_ARGS, the scene's length)."""
    return [*RUN_ARGS.get(scene.name, []), *scene.args(quick)]


def timed_args(runner, scene, r, minimum):
    """The arguments of a cell's timed runs: its figure run's, stretched to
    last `minimum` CPU seconds (timing.stretched) unless the scene's
    length is its figure (FIXED_LENGTH)."""
    if scene.name in FIXED_LENGTH:
        return list(r.spec.args)
    return timing.stretched(runner, r.spec.program, r.spec.args, minimum)


def costs(results):
    """A cell's cost columns from its timed runs (those that ended with
    status 0), each per simulated second under its one definition
    (costs.py): the engine's own calls (engine_s_per_sim_s, the primary
    cost), the link outside them and the whole run's CPU beside it, and the
    program's run-loop wall time."""
    ok = [r for r in results if r.rc == 0 and r.m("sim_seconds")]
    wall = timing.spread([per_sim_second(r, r.m("wall_seconds")) for r in ok])
    return dict(timed_sim_seconds=ok[0].m("sim_seconds") if ok else None, repeats=len(ok),
                shortest_run_cpu_seconds=min((r.cpu_seconds for r in ok), default=None),
                **cost_columns(ok),
                wall_s_per_sim_s=wall[0], wall_s_per_sim_s_min=wall[1], wall_s_per_sim_s_max=wall[2])


def cost_text(row, column="engine_s_per_sim_s"):
    """"0.031 [0.030-0.033]": a cell's cost, median [range] of its timed
    runs: engine seconds per simulated second (default) or `column`'s."""
    if row.get(column) is None:
        return "not timed"
    return f"{md.num(row[column], 2)} [{md.num(row[column + '_min'], 2)}-{md.num(row[column + '_max'], 2)}]"


def as_standing(row):
    """A peers row as peer_compare.standings reads it: its cost is the
    engine's own seconds per simulated second."""
    return dict(row, cost_median=row.get("engine_s_per_sim_s"), cost_min=row.get("engine_s_per_sim_s_min"),
                cost_max=row.get("engine_s_per_sim_s_max"))


def notes_said(row):
    """A row's translation notes in its table cell: how many (the scene's
    part lists them), or "-"."""
    count = row.get("translation_note_count") or 0
    return f"{count} (below)" if count else "-"


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
    title = "ODE, Bullet, MuJoCo, Havok, Jolt, Rapier and PhysX on the same scenes"
    section = 5
    programs = tuple(scene.name for scene in SCENES)
    cost = (1200.0, 40.0)
    float32 = NODE_ENGINES  # the engines whose state is float32 (run() reads them from --list-engines)

    def run(self, ctx):
        scenes = [s for s in SCENES if s.in_quick or not ctx.quick]
        # Which engines each scene's program has (--list-engines), and the world it builds (--export-world).
        listed = {scene.name: list_engines(ctx.runner.ask(scene.name, ["--list-engines"])) for scene in scenes}
        worlds = {scene.name: ctx.runner.export_world(scene.name) for scene in scenes}
        infos, skipped = available_engines(listed)
        engines = [e for e in ENGINES if e in infos]
        self.float32 = tuple(e for e in engines if "float32" in infos[e]["precision"])

        def runs_here(scene, engine):
            info = listed[scene.name].get(engine)
            return engine not in scene.missing and bool(info and info["available"])

        plan = [(scene, engine, setting, args, step) for scene in scenes for engine in engines
                if runs_here(scene, engine)
                for setting, args in settings_of(engine, scene) for step in scene.steps(ctx.quick, engine)]
        ctx.expect(len(plan) * (1 + timing.repeats(ctx.quick)))

        def one(point):
            scene, engine, setting, args, step = point
            search = {"test4": self.heaviest, "test5": self.tallest}.get(scene.name, self.measure)
            value, r, seen = search(ctx, scene, engine, args, step)
            ctx.advance()
            voided = bool(r) and scene.voided_by is not None and scene.voided_by[0](r)
            if voided:
                value = None
            notes = peers_notes.notes_of(seen)
            world = worlds[scene.name]
            return dict(voided=voided, scene=scene.name, engine=engine, setting=setting, step=step,
                        quantity=scene.quantity, value=value, surface=surface_words(world),
                        mu=mu_text(default_surface(world)), like_ode_surface=1,
                        by_construction=by_construction(engine, scene.name, notes),
                        translation_note_count=len(notes), notes=notes,
                        capped=bool(r) and scene.name == "test10" and r.m("first_failure_velocity") == 0,
                        exit_status=r.rc if r else None), r

        measured = ctx.runner.parallel([lambda p=p: one(p) for p in plan])
        rows = [row for row, _ in measured]
        self.time_cells(ctx, plan, measured)
        columns = ["scene", "engine", "setting", "step", "quantity", "value", "surface", "mu", "like_ode_surface",
                   "by_construction", "translation_note_count", "timed_sim_seconds", "repeats",
                   "shortest_run_cpu_seconds", "engine_s_per_sim_s", "engine_s_per_sim_s_min",
                   "engine_s_per_sim_s_max", "link_s_per_sim_s", "link_s_per_sim_s_min", "link_s_per_sim_s_max",
                   "cpu_s_per_sim_s", "cpu_s_per_sim_s_min", "cpu_s_per_sim_s_max",
                   "wall_s_per_sim_s", "wall_s_per_sim_s_min", "wall_s_per_sim_s_max", "capped"]
        csv = ctx.write_csv("peers", columns, rows, notes=[
            "every engine runs the scene's own program (build/tests/testN --engine E --engine-setting default|best; "
            "ODE: the program itself) on the scene's own world, at the same step; settings: doc/peers.md; value: "
            "the quantity named (empty: not reached, e.g. no 20th bounce), from one run of the scene's length",
            "surface: the scene's world's surface (testN --export-world: its default surface, and how many pairs "
            "of geoms have their own), the same for every engine by construction; mu: its friction; "
            "like_ode_surface: 1 (every engine builds the scene's world; what it could not express exactly is in "
            "translation_note_count and peers-notes.csv); by_construction: why the figure cannot be wrong on that "
            "engine (it takes no part in a comparison)",
            f"costs: the median, min and max over `repeats` interleaved timed runs of timed_sim_seconds each (at "
            f"least {timing.min_run_cpu(ctx.quick):g} CPU s where the scene can be lengthened; "
            f"{', '.join(FIXED_LENGTH)} and test4's search repeat the figure's own run or mass); "
            "engine_s_per_sim_s (the cost compared): the engine's own collision and step calls, "
            "engine_wall_seconds / sim_seconds (ODE: its dSpaceCollide and dWorldQuickStep or dWorldStep; the "
            "others: their adapter's step, not the pipe to Node.js nor the scene's measurement); "
            "link_s_per_sim_s: the link outside the engine's own calls (link_wall_seconds: translation, the pipe "
            "to Node.js, the state copy; 0 for ODE) / sim_seconds; "
            "cpu_s_per_sim_s: the whole run's user + system time (start-up, the scene's measurement and the "
            "Node.js engine's process, which the program waits for) / sim_seconds; these three are never "
            "compared with one another (lab/odelab_report/costs.py); "
            "wall_s_per_sim_s: the program's own run-loop wall_seconds / sim_seconds",
            "max_velocity_stopped: the program's max_velocity metric on each engine (test10's scan, stopped at "
            "the first failure); heaviest_held_kg: the search of limit-test4 on each engine",
            "capped: 1 when test10's scan reached its limit with no launch through (the figure is the scan's limit)",
            "energy_swing_error (test2): each engine's energy_max_deviation, |E - E0| / E0, times E0 / (m g d); "
            + swing_energy.header()])
        note_rows = peers_notes.rows_of((r["scene"], r["engine"], r["setting"], r["notes"]) for r in rows)
        notes_csv = ctx.write_csv(peers_notes.NOTES_CSV[:-len(".csv")], peers_notes.COLUMNS, note_rows, notes=[
            "what each engine's adapter could not express exactly of the scene's world: the translation_notes "
            "of its runs (each note once per scene, engine and setting); doc/peers.md's generated block lists them"])
        parts, headline, claims = [], [], {}
        for scene in scenes:
            mine = [r for r in rows if r["scene"] == scene.name]
            text, line, said = self.scene_part(ctx, scene, mine, worlds[scene.name], note_rows)
            parts.append(text)
            headline += line
            claims.update(said)
        named = ", ".join(f"{engine_name(e, infos[e])} ({infos[e]['precision'] or 'precision not said'})"
                          for e in engines)
        web = [e for e in NODE_ENGINES if e in engines]
        web_text = (f"""{", ".join(engine_name(e) for e in web)} run through their WebAssembly builds in
Node.js (`peers/wasm`), a second process the scene's program steps through a
pipe; their cost compared is the engine's own step, not the pipe.""" if web else "")
        if "havok" in engines:
            web_text += """ This Havok is today's Havok for the web, not the Havok 6.5 whose
figures the thesis quotes."""
        if self.float32:
            web_text += (f" {', '.join(engine_name(e) for e in self.float32)} hold their state in float32, so an "
                         f"error below {FLOAT32_ROUNDING:g} is rounding, not physics.")
        if skipped:
            web_text += "\n\n**Skipped** (not available in this build, as `--list-engines` says): " + "; ".join(
                f"{e}: {why}" for e, why in skipped.items()) + "."
        intro = f"""Each scene runs on every engine through the scene's own program
(`build/tests/testN --engine E --engine-setting default|best`): the program
describes its ODE world as data, the engine's adapter builds and steps it,
and the scene's own code measures it, so every engine runs the same
geometry, masses, gravity, surface, step and run length, and is measured by
the same code. Engines here (`--list-engines`): {named}. Each runs at its
defaults and at its best for the scene (the adapter's best settings,
doc/peers.md). What an adapter could not express exactly it says in
translation notes, listed in each scene's part and in
{peers_notes.NOTES_CSV}. Cost is the engine's own seconds (its collision and
step calls) per simulated second on this machine; the process's CPU seconds
are beside it.
{web_text}

The column "Havok 6.5 (thesis)" is quoted from the thesis, not measured. ODE's settings:
{"; ".join(f"{k}: {v}" for k, v in ODE_SETTING_TEXT.items() if any(s.name == k for s in scenes))}.

{md.files_line([csv, notes_csv])}

{self.matrix(scenes, engines, rows, worlds)}"""
        return Outcome(intro + "\n\n" + "\n\n".join(parts), headline, claims=claims)

    # ---- the matrix: scene by engine, at COMPARE_STEP ----------------------------------
    def matrix(self, scenes, engines, rows, worlds):
        """The scene-by-engine tables at COMPARE_STEP: every figure cell names
        the scene's surface and the step it ran at; the cost cells the
        engine's seconds per simulated second (each row's header names the
        surface and the step)."""
        columns = [(e, s) for e in engines for s in ("default", "best")]
        header = ["scene (surface, step)"]
        for e, s in columns:
            header.append(f"{e} {s}")
            if (e, s) == ("havok", "best"):
                header.append("Havok 6.5 (thesis)")
        if "havok" not in engines:
            header.append("Havok 6.5 (thesis)")
        figures, costs = [], []
        for scene in scenes:
            where = f"{surface_short(worlds[scene.name])}, step {md.num(COMPARE_STEP)}"
            figure_row, cost_row = [f"{scene.name} ({where})"], [f"{scene.name} ({where})"]
            for e, s in columns:
                found = [r for r in rows if r["scene"] == scene.name and r["engine"] == e and r["setting"] == s
                         and r["step"] == COMPARE_STEP]
                figure_row.append(f"{self.value_text(scene, found[0])} ({where})" if found
                                  else "cannot run it (below)" if e in scene.missing else "(one setting)")
                cost_row.append(cost_text(found[0]) if found else "-")
                if (e, s) == ("havok", "best") or (e, s) == columns[-1] and "havok" not in engines:
                    figure_row.append(havok_quote(scene.name)[0] or "-")
                    cost_row.append("-")
            figures.append(figure_row)
            costs.append(cost_row)
        quantities = "; ".join(f"{s.name}: {s.label}" for s in scenes)
        return f"""#### The matrix at step {COMPARE_STEP} s

The figure each engine reaches on the scene's own world, each cell with the
scene's surface and the step it ran at ({quantities}; mu ∞: friction
that never slides, e: restitution, pairs: pairs of geoms with a surface of
their own):

{md.table(header, figures)}

Its cost, engine seconds (the engine's own collision and step calls) per
simulated second, the median [min-max] of the timed runs (peers.csv has the
process's CPU seconds and the program's run-loop wall seconds too):

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
        # A cell whose length is its figure is timed as it is; the others are
        # timed again, longer, should a timed run come out short.
        fixed = [c for c in cells if c[0][0].name in FIXED_LENGTH]
        free = [c for c in cells if c[0][0].name not in FIXED_LENGTH]
        done = {}
        for group, floor in ((fixed, 0.0), (free, minimum)):
            timed = timing.interleaved_long_enough(
                ctx.runner, [(program_of(point[1], point[0]), args) for point, _, args in group],
                timing.repeats(ctx.quick), floor)
            done.update({id(row): results for (_, row, _), results in zip(group, timed)})
        ctx.advance(len(cells) * timing.repeats(ctx.quick))
        ctx.advance((len(plan) - len(cells)) * timing.repeats(ctx.quick))
        for row, _ in measured:
            row.update(costs(done.get(id(row), [])))

    # ---- one point ---------------------------------------------------------------
    def measure(self, ctx, scene, engine, args, step):
        r = ctx.runner.run(RunSpec(program_of(engine, scene),
                                   [*base_args(engine, scene, ctx.quick), *args, "--step", step],
                                   measures_blow_ups=True))
        value = r.m(scene.metric) if r.rc == 0 else None
        return (scene.convert(value) if scene.convert and value is not None else value), r, r

    def heaviest(self, ctx, scene, engine, args, step):
        """limit-test4's search and failure rule on any engine: (heaviest held
        kg, its run, a run that says the engine's translation notes)."""
        def probe(mass):
            r = ctx.runner.run(RunSpec(program_of(engine, scene),
                                       [*base_args(engine, scene, ctx.quick), *args, "--big-mass", mass,
                                        "--step", step], priority=0, measures_blow_ups=True))
            passed, reason = judge_test4(r)
            return passed, r

        result = highest_passing(probe, start=5000.0, factor=4.0, ratio=1.1, low=50.0, high=1e9)
        held = next((info for value, passed, info in result.probes if value == result.highest_pass), None)
        return result.highest_pass, held, held or next((info for _, _, info in result.probes if info), None)

    def tallest(self, ctx, scene, engine, args, step):
        """limit-test5's search and rule on any engine: (tallest aligned stack
        in real time, its run, a run that says the engine's translation notes)."""
        def probe(plates):
            extra = ["--plates", plates, "--spawn-interval", SPAWN_INTERVAL_TEST5,
                     "--seconds", round(plates * SPAWN_INTERVAL_TEST5 + SETTLE_TEST5, 3)]
            r = ctx.runner.run(RunSpec(program_of(engine, scene),
                                       [*base_args(engine, scene, ctx.quick), *args, *extra, "--step", step],
                                       timed=True, timeout=900, priority=0, measures_blow_ups=True))
            passed, reason = judge_test5(r, plates, step, cost=engine_step_cost)
            return passed, r

        result = highest_passing(probe, start=40, factor=1.5, ratio=1.2, low=5, high=600, integer=True)
        held = next((info for value, passed, info in result.probes if value == result.highest_pass), None)
        return result.highest_pass, held, held or next((info for _, _, info in result.probes if info), None)

    # ---- one scene's part of the report ----------------------------------------------
    def scene_part(self, ctx, scene, rows, world=None, note_rows=()):
        """The scene's part: its verdicts, its table (every row with the
        scene's surface and the engine's translation notes), its plot, and
        the notes per engine (each once)."""
        havok_text, havok_number, havok_conditions = havok_quote(scene.name)
        ctx.register_files(plots.peers_speed_accuracy(ctx.out_dir, f"peers-{scene.name}", rows, scene.label,
                                                      scene.lower_is_better, havok_number, ROUNDING))
        surface = surface_words(world) if world else (rows[0].get("surface", "") if rows else "")
        table = [[r["engine"], r["setting"], md.num(r["step"]), self.value_text(scene, r),
                  notes_said(r), cost_text(r), cost_text(r, "link_s_per_sim_s"), cost_text(r, "cpu_s_per_sim_s"),
                  md.num(r["repeats"])]
                 for r in rows]
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
            rounding = (self.float32, ROUNDING, FLOAT32_ROUNDING)
            headline = [peers_headline.headline(scene.name, scene.label, scene.lower_is_better,
                                                VERDICT_STEPS.get(scene.name, [COMPARE_STEP])[0], *rounding)]
        havok = (f"Havok 6.5, quoted by the thesis ({havok_conditions}): **{havok_text}**."
                 if havok_text else "The thesis quotes no Havok figure for this scene.")
        missing = "".join(f" Not run on {e}: {why}." for e, why in scene.missing.items())
        notes = peers_notes.per_engine(list(note_rows), scene.name)
        notes_text = "\n".join(f"- {engine}:\n" + "\n".join(f"  - {peers_notes.note_line(note, s)}" for note, s in said)
                               for engine, said in notes.items())
        text = f"""#### {scene.name}: {scene.label}

{" ".join(verdicts)} {havok}{missing} The thesis's ODE 0.11.1: {thesis_ode(scene.name) or "-"}.

Every engine runs the scene's own world, on its surface: {surface or "(not exported)"}.

{md.table(["engine", "setting", "step (s)", scene.quantity, "translation notes",
           "engine s / sim s, median [range]", "link s / sim s (beside, not added)",
           "whole run CPU s / sim s (Node.js included)", "timed runs"], table)}

{"What each engine could not express exactly (its translation notes, each once; "
 + peers_notes.NOTES_CSV + "):" if notes_text else "No engine gave a translation note on this scene."}

{notes_text}

{md.figure(f"peers-{scene.name}", f"{scene.name}: {scene.label} against engine seconds per simulated second, "
           "one curve per engine and setting (steps large to small), bars the range of the timed runs" +
           (", Havok's quoted figure as a line" if havok_number is not None else ""))}"""
        return text.replace("\n\n\n\n", "\n\n"), headline, {}

    def verdict(self, scene, rows, step, kind):
        """One sentence: who is best at `step` among the engines' `kind`
        settings (defaults with defaults, best with best; ODE's one setting
        counts as both), like with like (peer_compare.standings)."""
        mine = [r for r in rows if r["step"] == step and (
            r["setting"] == kind or r["engine"] == "ode" and len(ODE_SETTINGS[scene.name]) == 1)]
        winners, excluded = standings([as_standing(r) for r in mine], scene.lower_is_better,
                                      lambda r: rounding_of(r["engine"], self.float32))
        where = f"At step {md.num(step)}, {'defaults' if kind == 'default' else 'each engine at its best'}"
        left = "".join(f" Not compared: {r['engine']} ({why})." for r, why in excluded)
        if not winners:
            return f"{where}: no engine that compares reached a figure.{left}"
        first = winners[0]
        how = "exact to rounding" if self.exact(scene, first) else "best"
        figure = self.value_text(scene, first)
        if len(winners) == 1:
            text = (f"{where}: {first['engine']} ({first['setting']}) is {how} with {figure} at "
                    f"{cost_text(first)} engine s per simulated s")
        else:
            names = ", ".join(f"{r['engine']} ({r['setting']}, {cost_text(r)})" for r in winners)
            text = (f"{where}: a tie within the timing's scatter at {figure}: {names} engine s per simulated s")
        return text + "." + left

    def exact(self, scene, r):
        return (scene.lower_is_better and r["value"] is not None
                and r["value"] < rounding_of(r["engine"], self.float32))

    def value_text(self, scene, r):
        if r.get("voided"):
            return scene.voided_by[1]
        if r["value"] is None:
            return scene.not_reached if r["exit_status"] in (0, None) else f"blew up (exit {r['exit_status']})"
        text = md.num(r["value"], 3)
        if r.get("by_construction"):
            return f"{text}: {r['by_construction']}"
        return text + " (scan limit)" if r.get("capped") else text
