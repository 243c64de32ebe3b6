"""The search for a stability limit: the largest value of a parameter
(a mass, a plate count) at which a run still passes its failure rule.

A geometric ladder from `start` (up by `factor` while runs pass, down while
they fail) brackets the limit; geometric bisection then narrows the bracket
until hi / lo <= `ratio`. The search assumes that failing is monotone in the
parameter: values above the first failure are not all tried, and the report
says so."""

import math


class SearchResult:
    def __init__(self, highest_pass, lowest_fail, probes, capped):
        self.highest_pass = highest_pass  # None: even the lowest value tried failed
        self.lowest_fail = lowest_fail    # None: nothing failed up to the cap
        self.probes = probes              # [(value, passed, info)] in the order tried
        self.capped = capped              # the ladder hit `high` (or `low`) without a bracket


def highest_passing(probe, start, factor, ratio, low, high, integer=False, max_probes=40, on_probe=None):
    """`probe(value)` -> (passed, info); `on_probe()` after each. Returns a SearchResult."""
    probes = []
    seen = {}

    def tried(value):
        if integer:
            value = int(round(value))
        if value not in seen:
            passed, info = probe(value)
            seen[value] = passed
            probes.append((value, passed, info))
            if on_probe:
                on_probe()
        return value, seen[value]

    value, passed = tried(start)
    lo = value if passed else None
    hi = None if passed else value
    capped = False
    while len(probes) < max_probes:  # the ladder
        if lo is not None and hi is not None:
            break
        if passed:
            if value >= high:
                capped = True
                break
            value, passed = tried(min(high, value * factor))
        else:
            if value <= low:
                capped = True
                break
            value, passed = tried(max(low, value / factor))
        if passed:
            lo = value if lo is None else max(lo, value)
        else:
            hi = value if hi is None else min(hi, value)
    while lo is not None and hi is not None and hi / lo > ratio and len(probes) < max_probes:
        middle = math.sqrt(lo * hi)
        if integer:
            middle = int(round(middle))
            if middle <= lo or middle >= hi:
                break
        value, passed = tried(middle)
        if passed:
            lo = value
        else:
            hi = value
    return SearchResult(lo, hi, probes, capped)
