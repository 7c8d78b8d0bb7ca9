"""Cases for `masked_compare` families: examples, orderings, forms, selector classes, boundaries,
nonexistent dates, device range, current clock, latching, and random draws."""
import calendar
import itertools

from plcvec.cases.common import Operands, hexw, signed_boundaries, top_head
from plcvec.cases.model_cases import model_cases
from plcvec.cases.random_cases import draw_compare
from plcvec.engine.words import split_address

ORDER_SIGN = {"lt": -1, "eq": 0, "gt": 1}


class CompareCases:
    def __init__(self, fam, builder):
        self.fam, self.b, doc = fam, builder, fam.doc
        self.doc = doc
        self.fields = doc["data"]["fields"]
        self.names = [f["name"] for f in self.fields]
        self.ops = Operands(self.fields)
        self.sel = doc["selector"]
        self.first, self.second = [k for k, v in doc["operands"].items() if v["role"] == "data"]
        self.selop = self.sel["operand"]
        self.place = doc["generation"]["placement"]
        self.forms = {f["form"]: f for f in doc["instructions"]["forms"]}
        self.conditions = [c["symbol"] for c in doc["instructions"]["conditions"]]
        self.instr = {(i["form"]["form"], i["symbol"]): name for name, i in builder.instructions.items()}
        self.load_form = next(f for f, v in self.forms.items() if v["logic"] == "load")
        self.error_device = doc["validity"]["error"]["device"]
        self.flags = doc.get("flags")
        self.clock_bit = self.sel.get("source_bit")
        self.words = doc["operands"][self.first]["words"]

    # -- building blocks ----------------------------------------------------------------------------
    def selector(self, selected, clock=False, extra=0):
        bits = self.sel["field_bits"]
        if self.sel["polarity"] == "select":
            value = sum(1 << bits[n] for n in selected)
        else:
            value = sum(1 << bits[n] for n in self.names if n not in selected)
        if clock:
            value |= 1 << self.clock_bit["bit"]
        return (value | extra) & 0xFFFF

    def outputs(self):
        """Initial values of everything the instruction may write, chosen so that a write shows."""
        out = {self.error_device: False}
        if self.flags:
            # Opposite of what an "equal" result sets, so every flag changes under some ordering.
            for symbol, device in self.flags["devices"].items():
                out[device] = not self.flags["table"]["eq"][symbol]
        return out

    def step_for(self, form, contact_decides=True, rlo_in=None):
        logic = self.forms[form]["logic"]
        if logic == "load":
            return {}
        if rlo_in is None:
            rlo_in = logic == "and" if contact_decides else logic != "and"
        return {"rlo_in": rlo_in}

    def case(self, form, symbol, key, *, tags, description, s1, s2, sel, sel_constant=False, clock=None,
             rlo_in=None, heads=None, extra_devices=None, steps=None, clauses=(), printed=None):
        heads = dict(self.place, **(heads or {}))
        devices = self.outputs()
        devices.update(extra_devices or {})
        self.ops.place(devices, heads[self.first], s1)
        if s2 is not None:
            self.ops.place(devices, heads[self.second], s2)
        operands = {self.first: {"device": heads[self.first]}, self.second: {"device": heads[self.second]}}
        if sel_constant:
            operands[self.selop] = {"constant": sel}
        else:
            operands[self.selop] = {"device": heads[self.selop]}
            devices[heads[self.selop]] = sel
        if steps is None:
            step = self.step_for(form, rlo_in=rlo_in)
            if clock is not None:
                step["clock"] = self.on_the_calendar(clock)
            steps = [step]
        return self.b.vector(self.instr[(form, symbol)], key, tags=tags, description=description,
                             operands=operands, devices=devices, steps=steps, clauses=clauses, printed=printed)

    def on_the_calendar(self, clock):
        """The clock as a clock can hold it: a date past the end of its month (which a device may hold,
        but no calendar) moved to the month's last day. Only a family whose spec names its calendar
        (nonexistent_dates.calendar) has dates; every in-range time of day is real."""
        cal = self.doc.get("nonexistent_dates", {}).get("calendar")
        if not cal:
            return clock
        last = calendar.monthrange(clock[cal["year"]], clock[cal["month"]])[1]
        return clock if clock[cal["day"]] <= last else dict(clock, **{cal["day"]: last})

    def pair_with(self, decider, ordering):
        """s1, s2 values that differ first at field `decider` in the given ordering, and differently below it."""
        a, b = self.ops.values(), self.ops.values()
        if decider is None:
            return a, b
        i = self.names.index(decider)
        sign = ORDER_SIGN[ordering]
        a[decider], b[decider] = self.ops.mid(decider, sign), self.ops.mid(decider, -sign)
        for n in self.names[i + 1:]:  # less significant fields disagree the other way: order matters
            a[n], b[n] = self.ops.mid(n, -sign), self.ops.mid(n, sign)
        return a, b

    def all_fields(self):
        return self.selector(self.names)

    def symbol_for(self, ordering):
        """The condition that is true for exactly this one ordering (=, <, >)."""
        return next(c["symbol"] for c in self.doc["instructions"]["conditions"] if c["true_when"] == [ordering])

    # -- case families ------------------------------------------------------------------------------
    def manual_examples(self):
        for ex in self.doc["examples"]:
            if "table" in ex:
                yield from self._example_table(ex)
            if "selector" in ex:
                yield from self._example_selector(ex)

    def _example_table(self, ex):
        tags = ["manual-example"] + (["reconstructed"] if ex.get("reconstructed") else [])
        for row in ex["table"]:
            for (pair, (x, y)), printed in zip(ex["pairs"].items(), row["printed"]):
                s1 = self.ops.words(self.ops.values(**ex["values"][x]))
                s2 = self.ops.words(self.ops.values(**ex["values"][y]))
                slug = row["target"].lower().replace(", and ", "+").replace(", ", "+").replace(" and ", "+").replace(" ", "-")
                yield self.case(self.load_form, ex["condition"], f"manual-example/{ex['id']}/{pair}/{slug}",
                                tags=tags, clauses=[ex["clause"]],
                                description=f"{ex['says']} Row '{row['target']}' ({self.selop} = {hexw(row['s3'])}), {pair}.",
                                s1=s1, s2=s2, sel=row["s3"],
                                printed={"result": printed, "table": ex["id"], "row": row["target"], "cell": pair})

    def _example_selector(self, ex):
        compared = ex["compared"]
        # Data equal in the compared fields and different in every masked one; then one compared field differs.
        a = self.ops.values()
        b = {n: (v if n in compared else self.ops.mid(n, 1)) for n, v in a.items()}
        symbol = self.symbol_for("eq")
        yield self.case(self.load_form, symbol, f"manual-example/{ex['id']}/masked-fields-differ",
                        tags=["manual-example"], clauses=[ex["clause"]],
                        description=f"{ex['says']} Only the masked fields differ, so the data are equal.",
                        s1=self.ops.words(a), s2=self.ops.words(b), sel=ex["selector"],
                        printed={"compared": compared})
        for name in compared:
            c = dict(b, **{name: self.ops.mid(name, 1)})
            yield self.case(self.load_form, symbol, f"manual-example/{ex['id']}/{name}-differs",
                            tags=["manual-example"], clauses=[ex["clause"]],
                            description=f"{ex['says']} The compared field {name} differs.",
                            s1=self.ops.words(a), s2=self.ops.words(c), sel=ex["selector"],
                            printed={"compared": compared})

    def orderings(self):
        """Every instruction against every ordering, decided by each field in turn."""
        for (form, symbol), _ in sorted(self.instr.items()):
            for decider, ordering in [(None, "eq")] + [(n, o) for n in self.names for o in ("lt", "gt")]:
                a, b = self.pair_with(decider, ordering)
                key = "ordering/eq" if decider is None else f"ordering/{decider}-{ordering}"
                yield self.case(form, symbol, key, tags=["condition"],
                                description=f"All fields compared; {'the data are equal' if decider is None else f'{self.first} is {ordering} at {decider}, the first field that differs'}.",
                                s1=self.ops.words(a), s2=self.ops.words(b), sel=self.all_fields())

    def forms_and_logic(self):
        """AND and OR forms with the preceding logic on and off, with a true and a false contact."""
        for (form, symbol), _ in sorted(self.instr.items()):
            if self.forms[form]["logic"] == "load":
                continue
            for rlo_in in (True, False):
                for truth in ("eq", "lt", "gt"):
                    a, b = self.pair_with(None if truth == "eq" else self.names[0], truth)
                    yield self.case(form, symbol, f"logic/rlo-{'on' if rlo_in else 'off'}/{truth}",
                                    tags=["logic"], rlo_in=rlo_in,
                                    description=f"Preceding logic {'on' if rlo_in else 'off'}; {self.first} {truth} {self.second}.",
                                    s1=self.ops.words(a), s2=self.ops.words(b), sel=self.all_fields())
                # Invalid data while the preceding logic would make the contact irrelevant.
                bad = self.ops.words(self.ops.values(), raw={self.names[0]: self._invalid_raw(self.fields[0])})
                yield self.case(form, symbol, f"logic/rlo-{'on' if rlo_in else 'off'}/invalid-data",
                                tags=["logic", "invalid-range"], rlo_in=rlo_in,
                                description=f"Preceding logic {'on' if rlo_in else 'off'}; {self.first} holds an invalid {self.names[0]}.",
                                s1=bad, s2=self.ops.words(self.ops.values()), sel=self.all_fields())

    def _invalid_raw(self, f):
        """Raw bits of an invalid value: above the range, or a non-BCD digit for BCD."""
        if f["encoding"] == "bcd":
            return 0xA
        return (f["max"] + 1) & ((1 << f["width"]) - 1)

    def selector_classes(self):
        eq_symbol, lt_symbol, gt_symbol = (self.symbol_for(o) for o in ("eq", "lt", "gt"))
        sources = [False, True] if self.clock_bit else [False]
        # Two data patterns: every field differs with alternating direction; and the top field equal.
        a = self.ops.values()
        b = {n: self.ops.mid(n, 1 if i % 2 else -1) for i, n in enumerate(self.names)}
        c = dict(b, **{self.names[0]: a[self.names[0]]})
        for clock in sources:
            for r in range(1, len(self.names) + 1):
                for subset in itertools.combinations(self.names, r):
                    sel = self.selector(subset, clock)
                    for pattern, other in (("alternating", b), ("top-equal", c)):
                        for symbol in (eq_symbol, lt_symbol, gt_symbol):
                            s2 = self.ops.words(other)
                            clk = other if clock else None
                            yield self.case(self.load_form, symbol, f"selector/{hexw(sel)}/{pattern}",
                                            tags=["selector"] + (["current-clock"] if clock else []),
                                            description=f"{self.selop} = {hexw(sel)} compares {', '.join(subset)}"
                                                        + (" of (s1) with the current clock" if clock else "") + f"; data pattern {pattern}.",
                                            s1=self.ops.words(a), s2=s2, sel=sel, clock=clk)
        yield from self._selector_specials(eq_symbol)

    def _selector_specials(self, eq_symbol):
        equal = self.ops.words(self.ops.values())
        specials = [(self.selector([]), "no field selected")]
        if self.clock_bit:
            specials.append((self.selector([], clock=True), "no field selected, current-clock bit set"))
        for bit in self.sel["reserved_bits"]:
            specials.append((self.selector(self.names, extra=1 << bit), f"all fields and reserved bit {bit}"))
            specials.append((1 << bit, f"reserved bit {bit} alone"))
        specials += [(0xFFFF, "every bit set"), (0x7FFF, "every bit but 15 set")]
        seen = set()
        for value, why in specials:
            if value in seen:  # with mask polarity "all fields + bit" is the bit alone
                continue
            seen.add(value)
            clock = self.ops.values() if self.clock_bit and value >> self.clock_bit["bit"] & 1 else None
            for constant in (False, True):
                yield self.case(self.load_form, eq_symbol, f"selector/{hexw(value)}/equal-data/{'constant' if constant else 'device'}",
                                tags=["selector", "reserved-bit" if "reserved" in why or "every" in why else "zero-selector"],
                                description=f"{self.selop} = {hexw(value)} ({why}), given as a {'constant' if constant else 'word device'}; the data are equal, so only the selector decides.",
                                s1=equal, s2=equal, sel=value, sel_constant=constant, clock=clock)

    def boundaries(self):
        eq_symbol = self.symbol_for("eq")
        for f in self.fields:
            for op in (self.first, self.second):
                for v in signed_boundaries(f):
                    valid = f["min"] <= v <= f["max"]
                    here = self.ops.values(**{f["name"]: v})
                    there = self.ops.values(**({f["name"]: v} if valid else {}))
                    s1, s2 = (here, there) if op == self.first else (there, here)
                    tag = "boundary" if valid else "invalid-range"
                    for which, sel in (("only", self.selector([f["name"]])), ("all", self.all_fields()),
                                       ("others", self.selector([n for n in self.names if n != f["name"]]))):
                        if which == "others" and (valid or len(self.names) == 1):
                            continue
                        yield self.case(self.load_form, eq_symbol, f"boundary/{op}.{f['name']}={v}/{which}",
                                        tags=[tag],
                                        description=f"{op} {f['name']} = {v} ({'inside' if valid else 'outside'} {f['min']}..{f['max']}); "
                                                    f"selected: {'only ' + f['name'] if which == 'only' else 'all fields' if which == 'all' else 'the other fields'}.",
                                        s1=self.ops.words(s1), s2=self.ops.words(s2), sel=sel)
            if f["encoding"] == "bcd":
                yield from self._non_bcd(f, eq_symbol)

    def _non_bcd(self, f, eq_symbol):
        digits = f["width"] // 4
        patterns = sorted({0xA, 0xF, 0xA << 4, 0x1A, 0x9F, (1 << f["width"]) - 1} & set(range(1 << f["width"])))
        for op in (self.first, self.second):
            for raw in patterns:
                words = self.ops.words(self.ops.values(), raw={f["name"]: raw})
                good = self.ops.words(self.ops.values())
                s1, s2 = (words, good) if op == self.first else (good, words)
                for which, sel in (("only", self.selector([f["name"]])), ("others", self.selector([n for n in self.names if n != f["name"]]))):
                    yield self.case(self.load_form, eq_symbol, f"non-bcd/{op}.{f['name']}={raw:0{digits}X}/{which}",
                                    tags=["invalid-bcd"],
                                    description=f"{op} {f['name']} holds {raw:0{digits}X} hex, not a BCD number; "
                                                f"{'it is compared' if which == 'only' else 'it is masked'}.",
                                    s1=s1, s2=s2, sel=sel)

    def nonexistent_dates(self):
        spec = self.doc.get("nonexistent_dates")
        if not spec:
            return
        lt_symbol, eq_symbol = self.symbol_for("lt"), self.symbol_for("eq")
        last = self.names[-1]
        for date in spec["dates"]:
            slug = "-".join(str(date[n]) for n in self.names)
            before = dict(date, **{last: date[last] - 1})
            for symbol, other, rel in ((eq_symbol, date, "itself"), (lt_symbol, before, "the day before")):
                for mine in (self.first, self.second):
                    s1, s2 = (date, other) if mine == self.first else (other, date)
                    yield self.case(self.load_form, symbol, f"nonexistent/{slug}/{mine}/vs-{'same' if other is date else 'previous'}",
                                    tags=["nonexistent-date"], clauses=[spec["clause"]],
                                    description=f"{mine} = {slug}, a date no calendar has, compared with {rel}: in range, so no {self.error_device}.",
                                    s1=self.ops.words(s1), s2=self.ops.words(s2), sel=self.all_fields())

    def device_range(self):
        dr = self.doc["validity"]["device_range"]
        if "clause" not in dr:
            # The page states no check: each operand at the top of its area, and past it where the spec
            # checks it all the same (what an operand past the end does is then an interpretation's).
            yield from self._top_of_area()
            if dr["check"]:
                yield from self._past_area_end()
            return
        eq_symbol = self.symbol_for("eq")
        equal = self.ops.words(self.ops.values())
        for op in (self.first, self.second):
            prefix = split_address(self.place[op])[0]
            size = self.b.sizes[prefix]
            for beyond in (0, 1, 2):
                head = top_head(prefix, size, self.words, beyond)
                # Besides every field: only the fields whose words exist. Then no data check can
                # raise the error, and an implementation that skips the device-range check (reading
                # the missing words as 0, say) is caught even where 0 is an invalid value.
                inside = [f["name"] for f in self.fields if f["word"] < self.words - beyond]
                selections = [(self.names, "")]
                if beyond and inside:
                    selections.append((inside, f"; {self.selop} selects only {', '.join(inside)} (in words that exist)"))
                for clock in ([False, True] if self.clock_bit else [False]):
                    for fields, which in selections:
                        sel = self.selector(fields, clock)
                        yield self.case(self.load_form, eq_symbol, f"device-range/{op}={head}/{hexw(sel)}",
                                        tags=["device-range"] + (["current-clock"] if clock else []),
                                        description=f"{op} at {head}: its {self.words} words {'end at the last' if beyond == 0 else f'run {beyond} past the last'} "
                                                    f"{prefix} device ({prefix}{size - 1}){which}.",
                                        s1=equal[:self.words - beyond] if op == self.first and beyond else equal,
                                        s2=equal[:self.words - beyond] if op == self.second and beyond else equal,
                                        sel=sel, heads={op: head}, clock=self.ops.values() if clock else None)

    def _top_of_area(self):
        """Without a device-range check in the spec: each operand at the top of its area, its last word the
        area's last, the data differing only in the least significant field."""
        s1, s2 = self.pair_with(self.names[-1], "gt")
        symbol = self.symbol_for("gt")
        for op in (self.first, self.second, self.selop):
            prefix = split_address(self.place[op])[0]
            size = self.b.sizes[prefix]
            head = top_head(prefix, size, self.doc["operands"][op].get("words", 1), 0)
            yield self.case(self.load_form, symbol, f"device-range/{op}={head}", tags=["boundary", "device-range"],
                            description=f"{op} at {head}: its last word is the last {prefix} device ({prefix}{size - 1}); "
                                        f"{self.first} is after {self.second} in the {self.names[-1]} alone.",
                            s1=self.ops.words(s1), s2=self.ops.words(s2), sel=self.all_fields(), heads={op: head})

    def _past_area_end(self):
        """Without a device-range check the page states: S1 and S2 at the last one and two words of their
        area, in each form whose logic lets the instruction decide, the data differing in the least
        significant field. An implementation that reads the missing words as anything still finds an
        ordering, and the condition that holds for either ordering shows it."""
        s1, s2 = self.pair_with(self.names[-1], "gt")
        symbol = next(c["symbol"] for c in self.doc["instructions"]["conditions"] if set(c["true_when"]) == {"lt", "gt"})
        for op in (self.first, self.second):
            prefix = split_address(self.place[op])[0]
            size = self.b.sizes[prefix]
            for beyond in (1, 2):
                head = top_head(prefix, size, self.words, beyond)
                words = {self.first: self.ops.words(s1), self.second: self.ops.words(s2)}
                words[op] = words[op][:self.words - beyond]
                for form in self.forms:
                    yield self.case(form, symbol, f"device-range/{op}={head}", tags=["device-range"],
                                    description=f"{op} at {head}, the last {self.words - beyond} of the {prefix} words: {op}+{self.words - beyond} "
                                                f"would be {prefix}{size}, past the last ({prefix}{size - 1}); {self.first} is after "
                                                f"{self.second} in the {self.names[-1]} alone.",
                                    s1=words[self.first], s2=words[self.second], sel=self.all_fields(), heads={op: head})

    def current_clock(self):
        if not self.clock_bit:
            return
        conditions = self.doc["instructions"]["conditions"]
        sel = self.selector(self.names, clock=True)
        dummy = self.ops.words({n: -1 for n in self.names})
        for decider, ordering in [(None, "eq")] + [(n, o) for n in self.names for o in ("lt", "gt")]:
            a, clock = self.pair_with(decider, ordering)
            for c in conditions:
                yield self.case(self.load_form, c["symbol"], f"current-clock/{'eq' if decider is None else decider + '-' + ordering}/dummy-invalid",
                                tags=["current-clock"],
                                description=f"{self.first} against the current clock ({'equal' if decider is None else ordering + ' at ' + decider}); "
                                            f"{self.second} holds invalid dummy data that must be ignored.",
                                s1=self.ops.words(a), s2=dummy, sel=sel, clock=clock)

    def latching(self):
        eq_symbol = self.symbol_for("eq")
        err = self.doc["validity"]["error"]
        good = self.ops.words(self.ops.values())
        bad = self.ops.words(self.ops.values(), raw={self.names[0]: self._invalid_raw(self.fields[0])})
        head = self.place[self.first]
        sel = self.all_fields()
        fixed = {a: w for a, w in zip([f"{split_address(head)[0]}{split_address(head)[1] + k}" for k in range(self.words)], good)}
        steps = [{}, {"set": fixed}, {"set": {err["device"]: False}}]
        yield self.case(self.load_form, eq_symbol, "latch/invalid-then-valid-then-cleared",
                        tags=["latch", "invalid-range"],
                        description=f"Invalid data, then valid data, then the program turns {err['device']} off: "
                                    "whether it stays on until cleared is the spec's latch rule for this flag.",
                        s1=bad, s2=good, sel=sel, steps=steps)
        yield self.case(self.load_form, eq_symbol, "latch/already-on-valid-data",
                        tags=["latch"], extra_devices={err["device"]: True},
                        description=f"{err['device']} is already on and the data are valid: {self._latch_text(err)}.",
                        s1=good, s2=good, sel=sel)

    def _latch_text(self, err):
        """What a normal execution does to the error flag already on, under the default reading."""
        latch = err.get("latch", True)
        if not isinstance(latch, dict):
            return "a normal execution leaves it as it is" if latch else "a normal execution turns it off"
        interp = self.fam.interpretations[latch["interpretation"]]
        default = next(a for a in interp["alternatives"] if a["id"] == interp["default"])
        done = "leaves it as it is" if default["sets"]["latch"] else "turns it off"
        return f"a normal execution {done} (the default of {interp['id']})"

    def clock_area(self):
        area = self.doc.get("clock_area")
        if not area:
            return
        eq_symbol = self.symbol_for("eq")
        lt_symbol = self.symbol_for("lt")
        now = self.ops.values()
        for symbol, other, rel in ((eq_symbol, now, "equal to"), (lt_symbol, self.pair_with(self.names[0], "lt")[1], "before")):
            yield self.case(self.load_form, symbol, f"clock-area/{'equal' if other is now else 'before'}",
                            tags=["current-clock"], clauses=[area["clause"]], heads={self.first: area["words"][0]},
                            description=f"{self.first} is the calendar/clock area {area['words'][0]} (present time), {rel} {self.second}.",
                            s1=self.ops.words(now), s2=self.ops.words(other), sel=self.all_fields())

    # -- the coverage model's rows -----------------------------------------------------------------
    def selector_of(self, cls, clock):
        """A selector word of the class `cls` (plcvec.coverage.compare_cells.selector_classes)."""
        names, reserved = self.names, self.sel["reserved_bits"]
        if cls == "reserved":   # the reserved bit and no field bit (with mask polarity: every field compared)
            return (1 << reserved[0]) | ((1 << self.clock_bit["bit"]) if clock else 0)
        if cls == "reserved+fields":
            return self.selector(names[:1], clock, extra=1 << reserved[-1])
        chosen = {"all": names, "none": [], "some": names[::2][:2]}.get(cls)
        if chosen is None:
            chosen = [n for n in names if n != cls[len("all-but-"):]] if cls.startswith("all-but-") else cls.split("+")
        return self.selector(chosen, clock)

    def from_row(self, row, key):
        """The vector of one row of the coverage model: {derivation: class}, or None if it cannot be built."""
        clock = row.get("source-bit") == "current-clock"
        sel = self.selector_of(row["selector-classes"], clock)
        want = 1 if self.sel["polarity"] == "select" else 0
        chosen = [n for n in self.names if (sel >> self.sel["field_bits"][n] & 1) == want]
        data = row.get("data-validity", "valid")
        owner, bad_field, kind = (data.split(".") + [None, None])[:3] if data.count(".") == 2 else (None, None, None)
        ordering = row.get("orderings", "eq")
        deciders = [n for n in chosen if n != bad_field] or chosen
        a, b = self.pair_with(deciders[0] if deciders and ordering in ("lt", "gt") else None,
                              ordering if ordering in ("lt", "gt") else "eq")
        if data == "nonexistent":
            date = self.doc["nonexistent_dates"]["dates"][0]
            shift = {n: b[n] - a[n] for n in self.names}
            a = dict(date)
            b = {n: min(max(date[n] + shift[n], f["min"]), f["max"]) for n, f in zip(self.names, self.fields)}
        s1, s2 = self.ops.words(a), self.ops.words(b)
        heads = {}
        if owner is not None:
            f = self.ops.by_name[bad_field]
            raw = {"below": f["min"] - 1, "above": f["max"] + 1}.get(kind)
            if f["encoding"] == "bcd":
                raw = self._invalid_raw(f) if raw is None else self.ops.codec.pack({bad_field: raw})[f["word"]] >> f["lsb"]
            target = a if owner == self.first else b
            words = self.ops.words(target, raw={bad_field: raw})
            if owner == self.first:
                s1 = words
            else:
                s2 = words
        elif data.endswith(".device-range"):
            op = data.split(".")[0]
            prefix = split_address(self.place[op])[0]
            heads[op] = top_head(prefix, self.b.sizes[prefix], self.words, 1)
            if op == self.first:
                s1 = s1[:self.words - 1]
            else:
                s2 = s2[:self.words - 1]
        logic = row.get("preceding-logic")
        form = row["forms"]
        extra = {self.error_device: row.get("error-device") == "on"}
        return self.case(form, row["conditions"], key, tags=["model"] + (["current-clock"] if clock else []),
                         description=f"Coverage model row: {', '.join(f'{k} {v}' for k, v in row.items() if v is not None)}.",
                         s1=s1, s2=s2, sel=sel, clock=b if clock else None, heads=heads, extra_devices=extra,
                         rlo_in=None if logic is None else logic == "on")

    def random(self):
        gen = self.doc["generation"]
        for draw in draw_compare(self, gen["seed"], gen["random_examples"]):
            yield self.case(draw["form"], draw["symbol"], f"random/{draw['key']}", tags=["random"],
                            description="Drawn from the spec's ranges with the spec's seed.",
                            s1=draw["s1"], s2=draw["s2"], sel=draw["sel"], clock=draw["clock"], rlo_in=draw["rlo_in"])


def masked_compare_cases(fam, builder):
    c = CompareCases(fam, builder)
    vectors = []
    # The forms and their logic before the orderings: of a test both build (an AND or OR form whose logic
    # lets its own comparison decide), the vector kept is the one named for its form and logic.
    for family in (c.manual_examples, c.forms_and_logic, c.orderings, c.selector_classes, c.boundaries,
                   c.nonexistent_dates, c.device_range, c.current_clock, c.latching, c.clock_area, c.random):
        vectors += family()
    return vectors + model_cases(builder, vectors, c.from_row, ("forms", "conditions"))
