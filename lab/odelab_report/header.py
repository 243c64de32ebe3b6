"""The run header that starts every CSV and RESULTS.md: what was measured
with what (ODE, compiler, CPU, date, commit, the lab's options)."""

import datetime
import os
import re
import subprocess
import tempfile
from pathlib import Path


def _first_line(command, cwd=None):
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
            text = (Path(folder) / "Test2_output.txt").read_text()
            version = re.search(r"^# ode_version: (.+)$", text, re.M)
            precision = re.search(r"^# ode_precision: (.+)$", text, re.M)
            if version and precision:
                return f"{version.group(1).strip()}, {precision.group(1).strip()} precision (reported by test2)"
        except (OSError, subprocess.TimeoutExpired):
            pass
    version = _first_line(["pkg-config", "--modversion", "ode"])
    precision = _first_line(["pkg-config", "--variable=precision", "ode"])
    return f"{version or 'unknown'}, precision {precision or 'unknown'} (pkg-config)"


def compiler(build_dir):
    """The C++ compiler the build used (its CMakeCache), with its version line."""
    cache = Path(build_dir).parent / "CMakeCache.txt"
    path, build_type = None, None
    if cache.exists():
        for line in cache.read_text(errors="replace").splitlines():
            if line.startswith("CMAKE_CXX_COMPILER:"):
                path = line.split("=", 1)[1].strip()
            elif line.startswith("CMAKE_BUILD_TYPE:"):
                build_type = line.split("=", 1)[1].strip()
    version = _first_line([path or "c++", "--version"])
    text = f"{version or 'unknown'} ({path or 'c++ on PATH'})"
    return text + (f", CMAKE_BUILD_TYPE {build_type}" if build_type else "")


def cpu():
    model = "unknown"
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                model = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    return f"{model}, {os.cpu_count()} cores"


def git_commit(repo_root):
    commit = _first_line(["git", "-C", str(repo_root), "rev-parse", "HEAD"])
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
