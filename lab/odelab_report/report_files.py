"""The report's own files besides the experiments': runs.csv (every run)
and RESULTS.md, written into the staging folder."""

import shlex
from collections import Counter

from . import csvout, header as run_header, results_md
from .progress import clock


def hosts_text(runs, timing_host):
    """Which hosts ran what: limits and accuracy may come from any host, wall
    times only from one (main.py refuses a report where they do not)."""
    counts = Counter(r.host for r in runs)
    timed = sorted({r.host for r in runs if r.spec.timed})
    text = ", ".join(f"{host} ({n} runs)" for host, n in sorted(counts.items()))
    if timed:
        text += f"; every timed run (the wall times) on {timed[0]}"
    else:
        text += f"; no timed runs (the executor's timing host was {timing_host})"
    return text


def blow_ups_text(runs):
    """What the report made of runs that blew up: only the experiments that
    measure blow-ups accept them (RunResult.check), as a failure by their rule."""
    failed = Counter(r.spec.program for r in runs if r.blew_up or r.ode_error)
    if not failed:
        return "no run blew up (status 3) or met an ODE error (status 4)"
    listed = ", ".join(f"{program} {n}" for program, n in sorted(failed.items()))
    return (f"{sum(failed.values())} runs blew up (status 3) or met an ODE error (status 4) ({listed}; "
            f"runs.csv: exit_status), each a failure by the rule of the experiment that measures blow-ups; "
            f"anywhere else a blow-up fails the report")


def write_report(args, argv, staging, header, runner, progress, outcomes, jobs, timing_host):
    """Writes runs.csv and RESULTS.md into `staging`; returns the elapsed seconds."""
    runs_rows = [dict(program=r.spec.program, arguments=" ".join(shlex.quote(a) for a in r.spec.args),
                      timed=r.spec.timed, repeat=r.spec.repeat, exit_status=r.rc,
                      sim_seconds=r.m("sim_seconds"), steps=r.m("steps"), wall_seconds=r.m("wall_seconds"),
                      cpu_seconds=r.cpu_seconds, cpu_share=r.cpu_share, host=r.host) for r in runner.runs]
    csvout.write_csv(staging / "runs.csv", header, list(runs_rows[0].keys()), runs_rows,
                     notes=["every program run of this report (each with --headless --metrics-json); wall_seconds: "
                            "the program's run loop; cpu_seconds: user + system time of the process; "
                            "host: the machine that ran it"])
    elapsed = progress.elapsed()
    elapsed_text = (f"{clock(elapsed)} (min:s) for {len(runner.runs)} program runs, --jobs {jobs}; "
                    f"load average at the end {run_header.load_average()}")
    elapsed_text += "; " + blow_ups_text(runner.runs)
    timed = [r for r in runner.runs if r.spec.timed]
    if timed:
        shares = sorted(r.cpu_share for r in timed)
        elapsed_text += (f"; {len(timed)} timed runs, CPU share median {shares[len(shares) // 2]:.2f}, "
                         f"lowest {shares[0]:.2f}")
    command = "lab/odelab-report " + " ".join(shlex.quote(a) for a in argv)
    md_header = header + [("hosts", hosts_text(runner.runs, timing_host))]
    results_md.write(staging / "RESULTS.md", md_header, [(e, outcomes[e.name]) for e in args.experiments],
                     "runs.csv", elapsed_text, command.strip(), args.quick,
                     [e.name for e in args.experiments] if args.partial else [])
    return elapsed
