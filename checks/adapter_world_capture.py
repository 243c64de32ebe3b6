"""The world an engine adapter was given in one run, as a world file that a
bare harness (peers/wasm/bench/bare.js) can step: the scene's program runs
once with a Node.js engine, its messages to the engine server are copied on
their way (a `node` named by $ODELAB_NODE that tees its stdin), and the
last world the program sent ('build', then each 'add') is written with a
"drop" event for every body that an 'add' brought in, at the time of the
step it came before. test5 exports no plates (`--export-world` writes the
world as built; the plates come as it runs), so this is how its 40 plates
reach the harness; for test1 and test2 it is the exported world itself.
The world comes from one engine's run (Rapier's in the bench) and serves
every engine: the scenes place what they add without reading the engine's
state, except test5 above a stack near 6 m, which 40 plates 0.05 m thick
never reach.

A run that sends what a world file cannot say (a removed body, a state or
a force set by the program) is refused, naming the message."""

import json
import os
import shutil
import stat
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "lab"))
from odelab_report import files  # noqa: E402

REPLAYABLE = {"build", "add", "step", "quit", "reset"}


def tee_node(folder, log):
    """A `node` that copies its stdin to `log` on the way to the real one."""
    node = shutil.which("node")
    if not node:
        raise RuntimeError("node is not on PATH: the Node.js engines cannot run")
    wrapper = Path(folder) / "tee-node.sh"
    files.write_atomically(wrapper, f'#!/bin/sh\ntee "{log}" | "{node}" "$@"\n')
    wrapper.chmod(wrapper.stat().st_mode | stat.S_IXUSR)
    return str(wrapper)


def world_from_messages(lines):
    """The world file (a dict) from the engine server's input lines."""
    world, step_seconds, steps, drops = None, None, 0, {}
    for number, line in enumerate(lines, 1):
        if not line.strip():
            continue
        message = json.loads(line)
        op = message.get("op")
        if op not in REPLAYABLE:
            raise ValueError(f"message {number}: '{op}': a world file cannot replay it")
        if op == "build":
            world, steps, drops = message["world"], 0, {}
            step_seconds = world["settings"]["step"]
        elif op == "add":
            world = message["world"]
            for body in range(message["first_body"], len(world.get("bodies", []))):
                drops[body] = steps * step_seconds
        elif op == "step":
            steps += message.get("count", 1)
        elif op == "reset" and world is not None:
            raise ValueError(f"message {number}: 'reset' after a build: a world file cannot replay it")
    if world is None:
        raise ValueError("the run sent no world")
    world = dict(world)
    events = [e for e in world.get("events", []) if "drop" not in e]
    events += [{"at": at, "drop": body} for body, at in sorted(drops.items(), key=lambda item: item[1])]
    world["events"] = sorted(events, key=lambda e: e["at"])
    return world, steps


def capture_world(program, scene_args, engine, seconds, folder):
    """(world, steps): the world `program` gave `engine` in a headless run of
    `seconds`, and the steps it asked for."""
    log = Path(folder) / "messages.jsonl"
    env = dict(os.environ, ODELAB_NODE=tee_node(folder, log))
    args = [program, "--headless", "--seconds", str(seconds), "--engine", engine, "--out-dir", folder, *scene_args]
    subprocess.run(args, capture_output=True, text=True, check=True, env=env)
    return world_from_messages(log.read_text().splitlines())
