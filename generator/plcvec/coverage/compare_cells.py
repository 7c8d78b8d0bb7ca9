"""Coverage dimensions of `masked_compare` families: the classes each derives from the spec, and the
class an execution falls in, read from the vector's inputs and the engine's record of it."""
import calendar
import itertools

from plcvec.engine.words import FieldCodec, in_device_range


def _fields(doc):
    return [f["name"] for f in doc["data"]["fields"]]


def _data_ops(doc):
    return [k for k, v in doc["operands"].items() if v["role"] == "data"]


def selector_classes(doc):
    """Each field alone; each pair (three fields or fewer) or each all-but-one and "some" (more);
    all, none; a reserved bit alone, a reserved bit with field bits."""
    names = _fields(doc)
    out = list(names)
    if len(names) <= 3:
        out += ["+".join(p) for p in itertools.combinations(names, 2) if len(names) > 2]
    else:
        out += [f"all-but-{n}" for n in names] + ["some"]
    out += ["all", "none"]
    if doc["selector"]["reserved_bits"]:
        out += ["reserved", "reserved+fields"]
    return out


def data_classes(doc):
    """valid; each field of each data operand below / above its range or not BCD, where the encoding
    can hold such a value; the same for the ignored dummy operand of current-clock mode; an operand
    past its device range; a date that does not exist."""
    out = ["valid"]
    first, second = _data_ops(doc)
    owners = [first, second] + ([f"dummy-{second}"] if doc["selector"].get("source_bit") else [])
    for owner in owners:
        for f in doc["data"]["fields"]:
            out += [f"{owner}.{f['name']}.{kind}" for kind in invalid_kinds(f)]
    if doc["validity"]["device_range"]["check"]:
        out += [f"{op}.device-range" for op in (first, second)]
    if doc.get("nonexistent_dates"):
        out.append("nonexistent")
    return out


def invalid_kinds(f):
    """The ways a field's word can hold something outside its range, given its encoding."""
    kinds = []
    if f["encoding"] == "bcd":
        if f["min"] > 0:
            kinds.append("below")
        if f["max"] < 10 ** (f["width"] // 4) - 1:
            kinds.append("above")
        kinds.append("non-bcd")
    else:
        kinds += ["below", "above"]
    return kinds


DERIVE = {
    "forms": lambda doc: [f["form"] for f in doc["instructions"]["forms"]],
    "preceding-logic": lambda doc: ["on", "off"],
    "conditions": lambda doc: [c["symbol"] for c in doc["instructions"]["conditions"]],
    "selector-classes": selector_classes,
    "source-bit": lambda doc: ["operands", "current-clock"],
    "orderings": lambda doc: ["lt", "eq", "gt", "none"],
    "data-validity": data_classes,
    "error-device": lambda doc: ["off", "on"],
}
# Derivations that need a fact the family's spec may not have.
NEEDS = {"source-bit": ("selector", "source_bit")}


class CompareClassifier:
    """The class of each dimension for one execution."""

    def __init__(self, doc, sizes):
        self.doc, self.sizes = doc, sizes
        self.fields = doc["data"]["fields"]
        self.names = _fields(doc)
        self.codec = FieldCodec(self.fields)
        self.sel = doc["selector"]
        self.first, self.second = _data_ops(doc)
        self.reserved = sum(1 << b for b in self.sel["reserved_bits"])
        self.field_mask = sum(1 << b for b in self.sel["field_bits"].values())
        self.error_device = doc["validity"]["error"]["device"]
        dates = doc.get("nonexistent_dates", {})
        self.nonexistent = [tuple(d[n] for n in self.names) for d in dates.get("dates", [])]
        self.calendar = dates.get("calendar")
        self.words = doc["operands"][self.first]["words"]
        self._selector_classes = {}   # selector word -> class: a pure function of a 16-bit word

    def classify(self, instr, operands, before, step, record):
        """{derivation name: class} for one execution (None: the dimension does not apply)."""
        sel_op = operands[self.sel["operand"]]
        value = (sel_op["constant"] if "constant" in sel_op else before[sel_op["device"]]) & 0xFFFF
        clock = bool(self.sel.get("source_bit")) and bool(value >> self.sel["source_bit"]["bit"] & 1)
        logic = instr["form"]["logic"]
        ordering = record["ordering"] if record["executed"] and not record["error"] and record["ordering"] else "none"
        return {
            "forms": instr["form"]["form"],
            "preceding-logic": None if logic == "load" else ("on" if step.get("rlo_in") else "off"),
            "conditions": instr["symbol"],
            "selector-classes": self.selector_class(value),
            "source-bit": "current-clock" if clock else "operands",
            "orderings": ordering,
            "data-validity": self.data_class(operands, before, clock),
            "error-device": "on" if before[self.error_device] else "off",
        }

    def selector_class(self, value):
        got = self._selector_classes.get(value)
        if got is None:
            got = self._selector_classes[value] = self._selector_class(value)
        return got

    def _selector_class(self, value):
        if value & self.reserved:
            return "reserved+fields" if value & self.field_mask else "reserved"
        want = 1 if self.sel["polarity"] == "select" else 0
        chosen = [n for n in self.names if (value >> self.sel["field_bits"][n] & 1) == want]
        n = len(self.names)
        if not chosen:
            return "none"
        if len(chosen) == n:
            return "all"
        if len(chosen) == 1:
            return chosen[0]
        if n <= 3:
            return "+".join(chosen)
        if len(chosen) == n - 1:
            return "all-but-" + next(x for x in self.names if x not in chosen)
        return "some"

    def data_class(self, operands, before, clock):
        for op in (self.first, self.second):
            if not in_device_range(operands[op]["device"], self.words, self.sizes):
                return f"{op}.device-range"
        for op in (self.first, self.second):
            owner = f"dummy-{op}" if clock and op == self.second else op
            # The codec's memo of the operand's words says at once whether every field is valid
            # (the values are the codec's: read, never changed).
            values, valid = self.codec.read_checked(before, operands[op]["device"])
            if valid:
                continue
            for f in self.fields:
                v = values[f["name"]]
                if v is None:
                    return f"{owner}.{f['name']}.non-bcd"
                if v < f["min"]:
                    return f"{owner}.{f['name']}.below"
                if v > f["max"]:
                    return f"{owner}.{f['name']}.above"
        if self.nonexistent:
            for op in (self.first,) if clock else (self.first, self.second):
                values, _ = self.codec.read_checked(before, operands[op]["device"])
                if tuple(values[n] for n in self.names) in self.nonexistent or self.past_month_end(values):
                    return "nonexistent"
        return "valid"

    def past_month_end(self, values):
        """A date of the spec's calendar fields whose day is past the end of its month (2006/02/30)."""
        if not self.calendar:
            return False
        year, month, day = (values[self.calendar[k]] for k in ("year", "month", "day"))
        return day > calendar.monthrange(year, month)[1]
