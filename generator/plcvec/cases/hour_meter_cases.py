"""Cases for `hour_meter` families: scan sequences with the elapsed time of each scan."""
from plcvec.cases.common import Operands
from plcvec.cases.model_cases import model_cases
from plcvec.cases.random_cases import draw_hour_meter
from plcvec.engine.words import operand_words


class HourCases:
    def __init__(self, fam, builder):
        self.fam, self.b, self.doc = fam, builder, fam.doc
        self.fields = self.doc["data"]["fields"]
        self.names = [f["name"] for f in self.fields]
        self.ops = Operands(self.fields)
        ops = self.doc["operands"]
        role = {v["role"]: k for k, v in ops.items()}
        self.preset, self.measured, self.output, self.work = role["preset"], role["measured"], role["output"], role["work"]
        self.words = {k: v.get("words", 1) for k, v in ops.items()}
        self.place = self.doc["generation"]["placement"]
        self.unit = self.doc["data"]["subsecond_units_per_second"]
        self.error_device = self.doc["error"]["device"]
        self.instr = next(iter(builder.instructions))
        self.cf = self.doc["data"]["constant_field"]["field"]

    def hms(self, **kw):
        v = {n: 0 for n in self.names}
        v.update(kw)
        return v

    def seconds(self, n):
        """Field values for n whole seconds, by the spec's own radices."""
        return self.ops.codec.from_units(n)

    def case(self, key, *, tags, description, preset, measured, steps, output=False, error=False,
             preset_raw=None, clauses=(), output_device=None):
        output_device = output_device or self.place[self.output]
        devices = {self.error_device: error, output_device: output}
        operands = {op: {"device": self.place[op]} for op in (self.measured, self.work)}
        operands[self.output] = {"device": output_device}
        if isinstance(preset, int):
            operands[self.preset] = {"constant": preset}
        else:
            operands[self.preset] = {"device": self.place[self.preset]}
            self.ops.place(devices, self.place[self.preset], self.ops.words(preset, raw=preset_raw))
        self.ops.place(devices, self.place[self.measured], self.ops.words(measured))
        scratch = operand_words(self.place[self.work], self.words[self.work])
        devices.update({a: 0 for a in scratch})
        return self.b.vector(self.instr, key, tags=tags, description=description, operands=operands,
                             devices=devices, steps=steps, scratch=scratch, clauses=clauses)

    def on(self, ms, n=1):
        return [{"input": True, "elapsed_ms": ms}] * n

    def set_preset(self, values):
        """A step's `set` that writes `values` into the preset's registers."""
        return dict(zip(operand_words(self.place[self.preset], self.words[self.preset]), self.ops.words(values)))

    def clock(self, values):
        """Field values as the page writes a duration: 65535:59:58."""
        return ":".join(str(values[n]) if k == 0 else f"{values[n]:02d}" for k, n in enumerate(self.names))

    def basics(self):
        five = self.seconds(5)
        yield self.case("reach/whole-seconds", tags=["scan-sequence"], preset=five, measured=self.hms(),
                        steps=self.on(self.unit, 6), description="One second per scan for six scans; the preset of 5 s is reached at the fifth.")
        yield self.case("reach/one-big-step", tags=["scan-sequence"], preset=five, measured=self.hms(),
                        steps=self.on(self.unit * 7), description="A single scan of 7 s passes the 5 s preset.")
        yield self.case("reach/already-past", tags=["scan-sequence"], preset=five, measured=self.seconds(100),
                        steps=self.on(0), description="D1 already past the preset: the first execution turns the output on.")
        yield self.case("subsecond/tenths", tags=["subsecond"], preset=self.seconds(2), measured=self.hms(),
                        steps=self.on(self.unit // 10, 12), description="Twelve scans of a tenth of a second add up to 1 s, with the rest kept.")
        yield self.case("subsecond/remainder-kept", tags=["subsecond"], preset=self.seconds(2), measured=self.hms(),
                        steps=self.on(self.unit * 4 // 10, 5), description="Five scans of 0.4 s: 1 s after the third, 2 s after the fifth.")
        yield self.case("subsecond/just-under", tags=["subsecond"], preset=self.seconds(1), measured=self.hms(),
                        steps=self.on(self.unit - 1) + self.on(1), description="0.999 s then 0.001 s: the second completes on the second scan.")
        carry = {n: f["max"] for n, f in zip(self.names, self.fields)}
        carry[self.names[0]] = 0
        yield self.case("carry/into-top-field", tags=["wrap", "boundary"], preset=self.seconds(10 ** 7), measured=carry,
                        steps=self.on(self.unit), description="D1 at 0:59:59 plus 1 s carries into the hour.")

    def constants(self):
        top = self.fields[0]
        per_top = self.ops.codec.modulus() // (top["max"] + 1)  # seconds in one unit of the top field
        yield self.case("constant/one", tags=["constant", "boundary"], preset=1, measured=self.seconds(per_top - 1),
                        steps=self.on(self.unit, 2), description=f"Constant preset 1 ({self.cf} only): reached after 1 s from 0:59:59.")
        yield self.case("constant/max", tags=["constant", "boundary"], preset=top["max"],
                        measured={n: (top["max"] if n == self.cf else 0) for n in self.names},
                        steps=self.on(self.unit), description=f"Constant preset {top['max']}: D1 starts at it, so one scan turns D2 on.")
        yield self.case("constant/zero", tags=["constant", "boundary", "zero-preset"], preset=0, measured=self.hms(),
                        steps=self.on(0) + self.on(self.unit), description="Constant preset 0.")
        # A constant counts hours: D1 below the constant in hours is below it, whatever the
        # constant would be in minutes or seconds.
        for hours, start in ((2, 2 * per_top - 2), (90, 90 * 60), (1000, 1000 * 60)):
            yield self.case(f"constant/{hours}-hours", tags=["constant"], preset=hours, measured=self.seconds(start),
                            steps=self.on(self.unit, 2),
                            description=f"Constant preset {hours} ({self.cf} only): D1 from {start} s, two scans of 1 s; "
                                        f"reached only at {hours * per_top} s.")
        yield self.case("register/zero", tags=["boundary", "zero-preset"], preset=self.hms(), measured=self.hms(),
                        steps=self.on(self.unit), description="Preset 0:00:00 in data registers.")

    def wrap(self):
        top = {f["name"]: f["max"] for f in self.fields}
        one_top_unit = self.seconds(self.ops.codec.modulus() // (self.fields[0]["max"] + 1))
        yield self.case("wrap/output-stays-on", tags=["wrap"], preset=one_top_unit, measured=top, output=True,
                        steps=self.on(self.unit, 2), description="D1 at the largest value with D2 on: one second later it is 0:00:00, below the preset, and D2 stays on.")
        below = self.ops.codec.from_units(self.ops.codec.modulus() - 2)
        yield self.case("wrap/reach-then-wrap", tags=["wrap"], preset=top, measured=below,
                        steps=self.on(self.unit, 3), description="Reach the largest preset, wrap, and keep measuring.")
        # One long scan carries D1 past the top and on into the next cycle: two units of the top field
        # (two hours) from one unit below the top.
        per_top = self.ops.codec.modulus() // (self.fields[0]["max"] + 1)
        start = self.ops.codec.from_units(self.ops.codec.modulus() - per_top)
        yield self.case("wrap/one-long-step", tags=["wrap", "scan-sequence"], preset=one_top_unit, measured=start,
                        steps=self.on(self.unit * 2 * per_top),
                        description=f"D1 at {start[self.names[0]]}:00:00 and one scan of {2 * per_top} s: D1 wraps and ends at 1:00:00, "
                                    "which reaches the preset of 1:00:00 in the new cycle.")
        # One scan passes the preset and wraps (HOUR-WRAP-REACH): the largest preset, from two seconds below it.
        start = self.ops.codec.from_units(self.ops.codec.modulus() - 2)
        yield self.case("wrap/reach-while-wrapping", tags=["wrap", "scan-sequence"], preset=top, measured=start,
                        steps=self.on(self.unit * 2) + self.on(self.unit),
                        description=f"D1 at {self.clock(start)}, the preset {self.clock(top)}, one scan of 2 s and one of 1 s: "
                                    "the first passes the preset and wraps D1 to 0:00:00 in the same execution; "
                                    "compared after the wrap, D2 stays off.")

    def forbidden_operands(self):
        """Operands the page forbids: a constant above the range of its field (HOUR-S1-CONSTANT-RANGE), and
        D2 a special internal relay (HOUR-D2-SPECIAL)."""
        top = self.fields[0]
        per_top = self.ops.codec.modulus() // (top["max"] + 1)
        for value, start, scans in ((top["max"] + 1, 0, 1), (top["max"] + 2, per_top - 1, 2)):
            yield self.case(f"constant/above-range/{value}", tags=["constant", "forbidden-operand"], preset=value,
                            measured=self.seconds(start), steps=self.on(self.unit, scans),
                            description=f"Constant preset {value}, above the {top['max']} a constant may hold, D1 from {start} s, "
                                        f"{scans} scans of 1 s: read as an invalid preset, the error flag on, D1 still measured, D2 stays off.")
        relay = self.doc["generation"]["special_relay"]
        yield self.case("special-relay/reach", tags=["scan-sequence", "forbidden-operand"], preset=self.seconds(2),
                        measured=self.hms(), steps=self.on(self.unit, 3), output_device=relay,
                        description=f"D2 is the special internal relay {relay}, which the page forbids as D2: "
                                    "written as any relay, it turns on when the preset of 2 s is reached.")
        invalid = self.hms(**{self.names[1]: self.by_max(self.names[1]) + 1})
        yield self.case("special-relay/invalid-preset", tags=["invalid-range", "forbidden-operand"], preset=self.seconds(1),
                        measured=self.seconds(5), output=True, output_device=relay,
                        steps=[{"input": True, "elapsed_ms": self.unit, "set": self.set_preset(invalid)}],
                        description=f"D2 is the special internal relay {relay}, on; the preset is changed to an invalid one: "
                                    f"written as any relay, {relay} turns off and the error flag turns on.")

    def error_repeat(self):
        """An invalid preset checked again after the program turned the error flag off (HOUR-M8004-REPEAT)."""
        minute = self.names[1]
        invalid = self.hms(**{minute: self.by_max(minute) + 1})
        cleared = [{"input": True, "elapsed_ms": self.unit, "set": {self.error_device: False}}]
        yield self.case(f"error-flag/{minute}={invalid[minute]}/cleared-by-program", tags=["invalid-range", "latch", "scan-sequence"],
                        preset=invalid, measured=self.hms(), steps=self.on(self.unit) + cleared + self.on(self.unit),
                        description=f"Preset {minute} = {invalid[minute]} for three scans of 1 s; the program turns the error flag off "
                                    "before the second: the second check turns it on again.")
        top = self.fields[0]["max"] + 2
        yield self.case(f"error-flag/constant={top}/cleared-by-program", tags=["constant", "forbidden-operand", "latch", "scan-sequence"],
                        preset=top, measured=self.hms(), steps=self.on(self.unit) + cleared + self.on(self.unit),
                        description=f"Constant preset {top} for three scans of 1 s; the program turns the error flag off "
                                    "before the second: read as an invalid preset, the second check turns it on again.")
        valid_again = [{"input": True, "elapsed_ms": self.unit, "set": {self.error_device: False, **self.set_preset(self.seconds(5))}},
                       {"input": True, "elapsed_ms": self.unit, "set": self.set_preset(invalid)}]
        yield self.case(f"error-flag/{minute}={invalid[minute]}/valid-between", tags=["invalid-range", "latch", "scan-sequence"],
                        preset=invalid, measured=self.hms(), steps=self.on(self.unit) + valid_again,
                        description=f"Preset {minute} = {invalid[minute]}, then a valid preset with the error flag turned off by the program, "
                                    f"then {minute} = {invalid[minute]} again: the third check turns the error flag on again.")

    def invalid_preset(self):
        for f in self.fields[1:]:
            for bad in (f["max"] + 1, 0xFFFF):
                preset = self.hms(**{f["name"]: bad})
                yield self.case(f"invalid-preset/{f['name']}={bad}/before-output", tags=["invalid-range"], preset=preset,
                                measured=self.hms(), steps=self.on(self.unit, 2),
                                description=f"Preset {f['name']} = {bad} (over {f['max']}) before D2 turned on: error flag on, D1 still measured, D2 stays off.")
                yield self.case(f"invalid-preset/{f['name']}={bad}/after-output", tags=["invalid-range"],
                                preset=self.seconds(1), measured=self.seconds(5), output=True,
                                steps=[{"input": True, "elapsed_ms": self.unit,
                                        "set": dict(zip(operand_words(self.place[self.preset], self.words[self.preset]), self.ops.words(preset)))}],
                                description=f"Preset changed to {f['name']} = {bad} after D2 turned on: D2 off, error flag on, D1 still measured.")
        yield self.case("invalid-preset/recovers", tags=["invalid-range", "scan-sequence"], preset=self.hms(**{self.names[1]: self.fields[1]["max"] + 1}),
                        measured=self.hms(), steps=self.on(self.unit) + [{"input": True, "elapsed_ms": self.unit,
                        "set": dict(zip(operand_words(self.place[self.preset], self.words[self.preset]), self.ops.words(self.seconds(1))))}],
                        description="An invalid preset, then a valid one already reached: D2 turns on; the error flag stays as it was.")

    def measured_out_of_range(self):
        """D1 holding a minute or a second above its range when the input is on (HOUR-D1-OUT-OF-RANGE)."""
        hour, minute, second = self.names
        preset = self.seconds(self.ops.codec.modulus() // (self.fields[0]["max"] + 1))   # 1:00:00
        for name, value, ms in ((minute, self.by_max(minute) + 16, self.unit), (second, self.by_max(second) + 1, self.unit),
                                (second, self.by_max(second) + 16, self.unit // 2), (minute, 0xFFFF, self.unit),
                                (second, 0xFFFF, 2 * self.unit)):
            measured = self.hms(**{name: value})
            yield self.case(f"measured-out-of-range/{name}={value}/{ms}ms", tags=["invalid-range"], preset=preset,
                            measured=measured, steps=self.on(ms),
                            description=f"D1 {name} = {value} (over {self.by_max(name)}) and one scan of {ms} ms with the input on; "
                                        "the preset is 1:00:00.")
        # A second in range carrying into a minute out of range.
        measured = self.hms(**{minute: self.by_max(minute) + 16, second: self.by_max(second)})
        yield self.case(f"measured-out-of-range/{minute}={measured[minute]},{second}={measured[second]}/{self.unit}ms",
                        tags=["invalid-range"], preset=preset, measured=measured, steps=self.on(self.unit),
                        description=f"D1 at {self.clock(measured)} ({minute} over {self.by_max(minute)}) and one scan of {self.unit} ms "
                                    "with the input on: the second carries into the minute; the preset is 1:00:00.")

    def by_max(self, name):
        return self.ops.by_name[name]["max"]

    def output_relay(self):
        """D2 an output relay, as the device table has it, beside the internal relay the other vectors use."""
        relay = self.doc["generation"]["output_relay"]
        yield self.case("output-relay/reach", tags=["scan-sequence"], preset=self.seconds(2), measured=self.hms(),
                        steps=self.on(self.unit, 3), output_device=relay,
                        description=f"D2 is the output relay {relay}: it turns on when the preset of 2 s is reached.")
        invalid = self.hms(**{self.names[1]: self.by_max(self.names[1]) + 1})
        yield self.case("output-relay/invalid-preset", tags=["invalid-range"], preset=self.seconds(1), measured=self.seconds(5),
                        output=True, output_device=relay,
                        steps=[{"input": True, "elapsed_ms": self.unit,
                                "set": dict(zip(operand_words(self.place[self.preset], self.words[self.preset]), self.ops.words(invalid)))}],
                        description=f"D2 is the output relay {relay}, on; the preset is changed to an invalid one: {relay} turns off.")

    def error_flag(self):
        """M8004 already on, or an invalid preset, at executions with the input on and off: whether a valid
        preset turns M8004 off (HOUR-M8004-OFF) and whether the input off checks the preset (HOUR-PRESET-CHECK)."""
        five, minute = self.seconds(5), self.names[1]
        invalid = self.hms(**{minute: self.fields[1]["max"] + 1})
        off = [{"input": False, "elapsed_ms": self.unit}]
        yield self.case("error-flag/valid-preset/input-on", tags=["scan-sequence"], preset=five, measured=self.hms(),
                        error=True, steps=self.on(self.unit, 2),
                        description="The error flag already on, a valid preset in data registers, the input on for two scans of 1 s.")
        yield self.case("error-flag/constant-preset/input-on", tags=["constant", "scan-sequence"], preset=5, measured=self.hms(),
                        error=True, steps=self.on(self.unit, 2),
                        description="The error flag already on, a constant preset, the input on for two scans of 1 s.")
        yield self.case("error-flag/valid-preset/input-off", tags=["input-off"], preset=five, measured=self.seconds(2),
                        error=True, steps=off, description="The error flag already on, a valid preset, the input off.")
        yield self.case(f"invalid-preset/{minute}={invalid[minute]}/input-off", tags=["invalid-range", "input-off"],
                        preset=invalid, measured=self.seconds(2), output=True, steps=off,
                        description=f"Preset {minute} = {invalid[minute]} with D2 on and the input off for one scan.")
        yield self.case(f"invalid-preset/{minute}={invalid[minute]}/off-then-on", tags=["invalid-range", "input-off", "scan-sequence"],
                        preset=invalid, measured=self.seconds(2), output=True, steps=off + self.on(self.unit),
                        description=f"Preset {minute} = {invalid[minute]} with D2 on: the input off for one scan, then on for 1 s.")

    def input_off(self):
        yield self.case("input/off-on-off", tags=["input-off", "scan-sequence"], preset=self.seconds(3), measured=self.hms(),
                        steps=self.on(self.unit * 15 // 10) + [{"input": False, "elapsed_ms": self.unit * 5}] + self.on(self.unit * 15 // 10),
                        description="1.5 s on, 5 s off, 1.5 s on: only ON time counts.")
        yield self.case("input/off-after-reach", tags=["input-off", "scan-sequence"], preset=self.seconds(1), measured=self.hms(),
                        steps=self.on(self.unit) + [{"input": False, "elapsed_ms": self.unit}],
                        description="The input goes off after D2 turned on.")
        yield self.case("input/off-then-on", tags=["input-off", "scan-sequence"], preset=self.seconds(2), measured=self.hms(),
                        steps=[{"input": False, "elapsed_ms": self.unit}] + self.on(self.unit, 2),
                        description="The input off for the first scan, then on for two scans of 1 s: "
                                    "the preset of 2 s is reached at the third.")
        yield self.case("input/preset-raised-after-reach", tags=["scan-sequence"], preset=self.seconds(1), measured=self.hms(),
                        steps=self.on(self.unit) + [{"input": True, "elapsed_ms": self.unit,
                                                     "set": dict(zip(operand_words(self.place[self.preset], self.words[self.preset]), self.ops.words(self.seconds(self.ops.codec.modulus() // (self.fields[0]["max"] + 1)))))}],
                        description="After D2 turned on the preset is raised above D1.")

    # -- the coverage model's rows -----------------------------------------------------------------
    def from_row(self, row, key):
        """The vector of one execution for a row of the coverage model: {derivation: class}."""
        codec = self.ops.codec
        per_top = codec.modulus() // (self.fields[0]["max"] + 1)   # seconds in one unit of the top field
        whole = {"none": 0, "one": 1, "several": 3}[row.get("whole-seconds", "one")]
        on = row.get("input", "on") == "on"
        if row.get("wrap") == "yes":
            after = max(whole - 1, 0)
            before = (codec.modulus() - whole + after) % codec.modulus()
        else:
            after = 5 * per_top
            before = after - whole
        reach = row.get("reach", "at")
        target = {"below": after + per_top, "at": after, "above": after - per_top if after >= per_top else 0}.get(reach, after)
        constant = row.get("preset-operand") == "constant"
        preset = target // per_top if constant else self.seconds(target)
        validity = row.get("preset-validity")
        if validity not in (None, "valid") and constant:
            # Past the constant's range by a whole cycle of its field: cut to the field's bits it is the
            # row's preset again (HOUR-S1-CONSTANT-RANGE=low-16-bits).
            preset += self.fields[0]["max"] + 1
        elif validity not in (None, "valid"):
            name = validity.split(".")[0]
            preset = dict(preset, **{name: self.ops.by_name[name]["max"] + 1})
        step = {"input": on, "elapsed_ms": whole * self.unit + (self.unit // 2 if whole == 0 else 0)}
        return self.case(key, tags=["model"], preset=preset, measured=self.seconds(before), steps=[step],
                         output=row.get("output-before") == "on", error=row.get("error-before") == "on",
                         description=f"Coverage model row: {', '.join(f'{k} {v}' for k, v in row.items() if v is not None)}.")

    def random(self):
        gen = self.doc["generation"]
        for d in draw_hour_meter(self.fields, gen["seed"], gen["random_examples"]):
            yield self.case(f"random/{d['key']}", tags=["random"], preset=d["preset"], measured=d["measured"], steps=d["steps"],
                            description="A scan sequence drawn with the spec's seed.")


def hour_meter_cases(fam, builder):
    c = HourCases(fam, builder)
    vectors = []
    for family in (c.basics, c.constants, c.wrap, c.invalid_preset, c.error_flag, c.error_repeat, c.measured_out_of_range,
                   c.output_relay, c.forbidden_operands, c.input_off, c.random):
        vectors += family()
    return vectors + model_cases(builder, vectors, c.from_row, ())
