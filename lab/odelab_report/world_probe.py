"""Asking odelab about a world before any measurement: whether it reads the
file at all, and whether an engine can express it (exit status 2: bad
input, with the reason on standard error). A question, not a run of the
report: made here, not through the executor, like Runner.ask."""

import subprocess
import tempfile

REFUSED = 2


def probe(build_dir, args, timeout=120):
    """(exit status, the last line of standard error) of `odelab args`, run
    in a folder of its own; (None, why) when it could not be run."""
    with tempfile.TemporaryDirectory(prefix="odelab-world-probe-") as folder:
        try:
            done = subprocess.run([str(build_dir / "odelab"), *[str(a) for a in args]], cwd=folder,
                                  stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                                  text=True, timeout=timeout)
        except subprocess.TimeoutExpired:
            return None, f"gave no answer within {timeout} s"
        except OSError as error:
            return None, f"cannot be run: {error.strerror or error}"
    lines = [line.strip() for line in done.stderr.splitlines() if line.strip()]
    errors = [line for line in lines if line.startswith("error")]
    return done.returncode, (errors or lines or [""])[-1]


def check_world(build_dir, world):
    """None when odelab reads the world file; else its message (status 2)."""
    rc, message = probe(build_dir, ["--world", world, "--list-engines"])
    if rc == 0:
        return None
    return message or f"odelab --world {world} ended with status {rc}"
