"""A vector runs only under the combinations of the interpretations its executions consulted.

The result must be exactly what running it under every combination of the family's alternatives
gives (the plain way, computed here with engines that record nothing), and an interpretation few
vectors consult must not multiply the number of executions.

A family with more combinations than PRODUCT_BOUND (HOUR's eleven interpretations have 34,560, a
few seconds a case) is checked the plain way over a closed grid instead: every combination of the
interpretations the builder says touch the case, grown until no single other alternative, at any
point of that grid, changes the result. Over that grid the plain runs decide which interpretations
touch the case and what each entry expects, so a touched one that does not decide, a wrong entry, or
one the builder missed that changes the result by itself is found; what the check cannot see is an
interpretation the builder missed that changes the result only together with another one it missed
(HOUR has a case three readings decide only together: a grid grown from nothing misses it).
"""
import itertools
import math
import shutil

import pytest

from combinations import PRODUCT_BOUND
from conftest import REPO
from plcvec.cases.build import VectorBuilder
from plcvec.output import golden
from plcvec.spec.loader import load_spec

TC_FILE = "fx5-time-compare.yaml"


def plain_run(builder, instr, operands, devices, steps, scratch, choices):
    """One run of a case with an engine resolved without recording: (expects, final, outcome, unjudged,
    trace), the devices the engine found undefined left out of expects and final."""
    engine = _plain_engine(builder, choices)
    state, ctx = dict(devices), {"device_sizes": builder.sizes}
    trace, expects, errors = set(), [], []
    for index, step in enumerate(steps):
        state.update(step.get("set", {}))
        before = dict(state)
        result = engine.execute(instr, operands, state, step, ctx, trace)
        expect = {} if result is None else {"result": result}
        expect["devices"] = {k: state[k] for k in sorted(k for k in state if state[k] != before[k] and k not in scratch)}
        expects.append(expect)
        if "error" in ctx:
            errors.append(dict(step=index, **ctx.pop("error")))
    final = {k: state[k] for k in sorted(state) if k not in scratch}
    trace.discard(None)
    if "undefined" in ctx:   # most runs find nothing undefined: nothing to leave out
        unjudged = builder.unjudged(ctx["undefined"], choices, operands, devices)
        left_out = {d for ds in unjudged.values() for d in ds}
        expects = [dict(e, devices={k: v for k, v in e["devices"].items() if k not in left_out}) for e in expects]
        final = {k: v for k, v in final.items() if k not in left_out}
    else:
        unjudged = {}
    outcome = {"category": "error", "errors": errors} if errors else {"category": "value"}
    return expects, final, outcome, unjudged, trace


def _plain_engine(builder, choices):
    """builder.engine(choices), kept per builder under the combination's (interpretation, alternative)
    pairs (every case of a family asks for the same few hundred engines, once a case each)."""
    engines = builder.__dict__.setdefault("_plain_engines", {})
    key = tuple(choices.items())
    engine = engines.get(key)
    if engine is None:
        engine = engines[key] = builder.engine(choices)
    return engine


def outcome_classes(results):
    """combination -> the number of its result among the distinct results (expects, final, outcome),
    told apart with ==: most cases have one or two, so each deep comparison is made once, not per
    interpretation."""
    distinct, classes = [], {}
    for combo, result in results.items():
        for number, seen in enumerate(distinct):
            if seen == result[:4]:
                break
        else:
            number = len(distinct)
            distinct.append(result[:4])
        classes[combo] = number
    return classes


def closed_grid(run, names, options, defaults, seed):
    """{combination: result} over the grid of the interpretations `seed`, grown until no single
    alternative of another, at any point of the grid, changes the result (the module's docstring);
    the single changes tried are in it too."""
    results, grown = {}, list(seed)

    def result(choice):
        combo = tuple(choice.get(i, defaults[i]) for i in names)
        if combo not in results:
            results[combo] = run(dict(zip(names, combo)))
        return results[combo][:4]

    while True:
        grid = [dict(zip(grown, c)) for c in itertools.product(*(options[names.index(i)] for i in grown))]
        found = next((i for i in names if i not in grown
                      for point in grid for alt in options[names.index(i)]
                      if result({**point, i: alt}) != result(point)), None)
        if found is None:
            return results
        grown.append(found)


def decides(classes, k):
    """Whether two combinations that differ in interpretation k alone give different results.

    The combinations are grouped by every other choice; the results of a group all agree exactly
    when each agrees with the group's first, so one comparison a combination settles it."""
    first = {}
    for combo, number in classes.items():
        if first.setdefault(combo[:k] + combo[k + 1:], number) != number:
            return True
    return False


def every_combination(builder, instr, operands, devices, steps, scratch, seed=()):
    """expectations() the plain way: the case under every combination of every interpretation, or over
    the closed grid of a family with more than PRODUCT_BOUND combinations."""
    fam, defaults = builder.fam, builder.defaults
    names = list(fam.interpretations)
    options = [[a["id"] for a in fam.interpretations[i]["alternatives"]] for i in names]
    run = lambda choices: plain_run(builder, instr, operands, devices, steps, scratch, choices)   # noqa: E731
    if math.prod(map(len, options)) <= PRODUCT_BOUND:
        results = {combo: run(dict(zip(names, combo))) for combo in itertools.product(*options)}
    else:
        results = closed_grid(run, names, options, defaults, seed)
    expects, final, outcome, _, trace = results[tuple(defaults[i] for i in names)]
    classes = outcome_classes(results)
    touched = [iid for k, iid in enumerate(names) if decides(classes, k)]
    trace, alternatives = set(trace), []
    for combo in itertools.product(*(options[names.index(i)] for i in touched)):
        choice = dict(zip(touched, combo))
        if all(choice[i] == defaults[i] for i in touched):
            continue
        a_expects, a_final, a_outcome, a_unjudged, a_trace = results[tuple(choice.get(i, defaults[i]) for i in names)]
        trace |= a_trace
        entry = {"choices": choice, "expect": a_expects, "final": {"devices": a_final}, "outcome": a_outcome}
        if a_unjudged:
            entry["unjudged"] = a_unjudged
        alternatives.append(entry)
    return expects, final, outcome, trace, touched, alternatives


class CheckedBuilder(VectorBuilder):
    """Builds each vector, and every `every`-th case the plain way too, keeping every case where the two
    differ."""
    differences = []
    built = checked = 0
    every = 1

    def expectations(self, instr, operands, devices, steps, scratch):
        fast = super().expectations(instr, operands, devices, steps, scratch)
        CheckedBuilder.built += 1
        if CheckedBuilder.built % CheckedBuilder.every:
            return fast
        slow = every_combination(self, instr, operands, devices, steps, scratch, seed=fast[4])
        CheckedBuilder.checked += 1
        if fast != slow:
            CheckedBuilder.differences.append((self.fam.name, instr["name"], operands, devices, steps))
        return fast


class CountingBuilder(VectorBuilder):
    """Keeps every builder made and, per case in order, (executions, whether one consulted TEST-NO-FIELD)."""
    made = []

    def __init__(self, fam):
        super().__init__(fam)
        self.cases = []
        CountingBuilder.made.append(self)

    def runs(self, *args):
        before = self.executions
        runs = super().runs(*args)
        self.cases.append((self.executions - before, any("TEST-NO-FIELD" in choice for choice, _ in runs)))
        return runs


def build(fam, monkeypatch, builder_class):
    monkeypatch.setattr(golden, "VectorBuilder", builder_class)
    builder_class.made = []
    vectors = golden.family_vectors(fam)
    monkeypatch.undo()
    return vectors


# One test per family (the spec's file names), so that a parallel run spreads the whole set's check.
FAMILY_NAMES = sorted(p.stem for p in (REPO / "spec").glob("*.yaml"))


def test_every_family_is_checked(families):
    assert FAMILY_NAMES == sorted(families)


# The default run checks every SAMPLE-th case of each family the plain way (CP1E's 144 combinations over
# its whole set are most of this module's time); CI checks every case (-m slow).
SAMPLE = 24


@pytest.mark.parametrize("every", [pytest.param(1, id="whole-set", marks=pytest.mark.slow),
                                   pytest.param(SAMPLE, id="sample")])
@pytest.mark.parametrize("name", FAMILY_NAMES)
def test_same_vectors_as_every_combination_on_the_whole_set(name, every, families, generated, monkeypatch):
    CheckedBuilder.differences, CheckedBuilder.built, CheckedBuilder.checked = [], 0, 0
    monkeypatch.setattr(CheckedBuilder, "every", every)
    vectors = build(families[name], monkeypatch, CheckedBuilder)
    assert vectors == generated[1][name], name
    # Every vector is built (and every `every`-th checked); the coverage model's construction also builds
    # candidates it then drops.
    assert CheckedBuilder.built >= len(generated[1][name])
    assert CheckedBuilder.checked >= CheckedBuilder.built // every > 0
    assert not CheckedBuilder.differences, CheckedBuilder.differences[:3]


def family_copy(tmp_path, edit=None):
    """A spec folder with a copy of fx5-time-compare only, `edit` applied to its text."""
    folder = tmp_path / "spec"
    folder.mkdir(parents=True)
    text = (REPO / "spec" / TC_FILE).read_text(encoding="utf-8")
    (folder / TC_FILE).write_text(edit(text) if edit else text, encoding="utf-8")
    (folder / "regressions").mkdir()
    if (REPO / "spec" / "regressions" / TC_FILE).exists():
        shutil.copy(REPO / "spec" / "regressions" / TC_FILE, folder / "regressions" / TC_FILE)
    (fam,) = load_spec(folder)
    return fam


# Four readings of what an FX5 selector that selects no field gives: only a few selector vectors
# reach the parameter (with a reserved bit set, that bit decides first).
EXTRA = """\
  - id: TEST-NO-FIELD
    question: What does a selector that selects no field give?
    quotes:
      - {section: Processing details, quote: "test"}
    alternatives:
      - {id: non-continuity, says: "non-continuity", sets: {on_no_field: non_continuity}}
      - {id: equal, says: "the data are equal", sets: {on_no_field: equal}}
      - {id: error, says: "an error", sets: {on_no_field: error}}
      - {id: equal-too, says: "the data are equal, said another way", sets: {on_no_field: equal}}
    default: non-continuity
    why: A test of the generator, not a reading of the manual.
"""


def with_extra_interpretation(text):
    for old, new in (("  on_no_field: non_continuity\n", "  on_no_field: {interpretation: TEST-NO-FIELD}\n"),
                     ("\ninterpretations:\n", "\ninterpretations:\n" + EXTRA)):
        assert text.count(old) == 1, old
        text = text.replace(old, new)
    return text


def test_an_interpretation_few_vectors_consult_does_not_multiply_the_executions(tmp_path, monkeypatch):
    base_fam = family_copy(tmp_path / "base")
    extra_fam = family_copy(tmp_path / "extra", with_extra_interpretation)
    assert len(extra_fam.interpretations) == len(base_fam.interpretations) + 1
    base = build(base_fam, monkeypatch, CountingBuilder)
    (base_builder,) = CountingBuilder.made
    extra = build(extra_fam, monkeypatch, CountingBuilder)
    (extra_builder,) = CountingBuilder.made

    touched = [v for v in extra if "TEST-NO-FIELD" in v["outcome"].get("interpretations", [])]
    reading = sum(reads for _, reads in extra_builder.cases)
    assert touched and len(touched) <= reading < len(extra) // 20  # the reading decides a few vectors
    # Every other vector is the one the spec without the extra reading gives.
    by_id = {v["id"]: v for v in base}
    assert len(base) == len(extra)
    for v in extra:
        if v not in touched:
            assert v == by_id[v["id"]], v["id"]
    # Running every case under every combination would take 4 times the executions. A case that does
    # not read the new parameter runs as often as before; one that does, at most 4 times as often, and
    # twice that again where the reading "error" makes an OR form read FX5-OR-ON-ERROR (two
    # alternatives), which only an execution that ends in error reads.
    or_on_error = len(extra_fam.interpretations["FX5-OR-ON-ERROR"]["alternatives"])
    assert len(base_builder.cases) == len(extra_builder.cases)
    for (before, _), (after, reads) in zip(base_builder.cases, extra_builder.cases):
        assert (after <= 4 * or_on_error * before if reads else after == before), (before, after, reads)
    # The coverage model asks for a selector of no field beside every class of every other dimension,
    # so more vectors read the parameter than the hand-made cases alone; still far from 4 times.
    assert base_builder.executions < extra_builder.executions < 1.25 * base_builder.executions


def test_consulted_names_only_what_the_execution_read(families):
    """An LD comparison of valid data reads none of the FX5 interpretations; the same comparison under
    an AND form with the preceding logic off reads the AND/OR one; invalid data reads the check's scope."""
    fam = families["fx5-time-compare"]
    builder = VectorBuilder(fam)
    devices = {"D100": 12, "D101": 30, "D102": 0, "D200": 12, "D201": 30, "D202": 0, "D300": 7, "SM709": False}
    operands = {"s1": {"device": "D100"}, "s2": {"device": "D200"}, "s3": {"device": "D300"}}
    run = builder.execute(builder.instructions["LDTM="], operands, devices, [{}], (), fam.default_choices())
    assert run.consulted == frozenset() and run.expects[0]["result"] is True
    run = builder.execute(builder.instructions["ANDTM="], operands, devices, [{"rlo_in": False}], (), fam.default_choices())
    assert run.consulted == {"FX5-AND-OR-WHEN-OFF"}
    bad = dict(devices, D100=24)  # hour 24 is out of range: the scope of the check now decides
    run = builder.execute(builder.instructions["LDTM="], operands, bad, [{}], (), fam.default_choices())
    assert run.consulted == {"FX5-SM709-SCOPE"}


@pytest.mark.parametrize("choice", ["all-words", "selected-fields"])
def test_an_unselected_invalid_field_consults_the_scope_under_either_reading(families, choice):
    fam = families["fx5-time-compare"]
    builder = VectorBuilder(fam)
    devices = {"D100": 24, "D101": 30, "D102": 0, "D200": 12, "D201": 30, "D202": 0, "D300": 3, "SM709": False}
    operands = {"s1": {"device": "D100"}, "s2": {"device": "D200"}, "s3": {"device": "D300"}}
    choices = dict(fam.default_choices(), **{"FX5-SM709-SCOPE": choice})
    run = builder.execute(builder.instructions["LDTM="], operands, devices, [{}], (), choices)
    assert run.consulted == {"FX5-SM709-SCOPE"}
    # Hour 24 is not selected (s3 = 3: second and minute): only the all-words reading reports it.
    assert (run.outcome["category"] == "error") is (choice == "all-words")
