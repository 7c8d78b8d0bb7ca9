"""Which combinations of a family's interpretation alternatives a test runs.

Every combination while there are at most PRODUCT_BOUND of them; past that (HOUR's eleven
interpretations have 34,560) a pairwise covering set: every alternative of each interpretation
beside every alternative of each other in some combination. What a full product adds over it is an
interaction of three or more readings at once, which the tests that use it show otherwise (each
vector's own combinations, one by one).
"""
import itertools
import math

PRODUCT_BOUND = 1024


def combinations_to_run(interps, bound=PRODUCT_BOUND):
    """The combinations (tuples in the order of `interps`, {interpretation: [alternatives]}) to run: the
    product while it has at most `bound`, else a pairwise covering set (bound=0: always that)."""
    if math.prod(len(alts) for alts in interps.values()) <= bound:
        return list(itertools.product(*interps.values()))
    from plcvec.coverage.pairwise import Dimension, cover, required_pairs

    dims = [Dimension(i, tuple(alts)) for i, alts in interps.items()]
    found = cover(dims, required_pairs(dims))
    assert not found.missing
    return [tuple(row[i] for i in interps) for row, _ in found.rows]
