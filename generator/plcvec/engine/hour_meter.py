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
        was_on, ctx["input"] = ctx.get("input", False), step["input"]   # off before the first step
        if not step["input"]:
            if self.knobs["input_off"] == "reset":
                self.codec.write(state, d1, self.codec.from_units(0))
            if self.knobs["input_off"] in ("reset", "hold_drop_fraction"):
                ctx["fraction"] = 0
            self._check_when_off(operands, state, ctx, trace, record)
            return None
        # A measured value out of its fields' range decides something only through the spec's reading
        # of it, so only then is the reading asked.
        held = self.codec.read(state, d1)
        if (not all(self.codec.in_range(f, held[f["name"]]) for f in self.codec.fields)
                and self.knobs["measured_invalid"] == "error"):
            trace.add(self.doc["data"]["measured_range_clause"])
            state[self.error["device"]] = True
            ctx["error"] = {"device": self.error["device"]}
            record["error"] = True
            return None
        elapsed = step["elapsed_ms"]
        # Whether the execution at which the input turns on counts its elapsed time decides something
        # only when there is some, so only then is it asked.
        if not was_on and elapsed and self.knobs["first_scan"] == "from_next_scan":
            elapsed = 0
        fraction = ctx.get("fraction", 0) + elapsed
        whole, ctx["fraction"] = divmod(fraction, self.units)
        record["whole"] = whole
        if whole and state[d2]:
            trace.add(self.doc["data"].get("keep_measuring_clause"))  # D1 goes on growing past the preset
        total = self.codec.to_units(held) + whole
        modulus = self.codec.modulus()
        if total >= modulus:
            trace.add(self.doc["wrap"]["clause"])
            ctx["wrapped_since_on"] = True
            record["wrapped"] = True
        total %= modulus
        self.codec.write(state, d1, self.codec.from_units(total))

        preset = self._preset(operands[self.preset], state, trace)
        if preset is None:
            self._invalid_preset(d2, state, ctx, trace, record)
            return None
        self._valid_preset(state)
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

    def _invalid_preset(self, d2, state, ctx, trace, record):
        trace.add(self.error["clause"])
        state[self.error["device"]] = True
        ctx["error"] = {"device": self.error["device"]}
        record["error"] = True
        if state[d2]:
            trace.add(self.error["output_off_clause"])
            state[d2] = False

    def _valid_preset(self, state):
        # Whether a valid preset turns the error device off decides something only when it is on.
        device = self.error["device"]
        if state[device] and self.knobs["error_clear"] == "valid_preset":
            state[device] = False

    def _check_when_off(self, operands, state, ctx, trace, record):
        """The preset check of an execution with the input off, where the spec's reading makes one: asked
        only when it could change something (an invalid preset, or a valid one with the error device on)."""
        operand = operands[self.preset]
        if "constant" in operand:
            valid = True
        else:
            values = self.codec.read(state, operand["device"])
            valid = all(self.codec.in_range(f, values[f["name"]]) for f in self.codec.fields)
        if valid and not state[self.error["device"]]:
            return
        if self.knobs["preset_check"] != "every_execution":
            return
        if self._preset(operand, state, trace) is None:
            self._invalid_preset(operands[self.output]["device"], state, ctx, trace, record)
        else:
            self._valid_preset(state)

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
