#!/usr/bin/python3
"""Malformed world files are refused, naming what is wrong (issue 38).

Starts from valid worlds (exported by test programs, and checks/worlds/fuzz_seed.json,
written by hand), breaks each copy in one way that the format (doc/world-format.md,
doc/worlds.md) forbids, and runs `odelab --world F --headless`. Every file must give
exit status 2, a short message on stderr naming the broken field's path (a parse
error: its line), no crash, no hang, and no run: no metrics file, nothing written.
The same --seed gives the same files. Exit status 0 only when every file held.
"""

import argparse
import json
import os
import random
import re
import shutil
import subprocess
import sys

HUGE = 2 ** 64 - 1  # a whole number JSON allows that no index can be: read as signed, -1

# The fields each object of the format may hold (a typo must not land on one of them).
FIELDS = {
    "world": "format version scene title time settings bodies geoms joints surfaces default_surface "
             "pair_surfaces measures events",
    "settings": "step gravity erp cfm solver iterations sor_w contact_max_correcting_velocity "
                "contact_surface_layer max_contacts space",
    "body": "mass inertia position orientation linear_velocity angular_velocity enabled kinematic gravity "
            "max_angular_speed auto_disable",
    "auto_disable": "on linear_threshold angular_threshold steps time average_samples",
    "geom": "shape body size radius length plane position orientation category collide",
    "joint": "type body1 body2 anchor axis low_stop high_stop erp cfm",
    "surface": "mu restitution bounce_velocity soft_erp soft_cfm friction_pyramid",
    "pair": "geoms surface",
    "measure": "kind scale linear_scale angular_scale geom body name until axis about expected speed "
               "angular_speed hold",
    "event": "at drop push impulse",
}
FIELDS = {kind: set(words.split()) for kind, words in FIELDS.items()}
LISTS = {"bodies": "body", "geoms": "geom", "joints": "joint", "surfaces": "surface",
         "pair_surfaces": "pair", "measures": "measure", "events": "event"}

# Values outside each scalar's documented range (every one of them malformed).
OUT_OF_RANGE = {
    ("settings", "step"): [0, -0.001, 2.0], ("settings", "erp"): [2, -0.5], ("settings", "cfm"): [-0.1],
    ("settings", "iterations"): [0, -3], ("settings", "max_contacts"): [0, -1], ("settings", "sor_w"): [-1.0],
    ("settings", "contact_max_correcting_velocity"): [-1.0], ("settings", "contact_surface_layer"): [-0.01],
    ("body", "mass"): [0, -1.0, -1e-3], ("body", "max_angular_speed"): [-1.0],
    ("auto_disable", "linear_threshold"): [-0.1], ("auto_disable", "steps"): [-1],
    ("auto_disable", "average_samples"): [0], ("auto_disable", "time"): [-1.0],
    ("geom", "radius"): [0, -0.2], ("geom", "length"): [-1.0],
    ("geom", "category"): [-1, 2 ** 32], ("geom", "collide"): [-1, 2 ** 32],
    ("joint", "erp"): [2, -0.1], ("joint", "cfm"): [-0.5],
    ("surface", "mu"): [-0.5], ("surface", "restitution"): [1.5, -0.1], ("surface", "bounce_velocity"): [-1.0],
    ("surface", "soft_erp"): [2, -0.2], ("surface", "soft_cfm"): [-1.0],
    ("measure", "scale"): [0, -1.0], ("measure", "linear_scale"): [-2.0], ("measure", "angular_scale"): [0],
    ("measure", "until"): [-1.0], ("measure", "expected"): [0, -1.6], ("measure", "speed"): [-0.01],
    ("measure", "angular_speed"): [-0.01], ("measure", "hold"): [-0.5],
    ("event", "at"): [-1.0], ("world", "time"): [-1.0], ("world", "version"): [0, 2],
}
# Text fields with a fixed set of words, and words outside it.
WORDS = {("world", "format"): ["odelab-worlds", "ODELAB-WORLD", ""], ("settings", "solver"): ["Quick", "quickstep"],
         ("settings", "space"): ["octree", "Simple"], ("geom", "shape"): ["sphre", "Box", "capsules", "mesh"],
         ("joint", "type"): ["hinges", "Ball", "universal"], ("measure", "kind"): ["energie", "Energy", "time"],
         ("measure", "axis"): ["w", "X", "xy"], ("measure", "name"): ["Ball", "my ball", ""]}


class Mutation:
    """One way a world was broken: the file's text and what its refusal must name."""

    def __init__(self, kind, detail, world=None, text=None, paths=(), span_paths=(), lines=None):
        self.kind, self.detail, self.world, self.text = kind, detail, world, text
        self.paths = list(paths)            # any of these named: the field is named
        self.span_paths = list(span_paths)  # a line inside one of these nodes' lines is the right line
        self.lines = lines                  # text mutations: (lowest, highest) line of the error


def render(value):
    """The JSON text (one value a line, as the exporter writes) and each node's first and last line."""
    out, spans = [], {}

    def emit(v, path, prefix, indent, tail):
        first = len(out) + 1
        pad = " " * (indent + 1)
        if isinstance(v, dict) and v:
            out.append(prefix + "{")
            for i, (k, x) in enumerate(v.items()):
                emit(x, path + (k,), pad + json.dumps(k) + ": ", indent + 1, "," if i < len(v) - 1 else "")
            out.append(" " * indent + "}" + tail)
        elif isinstance(v, list) and v:
            out.append(prefix + "[")
            for i, x in enumerate(v):
                emit(x, path + (i,), pad, indent + 1, "," if i < len(v) - 1 else "")
            out.append(" " * indent + "]" + tail)
        else:
            out.append(prefix + json.dumps(v, allow_nan=False) + tail)
        spans[path] = (first, len(out))

    emit(value, (), "", 0, "")
    return "\n".join(out) + "\n", spans


def path_text(path):
    text = ""
    for part in path:
        text += "[%d]" % part if isinstance(part, int) else ("." if text else "") + part
    return text


def nodes(world):
    """(path, object kind, field, value) of every field of every object in the world."""
    def walk(obj, path, kind):
        for key, value in obj.items():
            yield path + (key,), kind, key, value
            if kind == "world" and key in LISTS and isinstance(value, list):
                for i, item in enumerate(value):
                    if isinstance(item, dict):
                        yield from walk(item, path + (key, i), LISTS[key])
            elif kind == "world" and key == "settings":
                yield from walk(value, path + (key,), "settings")
            elif kind == "body" and key == "auto_disable":
                yield from walk(value, path + (key,), "auto_disable")
    yield from walk(world, (), "world")


def objects(world):
    yield (), "world", world
    for path, kind, key, value in nodes(world):
        if isinstance(value, dict):
            yield path, ("settings" if key == "settings" else "auto_disable" if key == "auto_disable"
                         else LISTS[path[-2]]), value


def numbers(world):
    """(path, kind, field) of every number, array elements included (field: the array's)."""
    for path, kind, key, value in nodes(world):
        if isinstance(value, bool):
            continue
        if isinstance(value, (int, float)) or value in ("infinity", "-infinity"):
            yield path, kind, key
        elif isinstance(value, list) and not (kind == "world"):
            for i, x in enumerate(value):
                if isinstance(x, (int, float)) and not isinstance(x, bool):
                    yield path + (i,), kind, key


def get(world, path):
    for part in path:
        world = world[part]
    return world


def put(world, path, value):
    get(world, path[:-1])[path[-1]] = value


def copy(world):
    return json.loads(json.dumps(world))


def required(kind, obj):
    """The fields of one object the format requires, given its shape, type or kind."""
    if kind == "world":
        return ["format", "version", "settings", "geoms", "surfaces"]
    if kind == "settings":
        return ["step", "gravity"]
    if kind == "body":
        return ["mass", "inertia", "position"]
    if kind == "geom":
        return ["shape", "body"] + {"box": ["size"], "sphere": ["radius"], "plane": ["plane"],
                                    "capsule": ["radius", "length"], "cylinder": ["radius", "length"]}[obj["shape"]]
    if kind == "joint":
        return ["type", "body1", "body2"] + (["anchor"] if obj["type"] in ("ball", "hinge") else []) + \
            (["axis"] if obj["type"] in ("hinge", "slider") else [])
    if kind == "surface":
        return ["mu"]
    if kind == "pair":
        return ["geoms", "surface"]
    if kind == "measure":
        return ["kind"] + {"tunnelling": ["geom"], "ballistic": ["body"],
                           "period": ["body", "axis", "about", "expected"]}.get(obj["kind"], [])
    if kind == "event":
        return ["at", "drop" if "drop" in obj else "push"] + (["impulse"] if "push" in obj else [])
    return []


# ---- the mutations: each returns a Mutation, or None where this world offers nothing to break.

def delete_required(world, rng):
    choices = [(path, kind, key) for path, kind, obj in objects(world) for key in required(kind, obj) if key in obj]
    path, kind, key = rng.choice(choices)
    w = copy(world)
    del get(w, path)[key]
    named = [path_text(path + (key,))] + ([path_text(path)] if kind == "event" else [])
    return Mutation("delete_required", "deleted " + path_text(path + (key,)), w, paths=named, span_paths=[path])


def wrong_type(world, rng):
    path, kind, key = rng.choice(list(numbers(world)) + [
        (p, k, f) for p, k, f, v in nodes(world) if isinstance(v, (bool, str)) and v not in ("infinity", "-infinity")])
    old = get(world, path)
    if isinstance(old, bool):
        new = rng.choice([1, 0, "true", None])
    elif isinstance(old, str) and old not in ("infinity", "-infinity"):
        new = rng.choice([3, None, True, [old]])
    else:
        new = rng.choice(["abc", "", "1.5", "inf", "NaN", [], [old], None, True, False, {}])
    w = copy(world)
    put(w, path, new)
    named = [path_text(path)] + ([path_text(path[:-1])] if isinstance(path[-1], int) else [])
    return Mutation("wrong_type", "%s: %s -> %s" % (path_text(path), json.dumps(old), json.dumps(new)), w,
                    paths=named, span_paths=[path, path[:-1]] if isinstance(path[-1], int) else [path])


WHOLE = {("world", "version"), ("world", "default_surface"), ("settings", "iterations"), ("settings", "max_contacts"),
         ("geom", "body"), ("geom", "category"), ("geom", "collide"), ("joint", "body1"), ("joint", "body2"),
         ("pair", "geoms"), ("pair", "surface"), ("measure", "body"), ("measure", "geom"), ("event", "drop"),
         ("event", "push"), ("auto_disable", "steps"), ("auto_disable", "average_samples")}


def fraction(world, rng):
    path, kind, key = rng.choice([n for n in numbers(world) if (n[1], n[2]) in WHOLE])
    w = copy(world)
    put(w, path, get(world, path) + 0.5)
    named = [path_text(path)] + ([path_text(path[:-1])] if isinstance(path[-1], int) else [])
    return Mutation("fraction_for_whole_number", "%s = %s" % (path_text(path), get(w, path)), w, paths=named,
                    span_paths=[path[:-1] if isinstance(path[-1], int) else path])


def out_of_range(world, rng):
    choices = [(p, k, f) for p, k, f, v in nodes(world) if (k, f) in OUT_OF_RANGE and not isinstance(v, str)]
    # a box's sides: each must be > 0
    choices += [(p + (i,), k, f) for p, k, f, v in nodes(world) if (k, f) == ("geom", "size") for i in range(3)]
    path, kind, key = rng.choice(choices)
    new = rng.choice([-0.1, 0.0, -2.0]) if key == "size" else rng.choice(OUT_OF_RANGE[(kind, key)])
    w = copy(world)
    put(w, path, new)
    named = [path_text(path)] + ([path_text(path[:-1])] if key == "size" else [])
    return Mutation("out_of_range", "%s = %s" % (path_text(path), new), w, paths=named,
                    span_paths=[path[:-1]] if key == "size" else [path])


def index_out_of_range(world, rng):
    count = {"body": len(world.get("bodies", [])), "geom": len(world["geoms"]), "surface": len(world["surfaces"])}
    choices = []
    for path, kind, key, value in nodes(world):
        if (kind, key) == ("geom", "body") and get(world, path[:-1])["shape"] != "plane":
            choices.append((path, "body", -2))
        elif (kind, key) in (("joint", "body1"), ("joint", "body2")):
            choices.append((path, "body", -2))
        elif (kind, key) in (("measure", "body"), ("event", "drop"), ("event", "push")):
            choices.append((path, "body", -1))
        elif (kind, key) == ("measure", "geom"):
            choices.append((path, "geom", -1))
        elif (kind, key) in (("pair", "surface"), ("world", "default_surface")):
            choices.append((path, "surface", -1))
        elif (kind, key) == ("pair", "geoms"):
            choices += [(path + (i,), "geom", -1) for i in range(2)]
    path, what, low = rng.choice(choices)
    new = rng.choice([count[what], count[what] + 7, low, HUGE, 2 ** 63])
    w = copy(world)
    put(w, path, new)
    named = [path_text(path)] + ([path_text(path[:-1])] if isinstance(path[-1], int) else [])
    return Mutation("index_out_of_range", "%s = %s (%s count %d)" % (path_text(path), new, what, count[what]), w,
                    paths=named, span_paths=[path[:-1] if isinstance(path[-1], int) else path])


def typo(word, rng):
    i = rng.randrange(len(word))
    return rng.choice([word[:i] + word[i + 1:], word[:i] + word[i] + word[i:], word + "s", word.capitalize(),
                       word.replace("_", "-") if "_" in word else word[:-1],
                       word[:i] + word[i + 1:i + 2] + word[i:i + 1] + word[i + 2:]])


def unknown_field(world, rng):
    path, kind, obj = rng.choice([o for o in objects(world) if o[2]])
    key = rng.choice(list(obj))
    for _ in range(50):
        wrong = typo(key, rng)
        if wrong and wrong not in FIELDS[kind] and wrong not in obj:
            break
    else:
        return None
    w = copy(world)
    target = get(w, path)
    items = list(target.items())
    items.insert(rng.randrange(len(items) + 1), (wrong, copy(obj[key])))
    target.clear()
    target.update(items)
    return Mutation("unknown_field", "%s beside %s" % (path_text(path + (wrong,)), key), w,
                    paths=[path_text(path + (wrong,))], span_paths=[path + (wrong,)])


def unknown_word(world, rng):
    path, kind, key = rng.choice([(p, k, f) for p, k, f, v in nodes(world) if (k, f) in WORDS and isinstance(v, str)])
    new = rng.choice(WORDS[(kind, key)])
    w = copy(world)
    put(w, path, new)
    return Mutation("unknown_word", "%s = %s" % (path_text(path), json.dumps(new)), w, paths=[path_text(path)],
                    span_paths=[path])


def non_unit_quaternion(world, rng):
    choices = [(("bodies", i), "orientation") for i in range(len(world.get("bodies", [])))]
    choices += [(("geoms", i), "orientation") for i, g in enumerate(world["geoms"]) if g["shape"] != "plane"]
    path, key = rng.choice(choices)
    new = rng.choice([[1, 1, 0, 0], [0, 0, 0, 0], [0.9, 0, 0, 0], [2, 0, 0, 0], [0.5, 0.5, 0.5, 0.4]])
    w = copy(world)
    get(w, path)[key] = new
    return Mutation("non_unit_quaternion", "%s = %s" % (path_text(path + (key,)), new), w,
                    paths=[path_text(path + (key,))], span_paths=[path + (key,)])


def inertia_not_positive_definite(world, rng):
    i = rng.randrange(len(world["bodies"]))
    xx, yy, zz = world["bodies"][i]["inertia"][:3]
    big = 2 * max(xx, yy, zz)
    new = rng.choice([
        [xx, yy, zz, big, 0, 0], [xx, yy, zz, 0, big, 0], [xx, yy, zz, 0, 0, big],
        # every 2x2 minor positive, the determinant negative: eigenvalues 1 + 2a and 1 - a (twice), a = -0.6
        [xx, xx, xx, -0.6 * xx, -0.6 * xx, -0.6 * xx],
        [xx, 0, zz, 0, 0, 0], [-xx, yy, zz, 0, 0, 0], [1, 1, 1, 5, 0, 0]])
    w = copy(world)
    w["bodies"][i]["inertia"] = new
    path = ("bodies", i, "inertia")
    return Mutation("inertia_not_positive_definite", "%s = %s" % (path_text(path), new), w,
                    paths=[path_text(path)], span_paths=[path])


def joint_to_itself(world, rng):
    i = rng.randrange(len(world["joints"]))
    w = copy(world)
    j = w["joints"][i]
    if j["body1"] >= 0:
        j["body2"] = j["body1"]
    else:
        j["body1"] = j["body2"]
    base = ("joints", i)
    return Mutation("joint_to_itself", "joints[%d]: body1 = body2 = %d" % (i, j["body1"]), w,
                    paths=[path_text(base), path_text(base + ("body1",)), path_text(base + ("body2",))],
                    span_paths=[base])


def bad_direction(world, rng):
    choices = [(("joints", i, "axis"), [[0, 0, 0]]) for i, j in enumerate(world.get("joints", [])) if "axis" in j]
    choices += [(("geoms", i, "plane"), [[0, 0, 0, g["plane"][3]], [0, 2, 0, g["plane"][3]], [0, 0.5, 0, 0]])
                for i, g in enumerate(world["geoms"]) if g["shape"] == "plane"]
    path, values = rng.choice(choices)
    new = rng.choice(values)
    w = copy(world)
    put(w, path, new)
    return Mutation("zero_axis_or_plane_normal_not_unit", "%s = %s" % (path_text(path), new), w,
                    paths=[path_text(path)], span_paths=[path])


def container_wrong_type(world, rng):
    choices = [((key,), rng.choice([{}, "x", 3, None])) for key in LISTS if key in world]
    choices += [(("settings",), rng.choice([[], 1, None, "quick"])), (("surfaces",), [])]
    for path, kind, key, value in nodes(world):
        if isinstance(value, dict):
            choices.append((path, rng.choice([[], 3, True, None])))
        elif (kind, key) in (("body", "inertia"), ("body", "position"), ("geom", "size"), ("joint", "anchor"),
                             ("event", "impulse"), ("pair", "geoms"), ("settings", "gravity")):
            choices.append((path, rng.choice([1.0, {"x": 0}, value[:-1], value + [0.0], "[0, 0, 0]"])))
    for key in LISTS:
        for i in range(len(world.get(key, []))):
            choices.append(((key, i), rng.choice([3, [], "x", None])))
    path, new = rng.choice(choices)
    w = copy(world)
    put(w, path, new)
    return Mutation("container_wrong_type", "%s -> %s" % (path_text(path), json.dumps(new)[:40]), w,
                    paths=[path_text(path)], span_paths=[path])


def top_level_not_object(world, rng):
    text = rng.choice(["[]\n", "42\n", '"odelab-world"\n', "null\n", "true\n", None])
    if text is None:
        text, _ = render([world])
    return Mutation("top_level_not_object", "the file is " + json.dumps(text[:20]), text=text,
                    paths=["world", "top level", "top-level"], lines=(1, text.count("\n") + 1))


# ---- text mutations: the file is no longer JSON; the error must name its line.

def parses(data):
    def refuse(token):
        raise ValueError(token)
    try:
        json.loads(data.decode("utf-8"), parse_constant=refuse)
        return True
    except ValueError:  # UnicodeDecodeError and JSONDecodeError are ValueErrors
        return False


def line_at(data, offset):
    return data.count(b"\n", 0, offset) + 1


def truncated(world, rng):
    text, _ = render(world)
    data = text.encode()
    cut = rng.randrange(0, data.rindex(b"}"))
    return Mutation("truncated", "cut at byte %d of %d" % (cut, len(data)), text=data[:cut],
                    lines=(line_at(data, cut), line_at(data, cut) + 1))


def byte_inserted(world, rng):
    data = render(world)[0].encode()
    for _ in range(200):
        at, byte = rng.randrange(len(data)), rng.randrange(256)
        out = data[:at] + bytes([byte]) + data[at:]
        if not parses(out):
            return Mutation("byte_inserted", "byte 0x%02x at offset %d" % (byte, at), text=out,
                            lines=(line_at(out, at), out.count(b"\n") + 1))
    return None


def number_text(world, rng, kind, tokens):
    """A number of the world replaced in the text by a token JSON cannot hold."""
    path, _, _ = rng.choice([n for n in numbers(world) if not isinstance(get(world, n[0]), str)])
    marker = "@@mutated@@"
    w = copy(world)
    put(w, path, marker)
    text, spans = render(w)
    token = rng.choice(tokens)
    # the parser may stop at the newline after the token: one line later
    return Mutation(kind, "%s = %s" % (path_text(path), token), text=text.replace('"%s"' % marker, token),
                    paths=[path_text(path)], lines=(spans[path][0], spans[path][1] + 1))


def number_overflow(world, rng):
    return number_text(world, rng, "number_overflow", ["1e999", "-1e999", "1e400", "-2e308"])


def invalid_number(world, rng):
    return number_text(world, rng, "invalid_number_literal",
                       ["NaN", "Infinity", "-Infinity", "0x10", "01", "+1", ".5", "1.", "1e", "--1", "inf"])


MUTATIONS = [delete_required, wrong_type, fraction, out_of_range, index_out_of_range, unknown_field, unknown_word,
             non_unit_quaternion, inertia_not_positive_definite, joint_to_itself, bad_direction,
             container_wrong_type, top_level_not_object, truncated, byte_inserted, number_overflow, invalid_number]


def applies(mutation, world):
    if mutation in (inertia_not_positive_definite, non_unit_quaternion):
        return bool(world.get("bodies"))
    if mutation is joint_to_itself:
        return bool(world.get("joints"))
    if mutation is bad_direction:
        return any("axis" in j for j in world.get("joints", [])) or any(g["shape"] == "plane" for g in world["geoms"])
    if mutation is unknown_word:
        return any((k, f) in WORDS and isinstance(v, str) for _, k, f, v in nodes(world))
    return True


# ---- running odelab on a file and judging what it did.

CRASH_WORDS = ["terminate called", "what():", "Aborted", "Segmentation", "core dumped", "AddressSanitizer",
               "runtime error", "Assertion", "assertion", "ODE INTERNAL ERROR", "ODE Message", "Traceback"]


# The mutations a JSON schema can see; the others (an index past its list, a
# quaternion's length, an inertia's definiteness, a joint's bodies) only the
# programs' reader can.
SCHEMA_KINDS = ("delete_required", "wrong_type", "fraction_for_whole_number", "out_of_range", "unknown_field",
                "unknown_word", "container_wrong_type", "top_level_not_object")


def schema_checker(path):
    import jsonschema  # python3-jsonschema: only this option needs it
    with open(path) as f:
        schema = json.load(f)
    jsonschema.Draft202012Validator.check_schema(schema)
    validator = jsonschema.Draft202012Validator(schema)

    def errors(data):
        try:
            world = json.loads(data)
        except ValueError as error:
            return ["not JSON: %s" % error]
        return [e.message for e in validator.iter_errors(world)]
    return errors


def run(odelab, world_file, run_dir, timeout):
    """(status or 'hang', stdout, stderr, files left in the output folder)."""
    os.makedirs(run_dir)
    metrics = os.path.join(run_dir, "metrics.json")
    cmd = [odelab, "--world", os.path.abspath(world_file), "--headless", "--seconds", "0.01",
           "--metrics-json", metrics, "--out-dir", run_dir]
    try:
        done = subprocess.run(cmd, cwd=run_dir, stdin=subprocess.DEVNULL, capture_output=True, timeout=timeout)
        status, out, err = done.returncode, done.stdout.decode(errors="replace"), done.stderr.decode(errors="replace")
    except subprocess.TimeoutExpired as expired:
        status = "hang (over %g s)" % timeout
        out = (expired.stdout or b"").decode(errors="replace")
        err = (expired.stderr or b"").decode(errors="replace")
    return status, out, err, sorted(os.listdir(run_dir))


def names(message, path):
    """Whether the message names the path as a field (top-level fields may read world.X)."""
    pattern = r"(?:^|[\s:'\"(])(?:world\.)?" + re.escape(path) + r"(?=$|[\s:,;'\")\[])"
    return re.search(pattern, message) is not None


def judge(m, spans, status, out, err, left, require_line):
    """What is wrong with odelab's answer to the mutation m (empty: it held)."""
    wrong = []
    if status != 2:
        wrong.append("exit status %s, not 2" % status)
    text = err.strip()
    if not text:
        wrong.append("nothing on stderr")
    if len(text.splitlines()) > 3:
        wrong.append("%d lines on stderr (a message is one line)" % len(text.splitlines()))
    wrong += ["stderr says %r (a crash)" % w for w in CRASH_WORDS if w in err]
    if left:
        wrong.append("files written: %s (nothing may run)" % ", ".join(left))
    if "state_hash" in out or "steps =" in out:
        wrong.append("metrics on stdout: the world ran")
    lines = [int(n) for n in re.findall(r"\bline (\d+)", text)]
    named = any(names(text, p) for p in m.paths)
    if m.lines is not None and m.paths and m.kind != "top_level_not_object":
        # a number JSON cannot hold: the parser may stop at its line, or the reader name its field
        in_range = any(m.lines[0] <= n <= m.lines[1] for n in lines)
        if not (in_range or named):
            wrong.append("names neither line %d nor %s" % (m.lines[0], m.paths[0]))
    elif m.lines is not None and m.kind != "top_level_not_object":
        if not any(m.lines[0] <= n <= m.lines[1] for n in lines):
            wrong.append("names no line in %d..%d (lines named: %s)" % (m.lines[0], m.lines[1], lines or "none"))
    else:
        if not named:
            wrong.append("does not name %s" % " or ".join(m.paths))
        if require_line:
            ranges = [spans[p] for p in m.span_paths if p in spans] if spans else [m.lines]
            if not any(a <= n <= b for n in lines for a, b in ranges):
                wrong.append("names no line in %s (lines named: %s)" % (
                    ", ".join("%d..%d" % r for r in ranges), lines or "none"))
    return wrong


def export_seeds(program_dir, programs, seed_dir, timeout):
    seeds = []
    for n in programs:
        target = os.path.join(seed_dir, "test%s.json" % n)
        done = subprocess.run([os.path.join(program_dir, "test%s" % n), "--export-world", target],
                              cwd=seed_dir, capture_output=True, timeout=timeout * 6)
        if done.returncode != 0 or not os.path.exists(target):
            sys.exit("world_fuzz: test%s --export-world failed (status %d): %s"
                     % (n, done.returncode, done.stderr.decode(errors="replace").strip()))
        seeds.append(target)
    return seeds


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--odelab", required=True, help="the odelab program")
    parser.add_argument("--program-dir", help="folder of the test programs whose worlds seed the fuzz "
                        "(default: --odelab's folder)")
    parser.add_argument("--programs", default="1,2,4,8,9", help="the programs exported (default 1,2,4,8,9)")
    parser.add_argument("--hand-world", default=os.path.join(here, "..", "worlds", "fuzz_seed.json"),
                        help="a hand-written valid world also mutated (default checks/worlds/fuzz_seed.json)")
    parser.add_argument("--seed", type=int, default=1, help="the random seed: the same seed, the same files")
    parser.add_argument("--count", type=int, default=200, help="mutated files (default 200)")
    parser.add_argument("--work", required=True, help="folder for seeds/, files/ and runs/ (each emptied first)")
    parser.add_argument("--timeout", type=float, default=10.0, help="seconds one run may take (default 10)")
    parser.add_argument("--require-line", action="store_true",
                        help="every refusal must also name the line of the broken field, not only parse errors")
    parser.add_argument("--strip-measures", action="store_true",
                        help="leave measures and events out of the hand-written world (an odelab that reads neither)")
    parser.add_argument("--keep-all", action="store_true", help="keep every mutated file (default: failures only)")
    parser.add_argument("--verbose", action="store_true", help="print every file's mutation, status and message")
    parser.add_argument("--schema", help="doc/world.schema.json: every seed must validate against it, and every file "
                                         "broken in a way a schema can see (%s) must fail it" % ", ".join(SCHEMA_KINDS))
    args = parser.parse_args()

    odelab = os.path.abspath(args.odelab)
    for sub in ("seeds", "files", "runs"):  # only what this script made before: --work may hold more
        shutil.rmtree(os.path.join(args.work, sub), ignore_errors=True)
        os.makedirs(os.path.join(args.work, sub))
    seed_dir = os.path.join(args.work, "seeds")
    seeds = export_seeds(os.path.abspath(args.program_dir or os.path.dirname(odelab)),
                         [p for p in args.programs.split(",") if p], seed_dir, args.timeout)
    with open(args.hand_world) as f:
        hand = json.load(f)
    if args.strip_measures:
        hand.pop("measures", None)
        hand.pop("events", None)
    hand_file = os.path.join(seed_dir, "fuzz_seed.json")
    with open(hand_file, "w") as f:
        f.write(render(hand)[0])
    seeds.append(hand_file)

    schema_errors = schema_checker(args.schema) if args.schema else None
    # Each seed must run as it is: else a status 2 could be the seed's, or the command's, not the mutation's.
    worlds = []
    for seed in seeds:
        if schema_errors:
            with open(seed, "rb") as f:
                found = schema_errors(f.read())
            if found:
                sys.exit("world_fuzz: the valid seed world %s fails the schema: %s" % (seed, "; ".join(found[:3])))
        status, out, err, left = run(odelab, seed, os.path.join(args.work, "runs", "seed_" + os.path.basename(seed)),
                                     args.timeout)
        if status != 0 or "metrics.json" not in left:
            sys.exit("world_fuzz: the valid seed world %s does not run (status %s): %s" % (seed, status, err.strip()))
        with open(seed) as f:
            worlds.append((os.path.basename(seed), json.load(f)))

    # The hand-written world alone has measures, events, a ball joint and pair surfaces: drawn twice as often.
    pool = worlds + worlds[-1:]
    rng = random.Random(args.seed)
    tally, failures = {}, []
    order = []
    for i in range(args.count):
        if not order:
            order = list(MUTATIONS)
            rng.shuffle(order)
        mutation = order.pop()
        m = None
        while m is None:
            name, world = rng.choice([w for w in pool if applies(mutation, w[1])])
            m = mutation(world, rng)
        spans = None
        if m.text is None:
            m.text, spans = render(m.world)
        data = m.text if isinstance(m.text, bytes) else m.text.encode()
        path = os.path.join(args.work, "files", "%03d_%s_%s" % (i, m.kind, name))
        with open(path, "wb") as f:
            f.write(data)
        status, out, err, left = run(odelab, path, os.path.join(args.work, "runs", "%03d" % i), args.timeout)
        wrong = judge(m, spans, status, out, err, left, args.require_line)
        if schema_errors and m.kind in SCHEMA_KINDS and not schema_errors(data):
            wrong.append("the schema (%s) accepts it" % args.schema)
        if args.verbose:
            print("%03d %-4s %s (%s): status %s: %s" % (i, "ok" if not wrong else "FAIL", m.kind, m.detail, status,
                                                        " | ".join(err.strip().splitlines())[:300]))
        held, total = tally.get(m.kind, (0, 0))
        tally[m.kind] = (held + (not wrong), total + 1)
        if wrong:
            failures.append((m, name, path, status, err.strip(), wrong))
        elif not args.keep_all:
            os.remove(path)

    print("world_fuzz: seed %d, %d files from %s" % (args.seed, args.count, ", ".join(n for n, _ in worlds)))
    print("%-36s %6s %6s" % ("mutation", "files", "held"))
    for kind in sorted(tally):
        print("%-36s %6d %6d" % (kind, tally[kind][1], tally[kind][0]))
    for m, name, path, status, err, wrong in failures:
        print("\nFAILED %s (%s, from %s)\n  file: %s\n  status: %s\n  stderr: %s\n  wrong: %s"
              % (m.kind, m.detail, name, path, status, err[:600], "; ".join(wrong)))
    print("\nworld_fuzz: %d of %d malformed files refused as they should be%s"
          % (args.count - len(failures), args.count, "" if failures else ": all held"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
