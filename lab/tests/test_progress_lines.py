"""Progress without a terminal (a log, a pipe): a line each time another
tenth of the work is done, in whole percentages, so a long experiment is
seen to move; before, nothing came between the first and the last line."""

import io
import os
import re
import sys
import unittest
from types import SimpleNamespace

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))

try:
    from odelab_report.progress import Progress  # noqa: E402
except ImportError as missing:  # tqdm, which the lab checks for before any run
    Progress = None
    MISSING = f"the lab's progress needs tqdm (python3-tqdm): {missing}"


@unittest.skipIf(Progress is None, globals().get("MISSING", ""))
class ProgressLines(unittest.TestCase):
    def test_a_line_per_tenth_in_whole_percentages(self):
        stream = io.StringIO()  # not a terminal: tqdm draws no bar
        world = SimpleNamespace(name="world", cost=(60.0, 60.0))
        progress = Progress([world], quick=True, stream=stream)
        progress.start()
        for step in range(1, 20):
            progress.update("world", step / 20)
        progress.finished("world", True)
        progress.stop()
        lines = stream.getvalue().splitlines()
        tenths = [line for line in lines if "running: world" in line]
        # 5% a step, capped at 95% until finished: 10, 20, ... 90.
        self.assertEqual([int(re.search(r"(\d+)%", line).group(1)) for line in tenths], list(range(10, 100, 10)))
        for line in lines:
            self.assertNotRegex(line, r"\d\.\d{4,}", "a count with a long fraction: " + line)
        self.assertRegex(lines[-1], r"100%.*done")


if __name__ == "__main__":
    unittest.main()
