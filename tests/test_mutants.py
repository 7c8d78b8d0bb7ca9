"""The verifier is tested by mutants (design principle 7).

The reference implementation passes every vector; each mutant of it (one plausible bug) must be
rejected, in process and over the stdio protocol, by vectors of every family the bug is in, for
what it computes (a wrong answer, not a crash). The vectors that catch each mutant are printed
(pytest -rP) and listed in verifiers/python/plcvec_reference/MUTANTS.md, which is checked here
against a fresh run.
"""
import re
import sys

import pytest

from plcvec_verify import InProcess, Selection, StdioAdapter, Suite, run
from plcvec_reference import MACHINES
from plcvec_reference.adapter import ReferenceAdapter
from plcvec_reference.mutants import MUTANTS
from plcvec_reference.mutants.report import dimensions, run_mutant

from conftest import REPO

DOC = REPO / "verifiers" / "python" / "plcvec_reference" / "MUTANTS.md"
SHOW = 5
ROW = re.compile(r"^\| `(?P<name>[^`]+)` \| (?P<families>[^|]+) \| (?P<bug>.+) \| (?P<dims>[^|]+) \| (?P<ids>[^|]+) \|$")
# Every mutant is caught by at least this many vectors: one vector is an accident of how it was built.
MIN_CATCHING = 3


@pytest.fixture(scope="module")
def suite():
    return Suite.load(REPO / "vectors")


@pytest.fixture(scope="module")
def in_process(suite):
    """name -> the in-process report on that mutant, each run once per module."""
    reports = {}

    def report(name):
        if name not in reports:
            reports[name] = run_mutant(suite, name)
        return reports[name]
    return report


def doc_rows():
    rows = {}
    for line in DOC.read_text(encoding="utf-8").splitlines():
        m = ROW.match(line)
        if m:
            rows[m["name"]] = {"families": tuple(f.strip() for f in m["families"].split(",")),
                               "bug": m["bug"], "dims": m["dims"], "ids": re.findall(r"`([^`]+)`", m["ids"])}
    return rows


def test_reference_passes_every_vector(suite):
    report = run(suite, InProcess(ReferenceAdapter()))
    assert report.exit_code == 0, [(r.id, r.status, r.problems[:1] or r.message) for r in report.failed[:SHOW]]
    assert report.counts["pass"] == len(suite.vectors)


def test_at_least_twelve_mutants_two_per_family():
    assert len(MUTANTS) >= 12, sorted(MUTANTS)
    per_family = {f: [n for n, m in MUTANTS.items() if f in m.families] for f in MACHINES}
    thin = {f: names for f, names in per_family.items() if len(names) < 2}
    assert not thin, f"families with fewer than two mutants: {thin}"
    for m in MUTANTS.values():
        assert set(m.families) <= set(MACHINES), m.name
        assert m.description.endswith(".") and len(m.description) > 30, m.name


@pytest.mark.parametrize("name", list(MUTANTS))
def test_mutant_bug_is_confined_to_its_families(name):
    m = MUTANTS[name]
    for family, (base, _args) in MACHINES.items():
        machine = m.make_machine(family, {}, {}, None)
        if family in m.families:
            assert type(machine) is m.cls and isinstance(machine, base), family
        else:
            assert type(machine) is base, family


@pytest.mark.parametrize("name", list(MUTANTS))
def test_verifier_rejects_mutant(name, in_process):
    m = MUTANTS[name]
    report = in_process(name)
    caught = [(r.id, r.status) for r in report.failed]
    print(f"{name}: caught by {len(caught)} vectors in process, e.g. {[vid for vid, _ in caught[:SHOW]]}")
    assert report.exit_code == 1 and caught, f"{name} survives: no vector catches '{m.description}'"
    crashed = [(r.id, r.status, r.message) for r in report.failed if r.status != "fail"]
    assert not crashed, f"{name} is rejected for a crash or a bad answer, not for its bug: {crashed[:SHOW]}"
    families = {r.family for r in report.failed}
    assert families == set(m.families), (
        f"{name}: the bug is in {m.families} but vectors of {sorted(families)} catch it")


# Over the stdio protocol, the verdicts of the run in process. The path is the same for every mutant
# (the reference adapter's --mutant, the runner's process adapter), so the default run takes the
# first mutant of each family and of each pair of families; `-m slow` takes every other (a process
# each, a sixth of this module's time).
_STDIO_FAST = {next(n for n, m in MUTANTS.items() if m.families == fams)
               for fams in {m.families for m in MUTANTS.values()}}


@pytest.mark.parametrize("name", [n if n in _STDIO_FAST else pytest.param(n, marks=pytest.mark.slow)
                                  for n in MUTANTS])
def test_stdio_gives_the_verdicts_of_the_run_in_process(name, suite, in_process):
    m = MUTANTS[name]
    caught = [(r.id, r.status) for r in in_process(name).failed]
    stdio = run(suite, StdioAdapter([sys.executable, "-m", "plcvec_reference.adapter", "--mutant", name]),
                Selection(families=m.families))
    assert name in stdio.adapter["name"]
    assert stdio.exit_code == 1 and not stdio.aborted, stdio.aborted
    over_stdio = [(r.id, r.status) for r in stdio.failed]
    print(f"{name}: caught by {len(over_stdio)} vectors over stdio")
    assert over_stdio == caught, (
        f"{name}: in process and stdio disagree; only in process {sorted(set(caught) - set(over_stdio))[:SHOW]}, "
        f"only over stdio {sorted(set(over_stdio) - set(caught))[:SHOW]}")


def test_doc_lists_every_mutant():
    rows = doc_rows()
    assert sorted(rows) == sorted(MUTANTS), "MUTANTS.md and MUTANTS differ; python3 -m plcvec_reference.mutants prints the table"
    for name, row in rows.items():
        assert row["families"] == MUTANTS[name].families, name
        assert row["bug"] == MUTANTS[name].description, name
        assert row["dims"] == dimensions(MUTANTS[name]), name
        assert row["ids"], f"MUTANTS.md names no vector that catches {name}"


@pytest.mark.parametrize("name", list(MUTANTS))
def test_doc_vectors_catch_their_mutant(name, in_process):
    row = doc_rows().get(name)
    if row is None:
        pytest.fail(f"{name} is not in MUTANTS.md")
    caught = {r.id for r in in_process(name).failed}
    assert set(row["ids"]) <= caught, f"MUTANTS.md says {sorted(set(row['ids']) - caught)} catch {name}; they do not"


@pytest.mark.parametrize("name", list(MUTANTS))
def test_mutant_is_caught_by_at_least_three_vectors(name, in_process):
    caught = [r.id for r in in_process(name).failed]
    assert len(caught) >= MIN_CATCHING, f"{name} is caught by only {len(caught)} vectors: {caught}"


def test_every_model_dimension_has_a_mutant():
    """Each dimension of each family's coverage model has a mutant whose bug lives in it."""
    from plcvec.spec.loader import load_spec

    for fam in load_spec(REPO / "spec"):
        dims = [d["id"] for d in fam.doc["coverage"]["model"]["dimensions"]]
        named = {dim for m in MUTANTS.values() if fam.name in m.families for dim, _ in m.exercises}
        assert set(dims) <= named, f"{fam.name}: no mutant lives in {sorted(set(dims) - named)}"
        assert named <= set(dims), f"{fam.name}: mutants name dimensions the model lacks: {sorted(named - set(dims))}"


@pytest.fixture(scope="module")
def cells():
    """{vector id: the coverage-model cells it exercises}, from the engine's record of each execution."""
    from plcvec.output.golden import family_vectors
    from plcvec.spec.loader import load_spec

    out = {}
    for fam in load_spec(REPO / "spec"):
        family_vectors(fam, out)
    return out


@pytest.mark.parametrize("name", [n for n, m in MUTANTS.items() if m.exercises])
def test_only_its_dimensions_vectors_catch_the_mutant(name, in_process, cells):
    """Every vector that catches the mutant exercises, in each dimension the bug lives in, one of the
    classes it names: the bug is invisible to the vectors of every other class of that dimension."""
    import fnmatch

    m = MUTANTS[name]
    outside = []
    for r in in_process(name).failed:
        for dim, patterns in m.exercises:
            got = {dict(cell)[dim] for cell in cells[r.id]} - {None}
            if not any(fnmatch.fnmatchcase(g, p) for g in got for p in patterns):
                outside.append((r.id, dim, sorted(got)))
    assert not outside, f"{name}: caught by vectors outside {m.exercises}: {outside[:SHOW]}"


@pytest.mark.parametrize("name", list(MUTANTS))
def test_no_mutant_is_explained_away_by_a_reading(name, in_process):
    """A mutant is a bug: where the roll-up proposes a declaration for its failures, every reading it
    proposes is marked partial (TEXT.md, "The roll-up by reading"), so the bug is never declared away."""
    from plcvec_verify.describe import rollup_lines
    from plcvec_verify.infer import inference

    report = in_process(name)
    lines = rollup_lines(report, inference(report, frozenset(report.cpu_writes)))
    if not any(line.startswith("    declare:") for line in lines):
        return
    start = lines.index(next(line for line in lines if line.startswith("READINGS:")))
    groups = [line for line in lines[start + 1:] if re.match(r" {4} *\d+  ", line) and "=" in line]
    unmarked = [line for line in groups if "(partial:" not in line]
    assert groups and not unmarked, f"{name}: a reading proposed unmarked: {unmarked}"
    assert any(line.startswith("    partial: ") for line in lines), name
