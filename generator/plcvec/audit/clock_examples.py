"""Audit of a clock addition's worked examples, and of the sentences of the page about them.

Every printed value of an example (the result in (d), the carry and zero flags) is recomputed. A
`prose` entry of an example is what a sentence of the page claims about it: addends or a result of
its own, or a rule worded so that it reads as one alternative of an interpretation. The claim is put
to the engine as the sentence states it and compared with what the sentence (or else the example)
prints.
"""
from plcvec.audit import findings as kinds
from plcvec.audit import wording
from plcvec.audit.findings import WHOLE_TABLE, FamilyAudit
from plcvec.audit.probe import AddProbe, reading


class ClockAddAudit(FamilyAudit):
    def __init__(self, fam):
        super().__init__(fam)
        self.probe = AddProbe(fam)
        self.c = self.probe.c
        self.fields = fam.doc["data"]["fields"]

    def show(self, key, value):
        if key == self.c.result:
            return wording.clock(value, self.fields)
        return wording.on_off(value)

    def addition(self, values, result):
        return " + ".join(wording.clock(values[op], self.fields) for op in self.c.addends) + \
            f" = {wording.clock(result, self.fields)}"

    def run(self):
        for index, ex in enumerate(self.fam.doc["examples"]):
            values = {op: ex[op] for op in self.c.addends}
            derived = self.probe.run(values, ex.get("devices"))
            self.cells[(ex["id"], "table")] = list(ex["printed"])
            agree = 0
            for key, want in ex["printed"].items():
                if self.tally(derived[key] == want):
                    agree += 1
                    continue
                self.add(kinds.CELL_DISAGREES, ex["id"], key,
                         f"Example '{ex['id']}': the manual prints {key} = {self.show(key, want)}, but by the rules "
                         f"{self.addition(values, derived[self.c.result])} gives {key} = {self.show(key, derived[key])}.",
                         printed=self.show(key, want), derived=self.show(key, derived[key]))
            flags = "".join(f", {k} {wording.on_off(derived[k])}" for k in self.probe.flags if k in ex["printed"])
            self.add(kinds.CELL_AGREES_COUNT, ex["id"], WHOLE_TABLE,
                     f"{agree} of {len(ex['printed'])} printed values of example '{ex['id']}' agree with the rules: "
                     f"{self.addition(values, derived[self.c.result])}{flags}.")
            self.cells[(ex["id"], "prose")] = []
            for k, prose in enumerate(ex.get("prose", [])):
                self.prose(("examples", index, "prose", k), ex, values, derived, prose)
        return self

    def prose(self, where, ex, table_values, table_derived, prose):
        values = {op: prose.get(op, ex[op]) for op in self.c.addends}
        choices = prose.get("reading", {})
        derived = self.probe.run(values, ex.get("devices"), reading(self.fam, where + ("reading",), choices))
        stated = prose.get("printed", ex["printed"])
        self.cells[(ex["id"], "prose")] += [k for k in stated if k not in self.cells[(ex["id"], "prose")]]
        own = [f"{op} = {wording.clock(values[op], self.fields)} where the table has {wording.clock(table_values[op], self.fields)}"
               for op in self.c.addends if values[op] != table_values[op]]
        readings = [f"{iid} = {alt} ({self._says(iid, alt)})" for iid, alt in sorted(choices.items())]
        for key, want in stated.items():
            if self.tally(derived[key] == want):
                continue
            claim = f"Example '{ex['id']}': the page says \"{prose['quote']}\""
            if own:
                claim += f", with {wording.listing(own)}"
            if readings:
                claim += f", which reads as {wording.listing(readings)}"
            source = "the sentence states" if "printed" in prose else "the example prints"
            claim += (f". Taken so, {self.addition(values, derived[self.c.result])} gives {key} = {self.show(key, derived[key])} "
                      f"by the rules, but {source} {self.show(key, want)}.")
            if own and table_derived[key] == ex["printed"].get(key):
                claim += f" The table's own values give {self.show(key, table_derived[key])}, as printed: the sentence disagrees with its table."
            self.add(kinds.PROSE_VS_TABLE, ex["id"], key, claim,
                     printed=self.show(key, want), derived=self.show(key, derived[key]))

    def _says(self, iid, alt):
        return next(a["says"] for a in self.fam.interpretations[iid]["alternatives"] if a["id"] == alt)
