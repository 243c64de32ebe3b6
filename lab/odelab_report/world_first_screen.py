"""The first screen of a world report (lab/odelab-report --world): one
answer to each of the three questions, every sentence a Claim (claims.py)
on the report's CSVs, shown only where its rule holds:
- which setting keeps the world accurate enough at the least cost
  (world-sweep.csv: the world's own setting, the cheapest within 1% and 0.1%);
- where it breaks (world-limit.csv: the step searches);
- whether another engine does better (world-engines.csv, at the world's step)."""

from . import markdown as md
from .claims import Claim, q
from .world_rules import BOUND, FIRST_FAIL, LAST_PASS_BELOW, LEVELS

SWEEP, LIMIT, ENGINES = "world-sweep.csv", "world-limit.csv", "world-engines.csv"


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


def engines():
    """Who comes closest to the reference at the world's step: another
    engine (default or best) ahead of ODE at the world's settings, or not."""
    values = {"engine": q(ENGINES, "engine", "texts"), "setting": q(ENGINES, "setting", "texts"),
              "status": q(ENGINES, "status", "texts"), "dev": q(ENGINES, "max_dev", "list"),
              "cost": q(ENGINES, "engine_s_per_sim_s", "list"),
              "d0": q(ENGINES, "max_dev", engine="ode", setting="default"),
              "c0": q(ENGINES, "engine_s_per_sim_s", engine="ode", setting="default"),
              "others": "[i for i, e in enumerate(engine) if e != 'ode' and status[i] == 'ran' "
                        "and dev[i] is not None and dev[i] < float('inf')]",
              "i": "min(others, key=lambda k: (dev[k], cost[k] if cost[k] is not None else float('inf')))",
              "name": "engine[i] + ' (' + setting[i] + ')'", "d": "dev[i]", "c": "cost[i]"}
    lost = Claim("world.engines.lost", "ODE at the world's settings is missing a measurement the reference has, so no "
                 "engine is ranked against it (world-engines.csv lists each engine's figures).",
                 {"d0": values["d0"]}, "d0 == float('inf')")
    return [
        lost,
        Claim("world.engines.better", "Another engine comes closer to ODE's reference at the world's step: "
              "{name}, largest deviation {d:p} against ODE's {d0:p} at the world's settings, at {c:n2} engine s per "
              "simulated s against ODE's {c0:n2}.", values, "d < d0"),
        Claim("world.engines.not", "No other engine comes closer to ODE's reference at the world's step than ODE "
              "at the world's settings ({d0:p}); the closest: {name}, {d:p}, at {c:n2} engine s per simulated s "
              "against ODE's {c0:n2}.", values, "d >= d0"),
        Claim("world.engines.none", "No other engine ran the world ({n:n} listed; world-engines.csv says why).",
              {"engine": values["engine"], "status": values["status"],
               "n": "len([e for e in engine if e != 'ode']) // 2",
               "ran": "[i for i, e in enumerate(engine) if e != 'ode' and status[i] == 'ran']"}, "len(ran) == 0"),
    ]


def questions():
    """[(question, [claim alternatives, ...])]: each question's sentences,
    each a list of alternatives (the first that holds is shown)."""
    return [
        ("Which setting keeps it accurate enough at the least cost?",
         [own_setting()] + [[cheapest(level)] for level in LEVELS]),
        ("Where does it break?", [limit("blow-up"), limit("bound")]),
        ("Would another engine do better?", [engines()]),
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
