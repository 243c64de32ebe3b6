#!/usr/bin/python3
"""A compare run in the browser build against the desktop's runs (checks/web.cmake, label web).

  check_compare.py --site DIR --native build/tests/test2 --out DIR --engines havok,jolt,rapier,physx
                   --metric NAME --tolerance X --view-bodies build/checks/view_bodies
                   [--seconds S] [--window-seconds W] -- ARGS...

In headless Chromium (web/drive.mjs), the page scene.html?scene=S&compare=ENGINES:
  1. in a window for W simulated seconds (default 3) at 1280x720 with --screenshot of
     its last frame: the run ends with status 0, names one view per engine
     ("view havok: x .. y .. width .. height .."), and every view shows the
     bodies where ODE's view shows them (view_bodies, as the desktop's
     compare_window_test2_views_and_figures asks): W is a moment when the
     engines' physics agree on where the bodies are (test9's ball before
     its first bounce; after it each engine bounces its own way);
  2. headless, --seconds S (or the scene's own length) with ARGS: every
     engine's block of the metrics (ode.NAME, havok.NAME, ...) against the
     desktop program's own run (PROGRAM --engine E --headless ARGS, ODE's
     without --engine): its steps and translation notes the same, and METRIC
     within TOLERANCE, the tolerance the scene's browser check states
     (checks/programs/<scene>.cmake) for the last-bit differences of
     Emscripten's maths library; the engines' own WebAssembly is the same
     module in both.

Exits 77 (CTest's skip) when DIR holds no browser build of the scene or no
engines (scripts/web/build.sh bundles them after npm ci in web/ and
peers/wasm/), 0 when all hold, 1 naming each that does not.
"""
import argparse
import json
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "checks", "scripts"))
from compare_same_runs import views_shown  # noqa: E402  (the desktop's check of the same picture)
WIDTH, HEIGHT = 1280, 720
SHOT = "shot.png"
METRICS = "metrics.json"


def drive(args, folder, program_args):
    """The scene in headless Chromium; the driver's result.json as a dict."""
    command = ["node", os.path.join(ROOT, "web", "drive.mjs"), "--site", args.site, "--scene", args.scene,
               "--out", folder, "--timeout", "400", "--", *program_args]
    done = subprocess.run(command, capture_output=True, text=True, timeout=600)
    try:
        with open(os.path.join(folder, "result.json")) as f:
            return json.load(f)
    except OSError:
        return {"error": f"the driver ended with status {done.returncode}: {done.stderr.strip()[-400:]}"}


def window(args, engines):
    folder = os.path.join(args.out, "window")
    result = drive(args, folder, ["--compare", ",".join(engines), "--seconds", args.window_seconds,
                                  "--width", str(WIDTH), "--height", str(HEIGHT), "--screenshot", SHOT, *args.rest])
    if result.get("status") != 0:
        return [f"the compare window ended with status {result.get('status')} ({result.get('error', '')}; "
                f"see {folder}/log.txt)"]
    with open(os.path.join(folder, "log.txt")) as f:
        log = f.read()
    return views_shown(args, log, os.path.join(folder, "files", SHOT), ["ode", *engines])


def headless(args, engines):
    length = ["--seconds", args.seconds] if args.seconds else []
    folder = os.path.join(args.out, "headless")
    result = drive(args, folder, ["--compare", ",".join(engines), "--headless", "--metrics-json", METRICS,
                                  *length, *args.rest])
    if result.get("status") != 0:
        return [f"the headless compare run ended with status {result.get('status')} ({result.get('error', '')}; "
                f"see {folder}/log.txt)"]
    with open(os.path.join(folder, "files", METRICS)) as f:
        together = json.load(f)
    failures = []
    for engine in ["ode", *engines]:
        alone = os.path.join(args.out, "native", engine)
        os.makedirs(alone, exist_ok=True)
        extra = [] if engine == "ode" else ["--engine", engine]
        done = subprocess.run([args.native, "--headless", *extra, "--metrics-json", METRICS, *length, *args.rest],
                              cwd=alone, capture_output=True, text=True, timeout=600)
        if done.returncode != 0:
            failures.append(f"{engine}: the desktop's run ended with status {done.returncode}: {done.stderr.strip()}")
            continue
        with open(os.path.join(alone, METRICS)) as f:
            own = json.load(f)
        web = {k[len(engine) + 1:]: v for k, v in together.items() if k.startswith(engine + ".")}
        for key in ("steps", "translation_notes"):
            if web.get(key) != own.get(key):
                failures.append(f"{engine}.{key}: {web.get(key)!r} in the browser, {own.get(key)!r} on the desktop")
        if args.metric not in web or args.metric not in own:
            failures.append(f"{engine}: {args.metric} missing (browser: {args.metric in web}, "
                            f"desktop: {args.metric in own})")
            continue
        difference = abs(float(web[args.metric]) - float(own[args.metric]))
        print(f"{args.scene} on {engine}: {args.metric} {web[args.metric]!r} in the browser, "
              f"{own[args.metric]!r} on the desktop, difference {difference:.3g} (tolerance {args.tolerance}); "
              f"{len(own.get('translation_notes') or [])} translation notes")
        if difference > args.tolerance:
            failures.append(f"{engine}: {args.metric} differs by {difference:.3g}, more than {args.tolerance}")
    return failures


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--site", required=True)
    parser.add_argument("--native", required=True, help="the desktop's program of the scene")
    parser.add_argument("--out", required=True)
    parser.add_argument("--engines", required=True, help="the engines beside ODE, comma-separated")
    parser.add_argument("--metric", required=True)
    parser.add_argument("--tolerance", required=True, type=float)
    parser.add_argument("--view-bodies", required=True)
    parser.add_argument("--seconds")
    parser.add_argument("--window-seconds", default="3")
    args, rest = parser.parse_known_args()
    args.rest = rest[1:] if rest and rest[0] == "--" else rest
    args.site, args.native, args.out = (os.path.abspath(p) for p in (args.site, args.native, args.out))
    args.scene = os.path.basename(args.native)
    engines = [e for e in args.engines.split(",") if e]
    if not os.path.isfile(os.path.join(args.site, args.scene + ".js")) or \
            not os.path.isfile(os.path.join(args.site, "engines", "index.js")) or \
            not os.path.isdir(os.path.join(ROOT, "web", "node_modules", "puppeteer-core")):
        print(f"skipped: no browser build of {args.scene} with its engines in {args.site}, or no web/node_modules "
              "(scripts/odelab.sh web makes both)")
        return 77
    os.makedirs(args.out, exist_ok=True)
    failures = window(args, engines) + headless(args, engines)
    for failure in failures:
        print("FAIL", failure)
    print(f"{args.scene} in the browser on ode and {', '.join(engines)}: {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
