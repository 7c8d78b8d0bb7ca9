"""Coverage dimensions of `hour_meter` families: classes derived from the spec, and the class of each
execution (one scan of a sequence), read from the vector's inputs and the engine's record of it."""
from plcvec.engine.words import FieldCodec


def _role(doc, role):
    return next(k for k, v in doc["operands"].items() if v["role"] == role)


def preset_classes(doc):
    """valid, or a field of the preset above its range: a register's field where its word can hold
    more, and the field a constant gives (a constant is not held in that field's word)."""
    constant = doc["data"]["constant_field"]["field"]
    out = ["valid"]
    for f in doc["data"]["fields"]:
        if f["max"] < (1 << f["width"]) - 1 or f["name"] == constant:
            out.append(f"{f['name']}.above")
    return out


DERIVE = {
    "input": lambda doc: ["on", "off"],
    "preset-operand": lambda doc: ["register", "constant"],
    "preset-validity": preset_classes,
    "output-before": lambda doc: ["off", "on"],
    "reach": lambda doc: ["below", "at", "above", "none"],
    "whole-seconds": lambda doc: ["none", "one", "several"],
    "wrap": lambda doc: ["no", "yes"],
    "error-before": lambda doc: ["off", "on"],
}
NEEDS = {}


class HourClassifier:
    def __init__(self, doc, sizes):
        self.doc = doc
        self.fields = doc["data"]["fields"]
        self.codec = FieldCodec(self.fields)
        self.preset, self.output = _role(doc, "preset"), _role(doc, "output")
        self.error_device = doc["error"]["device"]
        name = doc["data"]["constant_field"]["field"]
        self.constant_field = next(f for f in self.fields if f["name"] == name)

    def classify(self, instr, operands, before, step, record):
        """{derivation name: class} for one execution."""
        op = operands[self.preset]
        validity = "valid"
        if "device" in op:
            values = self.codec.read(before, op["device"])
            for f in self.fields:
                if not self.codec.in_range(f, values[f["name"]]):
                    validity = f"{f['name']}.above"
                    break
        elif op["constant"] > self.constant_field["max"]:
            validity = f"{self.constant_field['name']}.above"
        whole = record["whole"]
        return {
            "input": "on" if step.get("input") else "off",
            "preset-operand": "constant" if "constant" in op else "register",
            "preset-validity": validity,
            "output-before": "on" if before[operands[self.output]["device"]] else "off",
            "reach": record["reach"] or "none",
            "whole-seconds": "none" if whole == 0 else "one" if whole == 1 else "several",
            "wrap": "yes" if record["wrapped"] else "no",
            "error-before": "on" if before[self.error_device] else "off",
        }
