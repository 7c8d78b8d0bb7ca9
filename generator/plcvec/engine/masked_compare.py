"""Rule kind `masked_compare`: compare the fields a selector word picks, most significant first.

Covers the FX5 LDTM/LDDT families (select bits, current-clock bit, SM709) and the CP1E DT family
(mask bits, BCD bytes, arithmetic flags), each entirely described by its spec.
"""
from plcvec.engine import logic
from plcvec.engine.words import FieldCodec, encode, in_device_range, word_addresses

ORDERINGS = ("lt", "eq", "gt")
ERROR = "error"


class _Error(Exception):
    pass


class _NotExecuted(Exception):
    """The instruction is not executed at all: nothing is written, the contact does not conduct."""


# What _judge_selector() returns when the selector leaves fields to compare.
_COMPARE = object()


class MaskedCompare:
    def __init__(self, doc):
        self.doc = doc
        self.codec = FieldCodec(doc["data"]["fields"])
        self.fields = doc["data"]["fields"]
        self.sel = doc["selector"]
        self.validity = doc["validity"]
        self.flags = doc.get("flags")
        self.logic = doc["logic"]
        self.ops = doc["operands"]
        self.data_ops = [k for k, v in self.ops.items() if v["role"] == "data"]
        self.words = {k: v.get("words", 1) for k, v in self.ops.items()}
        self.conditions = {c["symbol"]: c for c in doc["instructions"]["conditions"]}
        self.reserved_mask = sum(1 << b for b in self.sel["reserved_bits"])
        # What the selector's bits mean, looked up once, not per execution.
        self._want = 1 if self.sel["polarity"] == "select" else 0
        self._field_bits = [(f, self.sel["field_bits"][f["name"]]) for f in self.fields]
        self._field_clauses = [self.sel["field_clauses"][f["name"]] for f in self.fields]
        # Parts of the document read on every execution that no interpretation sets (reading them here
        # consults nothing; the values an interpretation may set inside them are still read in place).
        self._error = self.validity["error"]
        self._error_device = self._error["device"]
        self._device_range = self.validity["device_range"]
        self._sel_operand = self.sel["operand"]
        self._source_bit = self.sel.get("source_bit")
        self._range_check = self._device_range["check"]
        self._range_clause = self._device_range.get("clause") if self._range_check else None
        self._valid_clause, self._unselected_clause = self.sel.get("valid_clause"), self.sel.get("unselected_clause")
        self._order_clause = doc["data"]["order_clause"]
        self._source_mask = 1 << self._source_bit["bit"] if self._source_bit else 0
        self._field_mask = sum(1 << bit for _, bit in self._field_bits)
        # The selector's field bits -> the fields they select, filled as values are met: a function of
        # the spec alone (field bits and polarity), so it carries nothing from one execution to the next.
        self._selections = {}
        self._names = [f["name"] for f in self.fields]
        self._error_clause = self._error.get("clause")
        # What each ordering writes to the flags, as (device, value) pairs (no interpretation sets the
        # flag table, so reading it here consults nothing).
        if self.flags:
            self._flag_clauses = (self.flags["clause"], self.flags.get("written_clause"))
            self._flag_writes = {ordering: [(device, row[symbol]) for symbol, device in self.flags["devices"].items()]
                                 for ordering, row in self.flags["table"].items()}

    # -- the instruction ---------------------------------------------------------------------------
    def execute(self, instr, operands, state, step, ctx, trace):
        """Run one execution; returns the logic result passed on to the rest of the rung."""
        form, cond = instr["form"], self.conditions[instr["symbol"]]
        trace.add(form["clause"])
        rlo_in = step.get("rlo_in")
        err = self._error
        if state[self._error_device] and err.get("latch", True):
            trace.add(err.get("latch_clause"))
        # What this execution did, for the coverage model (plcvec.coverage): executed, ordering, error.
        record = {"executed": False, "ordering": None, "error": False}
        ctx.setdefault("exercised", []).append(record)
        skip = logic.skipped(form["logic"], rlo_in, self.logic)
        if skip is not None:
            return skip
        trace.add(cond["clause"])
        outcome = self.evaluate(operands, state, step, ctx, trace)
        record.update(executed=True, error=outcome == ERROR, ordering=None if outcome == ERROR else outcome)
        # Whether an error passes on a contact combined like any other or a result of its own decides
        # something only in a parallel form whose preceding logic conducts, so only then is it asked.
        if outcome == ERROR and form["logic"] == "or" and rlo_in and self._error.get("in_or") == "result_off":
            return self._error["result"]
        return logic.combine(form["logic"], rlo_in, self.contact(cond["symbol"], outcome))

    def evaluate(self, operands, state, step, ctx, trace):
        """Compare once and write the error device and flags: "error", None (non-continuity) or an ordering.

        Which condition symbol asked does not change anything written, only the contact (see contact()).
        """
        try:
            ordering = self.compare(operands, state, step, ctx, trace)
        except _NotExecuted:
            return None
        except _Error:
            device = self._error_device
            state[device] = True
            trace.add(self._error_clause)
            ctx["error"] = {"device": device}
            # What an error does to the flags decides something only when one of them is on.
            if self.flags and any(state[d] for d, _ in self._flag_writes["eq"]) and self._error["flags"] == "off":
                state.update((d, False) for d, _ in self._flag_writes["eq"])
            return ERROR
        # An error flag that reports each execution, not a latch, is turned off; whether it latches is
        # only asked when there is something to turn off.
        if state[self._error_device] is not False and not self._error.get("latch", True):
            state[self._error_device] = False
        if ordering is not None and self.flags:
            trace.update(self._flag_clauses)
            state.update(self._flag_writes[ordering])
        return ordering

    def contact(self, symbol, outcome):
        """The contact state a condition symbol gives for an outcome of evaluate()."""
        if outcome == ERROR:
            return self._error["result"]
        return outcome is not None and outcome in self.conditions[symbol]["true_when"]

    def compare(self, operands, state, step, ctx, trace):
        """The ordering of the selected fields of the first data operand against the second (or the clock)."""
        operand = operands[self._sel_operand]
        sel = operand["constant"] if "constant" in operand else state[operand["device"]]
        clock_mode = bool(sel & self._source_mask)
        if clock_mode:
            trace.add(self._source_bit["clause"])
        first, second = self.data_ops
        compared_ops = [first] if clock_mode else [first, second]

        if self._range_check and self._past_device_range(operands, compared_ops, clock_mode, ctx["device_sizes"]):
            # Whether a selector that compares nothing is judged before the device range decides
            # something only when an operand runs past it, so only then is the order asked.
            if self._device_range["order"][0] == "selector":
                verdict, _ = self._judge_selector(sel, trace)
                if verdict is not _COMPARE:
                    return verdict
            trace.add(self._range_clause)
            if self._device_range["on_past"] == "not_executed":
                raise _NotExecuted
            raise _Error
        # Whether any field of the compared operands is out of range or not a valid encoding comes
        # with the values (the clock's are not checked).
        read = self.codec.read_checked
        held, valid = read(state, operands[first]["device"])
        values = {first: held}
        if clock_mode:
            clock = step["clock"]
            values[second] = {name: clock[name] for name in self._names}
        else:
            values[second], second_valid = read(state, operands[second]["device"])
            valid = valid and second_valid
        invalid = not valid

        # The check's scope decides something only when some value is invalid.
        if invalid and self.validity["scope"] == "all":
            self._check(values, compared_ops, self.fields, trace)

        verdict, selected = self._judge_selector(sel, trace)
        if verdict is not _COMPARE:
            return verdict
        # Reached with at least one field selected: a selector value the manual lists as valid when no
        # reserved bit is set; a field left out is the masking the manual describes.
        if not sel & self.reserved_mask:
            trace.add(self._valid_clause)
        if len(selected) < len(self.fields):
            trace.add(self._unselected_clause)
        # Checked only now that a comparison is made: the selected fields, or every field of each
        # compared operand (scope "compared"); scope "all" was checked before the selector. The scope
        # decides something only when some value is invalid, so only then is it asked.
        if invalid:
            scope = self.validity["scope"]
            if scope in ("selected", "compared"):
                self._check(values, compared_ops, selected if scope == "selected" else self.fields, trace)
        trace.add(self._order_clause)
        for f in selected:
            trace.add(f["clause"])
            a, b = values[first][f["name"]], values[second][f["name"]]
            if a is None or b is None:
                # Only reached when non-BCD data is not checked: compare the raw bytes.
                a = self._raw(state, operands[first], f) if a is None else self._raw_of(a, f)
                b = self._raw(state, operands[second], f) if b is None else self._raw_of(b, f)
            if a != b:
                return "lt" if a < b else "gt"
        return "eq"

    def _past_device_range(self, operands, compared_ops, clock_mode, sizes):
        """Whether a compared operand runs past the end of its device range."""
        for op in compared_ops:
            if not in_device_range(operands[op]["device"], self.words[op], sizes):
                return True
        # In clock mode the second operand is not compared; whether its range is checked all the
        # same decides something only when it runs past its device, so only then is it asked.
        second = self.data_ops[1]
        return (clock_mode and not in_device_range(operands[second]["device"], self.words[second], sizes)
                and self._device_range["s2_in_clock_mode"])

    def _judge_selector(self, sel, trace):
        """(verdict, selected fields): what the selector decides by itself. The verdict is compare()'s
        outcome when it compares nothing (None for non-continuity, "eq"; an error is raised), or _COMPARE
        with the fields to compare."""
        if sel & self.reserved_mask:
            trace.add(self.sel.get("reserved_clause"))
            action = self.sel["on_reserved"]
            if action == "non_continuity":
                return None, []
            if action == "error":
                raise _Error
        selected = self._selections.get(sel & self._field_mask)
        if selected is None:
            want = self._want
            selected = self._selections[sel & self._field_mask] = [f for f, bit in self._field_bits
                                                                    if (sel >> bit & 1) == want]
        trace.update(self._field_clauses)
        if not selected:
            trace.add(self.sel["no_field_clause"])
            action = self.sel["on_no_field"]
            if action == "non_continuity":
                return None, []
            if action == "error":
                raise _Error
            return "eq", []
        return _COMPARE, selected

    def _check(self, values, compared_ops, fields, trace):
        for op in compared_ops:
            for f in fields:
                v = values[op][f["name"]]
                if v is None:
                    if self.validity["bcd"] == "error":
                        trace.add(f["clause"])
                        raise _Error
                elif not self.codec.in_range(f, v) and self.validity["range"] == "error":
                    trace.add(f["clause"])
                    raise _Error

    def _raw(self, state, operand, f):
        words = [state[a] for a in word_addresses(operand["device"], self.codec.count)]
        return self.codec.raw(words, f)

    def _raw_of(self, value, f):
        return encode(value, f["encoding"], f["width"])
