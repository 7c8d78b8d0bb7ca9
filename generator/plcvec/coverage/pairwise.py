"""A small deterministic greedy covering array: rows that together hold every required pair of classes.

The construction is the greedy one of AETG and its descendants, made deterministic: take the first
uncovered pair (in the model's order), fix it, then give every other dimension, in order, the class
that covers the most still-uncovered pairs with what is fixed so far (the first such class on a tie).
A row is only counted for the pairs it really covers: `realize` may build a vector from the row and
return the pairs that vector exercises, which need not be the row's own (an input the rules make
impossible). A required pair no row manages to show is returned, so the caller can name it.

Pairs are ((dimension, class), (dimension, class)) with the dimensions in model order. A dimension
may be conditional (`when`): it takes part only when another dimension has one of some classes, and
is None in a row otherwise.
"""
from dataclasses import dataclass, field


@dataclass(frozen=True)
class Dimension:
    id: str
    classes: tuple
    when: tuple = ()          # (governing dimension, classes of it under which this one applies), or ()

    def applies(self, row):
        if not self.when:
            return True
        gov = row.get(self.when[0])
        return gov is None or gov in self.when[1]


def row_pairs(row, dims):
    """Every pair of classes a complete row (dimension -> class or None) holds."""
    order = {d.id: i for i, d in enumerate(dims)}
    items = sorted(((d, c) for d, c in row.items() if c is not None), key=lambda x: order[x[0]])
    return {(items[i], items[j]) for i in range(len(items)) for j in range(i + 1, len(items))}


def required_pairs(dims, excluded=lambda p: False):
    """Every pair of classes of two dimensions, minus those a condition rules out or `excluded` names."""
    out = set()
    for i, a in enumerate(dims):
        for b in dims[i + 1:]:
            for ca in a.classes:
                for cb in b.classes:
                    if a.when and a.when[0] == b.id and cb not in a.when[1]:
                        continue
                    if b.when and b.when[0] == a.id and ca not in b.when[1]:
                        continue
                    p = ((a.id, ca), (b.id, cb))
                    if not excluded(p):
                        out.add(p)
    return out


@dataclass
class Cover:
    rows: list = field(default_factory=list)      # (row, what realize returned) for each row kept
    missing: list = field(default_factory=list)   # required pairs no row showed, in model order


def cover(dims, required, covered=frozenset(), realize=None, excluded=lambda p: False):
    """Rows covering every pair of `required` not already in `covered`.

    realize(row) -> (pairs the row really exercises, payload) or None when it cannot be built;
    without it a row covers its own pairs. Deterministic: same arguments, same rows.
    """
    order = {d.id: i for i, d in enumerate(dims)}
    sort_key = lambda p: (order[p[0][0]], order[p[1][0]], dims[order[p[0][0]]].classes.index(p[0][1]),
                          dims[order[p[1][0]]].classes.index(p[1][1]))
    uncovered = set(required) - set(covered)
    clashes = exclusions(dims, excluded)
    result, failed = Cover(), []
    for seed in sorted(uncovered, key=sort_key):
        if seed not in uncovered:
            continue
        row = grow(dims, dict(seed), uncovered, order, excluded, clashes)
        shown, payload = _realize(row, dims, realize)
        if seed not in shown:
            # The rules rule the row out: change one other dimension at a time until one shows the seed.
            for d in dims:
                if d.id in dict(seed) or row[d.id] is None:
                    continue
                for c in _allowed(d, dims, {k: v for k, v in row.items() if k != d.id}, clashes):
                    if c == row[d.id]:
                        continue
                    other = _conditions_applied(dims, dict(row, **{d.id: c}))
                    got = _realize(other, dims, realize)
                    if seed in got[0]:
                        row, (shown, payload) = other, got
                        break
                if seed in shown:
                    break
        new = shown & uncovered
        if new:
            result.rows.append((row, payload))
            uncovered -= new
        if seed in uncovered:      # the row could not show the pair it was built for
            uncovered.discard(seed)
            failed.append(seed)
    result.missing = sorted(failed, key=sort_key)
    return result


def _realize(row, dims, realize):
    if realize is None:
        return row_pairs(row, dims), None
    got = realize(row)
    return got if got is not None else (set(), None)


def _conditions_applied(dims, row):
    return {d.id: (None if d.when and row.get(d.when[0]) not in d.when[1] else row[d.id]) for d in dims}


def exclusions(dims, excluded):
    """{(dimension, class): the (dimension, class) items `excluded` rules out in a pair with it}, each
    pair asked once: the greedy search checks a candidate class against every class of its row."""
    order = {d.id: i for i, d in enumerate(dims)}
    items = [(d.id, c) for d in dims for c in d.classes]
    out = {item: set() for item in items}
    for i, a in enumerate(items):
        for b in items[i + 1:]:
            if a[0] != b[0] and excluded((a, b) if order[a[0]] < order[b[0]] else (b, a)):
                out[a].add(b)
                out[b].add(a)
    return {item: frozenset(partners) for item, partners in out.items()}


def grow(dims, row, uncovered, order, excluded, clashes=None):
    """Complete a partial row greedily (see the module's docstring); `clashes` is exclusions(dims, excluded)."""
    if clashes is None:
        clashes = exclusions(dims, excluded)
    for d in dims:
        if d.id in row:
            continue
        if not d.applies(row):
            row[d.id] = None
            continue
        pairs_with = _pairs_with(d, row, order)
        best, best_gain = None, -1
        for c in _allowed(d, dims, row, clashes):
            gain = len(uncovered.intersection(pairs_with(c)))
            if gain > best_gain:
                best, best_gain = c, gain
        row[d.id] = best
    # A dimension whose governing class was chosen after it must not apply.
    return _conditions_applied(dims, row)


def _pairs_with(d, row, order):
    """pairs_with(c): the pairs class c of dimension d (not in the row) makes with the row's classes,
    each with its two dimensions in model order."""
    mine = order[d.id]
    earlier = [(e, ce) for e, ce in row.items() if ce is not None and order[e] < mine]
    later = [(e, ce) for e, ce in row.items() if ce is not None and order[e] > mine]

    def pairs_with(c):
        item = (d.id, c)
        return [(other, item) for other in earlier] + [(item, other) for other in later]
    return pairs_with


def _allowed(d, dims, row, clashes):
    """The classes of `d` compatible with the row so far: conditions of fixed dimensions and exclusions
    (`clashes`, see exclusions())."""
    # Dimensions that depend on d and are already given a class: d must take a class under which they apply.
    dependents = [e.when[1] for e in dims if e.when and e.when[0] == d.id and row.get(e.id) is not None]
    fixed = [(e, ce) for e, ce in row.items() if ce is not None]
    out = []
    for c in d.classes:
        if any(c not in classes for classes in dependents):
            continue
        if not clashes[d.id, c].isdisjoint(fixed):
            continue
        out.append(c)
    return out or list(d.classes)
