"""The devices an interpretation's alternative leaves unjudged, for one vector.

An alternative names them by operand and by flag group (spec: `unjudged`), never by address: the
addresses are the vector's own (its operands, placed by `generation.placement`). They apply where an
engine said it met the state that alternative leaves undefined (plcvec.engine.undefined), and then
for the whole vector: the entry of that combination lists them under `unjudged` and its steps and
final state leave them out.
"""
from plcvec.engine.words import operand_words
from plcvec.spec.flags import flag_groups


def _parameters(node, key=None, out=None):
    """{rule parameter: interpretation id} for every `{interpretation: ID}` of a spec document."""
    out = {} if out is None else out
    if isinstance(node, dict):
        if len(node) == 1 and "interpretation" in node:
            out[key] = node["interpretation"]
            return out
        for k, v in node.items():
            if k != "interpretations":
                _parameters(v, k, out)
    elif isinstance(node, list):
        for v in node:
            _parameters(v, key, out)
    return out


class Unjudged:
    def __init__(self, fam):
        doc = fam.doc
        self.interpretation_of = _parameters(doc)
        self.alternatives = {i["id"]: {a["id"]: a for a in i["alternatives"]} for i in doc["interpretations"]}
        self.flags = {g["name"]: g["devices"] for g in flag_groups(doc)}
        self.sizes = {name: op.get("words", 1) for name, op in doc["operands"].items()}

    def devices(self, parameters, choices, operands):
        """{interpretation id: sorted devices} that the chosen alternatives of the interpretations
        behind `parameters` (those an engine found undefined) leave unjudged in a vector with `operands`."""
        out = {}
        for parameter in parameters:
            iid = self.interpretation_of[parameter]
            spec = self.alternatives[iid][choices[iid]].get("unjudged", {})
            devices = set()
            for name in spec.get("operands", ()):
                operand = operands.get(name, {})
                if "device" in operand:
                    devices.update(operand_words(operand["device"], self.sizes[name]))
            for name in spec.get("flags", ()):
                devices.update(self.flags[name])
            out[iid] = sorted(devices)
        return dict(sorted(out.items()))
