#!/usr/bin/env python3
"""windows_same_metrics.py LINUX_PROGRAM WINDOWS_PROGRAM ARGS...

Runs a program's Linux build and its Windows build (under Wine) headless
with the same ARGS, each in a fresh folder that is also its --out-dir, and
checks that the Windows run measures the same thing:

- both end with status 0;
- the metrics JSON has the same names, and the same value for each, the
  clock's readings (wall time, real-time factor) left out;
- state_hash, the fingerprint of every body's final state, is equal: the
  two builds stepped the same world bit for bit;
- the output files (Test2_output.txt, ...) are the same, byte for byte,
  and whole: a file that ends a run ends with its "# complete:" line.

Exits 77 (skipped) when the Windows program was not built.
"""
import json
import os
import subprocess
import sys
import tempfile

from launcher_same_run import CLOCK_METRICS  # noqa: E402

# Readings of the clock, not of the simulation: they differ from run to run.
# The clock's readings, listed once (launcher_same_run.py), and the window's frame time.
CLOCK = CLOCK_METRICS | {"longest_frame_ms"}
TIMEOUT_S = 300


def run(command, folder):
    with open(os.path.join(folder, "stderr.txt"), "wb") as err:
        status = subprocess.run(command, cwd=folder, stdout=subprocess.DEVNULL, stderr=err,
                                timeout=TIMEOUT_S).returncode
    path = os.path.join(folder, "metrics.json")
    metrics = {}
    if status == 0 and os.path.exists(path):
        with open(path) as f:
            metrics = json.load(f)
    return status, metrics


def main():
    if len(sys.argv) < 3:
        print(__doc__)
        return 2
    linux, windows, args = sys.argv[1], sys.argv[2], sys.argv[3:]
    if not os.path.isfile(windows):
        print(f"SKIP: {windows} was not built (scripts/odelab.sh windows builds it)")
        return 77
    failures = 0

    def fail(text):
        nonlocal failures
        failures += 1
        print("FAIL: " + text)

    with tempfile.TemporaryDirectory(prefix="odelab_windows.") as root:
        results = {}
        for name, command in (("linux", [linux]), ("windows", ["wine", windows])):
            folder = os.path.join(root, name)
            os.mkdir(folder)
            full = command + ["--headless", *args, "--out-dir", ".", "--metrics-json", "metrics.json"]
            try:
                status, metrics = run(full, folder)
            except FileNotFoundError:
                status, metrics = "not written", {}
            if status != 0:
                with open(os.path.join(folder, "stderr.txt"), errors="replace") as f:
                    fail(f"the {name} run ended with status {status}: {f.read()[-600:]}")
                return 1
            outputs = sorted(f for f in os.listdir(folder) if f not in ("metrics.json", "stderr.txt"))
            results[name] = (metrics, outputs, folder)

        (lm, lout, ldir), (wm, wout, wdir) = results["linux"], results["windows"]
        if sorted(lm) != sorted(wm):
            fail(f"different metrics: only on Linux {sorted(set(lm) - set(wm))}, "
                 f"only on Windows {sorted(set(wm) - set(lm))}")
        compared = [k for k in lm if k in wm and k not in CLOCK]
        differing = [k for k in compared if lm[k] != wm[k]]
        for k in differing:
            fail(f"{k}: {lm[k]} on Linux, {wm[k]} on Windows")
        if "state_hash" in lm and lm["state_hash"] == wm.get("state_hash"):
            print(f"ok:   state_hash {lm['state_hash']} on both")
        print(f"ok:   {len(compared) - len(differing)} of {len(compared)} metrics equal "
              f"(left out, the clock's: {', '.join(k for k in lm if k in CLOCK)})")

        if lout != wout:
            fail(f"different output files: {lout} on Linux, {wout} on Windows")
        for name in lout:
            if name not in wout:
                continue
            with open(os.path.join(ldir, name), "rb") as f:
                a = f.read()
            with open(os.path.join(wdir, name), "rb") as f:
                b = f.read()
            if a != b:
                fail(f"{name} differs ({len(a)} bytes on Linux, {len(b)} on Windows)")
                continue
            last = b.rstrip(b"\n").rsplit(b"\n", 1)[-1]
            if name.endswith("_output.txt") and not last.startswith(b"# complete"):
                fail(f"{name} does not end with its '# complete' line")
            else:
                print(f"ok:   {name} identical ({len(a)} bytes), ending {last[:60].decode(errors='replace')!r}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
