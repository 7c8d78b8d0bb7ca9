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
