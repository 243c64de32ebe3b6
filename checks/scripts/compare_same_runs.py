#!/usr/bin/python3
"""A compare run equals the separate runs it stands for (checks/compare.cmake).

  compare_same_runs.py --program build/tests/test2 --engines bullet,mujoco [--skipped havok,jolt,rapier]
                       [--launcher build/tests/odelab] -- --seconds 2

Runs, each in a fresh folder:
  - PROGRAM --compare ENGINES --headless ARGS --metrics-json c.json
    (or LAUNCHER --scene NAME --compare ...), which must end with status 0;
  - PROGRAM --headless ARGS (ODE), and PROGRAM --engine E --headless ARGS for
    each engine.
Every block of the compare run's metrics (ode.NAME, bullet.NAME, ...) must
equal its separate run's metrics: the same names, the same values as
written (to the digits printed), the same lists of sentences, but for the
metrics read from a clock (launcher_same_run.py's CLOCK_METRICS);
<engine>.exit_status must be the separate run's status; and the output
files must be the same byte for byte (ODE's in the folder, each other
engine's in <folder>/<engine>/).

  compare_same_runs.py --window --view-bodies build/checks/view_bodies --program build/tests/test2
                       --engines bullet,jolt,rapier -- --seconds 3

runs the compare run in a window instead (under Xvfb, which the caller
starts), with --screenshot of its last frame at 1280x720: besides the same
figures (but for the window's own, in ODE's block: frames per second, the
longest frame, its failures), every engine's view in the picture, as the
program names it ("view bullet: x .. y .. width .. height .."), must show
the bodies where ODE's view shows them (view_bodies).

  compare_same_runs.py --inputs checks/scripts/compare_inputs.events --program build/tests/test2 --engines bullet

plays the --events script in a compare window (under Xvfb, which the caller
starts): every engine's run log (OUT/test2_run_log.txt, the others' in
OUT/<engine>/) must list the same inputs at the same steps as ODE's, at
least MIN_INPUTS of them, and every engine's block must end at ODE's step
with ODE's ERP and CFM and a drag_end_distance of its own.

  compare_same_runs.py --panel-hides checks/scripts/compare_panel_hides.events --hidden jolt
                       --view-bodies build/checks/view_bodies --program build/tests/test2
                       --engines bullet,jolt,rapier -- --seconds 2

plays the --events script, which clicks the panel's tick of the engine
--hidden off, in a compare window (under Xvfb, which the caller starts)
with --screenshot of its last frame: the window names a view for every
engine but that one, each showing the bodies where ODE's does, and the
hidden engine's block still ends at ODE's step (it stepped unseen).

  compare_same_runs.py --program build/tests/test2 --refusals

checks what is refused with status 2 before anything is written: --compare
with --engine, an unknown engine, ode named, an engine named twice, an empty
name, --export-world, and a link or a file where
an engine's folder goes.

--skipped names engines this build cannot run (no node): printed as skipped.
Exit 0 when all hold, 1 naming each that does not.
"""
import argparse
import json
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from launcher_same_run import CLOCK_METRICS  # noqa: E402

METRICS = "m.json"
# The frame loop's figures: in a compare window, ODE's block has them.
WINDOW_METRICS = {"window_fps", "longest_frame_ms", "window_failures", "longest_input_to_engines_ms"}
SHOT = "shot.png"
WIDTH, HEIGHT = 1280, 720
# The top of a view that its label may cover, left out of the picture's check.
# The inputs the --inputs script gives at least (ERP, drag, release, R, CFM).
MIN_INPUTS = 5


def run(command, folder):
    os.makedirs(folder, exist_ok=True)
    done = subprocess.run(command, cwd=folder, capture_output=True, text=True, timeout=900)
    return done


def files_of(folder, leave_out):
    files = {}
    for name in sorted(os.listdir(folder)):
        path = os.path.join(folder, name)
        if name in leave_out or not os.path.isfile(path):
            continue
        with open(path, "rb") as f:
            files[name] = f.read()
    return files


def same_runs(args, rest):
    engines = [e for e in args.engines.split(",") if e]
    name = os.path.basename(args.program)
    failures = []
    compared = 0
    with tempfile.TemporaryDirectory() as root:
        if args.launcher:
            command = [args.launcher, "--scene", name]
        else:
            command = [args.program]
        together = os.path.join(root, "compare")
        how = (["--screenshot", SHOT, "--width", str(WIDTH), "--height", str(HEIGHT)] if args.window
               else ["--headless"])
        done = run([*command, "--compare", ",".join(engines), *how, *rest, "--metrics-json", METRICS], together)
        if done.returncode != 0:
            print(f"FAIL: the compare run ended with status {done.returncode}: {done.stderr.strip()}")
            return 1
        if args.window:
            failures += views_shown(args, done.stdout, os.path.join(together, SHOT), ["ode", *engines])
        with open(os.path.join(together, METRICS)) as f:
            compare = json.load(f)
        if compare.get("engines") != len(engines) + 1:
            failures.append(f"engines is {compare.get('engines')}, not {len(engines) + 1}")
        for engine in ["ode", *engines]:
            alone = os.path.join(root, engine)
            extra = [] if engine == "ode" else ["--engine", engine]
            done = run([args.program, "--headless", *extra, *rest, "--metrics-json", METRICS], alone)
            with open(os.path.join(alone, METRICS)) as f:
                own = json.load(f)
            prefix = engine + "."
            block = {k[len(prefix):]: v for k, v in compare.items() if k.startswith(prefix)}
            status = block.pop("exit_status", None)
            if status != done.returncode:
                failures.append(f"{engine}: exit_status {status} in the compare run, status {done.returncode} alone")
            differ = [f"{engine}.{k}: {block.get(k)} together, {own.get(k)} alone"
                      for k in sorted(set(own) | set(block))
                      if k not in CLOCK_METRICS and block.get(k, "absent") != own.get(k, "absent")
                      and not (args.window and engine == "ode" and k in WINDOW_METRICS)]
            failures += differ
            values = len([k for k in own if k not in CLOCK_METRICS])
            compared += values
            # Output files: ODE's where its own run writes them, the others' in <folder>/<engine>.
            folder = together if engine == "ode" else os.path.join(together, engine)
            theirs = files_of(folder, {METRICS, SHOT, *engines})
            mine = files_of(alone, {METRICS})
            if sorted(theirs) != sorted(mine):
                failures.append(f"{engine}: files {sorted(theirs)} together, {sorted(mine)} alone")
            failures += [f"{engine}: {f} differs" for f in mine if f in theirs and mine[f] != theirs[f]]
            print(f"{name} {engine}: {values} metrics (state_hash {own.get('state_hash')}, status {done.returncode}) "
                  f"and {len(mine)} output files compared, {len(differ)} metrics differ")
    for engine in [e for e in (args.skipped or "").split(",") if e]:
        print(f"{name} {engine}: skipped (not in this build: node, or npm ci in peers/wasm)")
    for failure in failures:
        print("FAIL", failure)
    print(f"{name}: {len(engines) + 1} engines, {compared} metrics compared, {len(failures)} differences")
    return 1 if failures else 0


def views_shown(args, stdout, shot, engines):
    """Every engine's view of the screenshot shows the bodies where ODE's
    view shows them (view_bodies)."""
    views = {m.group(1): m.group(2, 3, 4, 5)
             for m in re.finditer(r"^view (\S+): x (\d+) y (\d+) width (\d+) height (\d+)", stdout, re.M)}
    if sorted(views) != sorted(engines):
        return [f"the window named views {sorted(views)}, not one per engine {sorted(engines)}"]
    command = [args.view_bodies, shot]
    for engine in engines:
        command += ["--view", ",".join(views[engine])]
    done = subprocess.run(command, capture_output=True, text=True, timeout=120)
    for engine, line in zip(engines, done.stdout.splitlines()):
        print(f"{engine}'s {line}")
    if done.returncode != 0:
        return [f"a view does not show the bodies where ODE's does (view_bodies status {done.returncode}): "
                f"{done.stdout.strip()} {done.stderr.strip()}"]
    return []


def same_inputs(args):
    """The compare window plays args.inputs: every engine's run log lists
    ODE's inputs at ODE's steps, and every block ends where ODE's does."""
    engines = [e for e in args.engines.split(",") if e]
    name = os.path.basename(args.program)
    failures = []
    with tempfile.TemporaryDirectory() as root:
        done = run([args.program, "--compare", ",".join(engines), "--events", os.path.abspath(args.inputs),
                    "--width", str(WIDTH), "--height", str(HEIGHT), "--metrics-json", METRICS], root)
        if done.returncode != 0:
            print(f"FAIL: the compare window ended with status {done.returncode}: {done.stderr.strip()}")
            return 1
        with open(os.path.join(root, METRICS)) as f:
            metrics = json.load(f)

        def log_of(folder):
            with open(os.path.join(folder, f"{name}_run_log.txt")) as f:
                return [line for line in f.read().splitlines() if not line.startswith("#")]

        ode = log_of(root)
        if len(ode) < MIN_INPUTS:
            failures.append(f"ODE's run log lists {len(ode)} inputs, fewer than the script's {MIN_INPUTS}: {ode}")
        for engine in engines:
            theirs = log_of(os.path.join(root, engine))
            if theirs != ode:
                failures.append(f"{engine}'s run log {theirs} is not ODE's {ode}")
            for key in ("steps", "world_erp", "world_cfm"):
                if metrics.get(f"{engine}.{key}") != metrics.get(f"ode.{key}"):
                    failures.append(f"{engine}.{key} {metrics.get(f'{engine}.{key}')} is not ode.{key} "
                                    f"{metrics.get(f'ode.{key}')}")
            if f"{engine}.drag_end_distance" not in metrics:
                failures.append(f"{engine} has no drag_end_distance: the drag did not reach it")
            print(f"{name} {engine}: {len(theirs)} inputs logged, steps {metrics.get(f'{engine}.steps')}, "
                  f"ERP {metrics.get(f'{engine}.world_erp')}, CFM {metrics.get(f'{engine}.world_cfm')}, "
                  f"drag_end_distance {metrics.get(f'{engine}.drag_end_distance')}")
        print(f"{name} ode: {len(ode)} inputs logged: {'; '.join(ode)}")
    for failure in failures:
        print("FAIL", failure)
    return 1 if failures else 0


def panel_hides(args, rest):
    """The panel's tick hides one engine's view; the others fill the window
    and the hidden one keeps stepping."""
    engines = [e for e in args.engines.split(",") if e]
    name = os.path.basename(args.program)
    with tempfile.TemporaryDirectory() as root:
        done = run([args.program, "--compare", ",".join(engines), "--events", os.path.abspath(args.panel_hides),
                    "--screenshot", SHOT, "--width", str(WIDTH), "--height", str(HEIGHT), *rest,
                    "--metrics-json", METRICS], root)
        if done.returncode != 0:
            print(f"FAIL: the compare window ended with status {done.returncode}: {done.stderr.strip()}")
            return 1
        shown = ["ode", *[e for e in engines if e != args.hidden]]
        failures = views_shown(args, done.stdout, os.path.join(root, SHOT), shown)
        with open(os.path.join(root, METRICS)) as f:
            metrics = json.load(f)
        steps = {engine: metrics.get(f"{engine}.steps") for engine in ["ode", *engines]}
        if len(set(steps.values())) != 1:
            failures.append(f"the engines ended at different steps: {steps}")
        print(f"{name}: views of {', '.join(shown)} with {args.hidden} hidden; steps {steps}")
    for failure in failures:
        print("FAIL", failure)
    return 1 if failures else 0


def refusals(args):
    name = os.path.basename(args.program)
    cases = [
        (["--compare", "bullet", "--engine", "bullet", "--headless"], "leave out --engine"),
        (["--compare", "bullet", "--engine", "ode", "--headless"], "leave out --engine"),
        (["--compare", "nosuch", "--headless"], "--compare nosuch: no such engine"),
        (["--compare", "ode", "--headless"], "--compare ode"),
        (["--compare", "bullet,ode", "--headless"], "--compare ode"),
        (["--compare", "bullet,bullet", "--headless"], "--compare bullet: named twice"),
        (["--compare", "bullet,", "--headless"], "an empty engine name"),
        (["--compare", "bullet", "--headless", "--export-world", "w.json"], "leave out --compare"),
    ]
    failures = []
    with tempfile.TemporaryDirectory() as root:
        for number, (options, words) in enumerate(cases):
            folder = os.path.join(root, str(number))
            done = run([args.program, *options, "--seconds", "0.1", "--metrics-json", METRICS], folder)
            left = sorted(os.listdir(folder))
            if done.returncode != 2 or words not in done.stderr or left:
                failures.append(f"{' '.join(options)}: status {done.returncode}, files {left}, said "
                                f"{done.stderr.strip()!r}; wanted status 2 saying {words!r} and no file")
        # What stands where an engine's folder goes: a link, a file.
        for kind in ("link", "file"):
            folder = os.path.join(root, kind)
            os.makedirs(os.path.join(folder, "elsewhere"))
            if kind == "link":
                os.symlink("elsewhere", os.path.join(folder, "bullet"))
            else:
                open(os.path.join(folder, "bullet"), "w").close()
            done = run([args.program, "--compare", "bullet", "--headless", "--seconds", "0.1",
                        "--metrics-json", METRICS], folder)
            words = "is a symbolic link" if kind == "link" else "is a file;"
            left = sorted(os.listdir(folder))
            if (done.returncode != 2 or words not in done.stderr or left != ["bullet", "elsewhere"]
                    or os.listdir(os.path.join(folder, "elsewhere"))):
                failures.append(f"a {kind} at bullet/: status {done.returncode}, files {left}, said "
                                f"{done.stderr.strip()!r}; wanted status 2 saying {words!r} and nothing written")
    for failure in failures:
        print("FAIL", failure)
    print(f"{name}: {len(cases) + 2} refusals checked, {len(failures)} wrong")
    return 1 if failures else 0


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--program", required=True, help="a scene's program (build/tests/test2)")
    parser.add_argument("--engines", default="", help="the engines beside ODE, comma-separated")
    parser.add_argument("--skipped", help="engines this build cannot run, printed as skipped")
    parser.add_argument("--launcher", help="run the compare run as LAUNCHER --scene NAME (odelab)")
    parser.add_argument("--refusals", action="store_true", help="check the refusals instead")
    parser.add_argument("--window", action="store_true", help="the compare run in a window, with a screenshot")
    parser.add_argument("--inputs", help="an --events script to play in a compare window instead")
    parser.add_argument("--view-bodies", help="the view_bodies tool, for --window and --panel-hides")
    parser.add_argument("--panel-hides", help="an --events script whose clicks hide --hidden's view by the panel")
    parser.add_argument("--hidden", help="the engine the --panel-hides script hides")
    args, rest = parser.parse_known_args()
    args.program = os.path.abspath(args.program)  # the runs are in folders of their own
    if args.launcher:
        args.launcher = os.path.abspath(args.launcher)
    if rest and rest[0] == "--":
        rest = rest[1:]
    if args.refusals:
        return refusals(args)
    if not args.engines:
        parser.error("--engines: name at least one")
    if args.inputs:
        return same_inputs(args)
    if args.panel_hides:
        if not (args.hidden and args.view_bodies):
            parser.error("--panel-hides needs --hidden and --view-bodies")
        return panel_hides(args, rest)
    if args.window and not args.view_bodies:
        parser.error("--window needs --view-bodies")
    return same_runs(args, rest)


if __name__ == "__main__":
    sys.exit(main())
