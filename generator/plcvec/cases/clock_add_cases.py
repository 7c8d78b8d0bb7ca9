"""Cases for `clock_add` families: the manual's examples, carries at every field, zero, the flags,
each range error of each field of each operand, device range at the top, source = destination,
and the pulse form over a sequence of scans."""
from plcvec.cases.common import Operands, signed_boundaries, top_head
from plcvec.cases.model_cases import model_cases
from plcvec.cases.random_cases import draw_addition
from plcvec.engine.words import operand_words, split_address


class AddCases:
    def __init__(self, fam, builder):
        self.fam, self.b, self.doc = fam, builder, fam.doc
        self.fields = self.doc["data"]["fields"]
        self.names = [f["name"] for f in self.fields]
        self.ops = Operands(self.fields)
        self.place = self.doc["generation"]["placement"]
        self.addends = [k for k, v in self.doc["operands"].items() if v["role"] == "addend"]
        self.result = next(k for k, v in self.doc["operands"].items() if v["role"] == "result")
        self.words = self.doc["operands"][self.result]["words"]
        flags = self.doc["flags"]
        self.flag_devices = flags["carry"]["devices"] + flags["zero"]["devices"]
        self.registers = self.doc["errors"]["registers"]["devices"]
        by_exec = {i["execution"]: i["name"] for i in builder.instructions.values()}
        self.every_scan, self.pulse_form = by_exec.get("every_scan"), by_exec.get("rising_edge")

    def case(self, instr, key, *, tags, description, values, heads=None, steps=None, flags_on=False,
             clauses=(), printed=None, result_initial=None, registers_before=0):
        heads = dict(self.place, **(heads or {}))
        devices = {d: flags_on for d in self.flag_devices}
        devices.update({r: registers_before for r in self.registers})
        for op in self.addends + [self.result]:
            if op == self.result:
                # (d) starts with words no valid result holds, so an unwritten (d) shows.
                words = result_initial or [0xFFFF] * self.words
            else:
                words = self.ops.words(values[op])
            for address, word in zip(operand_words(heads[op], self.words), words):
                prefix, number = split_address(address)
                if number < self.b.sizes.get(prefix, number + 1):  # words past the range do not exist
                    devices.setdefault(address, word & 0xFFFF)
        operands = {op: {"device": heads[op]} for op in self.addends + [self.result]}
        return self.b.vector(instr, key, tags=tags, description=description, operands=operands, devices=devices,
                             steps=steps or [{"en": True}], clauses=clauses, printed=printed)

    def hms(self, values):
        return ":".join(f"{values[n]:02d}" for n in self.names)

    def manual_examples(self):
        for ex in self.doc["examples"]:
            heads = ex.get("devices")
            values = {self.addends[0]: ex["s1"], self.addends[1]: ex["s2"]}
            yield self.case(self.every_scan, f"manual-example/{ex['id']}", tags=["manual-example"], clauses=[ex["clause"]],
                            description=f"{self.hms(ex['s1'])} + {self.hms(ex['s2'])} (manual example {ex['id']}).",
                            values=values, heads=heads, printed=ex["printed"])

    def carries(self):
        """A carry out of each field into the next, the wrap of the top field, and the zero result."""
        top = self.fields[0]
        patterns = []
        for i, f in enumerate(self.fields):
            a = {n: 0 for n in self.names}
            b = {n: 0 for n in self.names}
            a[f["name"]], b[f["name"]] = f["max"], 1
            patterns.append((f"carry-out-of-{f['name']}", a, b))
            maxed = {g["name"]: g["max"] for g in self.fields[i:]}
            patterns.append((f"ripple-from-{f['name']}", dict(a, **maxed), b))
        zero = {n: 0 for n in self.names}
        half = dict(zero, **{top["name"]: (top["max"] + 1) // 2})
        just = dict(zero, **{top["name"]: top["max"]})
        one_top = dict(zero, **{top["name"]: 1})
        maxall = {f["name"]: f["max"] for f in self.fields}
        patterns += [("exact-wrap-halves", half, half), ("exact-wrap-top", just, one_top), ("zero-plus-zero", zero, zero),
                     ("max-plus-max", maxall, maxall), ("max-plus-zero", maxall, zero), ("below-wrap", just, zero)]
        for name, a, b in patterns:
            for flags_on in (False, True):
                values = {self.addends[0]: a, self.addends[1]: b}
                yield self.case(self.every_scan, f"carry/{name}/flags-{'on' if flags_on else 'off'}-before", tags=["wrap", "boundary"],
                                description=f"{self.hms(a)} + {self.hms(b)}, flags {'on' if flags_on else 'off'} before the execution.",
                                values=values, flags_on=flags_on)

    def range_errors(self):
        for op in self.addends:
            for f in self.fields:
                for v in signed_boundaries(f):
                    values = {o: self.ops.values() for o in self.addends}
                    values[op] = self.ops.values(**{f["name"]: v})
                    valid = f["min"] <= v <= f["max"]
                    yield self.case(self.every_scan, f"range/{op}.{f['name']}={v}", tags=["boundary" if valid else "invalid-range"],
                                    description=f"{op} {f['name']} = {v} ({'inside' if valid else 'outside'} {f['min']}..{f['max']}).",
                                    values=values, flags_on=True)

    def device_range(self):
        values = {o: self.ops.values() for o in self.addends}
        for op in self.addends + [self.result]:
            prefix = split_address(self.place[op])[0]
            size = self.b.sizes[prefix]
            for beyond in (0, 1, 2):
                head = top_head(prefix, size, self.words, beyond)
                yield self.case(self.every_scan, f"device-range/{op}={head}", tags=["device-range"],
                                description=f"{op} at {head}: its words {'end at the last' if beyond == 0 else f'run {beyond} past the last'} {prefix} device.",
                                values=values, heads={op: head})

    def both_errors(self):
        """Both error conditions in one execution: a readable (s1) or (s2) with a field out of range while
        another operand runs past its device range (which code is stored is TADD-ERROR-ORDER)."""
        s1, s2 = self.addends
        hour, minute, second = self.fields[0], self.fields[1], self.fields[-1]
        for bad_op, f, value, past_op, beyond in ((s1, hour, hour["max"] + 1, self.result, 1),
                                                  (s2, minute, minute["max"] + 1, s1, 2),
                                                  (s1, second, second["min"] - 1, s2, 1)):
            values = {o: self.ops.values() for o in self.addends}
            values[bad_op] = self.ops.values(**{f["name"]: value})
            prefix = split_address(self.place[past_op])[0]
            head = top_head(prefix, self.b.sizes[prefix], self.words, beyond)
            yield self.case(self.every_scan, f"both-errors/{bad_op}.{f['name']}={value}/{past_op}={head}",
                            tags=["invalid-range", "device-range"], values=values, heads={past_op: head}, flags_on=True,
                            description=f"{bad_op} {f['name']} = {value} (outside {f['min']}..{f['max']}) while {past_op} at {head} "
                                        f"runs {beyond} past the last {prefix} device: both error conditions in one execution.")

    def registers_after_success(self):
        """The error registers holding each code from an earlier error: an execution without error stores
        no code, so they keep it."""
        for check in self.doc["errors"]["checks"]:
            code = check["code"]
            yield self.case(self.every_scan, f"error-registers/{code:04X}H-before/valid", tags=["boundary"],
                            values={o: self.ops.values() for o in self.addends}, registers_before=code,
                            clauses=[self.doc["errors"]["registers"]["clause"]],
                            description=f"{', '.join(self.registers)} hold {code:04X}H from an earlier error; a valid addition "
                                        "stores no error code, so they keep it.")

    def same_device(self):
        """(s1) and (d) the same device: TADD adds again every scan, TADDP once per rising edge."""
        s1, s2 = self.addends
        step = {n: 0 for n in self.names}
        step[self.names[-1]] = 1
        start = self.ops.values()
        for instr in (self.every_scan, self.pulse_form):
            steps = [{"en": True}, {"en": True}, {"en": False}, {"en": True}]
            heads = {self.result: self.place[s1]}
            yield self.case(instr, "same-device/s1-is-d", tags=["same-device", "pulse"],
                            description=f"(s1) and (d) are both {self.place[s1]}; EN on, on, off, on.",
                            values={s1: start, s2: step}, heads=heads, steps=steps, result_initial=self.ops.words(start))

    def overlap(self):
        """(d) one or two words from (s1) or (s2): whether a source word is read before or after (d)'s word at
        the same device is written is TADD-OVERLAP. (s1) holds the middle of each range (one more below the
        top field), (s2) two thirds of each: their sum carries out of every field and wraps, so a source word
        read after (d) wrote it changes the result."""
        start = self.ops.values()
        values = {self.addends[0]: dict(start, **{n: start[n] + 1 for n in self.names[1:]}),
                  self.addends[1]: {n: f["max"] * 2 // 3 for n, f in zip(self.names, self.fields)}}
        for op in self.addends:
            prefix, at = split_address(self.place[op])
            for shift in (-2, -1, 1, 2):
                heads = {self.result: f"{prefix}{at + shift}"}
                yield self.case(self.every_scan, f"overlap/d={op}{shift:+d}", tags=["overlap"], values=values, heads=heads,
                                description=f"(d) at {heads[self.result]}, {op}{shift:+d}: {abs(shift)} of their words are the same "
                                            f"devices; {self.hms(values[self.addends[0]])} + {self.hms(values[self.addends[1]])}.")

    def pulse(self):
        s1, s2 = self.addends
        seq = [False, True, True, False, True, True]
        a = self.ops.values()
        for instr in (self.every_scan, self.pulse_form):
            steps = []
            for i, en in enumerate(seq):
                # Change (s2) before every scan, so each execution leaves its own trace in (d).
                b = {n: 0 for n in self.names}
                b[self.names[-1]] = i + 1
                steps.append({"set": dict(zip(operand_words(self.place[s2], self.words), self.ops.words(b))), "en": en})
            yield self.case(instr, "pulse/off-on-on-off-on-on", tags=["pulse"],
                            description="EN off, on, on, off, on, on, with (s2) changed before every scan.",
                            values={s1: a, s2: {n: 0 for n in self.names}}, steps=steps)
            yield self.case(instr, "pulse/en-off", tags=["pulse"], description="EN stays off: nothing is written.",
                            values={s1: a, s2: a}, steps=[{"en": False}], flags_on=True,
                            clauses=[self.b.instructions[instr]["clause"]])

    # -- the coverage model's rows -----------------------------------------------------------------
    def sum_values(self, where, same):
        """Addends whose sum falls `where` against the wrap (plcvec.coverage.add_cells.sum_classes);
        with `same` both addends are one device, so they are equal."""
        zero = {n: 0 for n in self.names}
        top = self.fields[0]
        half = dict(zero, **{top["name"]: (top["max"] + 1) // 2})
        maxall = {f["name"]: f["max"] for f in self.fields}
        one = dict(zero, **{self.names[-1]: 1})
        pairs = {"zero": (zero, zero), "exact-wrap": (half, half), "above-wrap": (maxall, maxall),
                 "below-wrap": (one, one) if same else (self.ops.values(), one)}
        return pairs.get(where, (self.ops.values(), self.ops.values()) if not same else (one, one))

    def from_row(self, row, key):
        """The vector of one row of the coverage model: {derivation: class}."""
        s1, s2 = self.addends
        alias = row.get("aliasing", "distinct")
        a, b = self.sum_values(row.get("sum"), alias == f"{s1}={s2}")
        values = {s1: dict(a), s2: dict(b)}
        heads, initial = {}, None
        data = row.get("data-validity", "valid")
        if data.endswith(".device-range"):
            op = data.split(".")[0]
            prefix = split_address(self.place[op])[0]
            heads[op] = top_head(prefix, self.b.sizes[prefix], self.words, 1)
        elif data != "valid":
            op, name, kind = data.split(".")
            f = self.ops.by_name[name]
            codec, total = self.ops.codec, sum(self.ops.codec.to_units(v) for v in values.values())
            values[op][name] = f["min"] - 1 if kind == "below" else f["max"] + 1
            # Under the reading that still adds (TADD-ON-ERROR), keep the sum the row asks for: the
            # other addend makes up the difference, where a valid value can.
            other = s2 if op == s1 else s1
            rest = total - codec.to_units(values[op])
            if alias == "distinct" and 0 <= rest < codec.modulus():
                values[other] = codec.from_units(rest)
        if "-overlaps-" in alias:
            # (d) one word after the addend (or the addend one before (d), when (d) is the operand placed at
            # the top of its device range): two of their words are the same devices.
            _, op = alias.split("-overlaps-")
            if self.result in heads:
                prefix, at = split_address(heads[self.result])
                heads[op] = f"{prefix}{at - 1}"
            else:
                prefix, at = split_address(heads.get(op, self.place[op]))
                heads[self.result] = f"{prefix}{at + 1}"
        elif alias != "distinct":
            first, second = alias.split("=")
            heads[second] = heads.get(first, self.place[first])
            if second == self.result:
                initial = self.ops.words(values[first])
        en = row.get("execution-condition", "rising")
        steps = {"rising": [{"en": True}], "held": [{"en": True}, {"en": True}], "off": [{"en": False}]}[en]
        return self.case(row["instructions"], key, tags=["model"], values=values, heads=heads, steps=steps,
                         flags_on=row.get("flags-before") == "on", result_initial=initial,
                         description=f"Coverage model row: {', '.join(f'{k} {v}' for k, v in row.items() if v is not None)}.")

    def random(self):
        gen = self.doc["generation"]
        for d in draw_addition(self.fields, gen["seed"], gen["random_examples"]):
            yield self.case(self.every_scan, f"random/{d['key']}", tags=["random"],
                            description=f"{self.hms(d['s1'])} + {self.hms(d['s2'])}, drawn with the spec's seed.",
                            values={self.addends[0]: d["s1"], self.addends[1]: d["s2"]})


def clock_add_cases(fam, builder):
    c = AddCases(fam, builder)
    vectors = []
    for family in (c.manual_examples, c.carries, c.range_errors, c.device_range, c.both_errors, c.registers_after_success,
                   c.same_device, c.overlap, c.pulse, c.random):
        vectors += family()
    return vectors + model_cases(builder, vectors, c.from_row, ("instructions",))
