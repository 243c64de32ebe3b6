"""odelab-report: runs the lab's experiments on the test programs and writes
one CSV per experiment, plots (PNG + SVG) and RESULTS.md.

Exit status: 0 the report was written; 1 an experiment or the executor
failed (nothing written); 2 invalid option (nothing touched); 3 the test
programs (or matplotlib) are missing; 130 interrupted (nothing written)."""

import argparse
import os
import shlex
import shutil
import sys
import tempfile
import threading
import time
import traceback
from pathlib import Path

from . import executors, interrupt, output_folder
from .files import write_atomically
from .inputs import InputError

REPO_ROOT = Path(__file__).resolve().parents[2]
# Set the moment the report is in place, so that a signal landing after it
# (before the status is returned) still reports it as written.
_published = threading.Event()


def parse_args(argv):
    from .experiments import ALL, GROUPS
    names = ", ".join(e.name for e in ALL)
    parser = argparse.ArgumentParser(
        prog="odelab-report",
        description="Run ODE Lab's speed-accuracy experiments headless and write CSVs, plots and RESULTS.md.",
        epilog=f"Experiments: {names}. Groups: {', '.join(GROUPS)}, all. "
               "How to read the report: doc/lab.md; clusters: doc/cluster.md.")
    parser.add_argument("--quick", action="store_true",
                        help="fewer points and shorter runs (about 5 minutes on 2 cores; what CTest runs)")
    parser.add_argument("--jobs", type=int, default=None, metavar="N",
                        help="programs run at once (default: what the executor offers: all cores here, "
                             "the workers' threads with dask, the allocation's CPUs with srun)")
    parser.add_argument("--out", type=Path, default=None, metavar="DIR",
                        help="where the report goes: a new or empty folder, or one holding a previous "
                             "report, replaced as a whole when the run succeeds (default: doc/results/, with --atlas "
                             "doc/atlas-report/)")
    parser.add_argument("--only", action="append", default=[], metavar="EXPERIMENT",
                        help="run only these experiments or groups (repeatable, or a comma list)")
    parser.add_argument("--build-dir", type=Path, default=REPO_ROOT / "build" / "tests", metavar="DIR",
                        help="folder holding the test programs (default: build/tests of this checkout)")
    parser.add_argument("--second-build", type=Path, default=None, metavar="DIR",
                        help="the test programs built against another ODE (cmake -DODELAB_ODE_ROOT=...): the "
                             "thesis table gains a column measured with them")
    parser.add_argument("--world", type=Path, default=None, metavar="FILE",
                        help="the lab on your own world file (doc/world-format.md) instead of the thesis scenes: "
                             "step, solver, iterations, ERP and CFM swept on ODE, the step's stability limit, "
                             "every engine at its defaults and best (doc/lab.md, \"Your own world\")")
    parser.add_argument("--atlas", type=Path, nargs="?", const=REPO_ROOT / "doc" / "atlas", default=None,
                        metavar="DIR",
                        help="the accuracy atlas instead of the thesis scenes: every case of DIR (default "
                             "doc/atlas/, listed with its family in DIR/families.csv) on every engine at its "
                             "defaults and best, at steps 1/60, 1/240 and 1/1000 s (--quick: 1/240, one timed "
                             "run); writes ATLAS.md (default --out doc/atlas-report/; doc/atlas.md)")
    parser.add_argument("--executor", default="local", metavar="local|dask:ADDRESS|srun",
                        help="where the programs run: child processes here (default), tasks on the Dask "
                             "scheduler at ADDRESS (its port 1 to 65535), or srun steps of the Slurm allocation "
                             "(with at least one CPU); anything else is refused before any run (status 2) "
                             "(doc/cluster.md)")
    args = parser.parse_args(argv)
    if args.jobs is not None and args.jobs < 1:
        parser.error(f"--jobs must be at least 1, not {args.jobs}")
    try:
        executors.parse(args.executor)
    except ValueError as error:
        parser.error(f"--executor: {error}")
    if args.atlas is not None and (args.world is not None or args.only or args.second_build):
        parser.error("--atlas runs its own grid: it takes no "
                     + ("--world" if args.world is not None else "--only" if args.only else "--second-build"))
    if args.out is None:
        args.out = REPO_ROOT / "doc" / ("atlas-report" if args.atlas is not None else "results")
    if args.world is not None and (args.only or args.second_build):
        parser.error(f"--world runs its own sweep: it takes no {'--only' if args.only else '--second-build'}")
    names = [n.strip() for item in args.only for n in item.split(",") if n.strip()]
    if args.only and not names:
        parser.error(f"--only names no experiment ({' '.join(shlex.quote(o) for o in args.only)}); "
                     f"known: {names_help()}")
    from .experiments import select
    try:
        args.experiments = select(names) if names else list(ALL)
    except ValueError as error:
        parser.error(f"--only: unknown experiment {error}; known: {names_help()}")
    args.partial = bool(names)
    try:
        # As given, not resolved: a symbolic link at --out is refused as one
        # (resolving it first would send the report into where it points).
        output_folder.check(args.out.absolute())
    except output_folder.Refused as error:
        parser.error(f"--out: {error}")
    if args.atlas is not None:
        atlas, out = args.atlas.resolve(), args.out.resolve()
        if atlas == out or out in atlas.parents or atlas in out.parents:
            parser.error(f"--atlas: the cases in {args.atlas} and --out {args.out} must not hold one another: the "
                         f"report replaces --out as a whole")
    if args.world is not None:
        # The report replaces --out as a whole: a world file inside it would
        # be gone before the report that read it is written.
        world, out = args.world.resolve(), args.out.resolve()
        if world == out or out in world.parents:
            parser.error(f"--world: {args.world} is inside --out {args.out}, which the report replaces as a whole; "
                         f"keep the world file elsewhere")
    return args


def names_help():
    from .experiments import ALL, GROUPS
    return ", ".join([e.name for e in ALL] + list(GROUPS) + ["all"])


def check_build(build_dir, experiments):
    needed = sorted({p for e in experiments for p in e.programs}, key=lambda p: int(p[4:]))
    # A regular file: a FIFO or a folder with the x bit passes os.access but
    # cannot be run (the run would fail as a defect of the lab).
    missing = [p for p in needed if not ((build_dir / p).is_file() and os.access(build_dir / p, os.X_OK))]
    if missing:
        sys.stderr.write(
            f"odelab-report: error: no {', '.join(missing)} in {build_dir} (needed by the experiments chosen; "
            f"each must be an executable regular file).\n"
            f"Build the programs first, e.g. `cmake -S . -B build && cmake --build build -j`, "
            f"or point --build-dir at the folder that holds them.\n")
        sys.exit(3)
    return [build_dir / p for p in needed]


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    from .tolerant_stream import TolerantStream
    sys.stderr = TolerantStream(sys.stderr)  # a closed standard error loses the messages, not the report
    stop = interrupt.install()  # Ctrl-C, SIGTERM, SIGHUP: see interrupt.py
    try:
        interrupt.start_raising()
        status = _main(argv, stop)
    except interrupt.Interrupted:  # the finally blocks on the way removed the temporaries
        status = 0 if _published.is_set() else 1
    except SystemExit as exit_:  # argparse's status 2, check_build's 3
        status = exit_.code if isinstance(exit_.code, int) else 2
    except InputError as error:  # a file the lab reads is not what it should be
        sys.stderr.write(f"odelab-report: error: {error}; nothing written\n")
        status = 2
    except OSError as error:  # an unwritable folder, a full disk: a message, not a traceback
        sys.stderr.write(f"odelab-report: error: {error}; nothing written\n")
        status = 1
    except BaseException:  # noqa: BLE001 - once a signal came, what follows is its doing
        # Libraries turn an exception raised inside them into one of their
        # own (numpy's import makes Interrupted an ImportError).
        if not stop.is_set():
            raise
        status = 0 if _published.is_set() else 1
    return interrupt.close(status)


def _main(argv, stop):
    # Imports (numpy, matplotlib) wait on nothing outside the lab, and an
    # exception raised inside them comes out as another error: signals
    # only set the flag until they are done.
    with interrupt.deferred():
        args = parse_args(argv)
        missing = []
        for module, package in (("matplotlib", "python3-matplotlib"), ("tqdm", "python3-tqdm")):
            try:
                __import__(module)
            except ImportError:
                missing.append((module, package))
    interrupt.check()
    if missing:
        sys.stderr.write(f"odelab-report: error: {', '.join(m for m, _ in missing)} missing; install Debian's "
                         f"{' '.join(p for _, p in missing)} (scripts/odelab.sh installs them)\n")
        return 3
    build_dir = args.build_dir.resolve()
    if args.atlas is not None:  # lab/odelab_report/atlas_report.py: odelab, and every case it must read
        from . import atlas_report
        status = atlas_report.prepare(args, build_dir)
        if status:
            return status
        programs = [build_dir / "odelab"]
    elif args.world is not None:  # lab/odelab_report/world_report.py: odelab, and the world it must read
        from . import world_report
        status = world_report.prepare(args, build_dir)
        if status:
            return status
        programs = [build_dir / "odelab"]
    else:
        programs = check_build(build_dir, args.experiments)
    if args.second_build:
        check_build(args.second_build.resolve(), [e for e in args.experiments if e.name == "thesis"])
    out = args.out.resolve()

    try:
        executor = executors.make(args.executor)
    except executors.ExecutorError as error:
        sys.stderr.write(f"odelab-report: error: {error}\n")
        return 1
    try:
        return _report(args, argv, stop, build_dir, programs, out, executor)
    finally:
        with interrupt.deferred():
            executor.close()


def _report(args, argv, stop, build_dir, programs, out, executor):
    from . import header as run_header

    missing = executor.missing_programs(programs)
    if missing:
        listed = "; ".join(f"{worker}: {', '.join(Path(p).name for p in ps)}" for worker, ps in missing.items())
        sys.stderr.write(f"odelab-report: error: the test programs are not at {build_dir} everywhere "
                         f"(build at the same path on every host, doc/cluster.md): {listed}\n")
        return 3
    jobs = args.jobs or executor.cores
    if jobs < 1:  # no run could ever start
        sys.stderr.write(f"odelab-report: error: the executor {executor.description} offers no CPU to run on\n")
        return 1
    options = (("--quick, " if args.quick else "") + f"--jobs {jobs}, experiments: " +
               ("all" if not args.partial else ", ".join(e.name for e in args.experiments)))
    header = run_header.collect(build_dir, REPO_ROOT, options)
    header.append(("executor", f"{executor.description}; timed runs on {executor.timing_host} only"))
    out.parent.mkdir(parents=True, exist_ok=True)
    staging = runs_dir = None
    keep_runs = False
    try:
        with interrupt.deferred():  # made and named at once, so the finally below sees them
            staging = Path(tempfile.mkdtemp(prefix=f".{out.name}.new-", dir=out.parent))
            runs_dir = Path(tempfile.mkdtemp(prefix="odelab-report-runs-"))
        interrupt.check()
        staging.chmod(0o755)
        status = _run_and_write(args, argv, stop, staging, runs_dir, out, header, jobs, executor)
        keep_runs = status == 1  # a failed experiment: its runs are kept and named
        return status
    finally:
        with interrupt.deferred():
            if staging:
                shutil.rmtree(staging, ignore_errors=True)  # gone already when published
            if runs_dir and not keep_runs:
                shutil.rmtree(runs_dir, ignore_errors=True)


def _run_and_write(args, argv, stop, staging, runs_dir, out, header, jobs, executor):
    from .experiments.base import Context
    from .progress import Progress, clock
    from .report_files import write_report
    from .runner import LabError, Runner

    progress = Progress(args.experiments, args.quick)
    runner = Runner(args.build_dir.resolve(), jobs, runs_dir, executor, retry=not args.quick)
    runner.second = None
    if args.second_build:  # the thesis experiment runs its rows on these programs too
        runner.second = Runner(args.second_build.resolve(), jobs, runs_dir, executor, retry=False)
    outcomes, failures = {}, {}
    sys.stderr.write(f"odelab-report: {len(args.experiments)} experiments{' (quick)' if args.quick else ''}, "
                     f"{jobs} at a time, programs from {args.build_dir.resolve()}, "
                     f"executor {executor.description}\n")

    def run_one(experiment):
        ctx = Context(runner, args.quick, staging, header, progress, experiment.name)
        try:
            outcomes[experiment.name] = experiment.run(ctx)
            progress.finished(experiment.name, True)
        except LabError as error:
            failures[experiment.name] = str(error)
            if not runner.aborted:
                progress.finished(experiment.name, False)
        except BaseException as error:  # noqa: BLE001 - a defect of the lab: one line here, the trace kept
            trace = runs_dir / f"{experiment.name}-traceback.txt"
            write_atomically(trace, traceback.format_exc())
            failures[experiment.name] = f"{type(error).__name__}: {error} (Python traceback in {trace})"
            if not runner.aborted:
                progress.finished(experiment.name, False)

    # The costliest experiments start first; all run at once, their runs share the slots.
    ordered = sorted(args.experiments, key=lambda e: -e.cost[1 if args.quick else 0])
    threads = [threading.Thread(target=run_one, args=(e,), name=e.name, daemon=True) for e in ordered]
    # Signals only set the flag from here to the end of the runs: the threads
    # start whole and the abort below reaches every run.
    with interrupt.deferred():
        try:
            progress.start()
            for thread in threads:
                thread.start()
            while any(t.is_alive() for t in threads) and not stop.is_set():
                stop.wait(0.2)
        finally:
            if stop.is_set() or any(t.is_alive() for t in threads):
                runner.abort()
                interrupt.wait_for(threads, 60)  # the experiments end once their runs fail
            progress.stop()
            runner.close()
    if stop.is_set():
        sys.stderr.write(f"odelab-report: interrupted; the outstanding runs ({executor.description}) "
                         f"were cancelled, nothing written\n")
        return 130
    if not failures:
        failures.update(_check_timing_hosts(runner, executor))
    if stop.is_set():
        return 130
    if failures:
        _report_failures(failures)
        sys.stderr.write(f"odelab-report: nothing written to {out}; the runs are kept in {runs_dir}\n")
        return 1
    if args.atlas is not None:
        from .atlas_report import write_atlas_report as write_report
    elif args.world is not None:
        from .world_report import write_world_report as write_report
    elapsed = write_report(args, argv, staging, header, runner, progress, outcomes, jobs, executor.timing_host)
    if stop.is_set():
        return 130
    try:
        with interrupt.deferred():  # both renames happen, or neither
            output_folder.publish(staging, out)
            _published.set()
    except output_folder.Refused as error:
        sys.stderr.write(f"odelab-report: --out: {error}; nothing written\n")
        return 2
    sys.stderr.write(f"odelab-report: wrote {out} in {clock(elapsed)}\n")
    return 0


def _check_timing_hosts(runner, executor):
    """Wall times of different hosts never meet in one table: every timed run
    must come from the executor's timing host."""
    hosts = sorted({r.host for r in runner.runs if r.spec.timed})
    if len(hosts) > 1:
        return {"timing": f"timed runs came from {len(hosts)} hosts ({', '.join(hosts)}), so their wall "
                          f"times cannot share a table; the executor was to keep them on {executor.timing_host}"}
    return {}


def _report_failures(failures):
    """One message per cause: a lost scheduler fails every experiment alike."""
    by_message = {}
    for name, message in failures.items():
        by_message.setdefault(message, []).append(name)
    for message, names in by_message.items():
        which = f"experiment {names[0]}" if len(names) == 1 else f"experiments {', '.join(names)}"
        sys.stderr.write(f"odelab-report: {which} failed:\n{message}\n")
