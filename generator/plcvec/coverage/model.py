"""A family's coverage model: the dimensions its manual's rules vary, each with classes derived from
the spec's own facts, and the combinations of classes the vectors must exercise between them.

The spec names the dimensions (`coverage.model.dimensions`, each with a derivation from
`derive.py`), a strength (`pairwise`: every pair of classes of two dimensions), the full products
the manual's own tables make (`products`), and pairs no input can show (`exclude`, each with why).
Which cells a vector exercises is decided from its inputs and the engine's record of each execution
(`classify.py`), never from the case family that produced it.
"""
import fnmatch
import itertools
from dataclasses import dataclass

from plcvec.coverage.derive import DERIVATIONS
from plcvec.coverage.pairwise import Dimension, required_pairs, row_pairs

STRENGTHS = ("pairwise",)


@dataclass
class Requirement:
    """One combination of classes the model asks a vector for."""
    kind: str           # "pair" or "product"
    cells: tuple        # ((dimension, class), ...)
    source: tuple       # where in the spec it comes from: ("strength",) or ("products", i)

    def text(self):
        return " × ".join(f"{d}={c}" for d, c in self.cells)


class CoverageModel:
    def __init__(self, fam):
        self.fam = fam
        self.spec = fam.doc["coverage"]["model"]
        derive = DERIVATIONS[fam.kind]
        self.dims = []
        for d in self.spec["dimensions"]:
            when = ()
            if "when" in d:
                (gov, classes), = d["when"].items()
                when = (gov, tuple(classes))
            self.dims.append(Dimension(d["id"], tuple(derive[d["derive"]](fam.doc)), when))
        self.by_id = {d.id: d for d in self.dims}
        self.derive_of = {d["id"]: d["derive"] for d in self.spec["dimensions"]}
        self.order = {d.id: i for i, d in enumerate(self.dims)}
        # What a pair's exclusion is and what a cell exercises depend on the spec alone, and the greedy
        # search and the classification ask the same ones thousands of times: each is worked out once.
        self._excluded, self._cells, self._cell_pairs, self._cell_products = {}, {}, {}, {}

    # -- what is required -------------------------------------------------------------------------
    def excluded(self, p):
        hit = self._excluded.get(p)
        if hit is None:
            hit = self._excluded[p] = self.exclusion_of(p) is not None
        return hit

    def exclusion_of(self, p):
        """The index of the `exclude` entry that rules pair `p` out, or None."""
        (da, ca), (db, cb) = p
        for i, entry in enumerate(self.spec.get("exclude", [])):
            pats = entry["classes"]
            if da in pats and db in pats and _match(ca, pats[da]) and _match(cb, pats[db]):
                return i
        return None

    def pairs(self):
        return required_pairs(self.dims, self.excluded)

    def product_cells(self, i):
        prod = self.spec["products"][i]
        dims = [self.by_id[d] for d in prod["dimensions"]]
        only = prod.get("classes", {})
        options = [[c for c in d.classes if d.id not in only or c in only[d.id]] + ([None] if d.when else []) for d in dims]
        out = []
        for combo in itertools.product(*options):
            row = dict(zip((d.id for d in dims), combo))
            # A conditional dimension is None exactly when its governing class excludes it.
            if all((row[d.id] is None) == (d.when and d.when[0] in row and row[d.when[0]] not in d.when[1])
                   for d in dims if d.when):
                out.append(tuple((d.id, row[d.id]) for d in dims))
        return out

    def requirements(self):
        reqs = [Requirement("pair", p, ("strength",)) for p in sorted(self.pairs(), key=self.pair_key)]
        for i, _ in enumerate(self.spec.get("products", [])):
            reqs += [Requirement("product", cells, ("products", i)) for cells in self.product_cells(i)]
        return reqs

    def pair_key(self, p):
        (da, ca), (db, cb) = p
        return (self.order[da], self.order[db], self.by_id[da].classes.index(ca), self.by_id[db].classes.index(cb))

    # -- what vectors exercise --------------------------------------------------------------------
    def cell(self, classes):
        """The model's cell for a classifier's {derivation: class}: ((dimension, class), ...)."""
        key = tuple(classes.items())
        got = self._cells.get(key)
        if got is None:
            row = {d.id: classes[self.derive_of[d.id]] for d in self.dims}
            got = self._cells[key] = tuple((d.id, row[d.id] if d.applies(row) else None) for d in self.dims)
        return got

    def cell_pairs(self, cell):
        """The pairs of classes an execution cell holds (a frozenset, shared: do not change it)."""
        got = self._cell_pairs.get(cell)
        if got is None:
            got = self._cell_pairs[cell] = frozenset(row_pairs(dict(cell), self.dims))
        return got

    def cell_products(self, cell):
        """The cell of each product an execution cell falls in."""
        got = self._cell_products.get(cell)
        if got is None:
            row = dict(cell)
            got = self._cell_products[cell] = tuple(tuple((d, row.get(d)) for d in p["dimensions"])
                                                    for p in self.spec.get("products", []))
        return got

    def exercised(self, cells):
        """(pairs, product cells) exercised by a set of execution cells (tuples of (dimension, class))."""
        pairs, prods = set(), set()
        for cell in cells:
            pairs |= self.cell_pairs(cell)
            prods.update(self.cell_products(cell))
        return pairs, prods

    def report(self, cells_by_vector):
        """Every requirement with the vectors that meet it: [(Requirement, [vector ids])]."""
        meets = {}
        for vid in sorted(cells_by_vector):
            pairs, prods = self.exercised(cells_by_vector[vid])
            for key in pairs | prods:
                meets.setdefault(key, []).append(vid)
        return [(r, meets.get(r.cells, [])) for r in self.requirements()]


def _match(cls, patterns):
    patterns = [patterns] if isinstance(patterns, str) else patterns
    return any(fnmatch.fnmatchcase(str(cls), p) for p in patterns)


def model_of(fam):
    """The family's coverage model, or None when its spec has none."""
    return CoverageModel(fam) if "model" in fam.doc.get("coverage", {}) else None
