"""The engine's mutants, as cosmic-ray makes them: each one change of one operator at one place.

cosmic-ray (https://cosmic-ray.readthedocs.io) parses a module with parso and offers, per operator,
every position where that operator applies (`mutation_positions`), numbered in the order of a walk of
the tree (the occurrence); `mutate_code(source, operator, occurrence)` gives the source with that one
change. Only cosmic-ray's enumeration and its operators are used here: the mutated source is never
written to disk (oracle.py imports it in a process of its own).

Operators that need arguments (VariableReplacer, VariableInserter draw values at random) are left out,
as cosmic-ray's own `init` does when a configuration gives them none: the mutants are then the same
on every run.
"""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from plcvec.errors import PlcvecError


def _cosmic_ray():
    """cosmic-ray's modules, or a clear error naming the extra that brings it."""
    try:
        import cosmic_ray.ast
        import cosmic_ray.mutating
        import cosmic_ray.plugins
    except ImportError as exc:
        raise PlcvecError(f"the mutation run needs cosmic-ray ({exc}): pip install 'plcvec[mutation]'") from None
    return cosmic_ray


@dataclass(frozen=True)
class Mutant:
    """One change of the engine: `operator`'s `occurrence`-th position in `file` (an engine file name),
    spanning `start` to `end` ((line, column), lines from 1, as parso counts them)."""

    file: str
    operator: str
    occurrence: int
    start: tuple
    end: tuple

    @property
    def line(self):
        return self.start[0]

    @property
    def lines(self):
        """The source lines the changed node spans (first, last)."""
        return self.start[0], self.end[0]

    @property
    def name(self):
        """How reports name it: file:line:column, then the operator and its occurrence."""
        return f"{self.file}:{self.start[0]}:{self.start[1]} {self.operator.rpartition('/')[2]}#{self.occurrence}"

    def mutated(self, source):
        """The engine file's source with this one change, or None when cosmic-ray makes no change there."""
        cr = _cosmic_ray()
        operator = cr.plugins.get_operator(self.operator)()
        return cr.mutating.mutate_code(source, operator, self.occurrence)


def operators():
    """The names of cosmic-ray's operators that take no argument, sorted (the order of plugins found is
    not the same everywhere)."""
    cr = _cosmic_ray()
    return sorted(name for name in cr.plugins.operator_names() if not cr.plugins.get_operator(name).arguments())


def mutants_of(name, source):
    """Every mutant of one engine file, by operator then occurrence."""
    cr = _cosmic_ray()
    tree = cr.ast.get_ast(source)
    nodes = list(cr.ast.ast_nodes(tree))
    out = []
    for op_name in operators():
        operator = cr.plugins.get_operator(op_name)()
        positions = (pos for node in nodes for pos in operator.mutation_positions(node))
        out += [Mutant(name, op_name, k, tuple(start), tuple(end)) for k, (start, end) in enumerate(positions)]
    return out


def engine_sources(engine_dir: Path):
    """{file name: source} of the engine's modules, in name order."""
    return {path.name: path.read_text(encoding="utf-8") for path in sorted(Path(engine_dir).glob("*.py"))}
