"""One vector per test: no two golden vectors have the same instruction, initial state and steps; the
vector kept carries every tag, clause and description of the ids merged into it, and
vectors/manifest.json names (under "merged") each merged id so that `plcvec diff` (and so a release's
CHANGES) says where it went."""
import json

import pytest

from plcvec.output import diff, golden as golden_module
from plcvec.output.golden import family_vectors

from conftest import REPO


def same_test(vector):
    """The test a vector is, worked out here rather than by the generator's own key: the instruction,
    the initial state and what each step sets up (its expectation follows from these)."""
    steps = [{k: v for k, v in s.items() if k != "expect"} for s in vector["steps"]]
    return json.dumps([vector["instruction"], vector["initial"], steps], sort_keys=True)


def duplicates(vectors):
    seen, out = {}, []
    for v in vectors:
        key = same_test(v)
        if key in seen:
            out.append((seen[key], v["id"]))
        seen.setdefault(key, v["id"])
    return out


@pytest.fixture(scope="module")
def merged():
    return json.loads((REPO / "vectors" / "manifest.json").read_text())["merged"]


def test_no_two_golden_vectors_are_the_same_test(all_vectors):
    found = duplicates(all_vectors)
    assert not found, f"{len(found)} vectors are the same test as another, e.g. {found[:3]}"


def test_merged_ids_are_gone_and_their_vectors_are_kept(all_vectors, merged, golden):
    ids = {v["id"] for v in all_vectors}
    assert set(merged) == set(golden)
    assert sum(map(len, merged.values())) > 0
    for family, went in merged.items():
        for dropped, kept in went.items():
            assert dropped not in ids and kept in ids, (dropped, kept)
            assert dropped.startswith(family + "/") and kept.startswith(family + "/")


@pytest.fixture(scope="module")
def built_both_ways(families):
    """fx5-time-add's vectors as the generator makes them, and as it would without merging."""
    fam = families["fx5-time-add"]
    went = {}
    kept = {v["id"]: v for v in family_vectors(fam, merged=went)}
    real = golden_module.one_vector_per_test
    golden_module.one_vector_per_test = lambda vectors, cells=None: (vectors, {})
    try:
        raw = {v["id"]: v for v in family_vectors(fam)}
    finally:
        golden_module.one_vector_per_test = real
    return kept, raw, went


def test_without_merging_the_same_tests_come_back(built_both_ways):
    """The check above is not empty-handed by construction: the cases as built hold duplicates."""
    kept, raw, went = built_both_ways
    assert went and duplicates(raw.values())
    assert set(raw) == set(kept) | set(went) and not set(kept) & set(went)


def test_the_kept_vector_carries_every_tag_and_reason(built_both_ways):
    kept, raw, went = built_both_ways
    for dropped, into in went.items():
        gone, stays = raw[dropped], kept[into]
        assert same_test(gone) == same_test(stays)
        assert set(gone["tags"]) <= set(stays["tags"]), dropped
        assert set(gone["clauses"]) <= set(stays["clauses"]), dropped
        assert gone["description"] in stays["description"] and raw[into]["description"] in stays["description"]
        for key in ("steps", "final", "outcome"):
            assert gone[key] == stays[key], (dropped, key)
    # A kept id is one the generator built: no id is made up for the merged vector.
    assert set(kept) <= set(raw)


def test_diff_names_the_vector_each_merged_id_went_into(tmp_path, merged):
    """A previous set that still holds a merged id: the diff says which vector it is now."""
    family, went = next((f, w) for f, w in sorted(merged.items()) if w)
    dropped, into = next(iter(sorted(went.items())))
    new = diff.load_set(str(REPO / "vectors"))
    old = diff.load_set(str(REPO / "vectors"))
    old.families[family]["vectors"][dropped] = dict(old.families[family]["vectors"][into], id=dropped)
    report = diff.compare(old, new)
    assert report["families"][family]["removed"] == [dropped]
    assert report["families"][family]["merged"] == {dropped: into}
    assert f"  - {dropped} (the same test as {into}," in diff.render_text(report)
