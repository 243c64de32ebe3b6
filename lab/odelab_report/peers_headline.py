"""The engines experiment's headline finding for one scene, as a Claim on
peers.csv: at the comparison step, which engines and settings reach the best
figure (errors below an engine's rounding tie), the cheapest of them by wall
time, and ODE's figure at its default. Its text and rule are recomputed
from peers.csv alone (check_report.py), so a headline cannot say more than
the rows hold."""

from .claims import Claim, q


def headline(scene, label, lower_is_better, step, float32_engines, rounding, float32_rounding):
    """The headline finding (`headline.peers.<scene>`): see _claim."""
    return _claim(f"headline.peers.{scene}", f"peers {scene} ({label}): at step {step:g}: ", scene, lower_is_better,
                  step, float32_engines, rounding, float32_rounding)


def verdict(scene, lower_is_better, step, float32_engines, rounding, float32_rounding):
    """The same finding as the scene's section says it (`peers.<scene>.verdict`),
    or, when no engine reached a figure at `step`, that none did."""
    found = _claim(f"peers.{scene}.verdict", f"At step {step:g}: ", scene, lower_is_better, step, float32_engines,
                   rounding, float32_rounding)
    none = Claim(f"peers.{scene}.verdict.none", f"No engine reached a figure at step {step:g}.",
                 {"v": q("peers.csv", "value", "list", scene=scene, step=step)}, "all(x is None for x in v)")
    return [found, none]


def _claim(key, opening, scene, lower_is_better, step, float32_engines, rounding, float32_rounding):
    """The Claim `headline.peers.<scene>`: shown when some engine reached a
    figure at `step`, and its rule holds only when no engine's row at that
    step is better than the one the sentence names. An error below
    `rounding` (`float32_rounding` for `float32_engines`) is the engine's
    rounding, not physics: such errors tie."""
    f = "peers.csv"
    where = dict(scene=scene, step=step)
    better = "min" if lower_is_better else "max"
    values = {
        "engines": q(f, "engine", "texts", **where),
        "settings": q(f, "setting", "texts", **where),
        "v": q(f, "value", "list", **where),
        "wall": q(f, "wall_s_per_sim_s", "list", **where),
        "capped": q(f, "capped", "texts", **where),
        "floor": f"[{float32_rounding!r} if e in {tuple(float32_engines)!r} else {rounding!r} for e in engines]",
        "at": "[i for i in range(len(v)) if v[i] is not None]",
        # the figure as judged: an error below rounding counts as the rounding
        "score": ("[max(v[i], floor[i]) if i in at else None for i in range(len(v))]" if lower_is_better
                  else "[v[i] if i in at else None for i in range(len(v))]"),
        "best": f"{better}(score[i] for i in at)",
        "ties": "[i for i in at if score[i] == best]",
        "w": "min(ties, key=lambda i: wall[i] or 0)",
        "names": "', '.join(engines[i] + ' (' + settings[i] + ')' for i in ties)",
        "verb": "'is' if len(ties) == 1 else 'are'",
        "how": f"'exact to rounding' if {lower_is_better!r} and v[w] < floor[w] else 'best'",
        "figure": "num(v[w], 3) + (' (scan limit)' if capped[w] == '1' else '')",
        "cost": "wall[w]",
        "cheapest": "'' if len(ties) == 1 else ', the cheapest ' + engines[w] + ' (' + settings[w] + ')'",
        "ode": "[i for i in range(len(v)) if engines[i] == 'ode' and settings[i] == 'default']",
        "ode_text": "'' if not ode else '; ODE at its default ' + (num(v[ode[0]], 3) if v[ode[0]] is not None "
                    "else 'no figure')",
    }
    outdone = ("all(score[i] >= best for i in at)" if lower_is_better else "all(score[i] <= best for i in at)")
    template = (opening + "{names} {verb} {how} with {figure}{cheapest} "
                "at {cost:n} wall s per simulated s{ode_text}.")
    # The rule: an engine reached a figure; none at this step beats the one
    # named; the one named is the cheapest of its ties.
    rule = f"len(at) > 0 and {outdone} and all((wall[w] or 0) <= (wall[i] or 0) for i in ties)"
    return Claim(key, template, values, rule)
