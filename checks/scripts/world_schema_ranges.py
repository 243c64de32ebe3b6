#!/usr/bin/python3
"""doc/world.schema.json states the ranges the world reader enforces.

The ranges have one home: utils/world/FormatRanges.h (and, for the world
settings, the knobs' ranges in utils/WorldSettings.cpp); `world_read_tool
ranges` prints them as JSON. With --write this script writes them into the
schema (every place a field of that name appears in that object's
definition: a box's and a sphere's position alike); without it, it fails
naming each place where the schema says otherwise. Exit status 0: they agree.
"""

import argparse
import copy
import json
import subprocess
import sys

# Lists of the format and the schema's definition of their items: each holds at most `items`.
LISTS = ("bodies", "geoms", "joints", "surfaces", "pair_surfaces", "measures", "events")


def places(node, field):
    """Every properties[field] under a definition (through allOf, oneOf, if/then)."""
    if isinstance(node, dict):
        props = node.get("properties")
        if isinstance(props, dict) and field in props and props[field] is not True:
            yield props
        for key, value in node.items():
            if key != "properties":
                yield from places(value, field)
    elif isinstance(node, list):
        for item in node:
            yield from places(item, field)


def resolve(schema, node):
    while isinstance(node, dict) and "$ref" in node:
        node = schema["$defs"][node["$ref"].split("/")[-1]]
    return node


def apply(schema, ranges):
    want = copy.deepcopy(schema)
    for name, (low, high) in ((k, v) for k, v in ranges.items() if isinstance(v, list)):
        if "." not in name:
            continue
        kind, field = name.split(".")
        array = field.endswith("[]")
        field = field.rstrip("[]")
        # "world.": a field of the file's top level; any other kind: that $defs entry.
        found = list(places(want if kind == "world" else want["$defs"][kind], field))
        if kind == "world":
            found = [props for props in found if props is want["properties"]]
        if not found:
            raise SystemExit(f"world_schema_ranges: no place for {name} in the schema's $defs.{kind}")
        for props in found:
            old = resolve(want, props[field])
            whole = (old.get("items", {}) if array else old).get("type") == "integer"
            number = {"type": "integer" if whole else "number", "minimum": int(low) if whole else low,
                      "maximum": int(high) if whole else high}
            if array:
                props[field] = {"type": "array", "items": number, "minItems": old["minItems"], "maxItems": old["maxItems"]}
            else:
                props[field] = number
    for name in LISTS:
        want["properties"][name]["maxItems"] = ranges["items"]
    return want


def differences(have, want, path="$"):
    if type(have) is not type(want):
        return [f"{path}: {json.dumps(have)} (the reader: {json.dumps(want)})"]
    if isinstance(have, dict):
        out = []
        for key in sorted(set(have) | set(want)):
            if key not in have or key not in want:
                out.append(f"{path}.{key}: only in the {'reader' if key in want else 'schema'}")
            else:
                out += differences(have[key], want[key], f"{path}.{key}")
        return out
    if isinstance(have, list):
        if len(have) != len(want):
            return [f"{path}: {json.dumps(have)} (the reader: {json.dumps(want)})"]
        return [d for i, (a, b) in enumerate(zip(have, want)) for d in differences(a, b, f"{path}[{i}]")]
    return [] if have == want else [f"{path}: {json.dumps(have)} (the reader: {json.dumps(want)})"]


def dump(value, indent=0):
    """JSON as the schema is written: objects one member a line, short lists on one line."""
    pad = "  " * (indent + 1)
    if isinstance(value, dict):
        if not value:
            return "{}"
        inner = [f"{pad}{json.dumps(k)}: {dump(v, indent + 1)}" for k, v in value.items()]
        one = "{" + ", ".join(f"{json.dumps(k)}: {dump(v, indent + 1)}" for k, v in value.items()) + "}"
        if len(one) + len(pad) <= 110 and "\n" not in one:
            return one
        return "{\n" + ",\n".join(inner) + "\n" + "  " * indent + "}"
    if isinstance(value, list):
        one = "[" + ", ".join(dump(v, indent + 1) for v in value) + "]"
        if len(one) + len(pad) <= 110 and "\n" not in one:
            return one
        return "[\n" + ",\n".join(pad + dump(v, indent + 1) for v in value) + "\n" + "  " * indent + "]"
    return json.dumps(value)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--tool", required=True, help="checks' world_read_tool")
    parser.add_argument("--schema", required=True)
    parser.add_argument("--write", action="store_true", help="write the reader's ranges into the schema")
    args = parser.parse_args()
    ranges = json.loads(subprocess.run([args.tool, "ranges"], check=True, capture_output=True, text=True).stdout)
    with open(args.schema) as f:
        have = json.load(f)
    want = apply(have, ranges)
    if args.write:
        with open(args.schema + ".tmp", "w") as f:
            f.write(dump(want) + "\n")
        import os
        os.replace(args.schema + ".tmp", args.schema)
        return 0
    found = differences(have, want)
    for line in found:
        print("world.schema.json differs from the reader's ranges at " + line)
    if found:
        print(f"{len(found)} differences: run world_schema_ranges.py --write after changing utils/world/FormatRanges.h")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
