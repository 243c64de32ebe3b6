#!/usr/bin/env python3
"""What --list-settings says of a setting is what its option does.

usage: settings_listing.py PROGRAM...

For every program and every setting it lists:
- the option is named, and is one of the program's --help options;
- the kind is integer, real, interval (a real span of time) or choice;
- the range holds the default (0 too where 0 means off), an integer's
  bounds and default are whole, and a range reaching infinity says so with
  max "inf";
- the option takes its own default (status 0, listed back as that value);
- a value just outside the range is refused with status 2 and a message
  naming the option: just below min, just above a finite max, and inf
  where max is finite (where max is "inf", inf is taken);
- the kind is the option's: a whole number takes no fraction, a real one does.
Choices: the default is one of them. Switches: the default is true or
false, and the flag alone lists it back as true. Only parsing is run
(--list-settings exits before any simulation).
"""
import json
import math
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor

KINDS = {"integer", "real", "interval", "choice", "switch"}


def run(program, args):
    done = subprocess.run([program, *args, "--list-settings"], capture_output=True, text=True, timeout=60)
    return done.returncode, done.stdout, done.stderr


def number(value):
    return math.inf if value == "inf" else value


def text(value):
    if math.isinf(value):
        return "inf"
    return str(int(value)) if float(value).is_integer() and abs(value) < 1e16 else repr(float(value))


def companions(entry, value, step_min):
    """What a value needs beside it: the flag it only works with, a step no longer than an interval."""
    extra = [entry["only_with"]] if entry.get("only_with") else []
    if entry["kind"] == "interval" and value < 1e-3:  # below the default step
        extra += ["--step", text(max(value, step_min))]
    return extra


def in_range(entry, value):
    return entry["min"] <= value <= number(entry["max"]) or (entry["off_at_zero"] and value == 0)


def fraction_inside(entry):
    """A value inside the range that is not a whole number, or None."""
    low, high = entry["min"], number(entry["max"])
    for value in (low + 0.5, low + (min(high, low + 1e3) - low) / 3):
        if low <= value <= high and not float(value).is_integer():
            return value
    return None


def check_entry(program, entry, step_min, help_text):
    failures = []
    name, option, kind = entry["name"], entry["option"], entry["kind"]

    def fail(message):
        failures.append(f"{name}: {message}")

    def takes(value, what):
        status, out, err = run(program, [f"{option}={text(value)}", *companions(entry, value, step_min)])
        if status != 0:
            fail(f"{option}={text(value)} ({what}) refused: status {status}: {err.strip()}")
            return
        shown = next(e for e in json.loads(out) if e["name"] == name)["default"]
        if number(shown) != value:
            fail(f"{option}={text(value)} ({what}) listed back as {shown}")

    def refuses(value, what):
        status, _, err = run(program, [f"{option}={text(value)}", *companions(entry, abs(value), step_min)])
        if status != 2 or option not in err:
            fail(f"{option}={text(value)} ({what}): status {status}, not 2 naming the option: {err.strip()}")

    if not option:
        return [f"{name}: listed with no option"]
    if f"{option} " not in help_text and f"{option}\n" not in help_text and f"{option}," not in help_text:
        fail(f"{option} is not in --help")
    if kind not in KINDS:
        return failures + [f"{name}: kind {kind!r} is none of {sorted(KINDS)}"]
    if kind == "switch":
        if not isinstance(entry["default"], bool):
            fail(f"a switch's default {entry['default']!r} is not true or false")
        status, out, err = run(program, [option])
        if status != 0:
            fail(f"{option}: status {status}: {err.strip()}")
        elif next(e for e in json.loads(out) if e["name"] == name)["default"] is not True:
            fail(f"{option} given, the switch is not listed as on")
        return failures
    if kind == "choice":
        if entry["default"] not in entry["choices"]:
            fail(f"default {entry['default']!r} is none of {entry['choices']}")
        for choice in entry["choices"]:
            status, _, err = run(program, [option, choice])
            if status != 0:
                fail(f"{option} {choice}: status {status}: {err.strip()}")
        return failures
    low, high, default = entry["min"], number(entry["max"]), number(entry["default"])
    if not all(isinstance(v, (int, float)) for v in (low, high, default)):
        return failures + [f"min {entry['min']!r}, max {entry['max']!r}, default {entry['default']!r} are not numbers"]
    if math.isinf(low) or low > high:
        fail(f"range [{entry['min']}, {entry['max']}] is no range")
    if not in_range(entry, default):
        fail(f"default {entry['default']} is outside [{entry['min']}, {entry['max']}]"
             + (" (nor 0, off)" if entry["off_at_zero"] else ""))
    if kind == "integer" and not all(float(v).is_integer() for v in (low, default) + ((high,) if high < math.inf else ())):
        fail(f"an integer with min {low}, max {entry['max']}, default {entry['default']}")
    takes(default, "its own default")
    below = low - 1 if kind == "integer" else math.nextafter(low, -math.inf)
    if entry["off_at_zero"] and below == 0:
        below = math.nextafter(0.0, -math.inf)
    refuses(below, f"just below min {text(low)}")
    if math.isinf(high):
        takes(math.inf, "max is inf")
    else:
        refuses(high + 1 if kind == "integer" else math.nextafter(high, math.inf), f"just above max {text(high)}")
        refuses(math.inf, f"max is {text(high)}, not inf")
    fraction = fraction_inside(entry)
    if fraction is not None:
        if kind == "integer":
            refuses(fraction, "a fraction, for an integer")
        else:
            takes(fraction, f"a fraction, for a {kind} setting")
    return failures


def check_program(program):
    status, stdout, stderr = run(program, [])
    if status != 0:
        return program, 0, [f"--list-settings: status {status}: {stderr.strip()}"]
    entries = json.loads(stdout)
    help_text = subprocess.run([program, "--help"], capture_output=True, text=True, timeout=60).stdout
    step_min = next(entry["min"] for entry in entries if entry["name"] == "step")
    failures = []
    for entry in entries:
        failures += check_entry(program, entry, step_min, help_text)
    return program, len(entries), failures


def main():
    if len(sys.argv) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    total = 0
    with ThreadPoolExecutor(max_workers=4) as pool:
        for program, count, failures in pool.map(check_program, sys.argv[1:]):
            for failure in failures:
                print(f"FAIL {program}: {failure}")
            print(f"{program}: {count} settings, {len(failures)} failures")
            total += len(failures)
    return 1 if total else 0


if __name__ == "__main__":
    sys.exit(main())
