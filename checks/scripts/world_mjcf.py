#!/usr/bin/env python3
"""MJCF in (doc/world-format.md, "MJCF"): each example of doc/worlds/mjcf/ is
read by MuJoCo's loader and translated; its --export-world JSON must hold
the MJCF's own figures (counts; masses, inertias, poses, joint anchor and axis
turned from MuJoCo's z-up to y-up, within 1e-9), and a run on ODE must show
the physics the MJCF states:
- hinge_pendulum.xml: the exported world with a `period` measure added swings
  within 1% of the compound pendulum's period, 2 pi sqrt(I / (m g L)), with
  the 5 degree start's correction (1 + theta^2 / 16);
  with a hinge range (written into a copy), its stops are MuJoCo's and hold
  on the same side: a range of [-0.01, 60] degrees holds the pendulum where
  gravity pulls it to -5 degrees (it never swings), [-60, 0.01] does not;
- box_on_slope.xml: the cube holds on the 20 degree slope (energy within
  1e-3 of its start over 2 s), which it does only if the pair takes the
  larger friction (1, above tan 20 deg); the slope's 0.3 lets it slide.
A body whose principal axes are turned from its frame (tilted_inertia.xml)
exports the full tensor R diag(I) R^T in its own frame, a sphere that touches
nothing as its geom (it has <inertial> only), and the ball welded to it a
fixed joint, the bodies in MuJoCo's order.
And the refusals, each status 2 before anything runs, naming what was wrong:
an ellipsoid geom, a damped hinge, a file MuJoCo refuses (its text and path).
Usage: world_mjcf.py ODELAB EXAMPLES_DIR REFUSALS_DIR
Exit 0: all hold; 1: a failure, printed."""

import json
import math
import os
import sys
import tempfile

import world_import_check as check
from world_import_check import (TOLERANCE, about_y, close, counts, expect, failures, metric, metrics_of, run,
                                y_up, y_up_quat)

check.FORMAT = "MJCF"


def export(odelab, source, folder):
    out = os.path.join(folder, os.path.basename(source) + ".json")
    done = run(odelab, "--world", source, "--headless", "--export-world", out)
    expect(done.returncode == 0, "%s: --export-world exited %d: %s" % (source, done.returncode, done.stderr))
    notes = [line for line in done.stderr.splitlines() if "--world: note:" in line]
    expect(len(notes) == len(set(notes)), "%s: a note said twice: %s" % (source, notes))
    expect(any("solref not carried" in n for n in notes), "%s: no solref note on stderr" % source)
    expect(any("solimp not carried" in n for n in notes), "%s: no solimp note on stderr" % source)
    with open(out) as f:
        return out, json.load(f)


def pendulum(odelab, examples, folder):
    source = os.path.join(examples, "hinge_pendulum.xml")
    path, world = export(odelab, source, folder)
    counts(world, 1, 2, 1, source)
    length, radius, mass, g, tilt = 1.0, 0.05, 1.0, 9.81, 5.0
    body = world["bodies"][0]
    expect(abs(body["mass"] - mass) <= TOLERANCE, "pendulum mass %s" % body["mass"])
    moment = 0.4 * mass * radius ** 2
    close(body["inertia"], [moment, moment, moment, 0, 0, 0], "pendulum inertia")
    t = math.radians(tilt)
    close(body["position"], y_up([-math.sin(t) * length, 0, 2 - math.cos(t) * length]), "pendulum centre of mass")
    close(body["orientation"], y_up_quat(about_y(tilt)), "pendulum orientation")
    joint = world["joints"][0]
    expect(joint["type"] == "hinge" and joint["body1"] == 0 and joint["body2"] == -1, "pendulum joint %s" % joint)
    close(joint["anchor"], y_up([0, 0, 2]), "hinge anchor")
    close(joint["axis"], y_up([0, 1, 0]), "hinge axis")
    close(world["settings"]["gravity"], y_up([0, 0, -g]), "gravity")
    expect(world["settings"]["step"] == 0.001, "step %s" % world["settings"]["step"])
    # The compound pendulum about its pivot, with the finite swing's first correction.
    expected = 2 * math.pi * math.sqrt((mass * length ** 2 + moment) / (mass * g * length)) * (1 + t ** 2 / 16)
    world["measures"] = [{"kind": "period", "body": 0, "axis": "x", "about": 0.0, "expected": expected, "name": "swing"}]
    timed = os.path.join(folder, "hinge_pendulum_timed.json")
    with open(timed, "w") as f:
        json.dump(world, f)
    metrics = metrics_of(odelab, timed, folder, 10.2)
    error = metric(metrics, "swing_period_error")
    print("hinge_pendulum: period %s s, expected %.6f s, error %s" % (metric(metrics, "swing_period_s"), expected, error))
    expect(error is not None and abs(error) < 0.01, "pendulum period error %s, bound 1%%" % error)
    limited(odelab, source, folder)


def limited(odelab, source, folder):
    """The hinge's range on both sides: MuJoCo's qpos and ODE's hinge angle
    must grow the same way, or the stop holds the wrong swing."""
    with open(source) as f:
        text = f.read()
    hinge = '<joint name="pivot" type="hinge" axis="0 1 0"/>'
    expect(hinge in text, "hinge_pendulum.xml: no %s to limit" % hinge)
    for low, high, swings in [(-0.01, 60, False), (-60, 0.01, True)]:
        copy = os.path.join(folder, "limited_%s.xml" % swings)
        with open(copy, "w") as f:
            f.write(text.replace(hinge, hinge[:-2] + ' limited="true" range="%s %s"/>' % (low, high)))
        path, world = export(odelab, copy, folder)
        joint = world["joints"][0]
        close([joint["low_stop"], joint["high_stop"]], [math.radians(low), math.radians(high)], "hinge stops")
        world["measures"] = [{"kind": "period", "body": 0, "axis": "x", "about": 0.0, "expected": 2.0, "name": "swing"}]
        with open(path, "w") as f:
            json.dump(world, f)
        swung = metric(metrics_of(odelab, path, folder, 3), "swing_period_s") is not None
        expect(swung == swings, "hinge range [%s, %s] deg: swings %s, MuJoCo's stop gives %s" % (low, high, swung, swings))


def ball(odelab, examples, folder):
    source = os.path.join(examples, "ball_on_plane.xml")
    _, world = export(odelab, source, folder)
    counts(world, 1, 2, 0, source)
    radius = 0.1
    mass = 1000 * 4 / 3 * math.pi * radius ** 3
    body = world["bodies"][0]
    expect(abs(body["mass"] - mass) <= TOLERANCE * mass, "ball mass %s, MJCF gives %s" % (body["mass"], mass))
    moment = 0.4 * mass * radius ** 2
    close(body["inertia"], [moment, moment, moment, 0, 0, 0], "ball inertia")
    close(body["position"], y_up([0, 0, 1]), "ball position")
    plane = [g for g in world["geoms"] if g["shape"] == "plane"]
    expect(len(plane) == 1, "ball: one plane")
    if plane:
        close(plane[0]["plane"], [0, 1, 0, 0], "floor plane")
    mus = [s["mu"] for s in world["surfaces"]]
    expect(mus == [0.8], "ball: surfaces' mu %s, MuJoCo's pair rule gives max(0.8, 0.5) = 0.8" % mus)


def slope(odelab, examples, folder):
    source = os.path.join(examples, "box_on_slope.xml")
    _, world = export(odelab, source, folder)
    counts(world, 1, 2, 0, source)
    side, tilt = 0.2, 20.0
    mass = 1000 * side ** 3
    body = world["bodies"][0]
    expect(abs(body["mass"] - mass) <= TOLERANCE * mass, "cube mass %s, MJCF gives %s" % (body["mass"], mass))
    moment = mass * side ** 2 / 6
    close(body["inertia"], [moment, moment, moment, 0, 0, 0], "cube inertia")
    close(body["position"], y_up([0.06840402866, 0, 0.18793852416]), "cube position")
    close(body["orientation"], y_up_quat(about_y(tilt)), "cube orientation")
    static = [g for g in world["geoms"] if g["body"] == -1]
    expect(len(static) == 1 and static[0]["shape"] == "box", "slope: one static box")
    if static:
        close(static[0]["size"], [2, 1, 0.2], "slope sides")
        close(static[0]["orientation"], y_up_quat(about_y(tilt)), "slope orientation")
    expect([s["mu"] for s in world["surfaces"]] == [1], "slope: the pair's mu %s, MuJoCo's rule gives 1" % world["surfaces"])
    world["measures"] = [{"kind": "energy"}]
    measured = os.path.join(folder, "box_on_slope_energy.json")
    with open(measured, "w") as f:
        json.dump(world, f)
    metrics = metrics_of(odelab, measured, folder, 2)
    deviation = metric(metrics, "energy_max_deviation")
    print("box_on_slope: energy_max_deviation %s over 2 s" % deviation)
    expect(deviation is not None and deviation < 1e-3, "cube slid: energy_max_deviation %s, bound 1e-3" % deviation)


def tilted(odelab, refused, folder):
    source = os.path.join(refused, "tilted_inertia.xml")
    _, world = export(odelab, source, folder)
    counts(world, 2, 2, 1, source)
    c, s = math.cos(math.radians(30)), math.sin(math.radians(30))
    d = [0.1, 0.2, 0.3]
    frame = world["bodies"][0]
    expect(abs(frame["mass"] - 2) <= TOLERANCE, "tilted body mass %s" % frame["mass"])
    close(frame["inertia"], [d[0] * c * c + d[1] * s * s, d[0] * s * s + d[1] * c * c, d[2], (d[0] - d[1]) * c * s, 0, 0],
          "tilted inertia in the body's frame")
    close(frame["position"], y_up([0, 0, 1]), "tilted body position")
    close(world["bodies"][1]["position"], y_up([0.5, 0, 1]), "welded ball position")
    marker = [g for g in world["geoms"] if g["body"] == 0]
    expect(len(marker) == 1 and marker[0]["shape"] == "sphere" and marker[0].get("collide") == 0
           and marker[0].get("category") == 0, "tilted body: one sphere that touches nothing, got %s" % marker)
    joint = world["joints"][0]
    expect(joint["type"] == "fixed" and {joint["body1"], joint["body2"]} == {0, 1}, "welded ball: fixed joint, got %s" % joint)


def refusals(odelab, folder):
    for name, needle in [("ellipsoid.xml", "geom 'egg' is of type ellipsoid"),
                         ("damped_hinge.xml", "joint 'elbow' has damping 0.5"),
                         ("broken.xml", "MuJoCo refused it: XML parse error")]:
        source = os.path.join(folder, name)
        done = run(odelab, "--world", source, "--headless", "--seconds", "0.01")
        expect(done.returncode == 2, "%s: status %d, expected 2 (stderr: %s)" % (name, done.returncode, done.stderr))
        expect(needle in done.stderr and source in done.stderr,
               "%s: stderr does not name %r and the path: %s" % (name, needle, done.stderr))


def main():
    odelab, examples, refused = sys.argv[1:4]  # refused: the check's own files, refused or not
    with tempfile.TemporaryDirectory() as folder:
        # A part whose run wrote nothing fails alone; the others still run.
        for part, source in [(pendulum, examples), (ball, examples), (slope, examples), (tilted, refused)]:
            try:
                part(odelab, source, folder)
            except (OSError, ValueError, KeyError, IndexError) as error:
                expect(False, "%s: %s: %s" % (part.__name__, type(error).__name__, error))
    refusals(odelab, refused)
    print("%d failure(s)" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
