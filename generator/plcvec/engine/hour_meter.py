"""Rule kind `hour_meter`: accumulate the ON time of the input and compare it with a preset.

Elapsed time arrives in sub-second units per execution; whole seconds are added to the measured
value with carry through the fields, and the value wraps past the top field's range.
"""
from plcvec.engine.undefined import UNDEFINED, met
from plcvec.engine.words import FieldCodec, encode, split_address


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
        name = doc["data"]["constant_field"]["field"]
        self.constant_field = next(f for f in self.codec.fields if f["name"] == name)
        first = doc.get("special_relays", {}).get("first")
        self.special_from = split_address(first) if first else None

    def execute(self, instr, operands, state, step, ctx, trace):
        trace.add(instr["clause"])
        d1 = operands[self.measured]["device"]
        # What this execution did, for the coverage model (plcvec.coverage).
        record = {"whole": 0, "wrapped": False, "reach": None, "error": False}
        ctx.setdefault("exercised", []).append(record)
        was_on, ctx["input"] = ctx.get("input", False), step["input"]   # off before the first step
        first, ctx["executed"] = not ctx.get("executed"), True          # the first execution since the CPU started
        if self._undefined_program(operands, ctx):
            return None
        d2 = self._writable_output(operands)
        if not step["input"]:
            if self.knobs["input_off"] == "reset":
                self.codec.write(state, d1, self.codec.from_units(0))
            if self.knobs["input_off"] in ("reset", "hold_drop_fraction"):
                ctx["fraction"] = 0
            self._check_when_off(operands, d2, state, ctx, trace, record)
            return None
        held = self.codec.read(state, d1)
        mode = self._measured_mode(held, state, ctx, trace, record)
        if mode is None:
            return None
        whole = self._whole_seconds(step, was_on, first, ctx, record)
        if whole and d2 is not None and state[d2]:
            trace.add(self.doc["data"].get("keep_measuring_clause"))  # D1 goes on growing past the preset
        values, carry = self._count(held, whole, mode)
        if carry:
            trace.add(self.doc["wrap"]["clause"])
            record["wrapped"] = True
        # Whether D1 is written when no whole second is added decides something only for a D1 out of
        # its range (in range it holds those very values), where only the spec's reading is asked.
        if whole or mode != "as_seconds_if_added":
            self.codec.write(state, d1, values)

        preset = self._preset(operands[self.preset], state, trace)
        if preset is None:
            if carry:
                ctx["wrapped_since_on"] = True
            self._invalid_preset(d2, state, ctx, trace, record)
        else:
            self._valid_preset(state, ctx)
            self._compare(values, carry, preset, d2, state, ctx, trace, record)
        if d2 is None:
            self._forbidden_output(state, ctx, record)
        return None

    # -- operands the device table forbids -------------------------------------------------------
    def _special(self, device):
        """Whether `device` is a special internal relay (the spec's special_relays: that prefix, from that number)."""
        if self.special_from is None:
            return False
        prefix, number = split_address(device)
        return prefix == self.special_from[0] and number is not None and number >= self.special_from[1]

    def _constant_out_of_range(self, operand):
        return "constant" in operand and not self.codec.in_range(self.constant_field, operand["constant"])

    def _undefined_program(self, operands, ctx):
        """Whether the spec's reading leaves this program undefined: D2 a special internal relay, or a
        constant S1 outside the range of the field it gives (asked only when the program has one)."""
        if self._special(operands[self.output]["device"]) and self.knobs["special_output"] == UNDEFINED:
            met(ctx, "special_output")
            return True
        if self._constant_out_of_range(operands[self.preset]) and self.knobs["constant_range"] == UNDEFINED:
            met(ctx, "constant_range")
            return True
        return False

    def _writable_output(self, operands):
        """D2's device, or None when the spec's reading of a special internal relay as D2 is an error
        (the instruction then never writes it)."""
        d2 = operands[self.output]["device"]
        if self._special(d2) and self.knobs["special_output"] == "error":
            return None
        return d2

    def _forbidden_output(self, state, ctx, record):
        """The error of an execution with the input on whose D2 is a special internal relay (read as an error)."""
        state[self.error["device"]] = True
        ctx["error"] = {"device": self.error["device"]}
        record["error"] = True

    # -- measuring ---------------------------------------------------------------------------------
    def _measured_mode(self, held, state, ctx, trace, record):
        """How this execution counts D1: `as_seconds` for a D1 in range (every reading agrees there);
        for one out of range the spec's reading of it, or None when the execution stops there."""
        if all(self.codec.in_range(f, held[f["name"]]) for f in self.codec.fields):
            return "as_seconds"
        mode = self.knobs["measured_invalid"]
        if mode == UNDEFINED:
            met(ctx, "measured_invalid")
            return None
        if mode == "error":
            trace.add(self.doc["data"]["measured_range_clause"])
            state[self.error["device"]] = True
            ctx["error"] = {"device": self.error["device"]}
            record["error"] = True
            return None
        return mode

    def _whole_seconds(self, step, was_on, first, ctx, record):
        """The whole seconds this execution adds; the rest of a second is carried in the work area."""
        elapsed = step["elapsed_ms"]
        # Whether the execution at which the input turns on counts its elapsed time decides something
        # only when there is some, so only then is it asked.
        if not was_on and elapsed:
            mode = self.knobs["first_scan"]
            if mode == "from_next_scan" or (mode == "after_cpu_start" and first):
                elapsed = 0
        fraction = ctx.get("fraction", 0) + elapsed
        whole, ctx["fraction"] = divmod(fraction, self.units)
        record["whole"] = whole
        return whole

    def _count(self, held, whole, mode):
        """(D1 after `whole` more seconds, how many times it passed its largest value and wrapped)."""
        if mode == "by_field":
            return count_by_field(self.codec.fields, held, whole)
        carry, total = divmod(self.codec.to_units(held) + whole, self.codec.modulus())
        return self.codec.from_units(total), carry

    # -- comparing ---------------------------------------------------------------------------------
    def _reach_key(self, values, carry=0):
        """What is compared with S1: the fields from the most significant, the top one counting `carry`
        cycles more (for values within their ranges this orders them as their counts of seconds do)."""
        key = [values[f["name"]] for f in self.codec.fields]
        key[0] += carry * (self.codec.fields[0]["max"] + 1)
        return tuple(key)

    def _compare(self, values, carry, preset, d2, state, ctx, trace, record):
        # Whether D1 is compared before it wraps decides something only at an execution that wraps it.
        before_wrap = bool(carry) and self.knobs["wrap_compare"] == "before_wrap"
        if carry and not before_wrap:
            ctx["wrapped_since_on"] = True     # wrapped first, then compared
        mine, target = self._reach_key(values, carry if before_wrap else 0), self._reach_key(preset)
        reached = mine >= target
        written = self._reach_key(values)     # the coverage model classes D1 as written
        record["reach"] = "below" if written < target else "at" if written == target else "above"
        if self.codec.to_units(preset) == 0 and self.knobs["zero_preset"] == "never":
            reached = False
        if reached:
            trace.add(self.doc["data"]["reach_clause"])
        if d2 is not None:
            self._set_output(reached, d2, state, ctx)
        if before_wrap:
            ctx["wrapped_since_on"] = True     # compared, then wrapped (with D2 as the comparison left it)

    def _set_output(self, reached, d2, state, ctx):
        if reached and not state[d2]:
            state[d2] = True
            ctx["wrapped_since_on"] = False
        elif not reached and state[d2] and self.knobs["output_release"] != "latched":
            # Whether the output is latched decides something only when it is on below the preset, so
            # only then is it asked: on when the count wrapped since it turned on and the spec keeps it.
            state[d2] = ctx.get("wrapped_since_on", False) and self.doc["wrap"]["output"] == "keep"

    # -- the preset and the error device -----------------------------------------------------------
    def _invalid_preset(self, d2, state, ctx, trace, record):
        trace.add(self.error["clause"])
        device = self.error["device"]
        # Whether an invalid preset found again turns the error device on again decides something only
        # when the program turned it off since the previous check, which also found the preset invalid.
        if not state[device] and (ctx.get("preset_valid", True) or self.knobs["error_repeat"] == "every_check"):
            state[device] = True
        ctx["preset_valid"] = False
        ctx["error"] = {"device": device}
        record["error"] = True
        if d2 is not None and state[d2]:
            trace.add(self.error["output_off_clause"])
            state[d2] = False

    def _valid_preset(self, state, ctx):
        ctx["preset_valid"] = True
        # Whether a valid preset turns the error device off decides something only when it is on.
        device = self.error["device"]
        if state[device] and self.knobs["error_clear"] == "valid_preset":
            state[device] = False

    def _check_when_off(self, operands, d2, state, ctx, trace, record):
        """The preset check of an execution with the input off, where the spec's reading makes one: asked
        only when it could change something (an invalid preset, or a valid one with the error device on
        or after a check that found the preset invalid)."""
        operand = operands[self.preset]
        if "constant" in operand:
            valid = self._constant_values(operand) is not None
        else:
            values = self.codec.read(state, operand["device"])
            valid = all(self.codec.in_range(f, values[f["name"]]) for f in self.codec.fields)
        if valid and not state[self.error["device"]] and ctx.get("preset_valid", True):
            return
        if self.knobs["preset_check"] != "every_execution":
            return
        if self._preset(operand, state, trace) is None:
            self._invalid_preset(d2, state, ctx, trace, record)
        else:
            self._valid_preset(state, ctx)

    def _constant_values(self, operand):
        """The preset a constant S1 stands for, or None when the spec's reading makes it invalid; the
        reading of a constant outside its field's range is asked only for such a constant."""
        field = self.constant_field
        value = operand["constant"]
        if not self.codec.in_range(field, value):
            mode = self.knobs["constant_range"]
            if mode == "error":
                return None
            if mode == "low_bits":
                value = encode(value, field["encoding"], field["width"])
        values = {f["name"]: 0 for f in self.codec.fields}
        values[field["name"]] = value
        return values

    def _preset(self, operand, state, trace):
        fields = self.codec.fields
        trace.update(f["clause"] for f in fields)  # every field of the preset is checked against its range
        if "constant" in operand:
            trace.add(self.doc["data"]["constant_field"]["clause"])
            return self._constant_values(operand)
        values = self.codec.read(state, operand["device"])
        if not all(self.codec.in_range(f, values[f["name"]]) for f in fields):
            return None
        return values


def count_by_field(fields, values, units):
    """`values` plus `units` units of the last field, counted as one counter per field counts them:
    a field within its range carries into the field before it each time it passes its largest value
    (its max + 1 becomes 0); a field already above its range first climbs to the end of its word
    (2**width - 1 + 1 becomes 0, carrying nothing) and counts from 0 from there. Returns the fields
    and the carry out of the first field (how many times the whole value wrapped)."""
    out = dict(values)
    carry = units
    for f in reversed(fields):
        if not carry:
            break
        value = out[f["name"]]
        if value > f["max"]:
            room = (1 << f["width"]) - value
            if carry < room:
                out[f["name"]] = value + carry
                return out, 0
            value, carry = 0, carry - room
        carry, out[f["name"]] = divmod(value + carry, f["max"] + 1)
    return out, carry
