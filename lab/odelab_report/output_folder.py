"""The --out folder: what may be replaced, and replacing it in two renames.

The report replaces its folder as a whole, so it only goes into a folder
that does not exist yet, an empty one, or one a previous report made (it
holds MARKER). Anything else (a source folder, a file) is refused before
any run, and nothing there is touched."""

import shutil
import tempfile
from pathlib import Path

from .files import write_atomically

MARKER = ".odelab-report"
MARKER_TEXT = ("This folder was written by lab/odelab-report. The next report written here replaces it\n"
               "as a whole; files added to it by hand are lost then.\n")


class Refused(Exception):
    """--out names something the report must not replace."""


def check(out):
    """Raises Refused when `out` is not a place the report may replace."""
    out = Path(out)
    if out.is_symlink() or (out.exists() and not out.is_dir()):
        raise Refused(f"{out} is not a folder; the report goes into a folder of its own "
                      f"(a new one, an empty one, or a previous report's)")
    if not out.exists():
        return
    if any(out.iterdir()) and not (out / MARKER).is_file():
        raise Refused(f"{out} holds files and no previous report (no {MARKER} in it); the report replaces "
                      f"its folder as a whole, so choose a new or empty folder, or a previous report's")


def publish(staging, out):
    """Marks `staging` (a folder beside `out`) as a report and puts it in
    place of `out` in two renames."""
    write_atomically(Path(staging) / MARKER, MARKER_TEXT)
    check(out)  # again: something may have appeared there while the runs went on
    old = None
    if out.exists():
        old = Path(tempfile.mkdtemp(prefix=f".{out.name}.old-", dir=out.parent))
        old.rmdir()
        out.rename(old)
    staging.rename(out)
    if old:
        shutil.rmtree(old)
