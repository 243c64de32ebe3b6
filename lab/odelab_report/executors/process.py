"""One program run where the program runs: on this machine, on a Dask
worker, or in a Slurm step. Standard library only, and no imports from the
rest of the lab, because it is sent to Dask workers by value and started by
srun as a script (`python3 process.py TIMEOUT PROGRAM ARGS...`, which prints
the packed result as one JSON line).

A run gets a folder of its own; its standard output and error go to
stdout.txt and stderr.txt there, and its CPU time (user + system) comes from
the kernel's wait4, so it counts the program alone, not the lab or srun."""

import base64
import json
import os
import shutil
import signal
import socket
import stat
import subprocess
import sys
import tempfile
import threading
from pathlib import Path

# A run's files travel back whole; more than this is a mistake (an output
# file sampled far too often), not a result to ship over the network.
MAX_PACKED_BYTES = 256 * 1024 * 1024


TAG_VARIABLE = "ODELAB_REPORT_RUN"


def run_in_folder(argv, folder, timeout, started=None, tag=None):
    """Runs argv in `folder`; returns dict(rc, cpu_seconds, host). The
    program starts a session (and process group) of its own, so that
    kill_group ends it with whatever it started (a wrapper script that does
    not exec, its children); what is left of the group when the program
    ends is ended too. `started` (if given) is called with the Popen object,
    so that it can be killed; `tag` goes into the program's environment, so
    that kill_tagged finds it."""
    folder = Path(folder)
    env = dict(os.environ, **{TAG_VARIABLE: tag}) if tag else None
    with open(folder / "stdout.txt", "wb") as out, open(folder / "stderr.txt", "wb") as err:
        process = subprocess.Popen(argv, cwd=folder, stdout=out, stderr=err, stdin=subprocess.DEVNULL, env=env,
                                   start_new_session=True)
        if started:
            started(process)
        timer = threading.Timer(timeout, kill_group, (process,))
        timer.start()
        try:
            _, status, usage = os.wait4(process.pid, 0)
        finally:
            timer.cancel()
            # Reaped or not, the group's id stays taken while any member
            # lives, so this reaches only what the program left behind.
            kill_group(process)
    rc = os.waitstatus_to_exitcode(status)
    process.returncode = rc  # reaped here, so Popen must not wait for it again
    return dict(rc=rc, cpu_seconds=usage.ru_utime + usage.ru_stime, host=socket.gethostname())


def kill_group(process):
    """SIGKILL to the process group a run_in_folder program leads (os.killpg,
    not Popen.kill: Popen would reap the leader before wait4 gets its CPU
    time). A group already gone is no error."""
    try:
        os.killpg(process.pid, signal.SIGKILL)
    except OSError:
        pass


def kill_tagged(tag):
    """Kills this machine's programs started with `tag` (a cancelled report's
    runs: Dask cannot stop a task that is running). Returns how many."""
    needle = f"{TAG_VARIABLE}={tag}".encode() + b"\0"
    killed = 0
    for entry in Path("/proc").iterdir():
        if not entry.name.isdigit():
            continue
        try:
            if needle in (entry / "environ").read_bytes():
                os.kill(int(entry.name), 9)
                killed += 1
        except OSError:
            pass  # gone already, or not ours
    return killed


def run_packed(argv, timeout, tag=None, started=None):
    """Runs argv in a fresh temporary folder and returns run_in_folder's
    dict plus `files`: {name: bytes} of every regular file the run left."""
    folder = Path(tempfile.mkdtemp(prefix="odelab-run-"))
    try:
        result = run_in_folder(argv, folder, timeout, started, tag=tag)
        files, total = {}, 0
        for path in sorted(folder.iterdir()):
            info = path.lstat()
            if not stat.S_ISREG(info.st_mode):
                # A FIFO would block the read, a device never end: not shipped.
                continue
            # The size first: a sparse file of gigabytes is refused unread.
            total += info.st_size
            if total > MAX_PACKED_BYTES:
                raise RuntimeError(f"the run's files exceed {MAX_PACKED_BYTES} bytes: {argv}")
            with open(path, "rb") as stream:
                files[path.name] = stream.read(MAX_PACKED_BYTES + 1)
        result["files"] = files
        return result
    finally:
        shutil.rmtree(folder, ignore_errors=True)


def unpack(result, folder):
    """Writes a packed run's files into `folder`; returns the dict without them."""
    for name, data in result.pop("files").items():
        if "/" in name or name in (".", ".."):
            raise ValueError(f"a packed run returned a file named {name!r}")
        (Path(folder) / name).write_bytes(data)
    return result


def to_json(result):
    encoded = dict(result, files={n: base64.b64encode(d).decode("ascii") for n, d in result["files"].items()})
    return json.dumps(encoded)


def from_json(text):
    result = json.loads(text)
    result["files"] = {n: base64.b64decode(d) for n, d in result["files"].items()}
    return result


def _end_on_signal(process):
    """In a Slurm step: SIGTERM or SIGINT (srun passing on a cancel) ends
    the program's whole group (it runs in a session of its own) and this
    script, as the signal would have."""
    def handler(number, frame):
        kill_group(process)
        os._exit(128 + number)
    for number in (signal.SIGTERM, signal.SIGINT):
        signal.signal(number, handler)


if __name__ == "__main__":  # what srun starts
    try:
        packed = run_packed(sys.argv[2:], float(sys.argv[1]), started=_end_on_signal)
    except (OSError, RuntimeError) as error:  # a program missing on this node, a full disk
        sys.stderr.write(f"odelab-report on {socket.gethostname()}: cannot run {sys.argv[2:3]}: {error}\n")
        sys.exit(2)
    sys.stdout.write(to_json(packed) + "\n")
