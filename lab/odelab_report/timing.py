"""Timing figures a reader may rely on: each the median and the range of
several interleaved runs, every run long enough to time, and a choice
between two timings made only outside their scatter.

A run of a few milliseconds is timed mostly by the scheduler and the
process's start-up, not by the engine: a timed run lasts at least
MIN_RUN_CPU_SECONDS of CPU, its simulated length stretched from a first
(untimed) run's cost where the scene allows it."""

import math

from .runner import median

MIN_RUN_CPU_SECONDS = 0.5
# --quick is a smoke run of the lab, not a measurement: shorter runs.
QUICK_MIN_RUN_CPU_SECONDS = 0.1
# A run's CPU time on this shared machine scatters by up to half between
# runs of one command (measured: 0.16 s untimed, 0.10 s timed), so the
# untimed run that fixes a length must last SURE times the minimum, and a
# stretch aims LENGTH_MARGIN times above it.
LENGTH_MARGIN = 2.5
SURE = 2.0
# Untimed runs made at most to find a stretch that lasts long enough.
CALIBRATIONS = 6
MAX_TIMED_SIM_SECONDS = 1e6  # an engine costing nothing measurable is not run for ever
REPEATS = 5  # timed runs per figure (full report)
QUICK_REPEATS = 2  # --quick: enough to see a spread and to catch a replayed timing


def repeats(quick):
    return QUICK_REPEATS if quick else REPEATS


def min_run_cpu(quick):
    return QUICK_MIN_RUN_CPU_SECONDS if quick else MIN_RUN_CPU_SECONDS


def timed_seconds(sim_seconds, cpu_seconds, minimum=MIN_RUN_CPU_SECONDS, startup=0.0):
    """The simulated length of a timed run of the scene that a run of
    `sim_seconds` made in `cpu_seconds` (of which `startup` was the process's
    start-up, when known): the scene's own length, or longer so that the run
    lasts at least `minimum` CPU seconds (rounded up to two significant
    digits)."""
    if not sim_seconds or sim_seconds <= 0:
        raise ValueError(f"a run of {sim_seconds!r} simulated seconds cannot be stretched")
    if cpu_seconds is not None and cpu_seconds >= SURE * minimum:
        return sim_seconds
    per_second = max((cpu_seconds or 0.0) - startup, 1e-9) / sim_seconds
    wanted = min(MAX_TIMED_SIM_SECONDS, LENGTH_MARGIN * max(minimum - startup, 0.0) / per_second)
    if wanted <= sim_seconds:
        return sim_seconds
    digits = 10 ** (math.floor(math.log10(wanted)) - 1)
    return float(math.ceil(wanted / digits) * digits)


def with_seconds(args, seconds):
    """`args` with its --seconds value set to `seconds` (added if absent)."""
    args = list(args)
    if "--seconds" in args:
        args[args.index("--seconds") + 1] = seconds
    else:
        args += ["--seconds", seconds]
    return args


def spread(values):
    """(median, min, max) of the values that exist; (None, None, None) if none."""
    values = [v for v in values if v is not None]
    if not values:
        return None, None, None
    return median(values), min(values), max(values)


def overlap(a_low, a_high, b_low, b_high):
    """Whether two timing ranges overlap: neither is faster in every run."""
    return a_low <= b_high and b_low <= a_high


def ratio_range(low, high, base_low, base_high):
    """The range of a cost over a base cost, from both ranges: (least, most)."""
    return low / base_high, high / base_low


def stretched(runner, program, args, minimum=MIN_RUN_CPU_SECONDS):
    """`args` with --seconds stretched so that a run lasts `minimum` seconds
    of CPU: a first run's cost includes the process's start-up, so each
    stretch is checked by an untimed run at the new length and made again
    from it, up to CALIBRATIONS times. The arguments to time."""
    from .runner import RunSpec  # the runner imports nothing of this module's

    args = list(args)
    r = runner.run(RunSpec(program, args, measures_blow_ups=True))
    before = None  # the previous run's (sim, cpu): two runs give the start-up apart
    for _ in range(CALIBRATIONS):
        if r.rc != 0 or not r.m("sim_seconds"):
            break
        sim, cpu = r.m("sim_seconds"), r.cpu_seconds
        startup = 0.0
        if before and sim > before[0] and cpu > before[1]:
            slope = (cpu - before[1]) / (sim - before[0])
            startup = min(max(cpu - slope * sim, 0.0), 0.9 * cpu)
        seconds = timed_seconds(sim, cpu, minimum, startup)
        if seconds == sim:
            break
        # a noisy start-up can make the estimate too short: at least double
        seconds = max(seconds, 2 * sim)
        before = (sim, cpu)
        args = with_seconds(args, seconds)
        r = runner.run(RunSpec(program, args, measures_blow_ups=True))
    return args


def interleaved(runner, commands, count):
    """`count` timed runs of each (program, args) in `commands`, interleaved:
    every command's first, then every command's second..., so that a busy
    spell of the machine falls on many commands, not on the repeats of one.
    The results per command, in repeat order."""
    from .runner import RunSpec

    out = [[] for _ in commands]
    for repeat in range(count):
        results = runner.map([RunSpec(program, args, timed=True, repeat=repeat, measures_blow_ups=True)
                              for program, args in commands])
        for mine, result in zip(out, results):
            mine.append(result)
    return out


# Times a set of timed runs is thrown away and made again, longer, because
# one of them came out shorter than the minimum.
LENGTHENINGS = 2


def interleaved_long_enough(runner, commands, count, minimum):
    """interleaved(), then every command whose shortest timed run (of those
    that ended with status 0) used less than `minimum` CPU seconds is
    stretched from that run and timed again: a whole new set of `count`
    runs, interleaved with the other short commands', up to LENGTHENINGS
    times. The stretch comes from an untimed run, and the machine's load can
    make the timed runs shorter than it. The results per command."""
    out = interleaved(runner, commands, count)
    commands = list(commands)
    for _ in range(LENGTHENINGS):
        short = [i for i, results in enumerate(out) if _too_short(results, minimum)]
        if not short:
            break
        for i in short:
            program, args = commands[i]
            shortest = min((r for r in out[i] if r.rc == 0 and r.m("sim_seconds")), key=lambda r: r.cpu_seconds)
            seconds = timed_seconds(shortest.m("sim_seconds"), shortest.cpu_seconds, minimum)
            commands[i] = (program, with_seconds(args, max(seconds, 1.5 * shortest.m("sim_seconds"))))
        for i, results in zip(short, interleaved(runner, [commands[i] for i in short], count)):
            out[i] = results
    return out


def _too_short(results, minimum):
    ok = [r for r in results if r.rc == 0 and r.m("sim_seconds") and r.cpu_seconds is not None]
    return bool(ok) and min(r.cpu_seconds for r in ok) < minimum


def scatter_of(costs):
    """The timing's relative scatter from repeated runs of one setting:
    (max - min) / median of their costs (0 for fewer than two)."""
    costs = [c for c in costs if c is not None]
    if len(costs) < 2:
        return 0.0
    middle, low, high = spread(costs)
    return (high - low) / middle if middle else 0.0


def keep(scored, current, scatter):
    """The trial the descent keeps among `scored` [((margin, limit), setting,
    run)]: the smallest margin, but where it and the value already chosen
    (`current`) are both bound by real time, a margin smaller by no more
    than the timing's relative `scatter` is a tie, and the value already
    chosen stays. Returns (kept entry, [settings tied with it])."""
    smallest = min(scored, key=lambda x: (x[0][0], x[1] != current))
    mine = next((x for x in scored if x[1] == current), None)
    if mine is None or mine is smallest:
        kept = smallest
    elif (smallest[0][1] == mine[0][1] == "real time"
          and mine[0][0] - smallest[0][0] <= scatter * mine[0][0]):
        kept = mine
    else:
        kept = smallest
    tied = [x[1] for x in scored if x is not kept and x[0][1] == kept[0][1] == "real time"
            and abs(x[0][0] - kept[0][0]) <= scatter * max(x[0][0], kept[0][0])]
    return kept, tied
