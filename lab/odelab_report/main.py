"""odelab-report: runs the lab's experiments on the test programs and writes
one CSV per experiment, plots (PNG + SVG) and RESULTS.md.

Exit status: 0 the report was written; 1 an experiment failed (nothing
written); 2 invalid option; 3 the test programs (or matplotlib) are missing;
130 interrupted (nothing written)."""

import argparse
import os
import shlex
import shutil
import signal
import sys
import tempfile
import threading
import time
import traceback
from pathlib import Path

REPO_ROOT = Path(__file__).resolve().parents[2]


def parse_args(argv):
    from .experiments import ALL, GROUPS
    names = ", ".join(e.name for e in ALL)
    parser = argparse.ArgumentParser(
        prog="odelab-report",
        description="Run ODE Lab's speed-accuracy experiments headless and write CSVs, plots and RESULTS.md.",
        epilog=f"Experiments: {names}. Groups: {', '.join(GROUPS)}, all. "
               "How to read the report: doc/lab.md.")
    parser.add_argument("--quick", action="store_true",
                        help="fewer points and shorter runs (about 2 minutes on 2 cores; what CTest runs)")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1, metavar="N",
                        help="programs run at once (default: all cores, %(default)s here)")
    parser.add_argument("--out", type=Path, default=REPO_ROOT / "doc" / "results", metavar="DIR",
                        help="where the report goes; replaced as a whole when the run succeeds "
                             "(default: doc/results/ of this checkout)")
    parser.add_argument("--only", action="append", default=[], metavar="EXPERIMENT",
                        help="run only these experiments or groups (repeatable, or a comma list)")
    parser.add_argument("--build-dir", type=Path, default=REPO_ROOT / "build" / "tests", metavar="DIR",
                        help="folder holding the test programs (default: build/tests of this checkout)")
    args = parser.parse_args(argv)
    if args.jobs < 1:
        parser.error(f"--jobs must be at least 1, not {args.jobs}")
    names = [n.strip() for item in args.only for n in item.split(",") if n.strip()]
    from .experiments import select
    try:
        args.experiments = select(names) if names else list(ALL)
    except ValueError as error:
        parser.error(f"--only: unknown experiment {error}; known: {names_help()}")
    args.partial = bool(names)
    return args


def names_help():
    from .experiments import ALL, GROUPS
    return ", ".join([e.name for e in ALL] + list(GROUPS) + ["all"])


def check_build(build_dir, experiments):
    needed = sorted({p for e in experiments for p in e.programs}, key=lambda p: int(p[4:]))
    missing = [p for p in needed if not os.access(build_dir / p, os.X_OK)]
    if missing:
        sys.stderr.write(
            f"odelab-report: error: no {', '.join(missing)} in {build_dir} (needed by the experiments chosen).\n"
            f"Build the programs first, e.g. `cmake -S . -B build && cmake --build build -j`, "
            f"or point --build-dir at the folder that holds them.\n")
        sys.exit(3)


def publish(staging, out):
    """Replaces `out` with `staging` (a folder beside it) in two renames."""
    old = None
    if out.exists():
        old = Path(tempfile.mkdtemp(prefix=f".{out.name}.old-", dir=out.parent))
        old.rmdir()
        out.rename(old)
    staging.rename(out)
    if old:
        shutil.rmtree(old)


def _interrupt(signum, frame):
    raise KeyboardInterrupt


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    signal.signal(signal.SIGTERM, _interrupt)  # a killed report writes nothing, as with Ctrl-C
    args = parse_args(argv)
    try:
        import matplotlib
        del matplotlib
    except ImportError:
        sys.stderr.write("odelab-report: error: matplotlib is missing; install Debian's python3-matplotlib "
                         "(scripts/odelab.sh installs it)\n")
        return 3
    build_dir = args.build_dir.resolve()
    check_build(build_dir, args.experiments)
    out = args.out.resolve()
    out.parent.mkdir(parents=True, exist_ok=True)

    from . import csvout, header as run_header, results_md
    from .experiments.base import Context
    from .progress import Progress, clock
    from .runner import LabError, Runner

    options = (("--quick, " if args.quick else "") + f"--jobs {args.jobs}, experiments: " +
               ("all" if not args.partial else ", ".join(e.name for e in args.experiments)))
    header = run_header.collect(build_dir, REPO_ROOT, options)
    staging = Path(tempfile.mkdtemp(prefix=f".{out.name}.new-", dir=out.parent))
    staging.chmod(0o755)
    runs_dir = Path(tempfile.mkdtemp(prefix="odelab-report-runs-"))
    progress = Progress(args.experiments, args.quick)
    runner = Runner(build_dir, args.jobs, runs_dir, retry=not args.quick)
    outcomes, failures = {}, {}
    sys.stderr.write(f"odelab-report: {len(args.experiments)} experiments{' (quick)' if args.quick else ''}, "
                     f"{args.jobs} at a time, programs from {build_dir}\n")

    def run_one(experiment):
        ctx = Context(runner, args.quick, staging, header, progress, experiment.name)
        try:
            outcomes[experiment.name] = experiment.run(ctx)
            progress.finished(experiment.name, True)
        except BaseException as error:  # noqa: BLE001 - reported below, the report is not written
            failures[experiment.name] = error if isinstance(error, LabError) else traceback.format_exc()
            if not runner.aborted:
                progress.finished(experiment.name, False)

    # The costliest experiments start first; all run at once, their runs share the slots.
    ordered = sorted(args.experiments, key=lambda e: -e.cost[1 if args.quick else 0])
    threads = [threading.Thread(target=run_one, args=(e,), name=e.name, daemon=True) for e in ordered]
    progress.start()
    try:
        for thread in threads:
            thread.start()
        for thread in threads:
            while thread.is_alive():
                thread.join(0.2)
    except KeyboardInterrupt:
        runner.abort()
        deadline = time.monotonic() + 15  # the experiments end once their runs fail
        for thread in threads:
            thread.join(max(0.0, deadline - time.monotonic()))
        progress.stop()
        shutil.rmtree(staging, ignore_errors=True)
        shutil.rmtree(runs_dir, ignore_errors=True)
        sys.stderr.write("odelab-report: interrupted; nothing written\n")
        return 130
    progress.stop()
    runner.close()
    if failures:
        for name, error in failures.items():
            sys.stderr.write(f"odelab-report: experiment {name} failed:\n{error}\n")
        shutil.rmtree(staging, ignore_errors=True)
        sys.stderr.write(f"odelab-report: nothing written to {out}; the runs are kept in {runs_dir}\n")
        return 1

    runs_rows = [dict(program=r.spec.program, arguments=" ".join(shlex.quote(a) for a in r.spec.args),
                      timed=r.spec.timed, repeat=r.spec.repeat, exit_status=r.rc,
                      sim_seconds=r.m("sim_seconds"), steps=r.m("steps"), wall_seconds=r.m("wall_seconds"),
                      cpu_seconds=r.cpu_seconds, cpu_share=r.cpu_share) for r in runner.runs]
    csvout.write_csv(staging / "runs.csv", header, list(runs_rows[0].keys()), runs_rows,
                     notes=["every program run of this report (each with --headless --metrics-json); wall_seconds: "
                            "the program's run loop; cpu_seconds: user + system time of the process"])
    elapsed = progress.elapsed()
    elapsed_text = (f"{clock(elapsed)} (min:s) for {len(runner.runs)} program runs, --jobs {args.jobs}; "
                    f"load average at the end {run_header.load_average()}")
    timed = [r for r in runner.runs if r.spec.timed]
    if timed:
        shares = sorted(r.cpu_share for r in timed)
        elapsed_text += (f"; {len(timed)} timed runs, CPU share median {shares[len(shares) // 2]:.2f}, "
                         f"lowest {shares[0]:.2f}")
    command = "lab/odelab-report " + " ".join(shlex.quote(a) for a in argv)
    results_md.write(staging / "RESULTS.md", header, [(e, outcomes[e.name]) for e in args.experiments], "runs.csv", elapsed_text,
                     command.strip(), args.quick, [e.name for e in args.experiments] if args.partial else [])
    publish(staging, out)
    shutil.rmtree(runs_dir, ignore_errors=True)
    sys.stderr.write(f"odelab-report: wrote {out} in {clock(elapsed)}\n")
    return 0
