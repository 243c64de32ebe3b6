"""The run header that starts every CSV and RESULTS.md: what was measured
with what (ODE, compiler, CPU, date, commit, the lab's options)."""

import datetime
import os
import re
import subprocess
import tempfile
from pathlib import Path

from .inputs import InputError, read_text

# A CMake cache is some tens of KiB; the most a file read here may be.
MAX_CACHE_BYTES = 16 * 1024 * 1024
MAX_SMALL_FILE_BYTES = 16 * 1024 * 1024


def first_line(command, cwd=None):
    try:
        out = subprocess.run(command, cwd=cwd, capture_output=True, text=True, timeout=30)
    except (OSError, subprocess.TimeoutExpired):
        return None
    lines = out.stdout.strip().splitlines()
    return lines[0].strip() if out.returncode == 0 and lines else None


def ode_version(build_dir):
    """ODE's version and precision as a test program reports them (the
    header of Test2_output.txt), else as pkg-config reports them."""
    with tempfile.TemporaryDirectory(prefix="odelab-header-") as folder:
        try:
            subprocess.run([str(Path(build_dir) / "test2"), "--headless", "--seconds", "0.001",
                            "--sample-interval", "1", "--out-dir", folder],
                           capture_output=True, timeout=60, cwd=folder)
            text = read_text(Path(folder) / "Test2_output.txt", MAX_SMALL_FILE_BYTES, "test2's output file")
            version = re.search(r"^# ode_version: (.+)$", text, re.M)
            precision = re.search(r"^# ode_precision: (.+)$", text, re.M)
            if version and precision:
                return f"{version.group(1).strip()}, {precision.group(1).strip()} precision (reported by test2)"
        except (OSError, subprocess.TimeoutExpired, InputError):
            pass
    version = first_line(["pkg-config", "--modversion", "ode"])
    precision = first_line(["pkg-config", "--variable=precision", "ode"])
    return f"{version or 'unknown'}, precision {precision or 'unknown'} (pkg-config)"


def compiler(build_dir):
    """The C++ compiler the build used (its CMakeCache), with its version
    line. No cache: "unknown", never a guess. A cache that is not a regular
    text file of bounded size, or names no compiler, is an InputError: the
    header would otherwise name a compiler the build did not use."""
    cache = Path(build_dir).parent / "CMakeCache.txt"
    if not os.path.lexists(cache):
        return f"unknown (no {cache})"
    path, build_type = None, None
    for line in read_text(cache, MAX_CACHE_BYTES, "the build's CMake cache").splitlines():
        if line.startswith("CMAKE_CXX_COMPILER:"):
            path = line.split("=", 1)[1].strip()
        elif line.startswith("CMAKE_BUILD_TYPE:"):
            build_type = line.split("=", 1)[1].strip()
    if not path:
        raise InputError(f"the build's CMake cache {cache} names no C++ compiler (no CMAKE_CXX_COMPILER entry); "
                         f"is it a CMake cache?")
    version = first_line([path, "--version"])
    text = f"{version or 'unknown version'} ({path})"
    return text + (f", CMAKE_BUILD_TYPE {build_type}" if build_type else "")


def cpu():
    model = "unknown"
    try:
        for line in read_text("/proc/cpuinfo", MAX_SMALL_FILE_BYTES, "the CPU list").splitlines():
            if line.startswith("model name"):
                model = line.split(":", 1)[1].strip()
                break
    except InputError:
        pass
    return f"{model}, {os.cpu_count()} cores"


def git_commit(repo_root):
    commit = first_line(["git", "-C", str(repo_root), "rev-parse", "HEAD"])
    if not commit:
        return "unknown (not a git checkout)"
    status = subprocess.run(["git", "-C", str(repo_root), "status", "--porcelain", "--untracked-files=no"],
                            capture_output=True, text=True).stdout.strip()
    return commit + (" with uncommitted changes" if status else "")


def load_average():
    try:
        return "%.2f %.2f %.2f" % os.getloadavg()
    except OSError:
        return "unknown"


def collect(build_dir, repo_root, options_text):
    """Ordered (key, value) pairs."""
    now = datetime.datetime.now().astimezone()
    return [
        ("ODE", ode_version(build_dir)),
        ("compiler", compiler(build_dir)),
        ("CPU", cpu()),
        ("date", now.strftime("%Y-%m-%d %H:%M:%S %z")),
        ("commit", git_commit(repo_root)),
        ("programs", str(Path(build_dir).resolve())),
        ("options", options_text),
        ("load average at start (1, 5, 15 min)", load_average()),
    ]
