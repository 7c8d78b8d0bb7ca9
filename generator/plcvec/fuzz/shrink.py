"""Shrinking a disagreement to a minimal case with hypothesis' own shrinker, deterministically.

`@given` and `find()` were not used: their generation phase mixes in constants from whatever modules
are loaded, so the same seed could explore differently (see fuzz/seeded.py). Here the failing
example's choice sequence, found by the seeded search, is handed straight to hypothesis' engine with
only the shrink phase, no example database, and a Random seeded from --seed; draws past the replayed
choices come from the same constant-free provider as the search. The result is then a function of the
seed, the spec and the adapter's answers.

This uses hypothesis' internal engine API (ConjectureRunner), as fuzz/seeded.py does: the shrunk case
is the same for the same seed under one hypothesis version.
"""
import random

from hypothesis import HealthCheck, Phase, settings
from hypothesis.control import BuildContext
from hypothesis.errors import StopTest
from hypothesis.internal.conjecture.data import ConjectureData, Status
from hypothesis.internal.conjecture.engine import ConjectureRunner, RunIsComplete
from hypothesis.internal.escalation import InterestingOrigin

from plcvec.fuzz.seeded import SeededProvider


class Disagreement(Exception):
    """What hypothesis is told a failing example raised: one kind of failure, so the shrinker may move
    from one wrong field to another as long as the implementation still disagrees with the spec."""


class NotReproduced(Exception):
    """The disagreement went away when the same case was run again: the implementation is not a
    function of the vector (state kept between vectors, time, randomness)."""


_ORIGIN = InterestingOrigin.from_exception(Disagreement())
_SETTINGS = settings(database=None, phases=[Phase.shrink], report_multiple_bugs=False, deadline=None,
                     suppress_health_check=list(HealthCheck))


def _draw(data, strategy):
    with BuildContext(data, is_final=True, wrapped_test=None):
        return data.draw(strategy)


def shrink(strategy, choices, differs, seed):
    """(the minimal case, the number of cases run) among those `strategy` draws from choices no larger
    than `choices`, on which `differs(case)` still holds."""

    def test_function(data):
        if differs(_draw(data, strategy)):
            data.mark_interesting(_ORIGIN)

    runner = ConjectureRunner(test_function, settings=_SETTINGS, random=random.Random(seed))
    runner.provider = SeededProvider
    first = runner.cached_test_function(choices)
    if first.status != Status.INTERESTING:
        raise NotReproduced()
    try:
        runner.shrink_interesting_test_cases()
    except RunIsComplete:  # a limit of hypothesis' own (number of shrinks, time): keep the best so far
        pass
    best = runner.interesting_test_cases[_ORIGIN]
    replay = ConjectureData.for_choices(best.choices)
    try:
        return _draw(replay, strategy), runner.call_count
    except StopTest:  # pragma: no cover - the choices of an interesting case always replay
        raise NotReproduced()
