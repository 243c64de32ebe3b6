"""Benchmark (prints figures, asserts nothing): the time per program run
through one of the lab's executors, one run after another as a search makes
them, for a run that does almost nothing (test4 for 1 ms of simulated time),
so that what is measured is the executor's cost per run: starting the
program, shipping the request and the files back.

Usage: executor_overhead.py BUILD_TESTS_DIR EXECUTOR [RUNS]
  e.g. executor_overhead.py build/tests local 200
       executor_overhead.py build/tests dask:tcp://127.0.0.1:8786 200
       salloc -n1 -c2 /usr/bin/python3 executor_overhead.py build/tests srun 200"""

import statistics
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "lab"))
from odelab_report import executors  # noqa: E402


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    build, spec = Path(sys.argv[1]).resolve(), sys.argv[2]
    runs = int(sys.argv[3]) if len(sys.argv) > 3 else 100
    executor = executors.make(spec)
    argv = [str(build / "test4"), "--headless", "--seconds", "0.001", "--metrics-json", "metrics.json"]
    times, program = [], []
    with tempfile.TemporaryDirectory(prefix="odelab-overhead-") as root:
        for i in range(runs + 5):
            folder = Path(root) / str(i)
            folder.mkdir()
            start = time.perf_counter()
            done = executor.execute(argv, folder, 60, False)
            elapsed = time.perf_counter() - start
            if done["rc"] != 0 or not (folder / "metrics.json").is_file():
                sys.exit(f"run {i} failed: status {done['rc']}")
            if i >= 5:  # the first runs warm caches and connections
                times.append(elapsed)
                program.append(done["cpu_seconds"])
    executor.close()
    print(f"{spec}: {runs} sequential runs of test4 --seconds 0.001: per run median "
          f"{1000 * statistics.median(times):.1f} ms, mean {1000 * statistics.mean(times):.1f} ms "
          f"(the program's own CPU time: median {1000 * statistics.median(program):.1f} ms)")


if __name__ == "__main__":
    main()
