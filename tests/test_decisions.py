"""The decision inventory (generator/plcvec/review/decisions.yaml): each point where the engine decides
an observable outcome cites a clause or an interpretation, and flipping it changes some vector.

Like a mutant of `plcvec mutation`, each flip is judged in a process of its own that imports the engine
file with the flip in place of the real one (plcvec.mutation.oracle), so that every module that uses
it, the cases and the coverage model too, sees the flip; the expectation it must change is the
committed golden vectors (vectors/) of the decision's family, not the engine under test.
"""
import dataclasses

import pytest

from plcvec.mutation.mutants import Mutant, engine_sources
from plcvec.mutation.oracle import CHANGED
from plcvec.mutation.run import committed_vectors, judge_in_workers
from plcvec.output.workers import can_fork
from plcvec.review.decisions import ENGINE, inventory, load_inventory

from conftest import REPO

DECISIONS = load_inventory()


@dataclasses.dataclass(frozen=True)
class Flip(Mutant):
    """A decision's flip as a mutant: its `old` text replaced by its `new`."""

    old: str = ""
    new: str = ""

    def mutated(self, source):
        assert source.count(self.old) == 1, self.name
        return source.replace(self.old, self.new)


@pytest.fixture(scope="module")
def committed():
    return committed_vectors(REPO / "vectors", REPO / "spec", ENGINE, engine_sources(ENGINE))


def _flips():
    """Every decision; the default run flips the first of each engine file and each family (the
    machinery through every engine module, a regeneration per family), CI's slow lane all of them
    (each flip regenerates its family in a process of its own)."""
    seen = set()
    for d in DECISIONS:
        first = not {d["engine"], d["family"]} <= seen
        seen |= {d["engine"], d["family"]}
        yield pytest.param(d, id=d["id"], marks=() if first else pytest.mark.slow)


@pytest.mark.skipif(not can_fork(), reason="a flip is judged in a forked process (Linux)")
@pytest.mark.parametrize("decision", list(_flips()))
def test_flipping_a_decision_changes_a_vector(decision, committed):
    family_only = dataclasses.replace(committed, targets={decision["engine"]: [decision["family"]]})
    flip = Flip(decision["engine"], "flip", 0, (1, 0), (1, 0), old=decision["old"], new=decision["new"])
    outcome = judge_in_workers([flip], family_only, 1, 60)[0]
    assert outcome.status == CHANGED, (f"{decision['id']}: flipping {decision['old']!r} changes no vector of "
                                       f"{decision['family']} ({outcome.status} {outcome.error})")


def test_the_inventory_holds_against_the_spec_and_the_engine(families):
    rows, problems = inventory(list(families.values()))
    assert problems == []
    assert len(rows) == len(DECISIONS) >= 40
    assert all(r["line"] for r in rows) and all(r["cites"] for r in rows)


def test_every_interpretation_is_decided_somewhere_in_the_engine(families):
    cited = {c for d in DECISIONS for c in d["cites"]}
    interpretations = {i for fam in families.values() for i in fam.interpretations}
    assert interpretations - cited == set()


def test_a_decision_that_cites_nothing_or_a_stale_text_is_a_problem(families, tmp_path):
    bad = tmp_path / "decisions.yaml"
    bad.write_text(
        "decisions:\n"
        "  - {id: cites-nothing, family: fx5-time-add, engine: clock_add.py, decides: x, cites: [],"
        " old: 'zero = result == 0', new: 'zero = True'}\n"
        "  - {id: stale, family: fx5-time-add, engine: clock_add.py, decides: x, cites: [fx5-time-add#zero],"
        " old: 'zero = result == 00', new: 'zero = True'}\n"
        "  - {id: unknown, family: fx5-time-add, engine: clock_add.py, decides: x, cites: [NO-SUCH-INTERPRETATION],"
        " old: 'zero = result == 0', new: 'zero = True'}\n", encoding="utf-8")
    _, problems = inventory(list(families.values()), path=bad)
    messages = [(line, m.split(":")[0]) for line, m in problems]
    assert messages == [(2, "decision cites-nothing"), (3, "decision stale"), (4, "decision unknown")]
    assert "cites neither a clause nor an interpretation" in problems[0][1]
    assert "found 0 times in clock_add.py" in problems[1][1]
    assert "'NO-SUCH-INTERPRETATION', which is no clause" in problems[2][1]


def test_a_decision_may_cite_an_assumption_of_the_spec_and_not_one_it_lacks(families, tmp_path):
    listing = tmp_path / "decisions.yaml"
    listing.write_text(
        "decisions:\n"
        "  - {id: before-first, family: fx5-time-add, engine: clock_add.py, decides: x,"
        " cites: [fx5-time-add#assumptions.timing], old: 'zero = result == 0', new: 'zero = True'}\n"
        "  - {id: no-such, family: fx5-time-add, engine: clock_add.py, decides: x,"
        " cites: [fx5-time-add#assumptions.no_such], old: 'zero = result == 0', new: 'zero = True'}\n",
        encoding="utf-8")
    rows, problems = inventory(list(families.values()), path=listing)
    [cited] = rows[0]["cites"]
    assert (cited["ref"], cited["kind"]) == ("fx5-time-add#assumptions.timing", "assumption")
    assert "Before the first step the execution condition counts as off" in cited["text"]
    assert [(line, m.split(":")[0]) for line, m in problems] == [(3, "decision no-such")]
    assert "'fx5-time-add#assumptions.no_such', which is no clause (family#id), interpretation or assumption" in problems[0][1]
