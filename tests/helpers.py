"""Run one execution of an instruction through the spec engine, for the property tests."""
from plcvec.cases.build import VectorBuilder
from plcvec.engine.words import FieldCodec


class Runner:
    def __init__(self, fam):
        self.fam = fam
        self.builder = VectorBuilder(fam)
        self.codec = FieldCodec(fam.doc["data"]["fields"])

    def run(self, instruction, operands, devices, steps, scratch=()):
        instr = self.builder.instructions[instruction]
        expects, final, outcome, _ = self.builder.run(instr, operands, devices, steps, scratch, self.fam.default_choices())
        return expects, final, outcome

    def words(self, values):
        return self.codec.pack(values)
