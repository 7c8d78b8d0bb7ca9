"""Coverage dimensions of `clock_add` families: classes derived from the spec, and the class of each
execution, read from the vector's inputs and the engine's record of it."""
import itertools

from plcvec.engine.words import FieldCodec, in_device_range, split_address


def _ops(doc, *roles):
    return [k for k, v in doc["operands"].items() if v["role"] in roles]


def data_classes(doc):
    """valid; each field of each addend below or above its range; each operand past its device range."""
    out = ["valid"]
    for op in _ops(doc, "addend"):
        for f in doc["data"]["fields"]:
            out += [f"{op}.{f['name']}.below", f"{op}.{f['name']}.above"]
    if any(c["check"] == "device_range" for c in doc["errors"]["checks"]):
        out += [f"{op}.device-range" for op in _ops(doc, "addend", "result")]
    return out


def sum_classes(doc):
    """Where the sum falls against the wrap of the top field: zero, below, exactly at, above it; or no sum."""
    return ["zero", "below-wrap", "exact-wrap", "above-wrap", "none"]


def aliasing_classes(doc):
    """Every operand its own device, or two of them the same device, or the result sharing some words
    with an addend at another offset (its head fewer words from the addend's than the addend has)."""
    ops = list(doc["operands"])
    (result,) = _ops(doc, "result")
    overlaps = [f"{result}-overlaps-{op}" for op in _ops(doc, "addend") if doc["operands"][op]["words"] > 1]
    return ["distinct"] + [f"{a}={b}" for a, b in itertools.combinations(ops, 2)] + overlaps


DERIVE = {
    "instructions": lambda doc: [i["mnemonic"] for i in doc["instructions"]],
    "execution-condition": lambda doc: ["rising", "held", "off"],
    "data-validity": data_classes,
    "sum": sum_classes,
    "flags-before": lambda doc: ["off", "on"],
    "aliasing": aliasing_classes,
}
NEEDS = {}


class AddClassifier:
    def __init__(self, doc, sizes):
        self.doc, self.sizes = doc, sizes
        self.fields = doc["data"]["fields"]
        self.codec = FieldCodec(self.fields)
        self.addends = _ops(doc, "addend")
        self.all_ops = _ops(doc, "addend", "result")
        self.words = {k: v["words"] for k, v in doc["operands"].items()}
        flags = doc["flags"]
        self.flags = flags["carry"]["devices"] + flags["zero"]["devices"]

    def classify(self, instr, operands, before, step, record):
        """{derivation name: class} for one execution."""
        en = bool(step.get("en"))
        total, modulus = record["total"], self.codec.modulus()
        if total is None:
            where = "none"
        elif total % modulus == 0:
            where = "zero" if total == 0 else "exact-wrap" if total == modulus else "above-wrap"
        else:
            where = "below-wrap" if total < modulus else "above-wrap"
        return {
            "instructions": instr["name"],
            "execution-condition": "off" if not en else "held" if record["en_before"] else "rising",
            "data-validity": self.data_class(operands, before),
            "sum": where,
            "flags-before": "on" if any(before.get(d) for d in self.flags) else "off",
            "aliasing": self.aliasing(operands),
        }

    def aliasing(self, operands):
        heads = [operands[op]["device"] for op in self.all_ops]
        for (a, ha), (b, hb) in itertools.combinations(zip(self.all_ops, heads), 2):
            if ha == hb:
                return f"{a}={b}"
        (result,) = _ops(self.doc, "result")
        prefix, head = split_address(operands[result]["device"])
        for op in self.addends:
            other, at = split_address(operands[op]["device"])
            if (other == prefix and None not in (head, at)
                    and head < at + self.words[op] and at < head + self.words[result]):
                return f"{result}-overlaps-{op}"
        return "distinct"

    def data_class(self, operands, before):
        for op in self.all_ops:
            if not in_device_range(operands[op]["device"], self.words[op], self.sizes):
                return f"{op}.device-range"
        for op in self.addends:
            values = self.codec.read(before, operands[op]["device"])
            for f in self.fields:
                v = values[f["name"]]
                if v < f["min"]:
                    return f"{op}.{f['name']}.below"
                if v > f["max"]:
                    return f"{op}.{f['name']}.above"
        return "valid"
