"""Coverage matrix: every spec clause against the vectors that exercise it.

A vector exercises a clause when it cites it: its `clauses` list holds "family#clause" refs, which
the engine records as each rule fires, plus the clauses the case builders and the spec's coverage
section add (see plcvec.cases.build). A clause no vector cites is flagged, unless the spec lists it
under `coverage.no_vectors` with the reason no vector can show it; such a clause that vectors do
cite is flagged too, since the spec's reason is then out of date.
"""
from dataclasses import dataclass, field

# Each vector is counted in exactly one column, from its own data, in this order of precedence:
# - negative: the expected outcome (under the default reading of every interpretation) is an error,
#   or the vector feeds the instruction input the manual calls invalid (its tags say so);
# - boundary: a value at the edge of its range, or operand words ending exactly at the last device,
#   that must be accepted;
# - positive: every other vector, whose outcome is a value.
NEGATIVE_TAGS = ("invalid-range", "invalid-bcd", "reserved-bit", "zero-selector")
BOUNDARY_TAGS = ("boundary", "device-range")
COLUMNS = ("positive", "negative", "boundary")

DEFINITIONS = {
    "positive": "every other vector: valid input whose expected outcome is a value",
    "negative": "the expected outcome (default reading) is an error, or the vector carries a tag for invalid input: "
                + ", ".join(NEGATIVE_TAGS),
    "boundary": "not negative, and tagged " + " or ".join(BOUNDARY_TAGS)
                + " (a value at the edge of its range, or operand words that end at the last device)",
}

# How many vector ids each cell of the matrix names, so a reviewer can open one; the counts are exact.
SAMPLES = 3


def category(vector):
    """positive, negative or boundary, from the vector's own outcome and tags (see DEFINITIONS)."""
    outcome = vector["outcome"]
    expected = outcome.get("default", outcome)["category"]
    tags = set(vector["tags"])
    if expected == "error" or tags & set(NEGATIVE_TAGS):
        return "negative"
    if tags & set(BOUNDARY_TAGS):
        return "boundary"
    return "positive"


@dataclass
class ClauseCoverage:
    clause: str
    counts: dict = field(default_factory=lambda: {c: 0 for c in COLUMNS})
    samples: dict = field(default_factory=lambda: {c: [] for c in COLUMNS})
    no_vectors_why: str | None = None   # the spec's reason no vector can show this clause
    cited_by: str | None = None          # how vectors cite it when the spec says so (every vector, a tag)

    @property
    def total(self):
        return sum(self.counts.values())

    @property
    def status(self):
        """covered, uncovered (a problem), no-vectors (the spec says why), or cited-despite-no-vectors (a problem)."""
        if self.no_vectors_why is not None:
            return "cited-despite-no-vectors" if self.total else "no-vectors"
        return "covered" if self.total else "uncovered"

    @property
    def problem(self):
        if self.status == "uncovered":
            return (f"clause {self.clause}: no vector exercises it (cite it where a vector does, "
                    "or list it under coverage.no_vectors with the reason)")
        if self.status == "cited-despite-no-vectors":
            return (f"clause {self.clause}: listed under coverage.no_vectors, yet {self.total} vectors cite it; "
                    "remove it from no_vectors")
        return None


def family_coverage(fam, vectors):
    """{clause id: ClauseCoverage} in the spec's clause order, from the family's vectors."""
    coverage = fam.doc.get("coverage", {})
    rows = {cid: ClauseCoverage(cid) for cid in fam.clauses}
    for entry in coverage.get("no_vectors", []):
        rows[entry["clause"]].no_vectors_why = entry["why"]
    for cid in coverage.get("every_vector", []):
        rows[cid].cited_by = "every vector (spec: coverage.every_vector)"
    for tag, cid in sorted(coverage.get("by_tag", {}).items()):
        rows[cid].cited_by = f"every vector tagged {tag} (spec: coverage.by_tag)"
    refs = {fam.clause_ref(cid): cid for cid in fam.clauses}
    for vector in sorted(vectors, key=lambda v: v["id"]):
        column = category(vector)
        for ref in vector["clauses"]:
            row = rows[refs[ref]]
            row.counts[column] += 1
            if len(row.samples[column]) < SAMPLES:
                row.samples[column].append(vector["id"])
    return rows


def category_counts(vectors):
    counts = {c: 0 for c in COLUMNS}
    for vector in vectors:
        counts[category(vector)] += 1
    return counts


# How many missing combinations the report lists per family (the check names every one).
MODEL_SHOWN = 50


def model_coverage(fam, cells, problems, link):
    """The family's coverage model beside what its vectors exercise (None when the spec has no model).

    Each requirement (a pair of classes of two dimensions, or a cell of a product) is met by the
    vectors whose executions fall in it, as the engine's record classifies them; a requirement no
    vector meets is a problem, reported at the line of the model in the spec.
    """
    from plcvec.coverage.model import model_of

    model = model_of(fam)
    if model is None:
        return None
    spec = model.spec
    report = model.report(cells)
    missing = [(req, spec_line(fam, req)) for req, ids in report if not ids]
    for req, line in missing:
        what = "pair of classes (strength pairwise)" if req.kind == "pair" else f"cell of product {req.source[1] + 1}"
        problems.add("model", fam, line, f"coverage model: no vector exercises {req.text()} ({what})",
                     link("family", None) + "-model")
    counts = {}
    for req, ids in report:
        c = counts.setdefault(req.kind, {"required": 0, "met": 0})
        c["required"] += 1
        c["met"] += bool(ids)
    per_class = {}
    for vid, cs in cells.items():
        for cell in cs:
            for d, c in cell:
                if c is not None:
                    per_class.setdefault((d, c), set()).add(vid)
    dims = [{"id": d["id"], "says": d["says"], "derive": d["derive"],
             "when": ", ".join(f"{k} in {', '.join(v)}" for k, v in d.get("when", {}).items()),
             "classes": [{"name": c, "vectors": len(per_class.get((d["id"], c), ()))}
                         for c in model.by_id[d["id"]].classes]}
            for d in spec["dimensions"]]
    return {
        "strength": spec["strength"], "anchor": link("family", None) + "-model", "line": fam.line_of("coverage", "model"),
        "dimensions": dims,
        "products": [{"dimensions": " × ".join(p["dimensions"]), "why": p["why"],
                      "cells": sum(1 for r, _ in report if r.source == ("products", i)),
                      "met": sum(1 for r, ids in report if r.source == ("products", i) and ids)}
                     for i, p in enumerate(spec.get("products", []))],
        "exclude": [{"classes": "; ".join(f"{k} = {v if isinstance(v, str) else ', '.join(v)}" for k, v in e["classes"].items()),
                     "why": e["why"]} for e in spec.get("exclude", [])],
        "counts": counts,
        "required": len(report),
        "missing": [req.text() for req, _ in missing],
        "missing_shown": [req.text() for req, _ in missing[:MODEL_SHOWN]],
    }


def spec_line(fam, req):
    """The line of the spec a requirement comes from: its product, or the model's strength."""
    if req.kind == "product":
        return fam.line_of("coverage", "model", *req.source)
    return fam.line_of("coverage", "model", "strength")
