"""The three costs of a run, defined once, for every engine alike (ODE
included), and never mixed within one comparison.

- engine: the engine's own collision and step calls (metric
  engine_wall_seconds: ODE's dSpaceCollide and dWorldStep or
  dWorldQuickStep; another engine's own calls, timed where it runs, inside
  Node.js for the engines there);
- link: what the program spent in the link to the engine outside those calls
  (metric link_wall_seconds: translating edits and settings, the pipe to an
  engine in another process, the states copied back; 0 for ODE, which has
  no link);
- whole run: the program's CPU time, user and system, with every child it
  waited for (a Node.js engine's process included).

Each is given per simulated second. A cell says which it holds by its
column's name; `one_definition` refuses a comparison whose cells name more
than one."""

from . import timing

ENGINE, LINK, WHOLE_RUN = "engine", "link", "whole run"

DEFINITIONS = {
    ENGINE: "the engine's own collision and step calls (engine_wall_seconds), wall seconds per simulated second",
    LINK: "the link outside the engine's own calls: translation, the pipe to a Node.js engine, the state copy "
          "(link_wall_seconds; 0 for ODE, which has none), wall seconds per simulated second",
    WHOLE_RUN: "the whole run's CPU, user and system, a Node.js engine's process included, seconds per simulated "
               "second",
}

# The column that holds each cost per simulated second (with _min and _max beside it).
COLUMNS = {ENGINE: "engine_s_per_sim_s", LINK: "link_s_per_sim_s", WHOLE_RUN: "cpu_s_per_sim_s"}


def seconds(result, definition):
    """A run's seconds under `definition` (None when the run did not report them)."""
    if definition == ENGINE:
        return result.m("engine_wall_seconds")
    if definition == LINK:
        return result.m("link_wall_seconds")
    if definition == WHOLE_RUN:
        return result.cpu_seconds
    raise ValueError(f"no cost is called {definition!r}; the costs are {', '.join(DEFINITIONS)}")


def per_sim_second(result, definition):
    sim = result.m("sim_seconds")
    value = seconds(result, definition)
    return value / sim if value is not None and sim else None


def per_step(result, definition):
    steps = result.m("steps")
    value = seconds(result, definition)
    return value / steps if value is not None and steps else None


def columns(results):
    """Each cost's median, min and max per simulated second over `results`
    (runs that ended with status 0), under the names COLUMNS gives."""
    ok = [r for r in results if r.rc == 0 and r.m("sim_seconds")]
    out = {}
    for definition, column in COLUMNS.items():
        mid, low, high = timing.spread([per_sim_second(r, definition) for r in ok])
        out.update({column: mid, column + "_min": low, column + "_max": high})
    return out


def definition_of(column):
    """The definition a cost column holds, read from its name."""
    base = column.removesuffix("_min").removesuffix("_max")
    for definition, name in COLUMNS.items():
        if base == name:
            return definition
    raise ValueError(f"{column!r} is not a cost column; the cost columns are {', '.join(COLUMNS.values())}")


def one_definition(cells):
    """The one definition that every (label, definition) cell of a
    comparison uses; ValueError naming the cells when they differ."""
    used = {}
    for label, definition in cells:
        if definition not in DEFINITIONS:
            raise ValueError(f"{label}: no cost is called {definition!r}")
        used.setdefault(definition, []).append(label)
    if len(used) != 1:
        raise ValueError("one comparison mixes costs of different kinds: "
                         + "; ".join(f"{d}: {', '.join(labels)}" for d, labels in used.items()))
    return next(iter(used))
