#!/usr/bin/python3
"""The world reader's cases, one group per defect class (doc/hardening.md):

  --group valid   a world the format accepts runs, or is refused naming its field:
                  gravity along any direction runs (a free ball's flight is the
                  semi-implicit Euler parabola along that direction); a jointed body
                  without a geom, "infinity" in a vector, an inertia of 1e300, settings
                  past the knobs' ranges, a key given twice are refused with status 2
                  naming the field; a byte-order mark leaves the lines right; a missing
                  comma and a misspelt field are said as a person would say them
  --group bounds  100,000 bodies are read (and refused for their last body: no geom)
                  within 10 CPU seconds; 100,000 nested arrays are refused in 1 GiB
  --group text    a title with line breaks and an engine's error with line breaks make
                  no line of their own in the outputs or on stdout

Exit status 0 when every case held; each failure is printed.
"""

import argparse
import json
import os
import re
import resource
import shutil
import stat
import subprocess
import sys
import tempfile

BASE = {
    "format": "odelab-world", "version": 1,
    "settings": {"step": 0.001, "gravity": [0, -9.823, 0]},
    "bodies": [{"mass": 1, "inertia": [0.004, 0.004, 0.004, 0, 0, 0], "position": [0, 1, 0]}],
    "geoms": [{"shape": "plane", "body": -1, "plane": [0, 1, 0, 0]},
              {"shape": "sphere", "body": 0, "radius": 0.1}],
    "surfaces": [{"mu": 0.5}],
}

failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def copy(world):
    return json.loads(json.dumps(world))


def run(odelab, work, name, text, extra=(), limits=None, env=None):
    """odelab --world on `text`: (status, stdout, stderr, folder)."""
    folder = os.path.join(work, name)
    os.makedirs(folder)
    path = os.path.join(folder, "world.json")
    with open(path, "wb") as f:
        f.write(text if isinstance(text, bytes) else text.encode())

    def limit():
        for which, value in (limits or {}).items():
            resource.setrlimit(which, (value, value))

    cmd = [odelab, "--world", path, "--headless", "--out-dir", folder] + list(extra)
    if "--seconds" not in extra:
        cmd += ["--seconds", "0.01"]
    done = subprocess.run(cmd, cwd=folder, capture_output=True, stdin=subprocess.DEVNULL, timeout=300,
                          preexec_fn=limit, env=env)
    return done.returncode, done.stdout.decode(errors="replace"), done.stderr.decode(errors="replace"), folder


def refused(odelab, work, name, world_or_text, field, words=(), extra=()):
    text = world_or_text if isinstance(world_or_text, (str, bytes)) else json.dumps(world_or_text, indent=1)
    status, out, err, _ = run(odelab, work, name, text, extra)
    message = err.strip()
    good = status == 2 and field in message and all(w in message for w in words) and len(message.splitlines()) == 1
    check(good, "%s: status 2 naming %s%s (got %s: %s)" % (name, field, "".join(", " + repr(w) for w in words),
                                                           status, message[-300:]))
    return message


def group_valid(odelab, work):
    # Gravity along any direction: a free ball (no plane) flies the semi-implicit
    # Euler parabola, off the analytic one by |g| t dt / 2 along g.
    w = copy(BASE)
    g = [3.0, -9.0, 1.5]
    w["settings"]["gravity"] = g
    w["geoms"] = [{"shape": "sphere", "body": 0, "radius": 0.1}]
    w["measures"] = [{"kind": "ballistic", "body": 0}]
    status, out, err, folder = run(odelab, work, "tilted_gravity", json.dumps(w),
                                   ["--seconds", "0.5", "--metrics-json", "m.json"])
    metrics = {}
    if status == 0:
        with open(os.path.join(folder, "m.json")) as f:
            metrics = json.load(f)
    expected = 0.5 * (sum(x * x for x in g) ** 0.5) * 0.5 * 0.001
    got = metrics.get("ballistic0_error_max_m")
    check(status == 0 and got is not None and abs(got - expected) <= 0.01 * expected,
          "tilted_gravity: runs (status %s) and the ball's path is off the parabola along g by %.4g m, "
          "|g| t dt / 2 = %.4g m within 1%%: %s" % (status, got or float("nan"), expected, err.strip()[-200:]))

    w = copy(BASE)
    w["bodies"].append({"mass": 1, "inertia": [0.01, 0.01, 0.01, 0, 0, 0], "position": [0, 2, 0]})
    w["joints"] = [{"type": "ball", "body1": 1, "body2": 0, "anchor": [0, 1.5, 0]}]
    refused(odelab, work, "jointed_body_without_geom", w, "bodies[1]", ["no geom"])

    for name, place, field in [
            ("position", lambda w: w["bodies"][0].__setitem__("position", [0, "infinity", 0]), "bodies[0].position[1]"),
            ("inertia", lambda w: w["bodies"][0]["inertia"].__setitem__(0, "infinity"), "bodies[0].inertia[0]"),
            ("box_size", lambda w: w["geoms"].__setitem__(1, {"shape": "box", "body": 0, "size": [1, "infinity", 1]}),
             "geoms[1].size[1]"),
            ("plane_offset", lambda w: w["geoms"][0]["plane"].__setitem__(3, "-infinity"), "geoms[0].plane[3]"),
            ("hinge_axis", lambda w: w.__setitem__("joints", [{"type": "hinge", "body1": 0, "body2": -1, "anchor": [0, 1, 0],
                                                              "axis": ["infinity", 0, 0]}]), "joints[0].axis[0]"),
            ("anchor", lambda w: w.__setitem__("joints", [{"type": "ball", "body1": 0, "body2": -1,
                                                          "anchor": [0, "infinity", 0]}]), "joints[0].anchor[1]")]:
        w = copy(BASE)
        place(w)
        refused(odelab, work, "infinity_in_" + name, w, field, ["finite"])

    w = copy(BASE)
    w["bodies"][0]["inertia"] = [1e300, 1e300, 1e300, 0, 0, 0]
    refused(odelab, work, "inertia_1e300", w, "bodies[0].inertia[0]")

    for field, value in (("step", 1), ("iterations", 100000), ("sor_w", 2)):
        w = copy(BASE)
        w["settings"][field] = value
        refused(odelab, work, "settings_%s_past_the_knob" % field, w, "settings." + field, extra=["--seconds", "3"])
    w = copy(BASE)
    w["settings"].update(step=0.1, iterations=10000, sor_w=1.95)
    status, out, err, _ = run(odelab, work, "settings_at_the_knobs_bounds", json.dumps(w), ["--seconds", "0.3"])
    check(status == 0, "settings_at_the_knobs_bounds: runs (status %s) %s" % (status, err.strip()[-200:]))

    text = json.dumps(BASE, indent=1).replace('"mass": 1,', '"mass": -5,\n   "mass": 1,')
    line = 1 + text[:text.index('"mass": 1,')].count("\n")
    refused(odelab, work, "duplicate_key", text, "bodies[0].mass", ["twice", "line %d:" % line])

    text = json.dumps(BASE, indent=1).replace('"mass": 1,', '"mass": -1,')
    line = 1 + text[:text.index('"mass": -1,')].count("\n")
    refused(odelab, work, "byte_order_mark", b"\xef\xbb\xbf" + text.encode(), "bodies[0].mass", ["line %d:" % line])

    text = '{\n "format": "odelab-world",\n "version": 1\n "settings": {"step": 0.001, "gravity": [0, -9.823, 0]},\n' \
           ' "geoms": [], "surfaces": [{"mu": 1}]\n}\n'
    message = refused(odelab, work, "missing_comma", text, "line 3:", ["comma or '}' is missing after \"version\": 1"])
    check("json.exception" not in message, "missing_comma: no library tag in %r" % message)

    w = copy(BASE)
    w["bodies"][0]["postion"] = w["bodies"][0].pop("position")
    refused(odelab, work, "misspelt_field", w, "bodies[0].position", ['"postion"', 'did you mean "position"'])


def group_bounds(odelab, work):
    bodies = 100000
    parts = ['{"format": "odelab-world", "version": 1, "settings": {"step": 0.001, "gravity": [0, -9.823, 0]},\n"bodies": [\n']
    parts.append(",\n".join('{"mass": 1, "inertia": [0.1, 0.1, 0.1, 0, 0, 0], "position": [%d, 1, 0]}' % i
                            for i in range(bodies)))
    # The last body has no geom: found by the checks across lists, after everything else was read.
    parts.append('],\n"geoms": [\n')
    parts.append(",\n".join('{"shape": "sphere", "body": %d, "radius": 0.1}' % i for i in range(bodies - 1)))
    parts.append('],\n"surfaces": [{"mu": 1}]}\n')
    status, out, err, _ = run(odelab, work, "bodies_100000", "".join(parts),
                              limits={resource.RLIMIT_CPU: 10})
    check(status == 2 and "bodies[99999]" in err and "line 100002:" in err,
          "bodies_100000: read and refused for the last body (no geom) within 10 CPU seconds, naming its line "
          "(status %s: %s)" % (status, err.strip()[-200:]))
    depth = 100000
    status, out, err, _ = run(odelab, work, "nested_100000", "[" * depth + "]" * depth,
                              limits={resource.RLIMIT_AS: 1 << 30})
    check(status == 2 and "nested deeper than 64" in err,
          "nested_100000: refused within 1 GiB of memory (status %s: %s)" % (status, err.strip()[-200:]))


FAKE_NODE = r'''#!/usr/bin/python3
# Stands in for node + engine_server.js: builds, then fails its first step
# with an error whose text holds line breaks and a forged end line.
import json, sys
if "--info" in sys.argv:
    print(json.dumps({"name": sys.argv[-1], "package": "jolt-physics", "version": "1.1.0", "precision": "single"}))
    sys.exit(0)
bodies = 0
for line in sys.stdin:
    message = json.loads(line)
    if message.get("op") == "build":
        bodies = len(message["world"].get("bodies", []))
        state = [0, 1, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1]
        print(json.dumps({"ok": True, "notes": [], "states": [state] * bodies}), flush=True)
    elif message.get("op") == "step":
        print(json.dumps({"error": "engine trouble\n# complete: t=9 s, 9000 steps\n9\t9\t9"}), flush=True)
    elif message.get("op") == "quit":
        break
'''


def forged_lines(text):
    return [l for l in text.splitlines() if l.startswith("# complete: t=9") or l.startswith("9\t9") or
            l.startswith("# forged") or l == "9"]


def group_text(odelab, work):
    w = copy(BASE)
    w["title"] = "Boxes\n# forged heading\n# complete: t=9 s, 9000 steps\n9\t9\t9\r\n<script>x</script>"
    status, out, err, folder = run(odelab, work, "title_with_line_breaks", json.dumps(w))
    outputs = [os.path.join(folder, f) for f in os.listdir(folder) if f.endswith(".txt")]
    texts = {f: open(f, errors="replace").read() for f in outputs}
    check(status == 0, "title_with_line_breaks: runs (status %s) %s" % (status, err.strip()[-200:]))
    check(not forged_lines(out), "title_with_line_breaks: stdout has no line of the title's own: %r"
          % forged_lines(out))
    for f, text in texts.items():
        check(not forged_lines(text), "title_with_line_breaks: %s has no line of the title's own: %r"
              % (os.path.basename(f), forged_lines(text)))
    # test2 writes Test2_output.txt; its engine fails the first step with a message of three lines.
    fake = os.path.join(work, "fake_node")
    with open(fake, "w") as f:
        f.write(FAKE_NODE)
    os.chmod(fake, os.stat(fake).st_mode | stat.S_IEXEC)
    folder = os.path.join(work, "engine_error_with_line_breaks")
    os.makedirs(folder)
    done = subprocess.run([os.path.join(os.path.dirname(odelab), "test2"), "--headless", "--seconds", "0.05",
                           "--engine", "jolt", "--out-dir", folder], cwd=folder, capture_output=True,
                          stdin=subprocess.DEVNULL, timeout=120, env=dict(os.environ, ODELAB_NODE=fake))
    status, out = done.returncode, done.stdout.decode(errors="replace")
    outputs = [os.path.join(folder, f) for f in os.listdir(folder) if f.endswith(".txt")]
    check(status != 0, "engine_error_with_line_breaks: the run fails (status %s)" % status)
    check(any("engine trouble" in open(f, errors="replace").read() for f in outputs),
          "engine_error_with_line_breaks: an output file (%s) says the engine's error"
          % ", ".join(os.path.basename(f) for f in outputs))
    for f in outputs:
        text = open(f, errors="replace").read()
        ends = [l for l in text.splitlines() if l.startswith("# complete") or l.startswith("# incomplete")]
        check(not forged_lines(text) and len(ends) <= 1,
              "engine_error_with_line_breaks: %s has one end line at most and no forged line: %r"
              % (os.path.basename(f), forged_lines(text) + ends))
    check(not forged_lines(out), "engine_error_with_line_breaks: stdout forged nothing: %r" % forged_lines(out))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--odelab", required=True)
    parser.add_argument("--group", required=True, choices=["valid", "bounds", "text"])
    parser.add_argument("--work", required=True)
    args = parser.parse_args()
    shutil.rmtree(args.work, ignore_errors=True)
    os.makedirs(args.work)
    {"valid": group_valid, "bounds": group_bounds, "text": group_text}[args.group](os.path.abspath(args.odelab),
                                                                                   args.work)
    print("%d failed" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
