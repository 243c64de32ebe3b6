#!/usr/bin/env python3
"""The copied command line (the panel's "Copy as command line", printed at a
run's end by --print-command-line) starts the run it was copied from.

usage:
  copy_line.py names PROGRAM [ARGS...]
      Every setting and knob PROGRAM --list-settings lists (with ARGS) is on
      the line of a headless run given ARGS, with the listed value read back
      exactly (and the line itself, parsed, lists the same), except where
      naming it would change the run: a knob that needs
      a flag the line does not carry (only_with), a default the scene picks
      itself and was not given (scene_default), or a stand-in value outside
      its own range. mu and max_contacts are written as --mu and
      --max-contacts, the contact choices' own options.
  copy_line.py headless PROGRAM SECONDS [ARGS...]
      A headless run of SECONDS with ARGS prints a line that names each of
      ARGS' values; the line run headless for SECONDS prints itself again and
      ends in the same state_hash.
  copy_line.py window PROGRAM EVENTS SECONDS [ARGS...]
      A window run (under xvfb-run, given by the test) plays EVENTS, which
      change settings while paused at step 0 and mark "changed" there, and
      ends after SECONDS. Its line, run headless for SECONDS, ends in the
      window's state_hash; the same headless run without the line's options
      ends elsewhere, so the changes are shown to matter.
"""
import json
import math
import os
import shlex
import subprocess
import sys
import tempfile



def run(program, args, folder, timeout=300):
    metrics = os.path.join(folder, "metrics.json")
    done = subprocess.run([program, *args, "--out-dir", folder, "--metrics-json", metrics, "--print-command-line"],
                          capture_output=True, text=True, timeout=timeout, cwd=folder)
    if done.returncode != 0:
        raise SystemExit(f"FAIL: {program} {' '.join(args)}: status {done.returncode}: {done.stderr.strip()[-600:]}")
    lines = [line[len("command line: "):] for line in done.stdout.splitlines() if line.startswith("command line: ")]
    if not lines:
        raise SystemExit(f"FAIL: {program} {' '.join(args)} printed no 'command line: ' line")
    with open(metrics) as file:
        return lines[-1], json.load(file)


def options_of(line):
    """The line's words as {option: value} ("" for a flag) and its program name."""
    words = shlex.split(line)
    options, i = {}, 1
    while i < len(words):
        if i + 1 < len(words) and not words[i + 1].startswith("--"):
            options[words[i]] = words[i + 1]
            i += 2
        else:
            options[words[i]] = ""
            i += 1
    return words[0], options


def number(text):
    return math.inf if text in ("inf", "dInfinity") else float(text)


def check_names(program, args):
    listing = subprocess.run([program, *args, "--list-settings"], capture_output=True, text=True, timeout=60)
    if listing.returncode != 0:
        return [f"--list-settings: status {listing.returncode}: {listing.stderr.strip()}"]
    with tempfile.TemporaryDirectory() as folder:
        line, _ = run(program, ["--headless", "--seconds", "0.01", *args], folder)
    print("line:", line)
    name, options = options_of(line)
    failures = []
    if name != os.path.basename(program):
        failures.append(f"the line starts with {name!r}, not the program's name")
    for entry in json.loads(listing.stdout):
        option = entry["option"]
        if not option:
            failures.append(f"{entry['name']}: listed without an option the line could name")
            continue
        value = entry["default"]
        if entry["kind"] == "switch":  # a flag, on the line only while on
            if value and option not in options:
                failures.append(f"{entry['name']}: on, but {option} is not on the line")
            elif not value and option in options:
                failures.append(f"{entry['name']}: off, but {option} is on the line")
            continue
        if option not in options:
            given = option in args or any(arg.startswith(option + "=") for arg in args)
            if entry.get("only_with") and entry["only_with"] not in options:
                continue
            if entry.get("scene_default") and not given:
                continue
            if entry["kind"] != "choice" and value != "inf" and not (entry["min"] <= value <= entry["max"]) \
                    and not (entry["off_at_zero"] and value == 0):
                continue
            failures.append(f"{entry['name']}: {option} is not on the line")
            continue
        if entry["kind"] == "choice":
            if options[option] != value:
                failures.append(f"{option} {options[option]} on the line, {value} in force")
        elif number(options[option]) != (math.inf if value == "inf" else value):
            failures.append(f"{option} {options[option]} on the line does not read back as {value!r}")
    if "--seed" not in options:
        failures.append("--seed is not on the line")
    # The line parses, and sets every listed value back as it was.
    again = subprocess.run([program, *shlex.split(line)[1:], "--list-settings"], capture_output=True, text=True,
                           timeout=60)
    if again.returncode != 0:
        failures.append(f"the line is refused: status {again.returncode}: {again.stderr.strip()}")
    elif json.loads(again.stdout) != json.loads(listing.stdout):
        failures.append("the line's --list-settings differs from the run's")
    return failures


def given_pairs(args):
    """ARGS as (option, value) pairs, "--x=v" and "--x v" alike; a flag's value is ""."""
    pairs, i = [], 0
    while i < len(args):
        if "=" in args[i]:
            option, value = args[i].split("=", 1)
            pairs.append((option, value))
            i += 1
        elif i + 1 < len(args) and not args[i + 1].startswith("--"):
            pairs.append((args[i], args[i + 1]))
            i += 2
        else:
            pairs.append((args[i], ""))
            i += 1
    return pairs


def same_value(a, b):
    try:
        return number(a) == number(b)
    except ValueError:
        return a == b


def check_headless(program, seconds, args):
    failures = []
    with tempfile.TemporaryDirectory() as first, tempfile.TemporaryDirectory() as second:
        line, metrics = run(program, ["--headless", "--seconds", seconds, *args], first)
        print("line:", line)
        _, options = options_of(line)
        for option, value in given_pairs(args):
            if option not in options:
                failures.append(f"{option} {value} was given; the line leaves it out")
            elif not same_value(options[option], value):
                failures.append(f"{option} {value} was given; the line says {options[option]}")
        again, metrics_again = run(program, ["--headless", "--seconds", seconds, *shlex.split(line)[1:]], second)
        if again != line:
            failures.append(f"the line run again prints another line:\n  {again}")
        if metrics_again["state_hash"] != metrics["state_hash"]:
            failures.append(f"state_hash {metrics['state_hash']}, then {metrics_again['state_hash']} from the line")
        else:
            print(f"ok: the line ends in state_hash {metrics['state_hash']} after {metrics['steps']:.0f} steps")
    return failures


def check_window(program, events, seconds, args):
    failures = []
    with tempfile.TemporaryDirectory() as window, tempfile.TemporaryDirectory() as headless, \
            tempfile.TemporaryDirectory() as bare:
        line, metrics = run(program, ["--events", events, "--seconds", seconds, *args], window, timeout=150)
        print("line:", line)
        if metrics.get("mark_changed_steps") != 0:
            failures.append(f"the script's changes were made at step {metrics.get('mark_changed_steps')}, not 0")
        _, replayed = run(program, ["--headless", "--seconds", seconds, *shlex.split(line)[1:]], headless)
        _, unchanged = run(program, ["--headless", "--seconds", seconds, *args], bare)
        if replayed["steps"] != metrics["steps"]:
            failures.append(f"the window ran {metrics['steps']:.0f} steps, the line {replayed['steps']:.0f}")
        if replayed["state_hash"] != metrics["state_hash"]:
            failures.append(f"the window ended in state_hash {metrics['state_hash']}, its line in "
                            f"{replayed['state_hash']}")
        else:
            print(f"ok: window and line end in state_hash {metrics['state_hash']} after {metrics['steps']:.0f} steps")
        if unchanged["state_hash"] == metrics["state_hash"]:
            failures.append("a run without the script's changes ends in the same state: they changed nothing")
    return failures


def main():
    if len(sys.argv) < 3 or sys.argv[1] not in ("names", "headless", "window"):
        print(__doc__, file=sys.stderr)
        return 2
    mode, program = sys.argv[1], sys.argv[2]
    if mode == "names":
        failures = check_names(program, sys.argv[3:])
    elif mode == "headless":
        failures = check_headless(program, sys.argv[3], sys.argv[4:])
    else:
        failures = check_window(program, sys.argv[3], sys.argv[4], sys.argv[5:])
    for failure in failures:
        print("FAIL", failure)
    print(f"{os.path.basename(program)} {mode}: {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
