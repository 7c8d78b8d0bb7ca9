"""Check every committed golden vector against the independent reference oracle.

The reference implementation in verifiers/python/plcvec_reference was written
from the manual pages, not from the generator; every vector (and every
alternative expectation of an implementation-defined vector) must agree with it.
"""
import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO / "verifiers" / "python"))

import plcvec_reference  # noqa: E402
from combinations import PRODUCT_BOUND, combinations_to_run  # noqa: E402

FAMILIES = ["fx5-time-compare", "fx5-date-compare", "fx5-time-add",
            "fc6a-hour-meter", "cp1e-time-compare"]
SHOW = 20


def _diff(vid, label, expected_steps, expected_final, got_steps, got_final):
    """Readable mismatches between one expectation and the oracle's output."""
    out = []
    if len(expected_steps) != len(got_steps):
        out.append(f"{vid} [{label}]: {len(expected_steps)} steps expected, got {len(got_steps)}")
    for i, (exp, got) in enumerate(zip(expected_steps, got_steps)):
        if "result" in exp or "result" in got:
            if exp.get("result") != got.get("result"):
                out.append(f"{vid} [{label}] step {i} result: expected {exp.get('result')!r}, got {got.get('result')!r}")
        ed, gd = exp.get("devices", {}), got.get("devices", {})
        for dev in sorted(set(ed) | set(gd)):
            if ed.get(dev, "<unchanged>") != gd.get(dev, "<unchanged>"):
                out.append(f"{vid} [{label}] step {i} {dev}: expected {ed.get(dev, '<unchanged>')!r}, "
                           f"got {gd.get(dev, '<unchanged>')!r}")
    for dev in sorted(set(expected_final) | set(got_final)):
        if expected_final.get(dev, "<absent>") != got_final.get(dev, "<absent>"):
            out.append(f"{vid} [{label}] final {dev}: expected {expected_final.get(dev, '<absent>')!r}, "
                       f"got {got_final.get(dev, '<absent>')!r}")
    return out


def _check_family(vectors):
    mismatches, checked = [], 0
    for v in vectors:
        steps, final = plcvec_reference.run_vector(v)
        checked += 1
        mismatches += _diff(v["id"], "defaults", [s["expect"] for s in v["steps"]],
                            v["final"]["devices"], steps, final)
        for alt in v.get("alternatives", []):
            steps, final = plcvec_reference.run_vector(v, alt["choices"])
            # What the entry leaves unjudged the oracle may write as it likes: it is not compared.
            left_out = {d for devices in alt.get("unjudged", {}).values() for d in devices}
            steps = [dict(s, devices={k: x for k, x in s["devices"].items() if k not in left_out}) for s in steps]
            final = {k: x for k, x in final.items() if k not in left_out}
            checked += 1
            label = ", ".join(f"{k}={a}" for k, a in sorted(alt["choices"].items()))
            mismatches += _diff(v["id"], label, alt["expect"], alt["final"]["devices"], steps, final)
    return checked, mismatches


def test_every_family_is_checked(golden, all_vectors):
    assert sorted(golden) == sorted(FAMILIES)
    assert len(all_vectors) == sum(len(golden[f]["vectors"]) for f in FAMILIES)


@pytest.mark.parametrize("family", FAMILIES)
def test_vectors_agree_with_reference(family, golden, all_vectors):
    vectors = [v for v in all_vectors if v["family"] == family]
    assert vectors, f"no vectors for {family}"
    assert len(vectors) == len(golden[family]["vectors"])
    checked, mismatches = _check_family(vectors)
    if mismatches:
        shown = "\n  ".join(mismatches[:SHOW])
        more = f"\n  ... and {len(mismatches) - SHOW} more" if len(mismatches) > SHOW else ""
        pytest.fail(f"{family}: {len(mismatches)} mismatches over {checked} expectations "
                    f"({len(vectors)} vectors):\n  {shown}{more}", pytrace=False)


@pytest.mark.parametrize("family", FAMILIES)
def test_interpretations_match_file_header(family, golden):
    """The oracle hard-codes every interpretation; the file header must name the same ones."""
    header = {i["id"]: i for i in golden[family]["interpretations"]}
    assert set(header) == set(plcvec_reference.ALTERNATIVES[family])
    for iid, interp in header.items():
        assert interp["default"] == plcvec_reference.DEFAULTS[family][iid], iid
        assert {a["id"] for a in interp["alternatives"]} == set(plcvec_reference.ALTERNATIVES[family][iid]), iid


def test_unknown_interpretation_is_refused(all_vectors):
    v = next(v for v in all_vectors if v["family"] == "fx5-time-add")
    with pytest.raises(ValueError):
        plcvec_reference.run_vector(v, {"NO-SUCH-INTERPRETATION": "x"})
    with pytest.raises(ValueError):
        plcvec_reference.run_vector(v, {"TADD-EXACT-24": "no-such-alternative"})


# CP1E has 144 combinations of alternatives over 1,500 vectors: its share is split in parts, so that
# a parallel run (pytest -n) spreads it over the workers instead of waiting for it at the end.
COMBINATION_PARTS = {"cp1e-time-compare": 8, "fc6a-hour-meter": 2}
def test_a_family_past_the_bound_runs_a_set_that_holds_every_pair_of_alternatives():
    interps = {"A": ["a1", "a2", "a3"], "B": ["b1", "b2"], "C": ["c1", "c2", "c3", "c4"], "D": ["d1", "d2"],
               "E": ["e1", "e2", "e3"], "F": ["f1", "f2"], "G": ["g1", "g2", "g3"], "H": ["h1", "h2"],
               "I": ["i1", "i2"], "J": ["j1", "j2", "j3", "j4", "j5"]}
    combos = combinations_to_run(interps)
    assert 20 <= len(combos) < 100     # the product is 17,280
    names = list(interps)
    for x in range(len(names)):
        for y in range(x + 1, len(names)):
            seen = {(c[x], c[y]) for c in combos}
            assert len(seen) == len(interps[names[x]]) * len(interps[names[y]]), (names[x], names[y])


@pytest.fixture(scope="module")
def suite():
    """The committed vector set, loaded once for every combination run here (each run only reads it)."""
    from plcvec_verify import Suite

    return Suite.load(REPO / "vectors")


# The default run takes a pairwise covering set of each family's combinations (every alternative beside
# every alternative of each other interpretation); CI runs every combination (-m slow).
BOUNDS = [pytest.param(PRODUCT_BOUND, id="every", marks=pytest.mark.slow), pytest.param(0, id="pairwise")]


@pytest.mark.parametrize("bound", BOUNDS)
@pytest.mark.parametrize("family, part", [(f, k) for f in FAMILIES for k in range(COMBINATION_PARTS.get(f, 1))])
def test_reference_passes_under_every_combination_of_alternatives(family, part, bound, golden, suite):
    """An implementation may take several non-default alternatives at once; the vectors must hold
    the expectation of every combination, not only of one alternative at a time. (The parts of a
    family together run each of combinations_to_run once: combination n belongs to part n mod the parts.)"""
    from plcvec_verify import InProcess, Selection, run
    from plcvec_reference.adapter import ReferenceAdapter

    interps = {i["id"]: [a["id"] for a in i["alternatives"]] for i in golden[family]["interpretations"]}
    failures = []
    parts = COMBINATION_PARTS.get(family, 1)
    combos = combinations_to_run(interps, bound)
    assert len(combos) >= parts
    for combo in combos[part::parts]:
        choices = dict(zip(interps, combo))
        report = run(suite, InProcess(ReferenceAdapter(choices=choices)), Selection(families=(family,)))
        if report.exit_code:
            failures.append(f"{choices}: {[r.id for r in report.failed][:3]} ({len(report.failed)} failing)")
    assert not failures, "\n".join(failures[:10])
