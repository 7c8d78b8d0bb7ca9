"""Rule kind `hour_meter`: accumulate the ON time of the input and compare it with a preset.

Elapsed time arrives in sub-second units per execution; whole seconds are added to the measured
value with carry through the fields, and the value wraps past the top field's range.
"""
from plcvec.engine.words import FieldCodec


class HourMeter:
    def __init__(self, doc):
        self.doc = doc
        self.codec = FieldCodec(doc["data"]["fields"])
        ops = doc["operands"]
        self.preset = next(k for k, v in ops.items() if v["role"] == "preset")
        self.measured = next(k for k, v in ops.items() if v["role"] == "measured")
        self.output = next(k for k, v in ops.items() if v["role"] == "output")
        self.units = doc["data"]["subsecond_units_per_second"]
        self.knobs = doc["knobs"]
        self.error = doc["error"]

    def execute(self, instr, operands, state, step, ctx, trace):
        trace.add(instr["clause"])
        d1 = operands[self.measured]["device"]
        d2 = operands[self.output]["device"]
        # What this execution did, for the coverage model (plcvec.coverage).
        record = {"whole": 0, "wrapped": False, "reach": None, "error": False}
        ctx.setdefault("exercised", []).append(record)
        if not step["input"]:
            if self.knobs["input_off"] == "reset":
                self.codec.write(state, d1, self.codec.from_units(0))
            if self.knobs["input_off"] in ("reset", "hold_drop_fraction"):
                ctx["fraction"] = 0
            return None
        fraction = ctx.get("fraction", 0) + step["elapsed_ms"]
        whole, ctx["fraction"] = divmod(fraction, self.units)
        record["whole"] = whole
        if whole and state[d2]:
            trace.add(self.doc["data"].get("keep_measuring_clause"))  # D1 goes on growing past the preset
        total = self.codec.to_units(self.codec.read(state, d1)) + whole
        modulus = self.codec.modulus()
        if total >= modulus:
            trace.add(self.doc["wrap"]["clause"])
            ctx["wrapped_since_on"] = True
            record["wrapped"] = True
        total %= modulus
        self.codec.write(state, d1, self.codec.from_units(total))

        preset = self._preset(operands[self.preset], state, trace)
        if preset is None:
            trace.add(self.error["clause"])
            state[self.error["device"]] = True
            ctx["error"] = {"device": self.error["device"]}
            record["error"] = True
            if state[d2]:
                trace.add(self.error["output_off_clause"])
                state[d2] = False
            return None
        reached = total >= self.codec.to_units(preset)
        record["reach"] = "below" if not reached else "at" if total == self.codec.to_units(preset) else "above"
        if self.codec.to_units(preset) == 0 and self.knobs["zero_preset"] == "never":
            reached = False
        if reached:
            trace.add(self.doc["data"]["reach_clause"])
        if reached and not state[d2]:
            state[d2] = True
            ctx["wrapped_since_on"] = False
        elif not reached and state[d2] and self.knobs["output_release"] != "latched":
            # Whether the output is latched decides something only when it is on below the preset, so
            # only then is it asked: on when the count wrapped since it turned on and the spec keeps it.
            state[d2] = ctx.get("wrapped_since_on", False) and self.doc["wrap"]["output"] == "keep"
        return None

    def _preset(self, operand, state, trace):
        if "constant" in operand:
            cf = self.doc["data"]["constant_field"]
            trace.add(cf["clause"])
            values = {f["name"]: 0 for f in self.codec.fields}
            values[cf["field"]] = operand["constant"]
        else:
            values = self.codec.read(state, operand["device"])
        fields = self.codec.fields
        trace.update(f["clause"] for f in fields)  # every field of the preset is checked against its range
        if not all(self.codec.in_range(f, values[f["name"]]) for f in fields):
            return None
        return values
