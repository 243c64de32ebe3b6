"""What the checks of the imported formats (world_mjcf.py, world_sdf.py)
share: the failure list and its assertions, the turn from a z-up format to
this one's y-up, and running odelab on a world. FORMAT ("MJCF", "SDF") names
the source in a failure's text."""

import json
import math
import os
import subprocess

TOLERANCE = 1e-9
FORMAT = "the source"
failures = []


def expect(condition, what):
    if not condition:
        failures.append(what)
        print("FAIL: " + what)


def close(a, b, what, tolerance=TOLERANCE):
    ok = len(a) == len(b) and all(abs(x - y) <= tolerance for x, y in zip(a, b))
    expect(ok, "%s: got %s, %s gives %s" % (what, a, FORMAT, b))


def y_up(v):
    return [v[0], v[2], -v[1]]


def quat_mul(a, b):
    w1, x1, y1, z1 = a
    w2, x2, y2, z2 = b
    return [w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2, w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
            w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2, w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2]


def y_up_quat(q):
    h = math.sqrt(0.5)
    return quat_mul([h, -h, 0, 0], q)


def about_y(degrees):
    a = math.radians(degrees) / 2
    return [math.cos(a), 0, math.sin(a), 0]


def run(odelab, *arguments):
    return subprocess.run([odelab, *arguments], capture_output=True, text=True, timeout=300)


def counts(world, bodies, geoms, joints, source):
    got = (len(world.get("bodies", [])), len(world["geoms"]), len(world.get("joints", [])))
    expect(got == (bodies, geoms, joints),
           "%s: bodies, geoms, joints %s, %s has %s" % (source, got, FORMAT, (bodies, geoms, joints)))


def metrics_of(odelab, world_path, folder, seconds, *more):
    out = os.path.join(folder, os.path.basename(world_path) + ".metrics.json")
    done = run(odelab, "--world", world_path, "--headless", "--seconds", str(seconds), "--metrics-json", out, *more)
    expect(done.returncode == 0, "%s: run exited %d: %s" % (world_path, done.returncode, done.stderr))
    with open(out) as f:
        return json.load(f)


def metric(metrics, name):
    # Metrics files hold the figures at the top level or under "metrics".
    if name in metrics:
        return metrics[name]
    return metrics.get("metrics", {}).get(name)
