"""Rule kind `clock_add`: add two clock values field by field with carry, wrapping at the top field.

The radix of each field is its range (max + 1); the sum past the top field's range wraps and sets the
carry flags; a zero result sets the zero flags. Error checks run in the order the spec lists them.
"""
from plcvec.engine.words import FieldCodec, in_device_range


class ClockAdd:
    def __init__(self, doc):
        self.doc = doc
        self.codec = FieldCodec(doc["data"]["fields"])
        self.ops = doc["operands"]
        self.addends = [k for k, v in self.ops.items() if v["role"] == "addend"]
        self.result = next(k for k, v in self.ops.items() if v["role"] == "result")
        self.flags = doc["flags"]
        self.errors = doc["errors"]

    def execute(self, instr, operands, state, step, ctx, trace):
        en = bool(step["en"])
        previous, ctx["en"] = ctx.get("en", False), en
        # What this execution did, for the coverage model (plcvec.coverage).
        record = {"en_before": previous, "executed": False, "total": None, "error": None}
        ctx.setdefault("exercised", []).append(record)
        if not en:
            return None
        trace.add(instr["clause"])
        if instr["execution"] == "rising_edge" and previous:
            return None  # the pulse form executes on the rising edge only
        record["executed"] = True
        values = {}
        sizes = ctx["device_sizes"]
        failures = [(check, failed) for check in self.errors["checks"]
                    for failed in [self._failed(check, operands, state, values, sizes)] if failed]
        if failures:
            if len(failures) > 1:
                # Which code is stored when more than one check fails decides something only then.
                order = self.errors["order"]
                failures.sort(key=lambda f: order.index(f[0]["check"]))
            check, failed = failures[0]
            trace.update(failed)
            registers = self.errors["registers"]
            for register in registers["devices"]:
                state[register] = check["code"]
                trace.add(registers.get("device_clauses", {}).get(register))
            trace.add(registers["clause"])
            ctx["error"] = {"code": check["code"]}
            record["error"] = check["check"]
            # Only a field error alone leaves every operand there to compute with.
            if len(failures) == 1 and check["check"] == "field_range" and self.errors["on_error"] == "computed":
                record["total"] = self._add(values, operands, state, trace)
            return None
        record["total"] = self._add(values, operands, state, trace)
        return None

    def _failed(self, check, operands, state, values, device_sizes):
        """The clauses a failed check breaks (empty when it passes).

        A range check cites the clause of each field found out of range, not the check's own clause:
        the manual gives each range its own row of the error table (hour 0 to 23; minute, second 0 to 59).
        It reads only the operands whose words are all within their device range: a word that is not
        there cannot be range-checked.
        """
        for op in check["operands"]:
            head = operands[op]["device"]
            words = self.ops[op]["words"]
            if check["check"] == "device_range":
                if not in_device_range(head, words, device_sizes):
                    return {check["clause"]}
            elif in_device_range(head, words, device_sizes):
                values[op] = self.codec.read(state, head)
                bad = {f["clause"] for f in self.codec.fields if not self.codec.in_range(f, values[op][f["name"]])}
                if bad:
                    return bad
        return set()

    def _add(self, values, operands, state, trace):
        trace.add(self.doc["data"]["order_clause"])
        total = 0
        for op in self.addends:
            v = values.get(op) or self.codec.read(state, operands[op]["device"])
            total += self.codec.to_units(v)
        modulus = self.codec.modulus()
        # Whether the carry is set at the wrap itself or only past it decides something only at the wrap.
        carry = total > modulus or (total == modulus and self.flags["carry_at_wrap"])
        result = total % modulus
        self.codec.write(state, operands[self.result]["device"], self.codec.from_units(result))
        zero = result == 0
        for name, on in (("carry", carry), ("zero", zero)):
            if on:
                trace.add(self.flags[name]["clause"])
            for device in self.flags[name]["devices"]:
                if self.flags["written"] == "always" or on:
                    state[device] = on
                    trace.add(self.flags[name].get("device_clauses", {}).get(device))
        return total
