"""The reference implementation as a plcvec adapter, in process or over stdio.

In process:  plcvec verify --python plcvec_reference.adapter:ReferenceAdapter
As a process: plcvec verify --adapter "python3 -m plcvec_reference.adapter [--mutant NAME] [--choose ID=ALT]"

`mutant` names one of plcvec_reference.mutants.MUTANTS: the same implementation with one
plausible bug, used to show that the vectors and the verifier catch it.
"""
from __future__ import annotations

import argparse
import sys

from . import ALTERNATIVES, DEFAULTS, make_machine

NAME = "plcvec-reference"
VERSION = "1.0"


class ReferenceAdapter:
    def __init__(self, mutant: str | None = None, choices: dict | None = None):
        self.choices = dict(choices or {})
        self.make_machine = make_machine
        self.name = NAME
        if mutant:
            from .mutants import MUTANTS

            if mutant not in MUTANTS:
                raise ValueError(f"no mutant {mutant!r}; known: {', '.join(sorted(MUTANTS))}")
            self.make_machine = MUTANTS[mutant].make_machine
            self.name = f"{NAME} (mutant {mutant})"
        known = {i for family in ALTERNATIVES.values() for i in family}
        for interp, alt in self.choices.items():
            if interp not in known:
                raise ValueError(f"no interpretation {interp!r}")

    def hello(self, request: dict) -> dict:
        families = request["families"]
        instructions = sorted({i for name, f in families.items() if name in DEFAULTS for i in f["instructions"]})
        interpretations = {}
        for name in families:
            for interp, default in DEFAULTS.get(name, {}).items():
                interpretations[interp] = self.choices.get(interp, default)
        return {"adapter": {"name": self.name, "version": VERSION},
                "instructions": instructions, "interpretations": interpretations}

    def run(self, request: dict) -> dict:
        initial = request["initial"]
        machine = self.make_machine(request["family"], initial["devices"],
                                    request["assumes"].get("device_sizes", {}), self.choices)
        values = machine.mem.values
        instruction, operands = request["instruction"], initial["operands"]
        contact = machine.CONTACT
        steps = []
        for step in request["steps"]:
            if "set" in step:
                values.update(step["set"])
            result = machine.execute(instruction, operands, step)
            # The whole device image after the step; scratch words may be left in (never compared).
            out = {"devices": dict(values)}
            if contact:
                out["result"] = result
            steps.append(out)
        return {"steps": steps}


def main(argv=None) -> int:
    from plcvec_verify.serve import serve

    p = argparse.ArgumentParser(prog="python3 -m plcvec_reference.adapter",
                                description="Serve the reference implementation over the plcvec stdio protocol.")
    p.add_argument("--mutant", help="serve this mutant instead (see plcvec_reference.mutants)")
    p.add_argument("--choose", action="append", default=[], metavar="ID=ALT",
                   help="follow this interpretation alternative (repeatable)")
    args = p.parse_args(argv)
    try:
        choices = dict(c.split("=", 1) for c in args.choose)
        adapter = ReferenceAdapter(args.mutant, choices)
    except ValueError as exc:
        print(f"plcvec_reference.adapter: {exc}", file=sys.stderr)
        return 2
    return serve(adapter)


if __name__ == "__main__":
    sys.exit(main())
