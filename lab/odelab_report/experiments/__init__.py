"""Every experiment of the report, in report order."""

from .doc_samples import DocSamples
from .energy_test2 import EnergyTest2
from .limit_test4 import LimitTest4
from .limit_test5 import LimitTest5
from .limit_test8 import LimitTest8
from .limit_test9 import LimitTest9
from .limit_test10 import LimitTest10
from .peers import Peers
from .remedy_test4 import RemedyTest4
from .remedy_test5 import RemedyTest5
from .remedy_test6 import RemedyTest6
from .remedy_test10 import RemedyTest10
from .speed_accuracy import SpeedTest2, SpeedTest8, SpeedTest9
from .thesis import Thesis
from .thesis_havok import ThesisHavok

ALL = [
    Thesis(), ThesisHavok(),
    LimitTest4(), LimitTest10(), LimitTest5(), LimitTest8(), LimitTest9(), EnergyTest2(),
    SpeedTest2(), SpeedTest8(), SpeedTest9(),
    RemedyTest10(), RemedyTest4(), RemedyTest6(), RemedyTest5(),
    Peers(),
    DocSamples(),
]

SECTIONS = {
    1: "The thesis, reproduced",
    2: "Stability limits",
    3: "Speed against accuracy",
    4: "Remedies",
    5: "Other engines, live",
    6: "The sample runs the docs quote",
}

# Names --only accepts besides the experiments' own.
GROUPS = {"limits": 2, "speed": 3, "remedies": 4}


def select(names):
    """The experiments named (experiment names or group names), in report
    order; raises ValueError naming what is unknown."""
    by_name = {e.name: e for e in ALL}
    chosen, unknown = set(), []
    for name in names:
        if name in by_name:
            chosen.add(name)
        elif name in GROUPS:
            chosen.update(e.name for e in ALL if e.section == GROUPS[name])
        elif name == "all":
            chosen.update(by_name)
        else:
            unknown.append(name)
    if unknown:
        raise ValueError(", ".join(unknown))
    return [e for e in ALL if e.name in chosen]
