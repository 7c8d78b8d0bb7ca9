"""`plcvec mutation`: the engine's mutants judged by the committed vectors, and mapped onto the decision
inventory (review/decisions.yaml). A mutant that changes vectors on a decision's line is covered, one
that changes vectors anywhere else is a missing decision; one that hangs is stopped and counted."""
import json
from dataclasses import dataclass

import pytest

from plcvec import cli
from plcvec.errors import PlcvecError
from plcvec.mutation.mutants import Mutant, engine_sources, mutants_of
from plcvec.mutation.oracle import CHANGED, TIMEOUT, UNCHANGED, Outcome
from plcvec.mutation.run import committed_vectors, run_mutants, select
from plcvec.mutation.touch import COVERED, MISSING, RECORD, places, touched, verdict
from plcvec.output.workers import can_fork
from plcvec.review.decisions import ENGINE, load_inventory

from conftest import REPO

SOURCE = "a = 1\nif x == 2 and y:\n    z = (3 +\n         4)\nw = 5\n"
DECISIONS = [{"id": "two", "engine": "m.py", "old": "x == 2"},
             {"id": "sum", "engine": "m.py", "old": "(3 +\n         4)"}]
forking = pytest.mark.skipif(not can_fork(), reason="the run forks a process per mutant (Linux)")


def at(first, last=None, file="m.py"):
    return Mutant(file, "core/Op", 0, (first, 4), (last or first, 9))


# -- what "touch" means ---------------------------------------------------------------------------------
def test_a_decision_is_placed_on_the_lines_of_its_old_text():
    assert [(p.decision, p.first, p.last) for p in places(DECISIONS, {"m.py": SOURCE})] == [("two", 2, 2), ("sum", 3, 4)]


def test_a_mutant_touches_a_decision_when_they_share_a_line_of_one_file():
    spots = places(DECISIONS, {"m.py": SOURCE})
    assert touched(at(2), spots) == ["two"]             # the decision's own line, whatever the column
    assert touched(at(4), spots) == ["sum"]             # the last line of a decision of two lines
    assert touched(at(1, 3), spots) == ["two", "sum"]   # a node over three lines touches both
    assert touched(at(1), spots) == [] and touched(at(5), spots) == []   # the lines around
    assert touched(at(2, file="n.py"), spots) == []     # the same line of another file


def test_a_mutant_that_changes_vectors_is_covered_on_a_decision_and_missing_elsewhere():
    assert verdict(Outcome(CHANGED, counts={"expectation": 1}), ["two"]) == COVERED
    assert verdict(Outcome(CHANGED, counts={"inputs": 2}), []) == MISSING
    # Only the clauses cited, or which coverage-model rows get a vector: the engine's record, no outcome.
    assert verdict(Outcome(CHANGED, counts={"metadata": 2}, record_only=True), []) == RECORD
    assert verdict(Outcome(CHANGED, counts={"metadata": 2}, record_only=True), ["two"]) == COVERED
    assert verdict(Outcome(UNCHANGED), []) == UNCHANGED
    assert verdict(Outcome(TIMEOUT), []) == TIMEOUT


def test_a_stale_inventory_is_an_error_not_a_mapping():
    with pytest.raises(PlcvecError, match=r"decision two: its engine text is found 0 times in m.py"):
        places(DECISIONS, {"m.py": SOURCE.replace("x == 2", "x == 3")})
    with pytest.raises(PlcvecError, match=r"decision two: its engine text is found 2 times"):
        places(DECISIONS, {"m.py": SOURCE + "x == 2\n"})


def test_the_inventory_places_every_decision_in_the_engine():
    spots = places(load_inventory(), engine_sources(ENGINE))
    assert len(spots) == len(load_inventory()) and all(p.first >= 1 for p in spots)


# -- the mutants and the sample -------------------------------------------------------------------------
def test_the_mutants_of_a_line_are_cosmic_rays_with_their_place():
    found = mutants_of("m.py", "def f(x):\n    return x == 2\n")
    names = {m.operator.rpartition("/")[2] for m in found}
    assert {"ReplaceComparisonOperator_Eq_NotEq", "NumberReplacer"} <= names
    eq = next(m for m in found if m.operator.endswith("ReplaceComparisonOperator_Eq_NotEq"))
    assert eq.lines == (2, 2) and eq.mutated("def f(x):\n    return x == 2\n") == "def f(x):\n    return x != 2\n"


def test_a_sample_is_the_same_for_the_same_seed_and_a_part_of_the_whole():
    every = list(range(100))
    one, again, other = select(every, 7, seed=3), select(every, 7, seed=3), select(every, 7, seed=4)
    assert one == again and one != other
    assert len(set(one)) == 7 and one == sorted(one) and set(one) <= set(every)
    assert select(every, 100, seed=3) == every and select(every, 500, seed=3) == every


# -- the run, on real mutants of the engine -------------------------------------------------------------
@dataclass(frozen=True)
class Hangs(Mutant):
    """A mutant that computes without end at the start of every TADD execution."""

    def mutated(self, source):
        head = "    def execute(self, instr, operands, state, step, ctx, trace):\n"
        return source.replace(head, head + "        while True:\n            pass\n")


def _mutant(file, old_line, operator):
    """The mutant `operator` makes on the engine line holding `old_line`."""
    source = engine_sources(ENGINE)[file]
    line = source[:source.index(old_line)].count("\n") + 1
    return next(m for m in mutants_of(file, source) if m.line == line and m.operator.endswith(operator))


@pytest.fixture(scope="module")
def committed():
    return committed_vectors(REPO / "vectors", REPO / "spec", ENGINE, engine_sources(ENGINE))


@forking
def test_a_mutant_on_a_decision_is_covered_and_one_elsewhere_that_changes_vectors_is_missing(committed):
    zero = _mutant("clock_add.py", "zero = result == 0", "ReplaceComparisonOperator_Eq_NotEq")
    carry = _mutant("clock_add.py", "carry = total > modulus or", "ReplaceComparisonOperator_Gt_GtE")
    # The inventory without add.carry-at-wrap: the carry line then holds no decision.
    inventory = [d for d in load_inventory() if d["id"] != "add.carry-at-wrap"]
    run = run_mutants([zero, carry], committed, inventory, jobs=2)
    (z, c) = run.judged
    assert (z.verdict, z.touches, z.outcome.change) == (COVERED, ["add.zero"], "expectation")
    assert (c.verdict, c.touches, c.outcome.change) == (MISSING, [], "expectation")
    assert committed.targets["clock_add.py"] == ["fx5-time-add"]   # TADD's kind: its family alone
    assert run_mutants([carry], committed, load_inventory(), jobs=1).judged[0].verdict == COVERED


@forking
def test_a_mutant_that_changes_only_the_clauses_cited_is_no_missing_decision(committed):
    # `if len(selected) < len(self.fields):` only decides whether the vector cites the clause of fields
    # left out of the comparison.
    masking = _mutant("masked_compare.py", "if len(selected) < len(self.fields):", "AddNot")
    judged = run_mutants([masking], committed, load_inventory(), jobs=1).judged[0]
    assert (judged.verdict, judged.touches, judged.outcome.change) == (RECORD, [], "metadata")


@forking
def test_a_mutant_that_changes_nothing_is_counted_so(committed):
    memo = _mutant("words.py", "_MEMO_SIZE = 4096", "NumberReplacer")   # the size of a cache
    judged = run_mutants([memo], committed, load_inventory(), jobs=1).judged[0]
    assert (judged.verdict, judged.outcome.counts) == (UNCHANGED, {})
    assert set(committed.targets["words.py"]) == set(committed.families)   # shared by every kind


@forking
def test_a_mutant_that_hangs_is_stopped_and_counted_as_a_timeout(committed):
    hangs = Hangs("clock_add.py", "core/Hang", 0, (20, 0), (20, 0))
    run = run_mutants([hangs], committed, load_inventory(), jobs=1, timeout=1)
    assert run.judged[0].verdict == TIMEOUT and "CPU time" in run.judged[0].outcome.error
    assert run.seconds < 60


@forking
def test_the_command_exits_1_naming_a_missing_decision_by_file_and_line(tmp_path, monkeypatch, capsys):
    import plcvec.review.decisions as decisions

    inventory = tmp_path / "decisions.yaml"
    kept = [d for d in load_inventory() if d["id"] != "add.zero"]
    inventory.write_text(json.dumps({"decisions": kept}), encoding="utf-8")   # JSON is YAML
    monkeypatch.setattr(decisions, "INVENTORY", inventory)
    monkeypatch.setattr(decisions.load_inventory, "__defaults__", (inventory,))
    zero_line = engine_sources(ENGINE)["clock_add.py"].split("zero = result == 0")[0].count("\n") + 1
    line = f"clock_add.py:{zero_line}"
    code = cli.main(["mutation", "--line", line, "--line", line, "--json", str(tmp_path / "run.json"), "--jobs", "2"])
    out = capsys.readouterr().out
    record = json.loads((tmp_path / "run.json").read_text())
    assert code == 1
    assert record["mutants"] and {tuple(m["lines"]) for m in record["mutants"]} == {(zero_line, zero_line)}
    names = [m["name"] for m in record["mutants"]]
    assert len(names) == len(set(names))   # a line named twice is judged once
    missing = [m for m in record["mutants"] if m["verdict"] == MISSING]
    # `zero = result != 0` and the like change the zero flag; `zero = result is 0` may not (small ints).
    assert any(m["operator"].endswith("_Eq_NotEq") for m in missing)
    assert record["counts"][MISSING] == len(missing) and record["counts"][COVERED] == 0
    assert f"clock_add.py:{zero_line}: zero = result == 0" in out
    assert "-> zero = result != 0; fx5-time-add: expectation" in out


@pytest.mark.parametrize("args, message", [
    (["--file", "no_such.py"], "no engine file no_such.py; the engine's files are __init__.py, clock_add.py"),
    (["--sample", "0"], "--sample takes a number of mutants, 1 or more"),
    (["--timeout", "0"], "--timeout takes a number of seconds above 0"),
    (["--line", "clock_add.py"], "--line takes FILE:LINE (an engine file and a line number), got 'clock_add.py'"),
    (["--line", "clock_add.py:1"], "no mutant on clock_add.py:1"),
])
def test_bad_arguments_are_usage_errors(args, message, capsys):
    assert cli.main(["mutation", *args]) == 2
    assert message in capsys.readouterr().err
