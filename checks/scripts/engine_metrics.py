#!/usr/bin/env python3
"""A scene's own world run on another engine (checks/engine_claims.cmake).

  engine_metrics.py ENGINE PROGRAM ARGS...

Runs `PROGRAM --headless ARGS... --metrics-json m.json` twice, each in a fresh
folder of its own under the working folder: once on ode and
once with `--engine ENGINE` (its default setting). The engine's run must:
  - end with status 0;
  - report the same metric names as the ODE run, plus only those an engine
    run adds (engine, engine_cpu_seconds, translation_note_count,
    translation_notes, engine_failed), each of those present;
  - name itself: engine == [ENGINE, "default"];
  - say what the engine could not express: translation_notes a non-empty
    list of strings, translation_note_count its length (every engine is
    float32 or has finite friction, so every scene has at least one note:
    measured 4 to 10 notes on each of the 55 pairs);
  - have stepped the world itself: its state_hash differs from ODE's.
Exit 0 when all hold, 1 naming each that does not.
"""
import json
import os
import shutil
import subprocess
import sys

ENGINE_ONLY = {"engine", "engine_cpu_seconds", "translation_note_count", "translation_notes", "engine_failed"}


def run(program, args, folder):
    if os.path.exists(folder):
        shutil.rmtree(folder)
    os.makedirs(folder)
    command = [program, "--headless", *args, "--metrics-json", "m.json"]
    done = subprocess.run(command, cwd=folder, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          text=True, errors="replace", timeout=300)
    metrics = None
    path = os.path.join(folder, "m.json")
    if done.returncode == 0 and os.path.exists(path):
        with open(path, encoding="utf-8") as f:
            metrics = json.load(f)
    return done.returncode, done.stdout, metrics, " ".join(command)


def main():
    if len(sys.argv) < 3:
        print("usage: engine_metrics.py ENGINE PROGRAM ARGS...", file=sys.stderr)
        return 2
    engine, program, args = sys.argv[1], sys.argv[2], sys.argv[3:]
    status, output, reference, command = run(program, args, "ode")
    if status != 0 or reference is None:
        print(f"the reference run on ode failed (status {status}): {command}\n{output}")
        return 1
    status, output, metrics, command = run(program, ["--engine", engine, *args], engine)
    if status != 0 or metrics is None:
        print(f"{command}: status {status} (expected 0 and a metrics file)\n{output}")
        return 1

    failures = []
    missing = sorted(set(reference) - set(metrics))
    extra = sorted(set(metrics) - set(reference) - ENGINE_ONLY)
    absent = sorted(ENGINE_ONLY - set(metrics))
    if missing:
        failures.append(f"metrics of the ode run missing on {engine}: {', '.join(missing)}")
    if extra:
        failures.append(f"metrics the ode run does not report: {', '.join(extra)}")
    if absent:
        failures.append(f"an engine run's own metrics missing: {', '.join(absent)}")
    if metrics.get("engine") != [engine, "default"]:
        failures.append(f"engine is {metrics.get('engine')!r}, expected [{engine!r}, 'default']")
    notes = metrics.get("translation_notes")
    if not isinstance(notes, list) or not notes or not all(isinstance(n, str) and n for n in notes):
        failures.append(f"translation_notes is not a non-empty list of sentences: {notes!r}")
    elif metrics.get("translation_note_count") != len(notes):
        failures.append(f"translation_note_count {metrics.get('translation_note_count')} "
                        f"but {len(notes)} translation_notes")
    if "state_hash" not in reference or metrics.get("state_hash") == reference.get("state_hash"):
        failures.append(f"state_hash {metrics.get('state_hash')} equals ODE's: the engine did not step "
                        f"the world, or the run ended before it differed")
    if failures:
        print(f"{command}:")
        for failure in failures:
            print(f"  {failure}")
        return 1
    print(f"{command}: {len(reference)} metrics as on ode, {len(notes)} translation notes, "
          f"state_hash {metrics['state_hash']} (ode {reference['state_hash']})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
