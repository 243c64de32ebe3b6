"""The first screen of a world report (lab/odelab-report --world): one
answer to each of the three questions, every sentence a Claim (claims.py)
on the report's CSVs, shown only where its rule holds:
- which setting keeps the world accurate enough at the least cost
  (world-sweep.csv: the world's own setting, the cheapest within 1% and 0.1%);
- where it breaks (world-limit.csv: the step searches);
- whether another engine does better (world-engines.csv, at the world's step):
  each measurement against its reference (world-measures.csv: analytic,
  conservation or the engine's own finer run), a winner named only beyond
  the spread (claims.best_or_tie), and each engine's outcome against the
  world's expected one."""

from . import markdown as md
from .claims import Claim, q
from .world_rules import BOUND, FIRST_FAIL, LAST_PASS_BELOW, LEVELS

SWEEP, LIMIT, ENGINES = "world-sweep.csv", "world-limit.csv", "world-engines.csv"
MEASURES = "world-measures.csv"


def sweep_lookups(error="max_dev"):
    return {"names": q(SWEEP, "setting", "texts"), "errors": q(SWEEP, error, "list"),
            "cost": q(SWEEP, "engine_s_per_sim_s", "list"), "lo": q(SWEEP, "engine_s_per_sim_s_min", "list"),
            "hi": q(SWEEP, "engine_s_per_sim_s_max", "list"), "own": q(SWEEP, "setting", "text", own=1)}


def own_setting():
    values = {"own": q(SWEEP, "setting", "text", own=1), "d": q(SWEEP, "max_dev", own=1),
              "c": q(SWEEP, "engine_s_per_sim_s", own=1), "lo": q(SWEEP, "engine_s_per_sim_s_min", own=1),
              "hi": q(SWEEP, "engine_s_per_sim_s_max", own=1)}
    ran = Claim("world.own", "At its own settings ({own}) the world stays within {d:p} of the reference, at "
                "{c:n2} [{lo:n2}-{hi:n2}] engine s per simulated s.", values, "d == d and d < float('inf')")
    lost = Claim("world.own.lost", "At its own settings ({own}) a measurement the reference has is missing "
                 "(the run gave none).", {"own": values["own"], "d": values["d"]}, "d == float('inf')")
    failed = Claim("world.own.failed", "At its own settings ({own}) the world ended with status {x:n}.",
                   {"own": values["own"], "x": q(SWEEP, "exit_status", own=1)}, "x != 0")
    return [lost, failed, ran]  # the finite figure last: inf has no percentage


SHOWN = 3  # settings named in a tie; the rest counted (world-sweep.csv has them all)


def cheapest(level, error="max_dev", what="every measurement"):
    """The cheapest setting within `level` on `error` (claims.cheapest_set:
    the cheapest by its median cost and every setting tied with it within
    the timing's scatter), the world's own setting first when tied."""
    values = dict(sweep_lookups(error), tied=f"cheapest_set(errors, cost, lo, hi, {level!r})",
                  order="sorted(tied, key=lambda i: (names[i] != own, cost[i]))",
                  said="[names[i] + ' (' + num(cost[i], 2) + ' s/s)' for i in order]",
                  c="'none measured' if not tied else said[0] if len(tied) == 1 else "
                    f"'a tie within the timing\\'s scatter: ' + ', '.join(said[:{SHOWN}]) + "
                    f"(' and ' + str(len(said) - {SHOWN}) + ' more' if len(said) > {SHOWN} else '')")
    return Claim(f"world.cheapest.{error}.{level:g}", f"Cheapest within {md.pct(level)} of the reference on "
                 f"{what}: {{c}}.", values, "len(names) > 0")


def limit(search):
    """The step limit of one search of world-limit.csv, in the first
    alternative that holds: a limit bracketed, none up to the largest step
    tried, or a failure at the smallest."""
    what = "blows up (status 3)" if search == "blow-up" else f"departs from the reference by more than {md.pct(BOUND)}"
    ok = "runs" if search == "blow-up" else f"stays within {md.pct(BOUND)}"
    values = {"steps": q(LIMIT, "step_s", "list", search=search), "passed": q(LIMIT, "passed", "list", search=search),
              "solver": q(SWEEP, "solver", "text", own=1)}
    found = dict(values, f=FIRST_FAIL, p=LAST_PASS_BELOW)
    return [
        Claim(f"world.limit.{search}", f"Along the step ({{solver}}, the world's ERP and CFM) it {what} at "
              f"{{f:n}} s; the largest step below that {ok} is {{p:n}} s.", found, "p < f"),
        Claim(f"world.limit.{search}.none", f"Along the step ({{solver}}) nothing {what.split(' (')[0]} up to "
              f"{{m:n}} s, the largest step tried.", dict(values, m="max(steps)"), "all(passed)"),
        Claim(f"world.limit.{search}.all", f"Along the step ({{solver}}) it {what} even at {{m:n}} s, the "
              f"smallest step tried.", dict(values, m="min(steps)"), "not any(passed)"),
    ]


# Two deviations closer than this (the report's finest tolerance) are the
# same answer: the spread an engine must beat another's by to be named alone.
ACCURACY_SPREAD = LEVELS[-1]


def engines():
    """Which engine (ODE at the world's settings among them) comes closest
    to each measurement's reference (world-measures.csv: analytic,
    conservation or the engine's own finer run) at the world's step: named
    alone only when it beats every other by more than ACCURACY_SPREAD
    (claims.best_or_tie), else a tie naming the tied; agreement with ODE's
    finest run is not the verdict."""
    values = {"engine": q(ENGINES, "engine", "texts"), "setting": q(ENGINES, "setting", "texts"),
              "status": q(ENGINES, "status", "texts"), "dev": q(ENGINES, "max_dev", "list"),
              "cost": q(ENGINES, "engine_s_per_sim_s", "list"),
              "kinds": q(MEASURES, "reference_kind", "texts"),
              "d0": q(ENGINES, "max_dev", engine="ode", setting="default"),
              "ran": "[i for i, e in enumerate(engine) if status[i] == 'ran' and dev[i] is not None "
                     "and dev[i] < float('inf')]",
              "order": f"best_or_tie([dev[i] for i in ran], [dev[i] - {ACCURACY_SPREAD / 2!r} for i in ran], "
                       f"[dev[i] + {ACCURACY_SPREAD / 2!r} for i in ran])",
              "tied": "[ran[k] for k in order]",
              "i": "tied[0] if tied else 0", "name": "engine[i] + ' (' + setting[i] + ')'", "d": "dev[i] if tied else 0", "c": "cost[i]",
              "d0t": "pct(d0) if d0 is not None and d0 < float('inf') else 'not ranked (a measurement missing "
                     "or the other outcome)'",
              "refs": "', '.join(sorted(dict.fromkeys(kinds)))",
              "names": "', '.join(engine[k] + ' (' + setting[k] + ', ' + pct(dev[k]) + ')' for k in tied)"}
    return [
        Claim("world.engines.none", "No other engine ran the world ({n:n} listed; world-engines.csv says why).",
              {"engine": values["engine"], "status": values["status"],
               "n": "len([e for e in engine if e != 'ode']) // 2",
               "ran": "[i for i, e in enumerate(engine) if e != 'ode' and status[i] == 'ran']"}, "len(ran) == 0"),
        Claim("world.engines.best", "Closest to each measurement's reference ({refs}; world-measures.csv) at the "
              "world's step: {name}, largest deviation {d:p}, ahead of every other engine and setting by more than "
              f"{ACCURACY_SPREAD:.1%}, at {{c:n2}} engine s per simulated s; ODE at the world's settings: {{d0t}}.",
              values, "len(tied) == 1"),
        Claim("world.engines.tie", "No engine is closest alone to each measurement's reference ({refs}; "
              f"world-measures.csv) at the world's step: a tie within {ACCURACY_SPREAD:.1%}: {{names}}.",
              values, "len(tied) > 1"),
        Claim("world.engines.unranked", "No engine ran the world with every measurement and the expected "
              "outcome (world-engines.csv lists each engine's figures).", values, "len(tied) == 0"),
    ]


def outcomes():
    """Each engine whose outcome by rule (stops / tunnels, stays / slides)
    is not the one the world expects, in a sentence."""
    values = {"engine": q(ENGINES, "engine", "texts"), "setting": q(ENGINES, "setting", "texts"),
              "got": q(ENGINES, "outcome", "texts"), "want": q(ENGINES, "outcome_expected", "texts"),
              "ok": q(ENGINES, "outcome_as_expected", "list"),
              "wrong": "[i for i, x in enumerate(ok) if x == 0]",
              "said": "'; '.join(engine[i] + ' (' + setting[i] + '): ' + got[i] + ', expected ' + want[i] "
                      "for i in wrong)",
              "right": "len([x for x in ok if x == 1])"}
    return [Claim("world.outcomes.wrong", "Not the expected outcome: {said}.", values, "len(wrong) > 0"),
            Claim("world.outcomes.right", "Every engine that ran shows the expected outcome ({right:n} runs).",
                  values, "right > 0 and len(wrong) == 0")]


def questions():
    """[(question, [claim alternatives, ...])]: each question's sentences,
    each a list of alternatives (the first that holds is shown)."""
    return [
        ("Which setting keeps it accurate enough at the least cost?",
         [own_setting()] + [[cheapest(level)] for level in LEVELS]),
        ("Where does it break?", [limit("blow-up"), limit("bound")]),
        ("Would another engine do better?", [engines(), outcomes()]),
    ]


def knob(column, label):
    """What ERP or CFM does at the world's step and solver: the span of the
    largest deviation over the values swept, and the value with the least."""
    within = {f"in_{column}": 1}
    values = {"x": q(SWEEP, column, "list", **within), "d": q(SWEEP, "max_dev", "list", **within),
              "ok": "[i for i, v in enumerate(d) if v is not None and v < float('inf')]",
              "lo": "min(d[i] for i in ok)", "hi": "max(d[i] for i in ok)",
              "best": "x[min(ok, key=lambda i: d[i])]", "n": "len(x) - len(ok)"}
    return Claim(f"world.{column}", f"{label} from {{a:n}} to {{b:n}}: the largest deviation spans {{lo:p}} to "
                 f"{{hi:p}}, the least at {label} {{best:n}}{{tail}}.",
                 dict(values, a="min(x)", b="max(x)",
                      tail="'; no figure at ' + str(n) + ' of them (blown up or a measurement missing)' if n else ''"),
                 "len(ok) > 0")
