"""Drawing fuzz cases, and building each into a full vector with the spec engine.

The strategies draw what the golden random cases draw (fuzz/strategies.py), widened the way a fixed set
cannot be: fully valid data and data around and past the ranges side by side, raw words no value
encodes, the spec's nonexistent dates, reserved selector bits, constants, operands at the top of their
device range, flags already on, and sequences of scans (latching, the pulse form, HOUR with its
preset changed on the way). Independent draws almost never hit a tie or an exact boundary of a sum,
so some draws are tied to others: fields of (s2) equal to those of (s1), an addition that lands next
to the wrap of its top field, an hour meter that starts just below its preset.

A drawn case is a plain JSON-able dict; the case builders of cases/ turn it into a vector, so its
expectations, alternatives and clauses are exactly what `plcvec generate` gives the same case. The
order of a `one_of`'s branches and of a case's keys is the shrinker's order of preference: valid data
first, plain operands before the current clock, no device-range edge unless it is what differs.
"""
from hypothesis import strategies as st

from plcvec.cases.build import VectorBuilder
from plcvec.cases.clock_add_cases import AddCases
from plcvec.cases.common import top_head
from plcvec.cases.hour_meter_cases import HourCases
from plcvec.cases.masked_compare_cases import CompareCases
from plcvec.cases.random_cases import compare_case, key_of
from plcvec.engine.words import operand_words, split_address
from plcvec.fuzz.strategies import around_range, compare_parts, field_values, hour_meter_step, in_range

TAG = "fuzz"
DESCRIPTION = ("Drawn by `plcvec fuzz` from the spec's ranges and past them: the minimal case of a disagreement "
               "between an implementation and the spec, shrunk by hypothesis.")
MAX_SCANS = 6
TOP_BEYOND = 2   # how many words an operand may run past the end of its device range


def _outside(fields, values):
    return any(not f["min"] <= values[f["name"]] <= f["max"] for f in fields)


def _raw_bits(fields):
    """Some fields (any, none or all) given as raw bits of their width, whatever they encode."""
    return st.fixed_dictionaries({}, optional={f["name"]: st.integers(0, (1 << f["width"]) - 1) for f in fields})


def _sometimes(strategy, odds):
    """None, or a draw of `strategy` about once in `odds` cases: for what, drawn every other time, would
    hide everything else behind the error it raises."""
    return st.one_of(*[st.none()] * (odds - 1), strategy)


def _top(operands):
    """None, or (operand, words past the end): an operand placed at the top of its device range."""
    return _sometimes(st.tuples(st.sampled_from(operands), st.integers(0, TOP_BEYOND)), 4)


class _Drawer:
    """One family: the strategy of its cases and how a drawn case becomes a vector."""

    def __init__(self, fam, instructions):
        self.fam = fam
        self.builder = VectorBuilder(fam)
        # The manual's order (LD before AND/OR, = first): the shrinker prefers the first.
        self.instructions = [name for name in self.builder.instructions if name in instructions]

    def vector(self, case):
        # Every example is a vector of its own; the builder's duplicate-id guard is for the golden set.
        self.builder.ids.clear()
        return self.build(case, f"fuzz/{key_of(case)}")

    def top_head(self, operand, words, beyond):
        prefix = split_address(self.cases.place[operand])[0]
        return top_head(prefix, self.builder.sizes[prefix], words, beyond)


class CompareDrawer(_Drawer):
    def __init__(self, fam, instructions):
        super().__init__(fam, instructions)
        self.cases = c = CompareCases(fam, self.builder)
        self.reserved = sum(1 << b for b in c.sel["reserved_bits"])
        self.dates = list((fam.doc.get("nonexistent_dates") or {}).get("dates", []))
        self.constant_selector = bool(fam.doc["operands"][c.selop].get("constant"))
        # Operands are drawn past their device range where the page states the check (a clause, FX5). CP1E
        # checks its data area only to say what an operand past it does (CP1E-PAST-AREA-END, a reading the
        # golden vectors hold for each operand, head and form); drawing it would also move every other
        # family's seeded draws, and with them the cases the shrink tests of tests/test_fuzz.py expect.
        self.range_checked = "clause" in fam.doc["validity"]["device_range"]

    def strategy(self):
        c = self.cases
        parts = compare_parts(c)
        del parts["form"], parts["symbol"]  # drawn as one instruction, among those asked for
        for side in ("a", "b"):
            parts[side] = st.one_of(in_range(c.fields), parts[side], *([st.sampled_from(self.dates)] if self.dates else []))
        return st.fixed_dictionaries({
            # The selector before the data, so that the shrinker simplifies it first: a minimal case
            # compares with (s2) rather than the current clock unless the clock is what differs.
            "instruction": st.sampled_from(self.instructions), "sel": parts.pop("sel"), **parts,
            "tie": st.fixed_dictionaries({}, optional={n: st.just(True) for n in c.names}),  # (s2) fields equal to (s1)'s
            "raw": _sometimes(st.tuples(st.sampled_from(["a", "b"]), _raw_bits(c.fields)), 3),
            "sel_constant": st.booleans() if self.constant_selector else st.just(False),
            "flag_on": st.booleans(),
            # Further scans with the same inputs; True: the program turns the error flag off before it.
            "again": st.lists(st.booleans(), max_size=2),
            "top": _top([c.first, c.second]) if self.range_checked else st.none(),
        })

    def build(self, case, key):
        c = self.cases
        ins = self.builder.instructions[case["instruction"]]
        form, symbol = ins["form"]["form"], ins["symbol"]
        b = dict(case["b"], **{n: case["a"][n] for n in case["tie"]})
        d = compare_case(c, dict(case, form=form, symbol=symbol, b=b), raw=dict([case["raw"]] if case["raw"] else []))
        words, heads = {c.first: d["s1"], c.second: d["s2"]}, {}
        if case["top"]:
            op, beyond = case["top"]
            heads[op] = self.top_head(op, c.words, beyond)
            words[op] = words[op][:c.words - beyond]  # the words past the end do not exist
        step = c.step_for(form, rlo_in=d["rlo_in"])
        if d["clock"] is not None:
            step["clock"] = d["clock"]
        steps = [step] + [dict(step, set={c.error_device: False}) if clear else dict(step) for clear in case["again"]]
        tags = {TAG}
        if _outside(c.fields, case["a"]) or _outside(c.fields, b) or (case["raw"] and case["raw"][1]):
            tags.add("invalid-range")
        if case["a"] in self.dates or b in self.dates:
            tags.add("nonexistent-date")
        if d["clock"] is not None:
            tags.add("current-clock")
        if case["sel"] & self.reserved:
            tags.add("reserved-bit")
        if case["sel_constant"]:
            tags.add("constant")
        if case["flag_on"] or case["again"]:
            tags.add("latch")
        if c.forms[form]["logic"] != "load":
            tags.add("logic")
        if heads:
            tags.add("device-range")
        return c.case(form, symbol, key, tags=sorted(tags), description=DESCRIPTION, s1=words[c.first],
                      s2=words[c.second], sel=d["sel"], sel_constant=case["sel_constant"], steps=steps, heads=heads,
                      extra_devices={c.error_device: True} if case["flag_on"] else None)


class AddDrawer(_Drawer):
    def __init__(self, fam, instructions):
        super().__init__(fam, instructions)
        self.cases = AddCases(fam, self.builder)

    def strategy(self):
        c = self.cases
        values = st.one_of(in_range(c.fields), around_range(c.fields))
        return st.fixed_dictionaries({
            "instruction": st.sampled_from(self.instructions),
            **{op: values for op in c.addends},
            # The second addend made to bring the sum this many units of the last field from the wrap.
            "wrap": st.one_of(st.none(), st.integers(-1, 1)),
            "en": st.lists(st.booleans(), min_size=1, max_size=MAX_SCANS),
            "flags_on": st.booleans(),
            # The destination on top of an addend: each execution then adds to its own last result.
            "same": st.sampled_from([None] + c.addends),
            "top": _top(c.addends + [c.result]),
        })

    def build(self, case, key):
        c = self.cases
        first, second = c.addends
        values = {op: case[op] for op in c.addends}
        codec = c.ops.codec
        if case["wrap"] is not None and not _outside(c.fields, values[first]):
            values[second] = codec.from_units((codec.modulus() - codec.to_units(values[first]) + case["wrap"]) % codec.modulus())
        heads = {c.result: c.place[case["same"]]} if case["same"] else {}
        if case["top"]:
            op, beyond = case["top"]
            heads[op] = self.top_head(op, c.words, beyond)
        tags = {TAG}
        if any(_outside(c.fields, v) for v in values.values()):
            tags.add("invalid-range")
        if case["wrap"] is not None:
            tags.add("wrap")
        if len(case["en"]) > 1:
            tags.add("pulse")
        if heads.get(c.result) in (heads.get(op, c.place[op]) for op in c.addends):
            tags.add("same-device")
        if case["top"]:
            tags.add("device-range")
        return c.case(case["instruction"], key, tags=sorted(tags), description=DESCRIPTION, values=values,
                      heads=heads, steps=[{"en": en} for en in case["en"]], flags_on=case["flags_on"])


class HourDrawer(_Drawer):
    def __init__(self, fam, instructions):
        super().__init__(fam, instructions)
        self.cases = HourCases(fam, self.builder)
        self.constant = bool(fam.doc["operands"][self.cases.preset].get("constant"))

    def strategy(self):
        c = self.cases
        presets = [in_range(c.fields), around_range(c.fields)]
        if self.constant:
            presets.append(field_values(c.ops.by_name[c.cf]))
        return st.fixed_dictionaries({
            "preset": st.one_of(presets),
            "measured": in_range(c.fields),
            # D1 made to start this many seconds below the preset.
            "below": st.one_of(st.none(), st.integers(0, 2)),
            "output": st.booleans(),
            "error": st.booleans(),
            # Each scan, and the preset the program writes before it (None: unchanged).
            "steps": st.lists(st.tuples(hour_meter_step(), st.one_of(st.none(), around_range(c.fields))),
                              min_size=1, max_size=MAX_SCANS),
        })

    def build(self, case, key):
        c = self.cases
        constant = isinstance(case["preset"], int)
        preset = {n: (case["preset"] if n == c.cf else 0) for n in c.names} if constant else case["preset"]
        measured = case["measured"]
        if case["below"] is not None and not _outside(c.fields, preset):
            total = c.ops.codec.to_units(preset) - case["below"]
            measured = c.ops.codec.from_units(total) if total >= 0 else measured
        preset_words = operand_words(c.place[c.preset], c.words[c.preset])
        steps, written = [], []
        for step, new in case["steps"]:
            step = dict(step)
            if new is not None and not constant:
                step["set"] = dict(zip(preset_words, c.ops.words(new)))
                written.append(new)
            steps.append(step)
        tags = {TAG}
        if constant:
            tags.add("constant")
        if any(_outside(c.fields, p) for p in written + [preset]):
            tags.add("invalid-range")
        if not any(preset.values()):
            tags.add("zero-preset")
        if len(steps) > 1:
            tags.add("scan-sequence")
        if not all(s["input"] for s in steps):
            tags.add("input-off")
        if any(s["elapsed_ms"] % c.unit for s in steps):
            tags.add("subsecond")
        return c.case(key, tags=sorted(tags), description=DESCRIPTION, preset=case["preset"],
                      measured=measured, steps=steps, output=case["output"], error=case["error"])


DRAWERS = {"masked_compare": CompareDrawer, "clock_add": AddDrawer, "hour_meter": HourDrawer}


class Space:
    """Everything `plcvec fuzz` draws from: the asked-for instructions of each family.

    A case is (family name, drawn dict); `vector(case)` builds it.
    """

    def __init__(self, families, instructions):
        """`instructions`: {family name: the instruction names to draw}; families without any are left out."""
        self.drawers = {fam.name: DRAWERS[fam.kind](fam, instructions[fam.name])
                        for fam in families if instructions.get(fam.name)}
        self.families = {fam.name: fam for fam in families if fam.name in self.drawers}
        self.strategy = st.one_of([st.tuples(st.just(name), drawer.strategy()) for name, drawer in self.drawers.items()])

    def vector(self, case):
        family, drawn = case
        return self.drawers[family].vector(drawn)
