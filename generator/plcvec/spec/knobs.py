"""Resolve rule parameters that depend on an interpretation to the value of a chosen alternative."""
import copy


def resolve(doc, choices):
    """A copy of the spec document with every {interpretation: ID} replaced by the chosen alternative's value.

    `choices` maps interpretation id to alternative id; interpretations not named take their default.
    """
    alts = {}
    for interp in doc["interpretations"]:
        chosen = choices.get(interp["id"], interp["default"])
        alts[interp["id"]] = next(a for a in interp["alternatives"] if a["id"] == chosen)

    def walk(node, key):
        if isinstance(node, dict):
            if len(node) == 1 and "interpretation" in node:
                return copy.deepcopy(alts[node["interpretation"]]["sets"][key])
            return {k: walk(v, k) for k, v in node.items()}
        if isinstance(node, list):
            return [walk(v, key) for v in node]
        return node

    return {k: walk(v, k) for k, v in doc.items() if k != "interpretations"}
