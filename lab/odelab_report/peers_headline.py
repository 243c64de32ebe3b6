"""The engines experiment's headline finding for one scene, as Claims on
peers.csv: at the scene's comparison step, defaults beside defaults (ODE's
one setting counts as its default), like with like as peer_compare.py
decides it (a figure zero by construction, or a run marked as not on the
scene's surface, takes no part; an error below an engine's
rounding counts as that rounding), the best figure, and its cost, the engine's own seconds (its
collision and step calls) per simulated second, as the median [range] of
the timed runs. An equal figure whose cost range
overlaps the cheapest's is a tie within the timing's scatter. The text and
rule are recomputed from peers.csv alone (check_report.py), so a headline
cannot say more than the rows hold."""

from .claims import Claim, q


def headline(scene, label, lower_is_better, step, float32_engines, rounding, float32_rounding):
    """The headline's claims (`headline.peers.<scene>[.tie|.none]`): one of
    them holds for any peers.csv."""
    f = "peers.csv"
    where = dict(scene=scene, step=step)
    better = "min" if lower_is_better else "max"
    values = {
        "engines": q(f, "engine", "texts", **where),
        "settings": q(f, "setting", "texts", **where),
        "v": q(f, "value", "list", **where),
        "cost": q(f, "engine_s_per_sim_s", "list", **where),
        "lo": q(f, "engine_s_per_sim_s_min", "list", **where),
        "hi": q(f, "engine_s_per_sim_s_max", "list", **where),
        "like": q(f, "like_ode_surface", "list", **where),
        "made": q(f, "by_construction", "texts", **where),
        "odes": "[i for i in range(len(engines)) if engines[i] == 'ode']",
        # defaults beside defaults; ODE's one setting is its default
        "kind": "[i for i in range(len(engines)) if settings[i] == 'default' or (len(odes) == 1 and i in odes)]",
        "fair": "[i for i in kind if v[i] is not None and like[i] == 1 and not made[i] and cost[i] is not None]",
        "floor": f"[{float32_rounding!r} if e in {tuple(float32_engines)!r} else {rounding!r} for e in engines]",
        "score": ("[max(v[i], floor[i]) if v[i] is not None else None for i in range(len(v))]" if lower_is_better
                  else "[v[i] for i in range(len(v))]"),
        "best": f"{better}(score[i] for i in fair) if fair else None",
        "equal": "[i for i in fair if score[i] == best]",
        "w": "min(equal, key=lambda i: cost[i]) if equal else 0",
        "tied": "[i for i in equal if i != w and lo[i] <= hi[w] and lo[w] <= hi[i]]",
        "how": f"'exact to rounding' if {lower_is_better!r} and fair and v[w] < floor[w] else 'best'",
        "name": "engines[w]",
        "figure": "num(v[w], 3)",
        "c": "cost[w]", "a": "lo[w]", "b": "hi[w]",
        "names": "', '.join(engines[i] for i in [w] + tied)",
    }
    opening = f"peers {scene} ({label}): at step {step:g}, defaults beside defaults"
    # Every rule names the winner's standing: no fair row beats it, it is the
    # cheapest of the equal figures, and the tie list is exactly the overlaps.
    holds = "len(fair) > 0 and all(score[i] >= best if %r else score[i] <= best for i in fair) and " \
            "all(cost[w] <= cost[i] for i in equal)" % lower_is_better
    return [Claim(f"headline.peers.{scene}", opening + ": {name} is {how} with {figure} at {c:k2} [{a:k2}-{b:k2}] "
                  "engine s per simulated s.", values, holds + " and len(tied) == 0"),
            Claim(f"headline.peers.{scene}.tie", opening + ": a tie within the timing's scatter at {figure}: "
                  "{names}.", values, holds + " and len(tied) > 0"),
            Claim(f"headline.peers.{scene}.none", opening + ": no engine that compares reached a figure.", values,
                  "len(fair) == 0")]
