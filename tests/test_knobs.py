"""Resolving a spec under a set of choices: every {interpretation: ID} becomes the chosen alternative's
value, whatever else the document holds is left as it is, and the document itself is not changed."""
import copy

import pytest

from combinations import combinations_to_run

from plcvec.spec.knobs import Resolver, resolve


def plain(node, alts, key=None):
    """The resolved document the simple way: a full copy, each choice replaced where it stands."""
    if isinstance(node, dict):
        if set(node) == {"interpretation"}:
            return alts[node["interpretation"]]["sets"][key]
        return {k: plain(v, alts, k) for k, v in node.items()}
    if isinstance(node, list):
        return [plain(v, alts, key) for v in node]
    return node


def combinations(doc):
    """Every combination of a family's alternatives, or a pairwise set of them past the bound (each
    choice is resolved where it stands, whatever the others are: a pair is all two choices can share)."""
    interps = {i["id"]: [a["id"] for a in i["alternatives"]] for i in doc["interpretations"]}
    for combo in combinations_to_run(interps):
        yield dict(zip(interps, combo))


def test_every_combination_of_every_family_resolves_as_a_full_copy_would(families):
    for fam in families.values():
        before = copy.deepcopy(fam.doc)
        resolver = Resolver(fam.doc)
        for choices in combinations(fam.doc):
            alts = {i["id"]: next(a for a in i["alternatives"] if a["id"] == choices[i["id"]])
                    for i in fam.doc["interpretations"]}
            want = plain({k: v for k, v in fam.doc.items() if k != "interpretations"}, alts)
            assert resolver.resolve(choices) == want, (fam.name, choices)
            assert resolver.resolve(choices, consulted=set()) == want, (fam.name, choices)
        assert fam.doc == before, f"{fam.name}: resolving changed the spec document"


DOC = {
    "interpretations": [
        {"id": "A", "default": "a1", "alternatives": [{"id": "a1", "sets": {"mode": "x", "table": {"k": 1}}},
                                                       {"id": "a2", "sets": {"mode": "y", "table": {"k": 2}}}]},
        {"id": "B", "default": "b1", "alternatives": [{"id": "b1", "sets": {"deep": [1]}},
                                                       {"id": "b2", "sets": {"deep": [2]}}]},
    ],
    "mode": {"interpretation": "A"},
    "rules": {"table": {"interpretation": "A"}, "fixed": {"n": 3}},
    "list": [{"deep": {"interpretation": "B"}}, {"plain": True}],
    "untouched": {"nested": [1, 2, {"x": "y"}]},
}


@pytest.mark.parametrize("choices", [{}, {"A": "a2"}, {"B": "b2"}, {"A": "a2", "B": "b2"}])
def test_a_choice_anywhere_is_resolved_and_each_read_of_it_is_recorded(choices):
    a = "a2" if choices.get("A") == "a2" else "a1"
    b = "b2" if choices.get("B") == "b2" else "b1"
    sink = set()
    doc = Resolver(DOC).resolve(choices, consulted=sink)
    assert sink == set()
    assert doc["untouched"] == DOC["untouched"] and doc["rules"]["fixed"] == {"n": 3}
    assert sink == set(), "reading what no interpretation chooses consults nothing"
    assert doc["mode"] == {"a1": "x", "a2": "y"}[a] and sink == {"A"}
    sink.clear()
    assert doc["rules"]["table"]["k"] == {"a1": 1, "a2": 2}[a] and sink == {"A"}
    sink.clear()
    assert doc["list"][0]["deep"] == {"b1": [1], "b2": [2]}[b] and sink == {"B"}
    assert resolve(DOC, choices) == Resolver(DOC).resolve(choices)


def test_a_chosen_value_is_a_copy_not_the_alternative_itself():
    doc = Resolver(DOC).resolve({})
    doc["list"][0]["deep"].append(99)
    assert DOC["interpretations"][1]["alternatives"][0]["sets"]["deep"] == [1]
