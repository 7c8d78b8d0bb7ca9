"""Drawing from a hypothesis strategy with a seeded PRNG, reproducibly.

The @given test runner adapts how it explores from run to run, so the same seed did not always give
the same examples. Each example is drawn instead from a ConjectureData fed by one seeded PRNG: the
draws are then a pure function of (seed, strategy, hypothesis version). This is hypothesis' internal
API: another hypothesis version may draw other examples from the same --seed (the golden vectors do
not depend on it: they are drawn by cases/random_cases.py).
"""
from hypothesis.control import BuildContext
from hypothesis.internal.conjecture.data import ConjectureData
from hypothesis.internal.conjecture.providers import HypothesisProvider


class SeededProvider(HypothesisProvider):
    """Hypothesis' own provider, minus its habit of mixing in constants found in whatever modules the
    process has imported (which made the draws depend on, e.g., whether pytest had loaded the tests)."""

    def _maybe_draw_constant(self, choice_type, constraints, *, p=0.05):
        return None


def draw_seeded(strategy, rng):
    """One value of `strategy` drawn from `rng` alone, and the choices hypothesis made for it (which
    replay it, e.g. for shrinking)."""
    data = ConjectureData(random=rng, provider=SeededProvider)
    with BuildContext(data, is_final=True, wrapped_test=None):
        value = data.draw(strategy)
    return value, data.choices
