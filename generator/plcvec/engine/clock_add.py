"""Rule kind `clock_add`: add two clock values field by field with carry, wrapping at the top field.

The radix of each field is its range (max + 1); the sum past the top field's range wraps and sets the
carry flags; a zero result sets the zero flags. Error checks run in the order the spec lists them.
When the result shares words with an addend at another offset, the spec's `writes` says whether every
addend word is read before the result is written, or the result is written field by field between reads.
"""
from plcvec.engine.words import FieldCodec, in_device_range, split_address


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
        total = self._total(values, operands, state)
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

    def _total(self, values, operands, state):
        """The sum of the addends in units of the last field, read as the spec's `writes` says.

        When (d) is written between the reads decides something only when it shares words with an addend
        at another offset (a word of the addend is then one of the result), so only then is it asked.
        """
        writes = self.doc["writes"] if self._shares_words(operands) else "after_reads"
        if writes == "after_reads":
            total = 0
            for op in self.addends:
                v = values.get(op) or self.codec.read(state, operands[op]["device"])
                total += self.codec.to_units(v)
            return total
        # Field by field, each written to (d) before the next is read: from the last field up, the way the
        # carry goes, writing the field's digit of the sum so far; or from the first field down, writing the
        # field's plain sum (the whole result is written from the total afterwards, as for any reading).
        from_last = writes == "each_field_from_last"
        fields = self.codec.fields[::-1] if from_last else self.codec.fields
        result, modulus, total = operands[self.result]["device"], self.codec.modulus(), 0
        for f in fields:
            part = sum(self.codec.read_field(state, operands[op]["device"], f) for op in self.addends)
            total += part * self.codec.units(f)
            digit = self.codec.from_units(total % modulus)[f["name"]] if from_last else part
            self.codec.write_field(state, result, f, digit)
        return total

    def _shares_words(self, operands):
        """Whether (d) and an addend share a word at different offsets ((d) = (s1)+1, (s2)-2, ...)."""
        prefix, head = split_address(operands[self.result]["device"])
        words = self.ops[self.result]["words"]
        for op in self.addends:
            other, at = split_address(operands[op]["device"])
            if (other == prefix and head is not None and at is not None and head != at
                    and head < at + self.ops[op]["words"] and at < head + words):
                return True
        return False

