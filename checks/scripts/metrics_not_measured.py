"""metrics_not_measured.py TESTS_DIR

Short headless runs whose scenes have figures that need time: exactly those
metrics are null (not measured) in --metrics-json, and every other value is
a finite number or a list of strings (utils/Metrics.h; doc/manual.md,
"Outputs"). Before the rule, null also stood for a measured NaN."""

import json
import math
import os
import subprocess
import sys
import tempfile

# program, seconds, the metrics not measured in that time
CASES = [
    ("test1", "0.05", {"max_rebound_error", "worst_ball"}),
    ("test2", "0.05", {"period_seconds", "period_error"}),
    ("test9", "0.05", {"apex_error_5", "apex_error_10", "apex_error_20", "last_apex_error"}),
]


def main():
    tests = sys.argv[1]
    failures = 0
    with tempfile.TemporaryDirectory() as folder:
        for program, seconds, expected in CASES:
            metrics_file = os.path.join(folder, program + ".json")
            done = subprocess.run([os.path.join(tests, program), "--headless", "--seconds", seconds,
                                   "--out-dir", folder, "--metrics-json", metrics_file],
                                  capture_output=True, text=True, timeout=60)
            if done.returncode != 0:
                print(f"FAIL: {program} --seconds {seconds}: status {done.returncode}: {done.stderr[-300:]}")
                failures += 1
                continue
            with open(metrics_file, encoding="utf-8") as stream:
                metrics = json.load(stream)
            not_measured = {name for name, value in metrics.items() if value is None}
            other = [f"{name} = {value!r}" for name, value in metrics.items()
                     if value is not None and not isinstance(value, list)
                     and not (isinstance(value, (int, float)) and math.isfinite(value))]
            lines = {line.split(" = ")[0] for line in done.stdout.splitlines() if line.endswith(" = not measured")}
            if not_measured != expected or other or lines != expected:
                print(f"FAIL: {program} --seconds {seconds}: null {sorted(not_measured)}, printed not measured "
                      f"{sorted(lines)}, expected {sorted(expected)}; not finite numbers: {other}")
                failures += 1
            else:
                print(f"ok:   {program} --seconds {seconds}: not measured {sorted(expected)}, the rest finite")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
