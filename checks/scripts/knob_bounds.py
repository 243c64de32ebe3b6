#!/usr/bin/env python3
"""Every knob a program lists (--list-settings) takes its bounds and refuses
the values just past them.

usage: knob_bounds.py PROGRAM

For each listed setting with an option: the option at its min and at its
max must parse (status 0, and --list-settings then shows that very value as
the knob's value); the next double below min and above max (the next whole
number for counts) must end with status 2 and a message naming the option.
Choices: each is taken, a name that is none of them refused. An interval
knob's min is tried with --step at that min (an interval below one step is
refused), a knob that only works with a flag is given that flag. Only
parsing is exercised (--list-settings exits before running).
"""
import json
import math
import subprocess
import sys


def run(program, args):
    done = subprocess.run([program, *args, "--list-settings"], capture_output=True, text=True, timeout=60)
    return done.returncode, done.stdout, done.stderr


def listed(stdout):
    return {entry["name"]: entry for entry in json.loads(stdout)}


def number(value):
    return math.inf if value == "inf" else value


def text(value):
    return repr(float(value)) if not float(value).is_integer() or abs(value) >= 1e16 else str(int(value))


def companions(entry, value, step_min):
    extra = []
    if entry.get("only_with"):
        extra.append(entry["only_with"])
    if entry["kind"] == "interval" and value < 1e-3:  # below the default step
        extra += ["--step", text(max(value, step_min))]
    return extra


def main():
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    program = sys.argv[1]
    status, stdout, stderr = run(program, [])
    if status != 0:
        print(f"--list-settings failed with status {status}: {stderr}")
        return 1
    settings = json.loads(stdout)
    step_min = next(entry["min"] for entry in settings if entry["name"] == "step")
    failures, tried = [], 0
    for entry in settings:
        option = entry["option"]
        if not option:
            continue  # a panel-only knob
        if entry["kind"] == "switch":
            continue  # a flag: no bounds (settings_listing.py checks it turns on)
        if entry["kind"] == "choice":
            for choice in entry["choices"]:
                status, _, stderr = run(program, [option, choice])
                tried += 1
                if status != 0:
                    failures.append(f"{option} {choice}: status {status}: {stderr.strip()}")
            status, _, stderr = run(program, [option, "none-of-them"])
            tried += 1
            if status != 2 or option not in stderr:
                failures.append(f"{option} none-of-them: status {status}, not 2 naming the option")
            continue
        whole = entry["kind"] == "integer"
        # A range up to infinity (max "inf": mu) ends there.
        for bound, outward in ((entry["min"], -math.inf), (number(entry["max"]), math.inf)):
            status, out, stderr = run(program, [f"{option}={text(bound)}", *companions(entry, bound, step_min)])
            tried += 1
            if status != 0:
                failures.append(f"{option}={text(bound)} (a bound): status {status}: {stderr.strip()}")
            elif number(listed(out)[entry["name"]]["default"]) != bound:
                failures.append(f"{option}={text(bound)}: listed as {listed(out)[entry['name']]['default']}")
            if math.isinf(bound):
                continue  # nothing lies past infinity
            past = bound + (1 if outward > 0 else -1) if whole else math.nextafter(bound, outward)
            if entry["off_at_zero"] and past == 0:
                continue
            status, _, stderr = run(program, [f"{option}={text(past)}", *companions(entry, bound, step_min)])
            tried += 1
            if status != 2 or option not in stderr:
                failures.append(f"{option}={text(past)} (just past {text(bound)}): status {status}, "
                                f"not 2 naming the option: {stderr.strip()}")
    for failure in failures:
        print("FAIL", failure)
    print(f"{program}: {tried} values tried over {len(settings)} settings, {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
