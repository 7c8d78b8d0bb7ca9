"""The decision inventory (generator/plcvec/review/decisions.yaml): each point where the engine decides
an observable outcome cites a clause or an interpretation, and flipping it changes some vector.

Like the mutants of the references, each flip is a one-line change of the engine's source, built as a
module of its own; the expectation it must change is the committed golden vectors (vectors/), not the
engine under test.
"""
import json
import types

import pytest

import plcvec.engine as engine
from plcvec.output.golden import family_vectors
from plcvec.review.decisions import ENGINE, inventory, load_inventory

from conftest import REPO

DECISIONS = load_inventory()


def _flipped_engine(monkeypatch, decision):
    """Install the engine module of `decision` with its text flipped, for this test only."""
    name = "plcvec.engine." + decision["engine"].removesuffix(".py")
    module = __import__(name, fromlist=["_"])
    source = (ENGINE / decision["engine"]).read_text(encoding="utf-8")
    assert source.count(decision["old"]) == 1, decision["id"]
    flipped = types.ModuleType(name)
    flipped.__file__ = module.__file__
    exec(compile(source.replace(decision["old"], decision["new"]), module.__file__, "exec"), flipped.__dict__)
    for attr, value in vars(flipped).items():
        if not attr.startswith("__"):
            monkeypatch.setattr(module, attr, value)
    for kind, cls in list(engine.KINDS.items()):
        if cls.__module__ == name:
            monkeypatch.setitem(engine.KINDS, kind, getattr(flipped, cls.__name__))


@pytest.mark.parametrize("decision", DECISIONS, ids=[d["id"] for d in DECISIONS])
def test_flipping_a_decision_changes_a_vector(decision, families, golden, monkeypatch):
    _flipped_engine(monkeypatch, decision)
    got = {v["id"]: v for v in json.loads(json.dumps(family_vectors(families[decision["family"]])))}
    committed = {v["id"]: v for v in golden[decision["family"]]["vectors"]}
    changed = [k for k in committed if got.get(k) != committed[k]] + sorted(set(got) - set(committed))
    assert changed, f"{decision['id']}: flipping {decision['old']!r} changes no vector of {decision['family']}"


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
