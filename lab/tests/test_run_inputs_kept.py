"""The lab never writes over what a run reads, nor through a link: a world
file inside --out (which the report replaces as a whole) and --out given as
a symbolic link are refused before any run, with nothing touched.
Run: /usr/bin/python3 -m unittest discover -s lab/tests -p test_run_inputs_kept.py
(CTest: lab_run_inputs_kept)."""

import contextlib
import io
import os
import sys
import tempfile
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from odelab_report.main import parse_args  # noqa: E402


def refused(argv):
    """The message parse_args exits with (status 2), or None when it accepts argv."""
    err = io.StringIO()
    with contextlib.redirect_stderr(err):
        try:
            parse_args(argv)
        except SystemExit as end:
            return err.getvalue() if end.code == 2 else None
    return None


class RunInputsKept(unittest.TestCase):
    def test_a_world_file_inside_out_is_refused(self):
        with tempfile.TemporaryDirectory() as root:
            out = Path(root) / "report"
            out.mkdir()
            (out / ".odelab-report").write_text("a previous report\n")
            world = out / "w.json"
            world.write_text("{}\n")
            message = refused(["--world", str(world), "--out", str(out)])
            self.assertIsNotNone(message)
            self.assertIn("inside --out", message)
            self.assertEqual(world.read_text(), "{}\n")

    def test_out_as_a_symbolic_link_is_refused(self):
        with tempfile.TemporaryDirectory() as root:
            target = Path(root) / "somewhere"
            target.mkdir()
            link = Path(root) / "report"
            os.symlink(target, link)
            message = refused(["--quick", "--out", str(link)])
            self.assertIsNotNone(message)
            self.assertIn("is not a folder", message)


if __name__ == "__main__":
    unittest.main()
