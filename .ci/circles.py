#!/usr/bin/env python3
"""Import circles in the Python code: every import counts, at any depth of a file (an import inside a
function hides a circle from Python's loader, not from the reader).

    python3 .ci/circles.py                 # exit 1 naming each circle, 0 when there is none

A circle is a set of modules each reachable from the others through imports (a strongly connected
component of more than one module); a package's `__init__` counts as the module it is. The
generator's stages are also held to one direction (STAGES): a stage imports only stages before it.
"""
from __future__ import annotations

import ast
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
ROOTS = [REPO / "generator", REPO / "verifiers" / "python"]
PACKAGES = ("plcvec", "plcvec_verify", "plcvec_reference")

# The generator's stages (its folders, and its modules at the top), upstream first: each may import only
# those above it. Data flows down: the engine is the mechanisms (it reads no file and names no family);
# the coverage cells are the engine's word arithmetic; the spec loader checks that what a spec names (an
# engine's `undefined`, a coverage derivation) exists; cases turn the spec into vectors; output writes
# them; everything below reads the spec and the written vectors and writes something of its own. A
# helper two stages need lives in the upper one (the instructions' names and the tags are the spec's,
# write_atomic is output's) so nothing looks back up.
STAGES = [
    "plcvec.errors",
    "plcvec.engine",
    "plcvec.coverage",
    "plcvec.spec",
    "plcvec.cases",
    "plcvec.output",
    "plcvec.review",      # the review page and its model, from the spec and the written vectors
    "plcvec.export",      # the native runners' copies (the reference tables from review's renderer)
    "plcvec.release",
    "plcvec.audit",
    "plcvec.fuzz",
    "plcvec.mutation",
    "plcvec.bench",
    "plcvec.common_vectors",
    "plcvec.native_bench",
    "plcvec.cli",         # the commands over all of the above
    "plcvec.__main__",
]


def modules() -> dict[str, Path]:
    out = {}
    for root in ROOTS:
        for path in sorted(root.rglob("*.py")):
            rel = path.relative_to(root).with_suffix("")
            parts = list(rel.parts)
            if parts[0] not in PACKAGES or "templates" in parts:
                continue
            if parts[-1] == "__init__":
                parts = parts[:-1]
            out[".".join(parts)] = path
    return out


def imports_of(name: str, path: Path, known: dict) -> set[str]:
    """The known modules `name` imports, anywhere in its file."""
    tree = ast.parse(path.read_text(encoding="utf-8"), str(path))
    package = name if path.name == "__init__.py" else name.rpartition(".")[0]
    found = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            targets = [a.name for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                anchor = package.split(".")
                anchor = anchor[:len(anchor) - (node.level - 1)]
                base = ".".join(anchor + ([base] if base else []))
            # `from pkg import sub` depends on pkg.sub when that is a module, else on pkg itself.
            targets = [f"{base}.{a.name}" if f"{base}.{a.name}" in known else base for a in node.names]
        else:
            continue
        for t in targets:
            # the module itself, or the package that holds it
            while t and t not in known:
                t = t.rpartition(".")[0]
            if t and t != name:
                found.add(t)
    return found


def circles(graph: dict[str, set[str]]) -> list[list[str]]:
    """Strongly connected components of more than one node (Tarjan's), each sorted."""
    index, low, stack, on, out = {}, {}, [], set(), []
    counter = [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in sorted(graph.get(v, ())):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))

    sys.setrecursionlimit(10000)
    for v in sorted(graph):
        if v not in index:
            visit(v)
    return sorted(out)


def graph() -> dict[str, set[str]]:
    known = modules()
    return {name: imports_of(name, path, known) for name, path in known.items()}


def stage_of(module: str) -> str:
    """The folder a module is in, one level under its top package (plcvec.spec.loader -> plcvec.spec);
    a module at the top is its own stage."""
    parts = module.split(".")
    return ".".join(parts[:2])


def stage_graph(g: dict[str, set[str]]) -> dict[str, set[str]]:
    """The generator's folders (its stages: spec, engine, cases, output, export, ...) and which import
    which: data flows one way through them, so they may not import each other."""
    out: dict[str, set[str]] = {}
    for n, targets in g.items():
        if not n.startswith("plcvec."):
            continue
        targets = {t for t in targets if t.startswith("plcvec.")}
        out.setdefault(stage_of(n), set()).update(stage_of(t) for t in targets if stage_of(t) != stage_of(n))
    return out


def upstream_imports(sg: dict[str, set[str]]) -> list[str]:
    """Each import of a stage by a stage above it in STAGES, and each stage STAGES does not place."""
    out = [f"stage {s} is not in STAGES (.ci/circles.py): place it in the order" for s in sorted(sg) if s not in STAGES]
    for s, targets in sorted(sg.items()):
        for t in sorted(targets):
            if s in STAGES and t in STAGES and STAGES.index(t) > STAGES.index(s):
                out.append(f"stage {s} imports {t}, which comes after it in STAGES")
    return out


def main() -> int:
    g = graph()
    found = circles(g)
    for comp in found:
        print(f"import circle: {' <-> '.join(comp)}")
    sg = stage_graph(g)
    stages = circles(sg)
    for comp in stages:
        print(f"stage circle (folders that import each other): {' <-> '.join(comp)}")
    order = upstream_imports(sg)
    for line in order:
        print(line)
    print(f"circles: {len(found)} between modules, {len(stages)} between folders; "
          f"{len(order)} against the stages' order")
    return 1 if found or stages or order else 0


if __name__ == "__main__":
    sys.exit(main())
