"""Put one execution to the spec engine, the same way the vectors are made.

The audit computes no expected value of its own: every printed cell is run through
VectorBuilder.run (the engine under the spec's interpretations), with the operand placement,
the devices the instruction writes and the instruction names that the case families use.
"""
from plcvec.cases.build import VectorBuilder
from plcvec.cases.clock_add_cases import AddCases
from plcvec.cases.masked_compare_cases import CompareCases
from plcvec.engine.words import operand_words
from plcvec.errors import PlcvecError


class AuditError(PlcvecError):
    """The audit cannot vouch for its answer (the spec's rules break an assumption of the search)."""


def reading(fam, where, choices):
    """The default choice of every interpretation, with `choices` (interpretation -> alternative) over it."""
    out = fam.default_choices()
    for iid, alt in choices.items():
        interp = fam.interpretations.get(iid)
        if interp is None:
            raise fam.error(where + (iid,), f"unknown interpretation {iid!r}")
        if alt not in [a["id"] for a in interp["alternatives"]]:
            raise fam.error(where + (iid,), f"interpretation {iid!r} has no alternative {alt!r}")
        out[iid] = alt
    return out


class CompareProbe:
    """One execution of the load form of a masked comparison on two sets of field values."""

    def __init__(self, fam):
        self.fam = fam
        self.builder = VectorBuilder(fam)
        self.c = CompareCases(fam, self.builder)
        self.fields = self.c.fields
        self.choices = fam.default_choices()
        self.eq_symbol = self.c.symbol_for("eq")
        self._compared = {}

    def contact(self, symbol, selector, first, second):
        """(contact state, error) of the condition `symbol` for (s1) = first and (s2) = second.

        With the current-clock bit set in `selector`, `second` is the clock the step injects.
        """
        c = self.c
        devices = c.outputs()
        c.ops.place(devices, c.place[c.first], c.ops.words(c.ops.values(**first)))
        c.ops.place(devices, c.place[c.second], c.ops.words(c.ops.values(**second)))
        devices[c.place[c.selop]] = selector & 0xFFFF
        step = {}
        if c.clock_bit and selector >> c.clock_bit["bit"] & 1:
            step["clock"] = c.ops.values(**second)
        operands = {name: {"device": c.place[name]} for name in (c.first, c.second, c.selop)}
        instr = self.builder.instructions[c.instr[(c.load_form, symbol)]]
        expects, _, outcome, _ = self.builder.run(instr, operands, devices, [step], (), self.choices)
        return expects[0]["result"], outcome["category"] == "error"

    def compared_fields(self, selector):
        """The fields `selector` puts in the comparison: those whose change alone makes "=" false.

        None when the comparison gives non-continuity even for equal data (nothing is compared).
        """
        if selector not in self._compared:
            base = self.c.ops.values()
            same, error = self.contact(self.eq_symbol, selector, base, base)
            if not same or error:
                self._compared[selector] = None
            else:
                compared = []
                for f in self.fields:
                    other = dict(base, **{f["name"]: self.c.ops.mid(f["name"], 1)})
                    equal, error = self.contact(self.eq_symbol, selector, base, other)
                    if error:  # an error is no answer to "is this field compared?"
                        raise AuditError(f"{self.fam.path}: {self.c.selop} = {selector:#06x} gives an error for "
                                         f"in-range data differing in {f['name']}")
                    if not equal:
                        compared.append(f["name"])
                self._compared[selector] = compared
        return self._compared[selector]


class AddProbe:
    """One execution of the every-scan form of a clock addition."""

    def __init__(self, fam):
        self.fam = fam
        self.builder = VectorBuilder(fam)
        self.c = AddCases(fam, self.builder)
        flags = fam.doc["flags"]
        # The flags the manual names with devices (carry, zero), by the spec's own names.
        self.flags = {name: cfg["devices"] for name, cfg in flags.items() if isinstance(cfg, dict) and "devices" in cfg}

    def run(self, values, heads=None, choices=None):
        """{result operand: field values, flag name: on/off, "error": code or None} for addends `values`."""
        c = self.c
        heads = dict(c.place, **(heads or {}))
        devices = {d: False for d in c.flag_devices}
        devices.update({r: 0 for r in c.registers})
        for op in c.addends + [c.result]:
            # (d) starts with words no valid result holds, as in the vectors, so an unwritten (d) shows.
            words = c.ops.words(values[op]) if op in c.addends else [0xFFFF] * c.words
            for address, word in zip(operand_words(heads[op], c.words), words):
                devices[address] = word & 0xFFFF
        operands = {op: {"device": heads[op]} for op in c.addends + [c.result]}
        instr = self.builder.instructions[c.every_scan]
        _, final, outcome, _ = self.builder.run(instr, operands, devices, [{"en": True}], (),
                                                choices or self.fam.default_choices())
        out = {c.result: c.ops.codec.read(final, heads[c.result])}
        for name, flag_devices in self.flags.items():
            states = {final[d] for d in flag_devices}
            out[name] = states.pop() if len(states) == 1 else None  # None: the devices of one flag disagree
        errors = outcome.get("errors", [])
        out["error"] = errors[0].get("code") if errors else None
        return out
