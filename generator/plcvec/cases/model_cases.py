"""Vectors for the cells of a family's coverage model that the other cases leave unexercised.

The greedy pairwise construction (plcvec.coverage.pairwise) proposes rows of classes; the kind's
case builder turns each row into a vector (`from_row`), and the row counts only for the cells that
vector really exercises, as the engine's record classifies it. Random draws are left out of what is
already covered, so these vectors do not change when the draws do. Each id is the row itself.
"""
from plcvec.coverage.pairwise import cover, exclusions, grow


def model_cases(builder, vectors, from_row, instruction_dims):
    """The vectors to add: [vector], in the order built (ids name their row, so order is immaterial).

    from_row({derivation: class}, key) builds the vector of a row (or None); instruction_dims are the
    derivations the instruction's name already says, left out of the id.
    """
    model = builder.model
    if model is None:
        return []
    # What the vectors exercise together is what their distinct cells exercise (cells recur a lot).
    covered_pairs, covered_products = model.exercised(
        set().union(*(builder.cells[v["id"]] for v in vectors if "random" not in v["tags"])))
    built = {}

    def realize(row):
        key = tuple(row.items())
        if key not in built:
            slug = "/".join(f"{d}={c}" for d, c in row.items()
                            if c is not None and model.derive_of[d] not in instruction_dims)
            vector = from_row({model.derive_of[d]: c for d, c in row.items()}, f"model/{slug}")
            built[key] = None if vector is None else (model.exercised(builder.cells[vector["id"]]), vector)
        got = built[key]
        return None if got is None else (got[0][0], got)

    result = cover(model.dims, model.pairs(), covered_pairs, realize, model.excluded)
    out = [payload[1] for _, payload in result.rows]
    for _, payload in result.rows:
        covered_products |= payload[0][1]
    # Cells of the products the pairs did not reach: each is a row of its own, the rest filled greedily.
    order = {d.id: i for i, d in enumerate(model.dims)}
    clashes = exclusions(model.dims, model.excluded)
    for i, _ in enumerate(model.spec.get("products", [])):
        for cells in model.product_cells(i):
            if cells in covered_products:
                continue
            row = grow(model.dims, {d: c for d, c in cells if c is not None}, set(), order, model.excluded, clashes)
            got = realize(row)
            if got is not None and cells in got[1][0][1] and got[1][1] not in out:
                out.append(got[1][1])
                covered_products |= got[1][0][1]
    return out
