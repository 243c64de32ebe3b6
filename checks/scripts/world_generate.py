#!/usr/bin/python3
"""Random world files the schema accepts, each run as a user would run it.

Unlike world_fuzz.py (valid worlds broken one way), this makes worlds from
nothing: bodies, geoms, joints, surfaces, measures and events drawn at random
within the ranges the reader enforces (`world_read_tool ranges`, the one
table doc/world.schema.json is written from), at their edges as well as in
their middles, gravity along any direction. Every world must pass the schema
(else the generator is wrong, and says so). Then, for each world:

  odelab --world W --export-world E     reads and builds it in ODE and writes what ODE holds,
                                        or refuses it (status 2, one line naming a field)
  the export E passes the schema, and odelab --world E --headless --seconds S reads it back,
                                        builds it and runs it (status 0, or 3 for a blow-up, which is physics)
  odelab --world W --engine X (every --engine-every'th world, each engine named) runs or refuses as above

Never: a signal (134 abort, 139 segfault), status 4 (ODE's internal error)
but for dWorldStep's singular LCP (DWORLDSTEP_SINGULAR below), status 1, a hang, an export the schema or the reader refuses. The same --seed
gives the same worlds; a failing world stays under --work. Exit 0: all held.
Prints the time taken and the counts of each outcome.
"""

import argparse
import json
import math
import os
import random
import re
import shutil
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor

SHAPES = ("box", "sphere", "capsule", "cylinder")
MEASURE_KINDS = ("energy", "momentum", "joint_error", "penetration", "rest")
FIELD = re.compile(r"(?:^|: |line \d+: )(?:world\.)?[a-z_$]+(?:\[\d+\])?(?:\.[a-z_]+(?:\[\d+\])?)*: ")


class Draw:
    """Numbers within the reader's ranges: mostly ordinary, now and then at a bound."""

    def __init__(self, rng, ranges):
        self.rng, self.ranges = rng, ranges

    def bound(self, name):
        return self.ranges[name]

    def real(self, name, usual=None, edge=0.05):
        low, high = self.bound(name)
        if self.rng.random() < edge:
            return self.rng.choice([low, high, (low + high) / 2])
        if usual:
            low, high = max(low, usual[0]), min(high, usual[1])
        if low > 0 and high / low > 1e3:  # a wide positive range: log-uniform
            return math.exp(self.rng.uniform(math.log(low), math.log(high)))
        return self.rng.uniform(low, high)

    def vector(self, name, n, usual, edge=0.03):
        return [self.real(name, usual, edge) for _ in range(n)]

    def unit(self, n=3):
        while True:
            v = [self.rng.gauss(0, 1) for _ in range(n)]
            norm = math.sqrt(sum(x * x for x in v))
            if norm > 1e-3:
                return [x / norm for x in v]


def settings(d):
    rng = d.rng
    s = {"step": d.real("settings.step", (1e-4, 0.02))}
    magnitude = rng.choice([0.0, 9.823, rng.uniform(0, d.ranges["gravity_magnitude"][1])])
    direction = d.unit() if rng.random() < 0.5 else [0.0, -1.0, 0.0]
    s["gravity"] = [magnitude * x for x in direction]
    for name in ("erp", "cfm", "sor_w"):
        if rng.random() < 0.6:
            s[name] = d.real("settings." + name)
    if rng.random() < 0.6:
        low, high = d.bound("settings.iterations")
        s["iterations"] = int(rng.choice([low, high, rng.randint(int(low), 200)]))
    if rng.random() < 0.5:
        s["solver"] = rng.choice(["quick", "step"])
    if rng.random() < 0.3:
        s["contact_max_correcting_velocity"] = rng.choice(["infinity", rng.uniform(0, 100)])
    if rng.random() < 0.3:
        s["contact_surface_layer"] = rng.uniform(0, 0.01)
    if rng.random() < 0.3:
        s["max_contacts"] = rng.randint(1, 64)
    if rng.random() < 0.4:
        s["space"] = rng.choice(["simple", "hash", "sap", "quadtree"])
    return s


def inertia(d, mass, size):
    """A positive-definite tensor near a solid's (sometimes rotated: off-diagonal terms)."""
    rng = d.rng
    principal = [mass * size * size * rng.uniform(0.05, 0.4) for _ in range(3)]
    principal = [min(max(p, 1e-30), d.bound("body.inertia[]")[1] / 3) for p in principal]
    if rng.random() < 0.3:
        # R diag(p) R^T for a random rotation about a random axis.
        ax = d.unit()
        angle = rng.uniform(0, math.pi)
        c, s_ = math.cos(angle), math.sin(angle)
        x, y, z = ax
        r = [[c + x * x * (1 - c), x * y * (1 - c) - z * s_, x * z * (1 - c) + y * s_],
             [y * x * (1 - c) + z * s_, c + y * y * (1 - c), y * z * (1 - c) - x * s_],
             [z * x * (1 - c) - y * s_, z * y * (1 - c) + x * s_, c + z * z * (1 - c)]]
        m = [[sum(r[i][k] * principal[k] * r[j][k] for k in range(3)) for j in range(3)] for i in range(3)]
        return [m[0][0], m[1][1], m[2][2], m[0][1], m[0][2], m[1][2]]
    return principal + [0.0, 0.0, 0.0]


def world(d, index):
    rng = d.rng
    w = {"format": "odelab-world", "version": 1, "title": "random world %d" % index, "settings": settings(d)}
    bodies, geoms, joints = [], [], []
    if rng.random() < 0.7:
        geoms.append({"shape": "plane", "body": -1, "plane": d.unit() + [rng.uniform(-2, 2)]})
    for _ in range(rng.randrange(0, 3)):
        geoms.append({"shape": "box", "body": -1, "size": d.vector("geom.size[]", 3, (0.1, 5)),
                      "position": d.vector("geom.position[]", 3, (-5, 5))})
    for b in range(rng.randrange(0, 7)):
        size = d.real("geom.radius", (0.05, 2), edge=0.02)
        mass = d.real("body.mass", (0.01, 100), edge=0.03)
        body = {"mass": mass, "inertia": inertia(d, mass, size), "position": d.vector("body.position[]", 3, (-5, 5))}
        if rng.random() < 0.3:
            body["orientation"] = d.unit(4)
        if rng.random() < 0.3:
            body["linear_velocity"] = d.vector("body.linear_velocity[]", 3, (-10, 10))
        if rng.random() < 0.3:
            body["angular_velocity"] = d.vector("body.angular_velocity[]", 3, (-10, 10))
        for flag in ("enabled", "kinematic", "gravity"):
            if rng.random() < 0.1:
                body[flag] = rng.random() < 0.5
        bodies.append(body)
        low, high = d.bound("geom.size[]")
        clamp = lambda x: min(max(x, low), high)  # noqa: E731
        for _ in range(1 if rng.random() < 0.8 else 2):
            shape = rng.choice(SHAPES)
            g = {"shape": shape, "body": b}
            if shape == "box":
                g["size"] = [clamp(size * rng.uniform(0.5, 2)) for _ in range(3)]
            else:
                g["radius"] = size
                if shape != "sphere":
                    g["length"] = rng.choice([0.0, clamp(size * rng.uniform(0.5, 3))])
            if rng.random() < 0.2:
                g["position"] = d.vector("geom.position[]", 3, (-0.5, 0.5))
                g["orientation"] = d.unit(4)
            if rng.random() < 0.1:
                g["category"], g["collide"] = rng.randrange(2 ** 32), rng.choice([0, 2 ** 32 - 1, rng.randrange(2 ** 32)])
            geoms.append(g)
    for _ in range(rng.randrange(0, len(bodies) + 1) if bodies else 0):
        kind = rng.choice(["ball", "hinge", "slider", "fixed"])
        b1 = rng.randrange(len(bodies))
        b2 = rng.choice([-1] + [i for i in range(len(bodies)) if i != b1])
        j = {"type": kind, "body1": b1, "body2": b2}
        if kind in ("ball", "hinge"):
            j["anchor"] = d.vector("joint.anchor[]", 3, (-5, 5))
        if kind in ("hinge", "slider"):
            j["axis"] = d.unit() if rng.random() < 0.8 else d.vector("joint.axis[]", 3, (-3, 3))
            if rng.random() < 0.3:
                low = rng.uniform(-3, 0)
                j["low_stop"], j["high_stop"] = low, low + rng.uniform(0, 3)
        if kind in ("ball", "fixed"):  # a hinge's or slider's own erp/cfm has no meaning in ODE: refused
            for name in ("erp", "cfm"):
                if rng.random() < 0.2:
                    j[name] = rng.random()
        joints.append(j)
    surfaces = []
    for _ in range(rng.randint(1, 3)):
        s = {"mu": rng.choice([0.0, "infinity", rng.uniform(0, 2)])}
        if rng.random() < 0.4:
            s["restitution"] = rng.random()
            if rng.random() < 0.5:
                s["bounce_velocity"] = rng.uniform(0, 1)
        for name in ("soft_erp", "soft_cfm"):
            if rng.random() < 0.2:
                s[name] = rng.random()
        if rng.random() < 0.2:
            s["friction_pyramid"] = rng.random() < 0.5
        surfaces.append(s)
    w.update(bodies=bodies, geoms=geoms, joints=joints, surfaces=surfaces,
             default_surface=rng.randrange(len(surfaces)))
    if len(geoms) >= 2 and rng.random() < 0.3:
        a, b = rng.sample(range(len(geoms)), 2)
        w["pair_surfaces"] = [{"geoms": [a, b], "surface": rng.randrange(len(surfaces))}]
    if rng.random() < 0.5:
        w["measures"] = [{"kind": k} for k in rng.sample(MEASURE_KINDS, rng.randint(1, 3))]
        if bodies and rng.random() < 0.3:
            w["measures"].append({"kind": "ballistic", "body": rng.randrange(len(bodies))})
    free = [b for b in range(len(bodies)) if not any(b in (j["body1"], j["body2"]) for j in joints)]
    if bodies and rng.random() < 0.3:
        events, at = [], 0.0
        dropped = set(rng.sample(free, rng.randint(0, len(free)))) if free else set()
        for b in sorted(dropped):
            at += rng.uniform(0, 0.01)
            events.append({"at": at, "drop": b})
        for _ in range(rng.randint(0, 2)):
            at += rng.uniform(0, 0.01)
            events.append({"at": at, "push": rng.randrange(len(bodies)),
                           "impulse": d.vector("event.impulse[]", 3, (-5, 5))})
        w["events"] = events
    return w


def schema_errors(validator, data):
    return ["%s: %s" % ("/".join(str(p) for p in e.absolute_path) or "(top)", e.message)
            for e in validator.iter_errors(data)][:3]


def run(cmd, cwd, timeout):
    try:
        done = subprocess.run(cmd, cwd=cwd, stdin=subprocess.DEVNULL, capture_output=True, timeout=timeout)
        return done.returncode, done.stdout.decode(errors="replace"), done.stderr.decode(errors="replace")
    except subprocess.TimeoutExpired:
        return "hang", "", ""


# ODE's big-matrix solver (dWorldStep) fails its own quaternion check on some
# valid worlds (deep overlaps, CFM 0, unbounded friction make its LCP singular:
# doc/hardening.md, "The 18 ODE errors"). That is ODE's verdict on the world,
# ended cleanly with status 4 and a message naming the time and the settings;
# the same status from QuickStep, or without that message, is still a failure.
DWORLDSTEP_SINGULAR = re.compile(r'assertion "!bSafeNormalize4Fault" failed in dxNormalize4\(\).* at t=\S+ s \(.*solver step,')


def judge(status, out, err, seconds):
    """'' when the answer is one a valid world may get; else what was wrong."""
    if status == 0 or status == 3:
        return ""
    if status == 4 and DWORLDSTEP_SINGULAR.search(err):
        return ""
    if status == 2:
        text = err.strip()
        if not FIELD.search(text):
            return "status 2 without naming a field: %r" % text[-300:]
        return ""
    if status == "hang":
        return "no answer within the time limit"
    if isinstance(status, int) and status < 0:
        return "killed by signal %d" % -status
    return "status %s: %r" % (status, err.strip()[-300:])


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--odelab", required=True)
    parser.add_argument("--tool", required=True, help="checks' world_read_tool (the reader's ranges)")
    parser.add_argument("--schema", required=True)
    parser.add_argument("--work", required=True)
    parser.add_argument("--seed", type=int, default=51)
    parser.add_argument("--count", type=int, default=2000)
    parser.add_argument("--seconds", type=float, default=0.02, help="simulated seconds each world runs")
    parser.add_argument("--engines", default="", help="engines to run worlds on, comma-separated")
    parser.add_argument("--engine-every", type=int, default=40, help="every Nth world also runs on each engine")
    parser.add_argument("--timeout", type=float, default=60)
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 2, help="worlds run at once")
    args = parser.parse_args()
    args.odelab, args.work = os.path.abspath(args.odelab), os.path.abspath(args.work)

    import jsonschema
    with open(args.schema) as f:
        validator = jsonschema.Draft202012Validator(json.load(f))
    ranges = json.loads(subprocess.run([args.tool, "ranges"], check=True, capture_output=True, text=True).stdout)
    draw = Draw(random.Random(args.seed), ranges)
    shutil.rmtree(args.work, ignore_errors=True)
    os.makedirs(args.work)
    engines = [e for e in args.engines.replace(";", ",").split(",") if e]
    worlds = [world(draw, i) for i in range(args.count)]  # drawn in order: the seed fixes them all

    def one(i):
        """(path, what was wrong, odelab's status on the world)."""
        w = worlds[i]
        folder = os.path.join(args.work, "%04d" % i)
        os.makedirs(folder)
        path = os.path.join(folder, "world.json")
        with open(path, "w") as f:
            json.dump(w, f, indent=1)
        wrong = ["the generator made a world the schema refuses: %s" % e for e in schema_errors(validator, w)]
        exported = os.path.join(folder, "exported.json")
        status, out, err = run([args.odelab, "--world", path, "--export-world", exported], folder, args.timeout)
        what = judge(status, out, err, args.seconds)
        if what:
            wrong.append("odelab --world --export-world: " + what)
        # Three to 50 steps: a run shorter than one step is refused for its --seconds, and
        # 20,000 steps of 1 us at 10,000 iterations would be a long run, not a reader's check.
        step = w["settings"]["step"]
        seconds = max(3 * step, min(args.seconds, 50 * step))
        common = ["--headless", "--seconds", repr(seconds), "--out-dir", folder]
        if status == 0:
            try:
                with open(exported) as f:
                    wrong += ["the export fails the schema: %s" % e for e in schema_errors(validator, json.load(f))]
            except (OSError, ValueError) as error:
                wrong.append("the export cannot be read: %s" % error)
            status, out2, err2 = run([args.odelab, "--world", exported] + common, folder, args.timeout)
            if status == 2:
                wrong.append("the export does not read back: %s" % err2.strip()[-300:])
            elif judge(status, out2, err2, args.seconds):
                wrong.append("the export does not read back and run: %s" % judge(status, out2, err2, args.seconds))
        if engines and i % args.engine_every == 0:
            for engine in engines:
                status3, out3, err3 = run([args.odelab, "--world", path, "--engine", engine] + common, folder, args.timeout)
                what = judge(status3, out3, err3, args.seconds)
                if what:
                    wrong.append("--engine %s: %s" % (engine, what))
        if not wrong:
            shutil.rmtree(folder)
        return path, wrong, status

    started = time.monotonic()
    failures, outcomes = [], {}
    with ThreadPoolExecutor(max_workers=args.jobs) as pool:
        for path, wrong, status in pool.map(one, range(args.count)):
            outcomes[status] = outcomes.get(status, 0) + 1
            if wrong:
                failures.append((path, wrong))
    elapsed = time.monotonic() - started
    for path, wrong in failures[:20]:
        print("FAIL %s:\n  %s" % (path, "\n  ".join(wrong)))
    print("%d random worlds in %.0f s (%.0f ms each), seed %d, engines every %dth world: %s; statuses of the runs: %s; %d failed"
          % (args.count, elapsed, 1000 * elapsed / max(1, args.count), args.seed, args.engine_every,
             ", ".join(engines) or "none", ", ".join("%s: %d" % kv for kv in sorted(outcomes.items(), key=str)),
             len(failures)))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
