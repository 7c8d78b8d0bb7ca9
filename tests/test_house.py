"""The house's bound on a function, for the project's Python: every hand-written function (the
generator, the Python runner and reference, the table of faults, CI's scripts, these tests) is at most
80 lines, decorators to last line, or says why in the comment just before it or in its docstring with
the words "over 80 lines:". C (verifiers/c/tests/house.py), Go (house_test.go), Rust (clippy's
too_many_lines), Java (its JUnit house test) and TypeScript (eslint's max-lines-per-function) hold
their runners to the same bound (verifiers/VOCABULARY.md, "Functions under 80 lines")."""
import ast
import subprocess

import pytest

from conftest import REPO

LONGEST = 80
WHY = "over 80 lines:"


def long_functions(source: str, name: str = "<source>") -> list[str]:
    """`file:line: name is N lines long` for each function over LONGEST lines that does not say why."""
    lines = source.split("\n")
    found = []
    for node in ast.walk(ast.parse(source, name)):
        if not isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            continue
        first = min([node.lineno] + [d.lineno for d in node.decorator_list])
        length = node.end_lineno - first + 1
        comment_before = "\n".join(lines[max(0, first - 4):first - 1])
        if length > LONGEST and WHY not in comment_before and WHY not in (ast.get_docstring(node) or ""):
            found.append(f"{name}:{node.lineno}: {node.name} is {length} lines long (at most {LONGEST}, "
                         f"or say why with {WHY!r})")
    return found


def _project_python() -> list[str]:
    # What git tracks (what a clone holds), without the generated code, which is data.
    out = subprocess.run(["git", "ls-files", "-z", "--", "*.py"], cwd=REPO, capture_output=True, check=True,
                         timeout=60).stdout.decode()
    return [path for path in out.split("\0") if path and "/generated/" not in path]


def test_a_long_function_is_found_unless_it_says_why():
    body = "".join(f"    x{i} = {i}\n" for i in range(LONGEST))
    long_one = f"@decorator\ndef f():\n{body}"
    assert long_functions(long_one, "m.py") == [
        f"m.py:2: f is {LONGEST + 2} lines long (at most {LONGEST}, or say why with 'over 80 lines:')"]
    assert long_functions(f"# over 80 lines: one table, read in one go.\n{long_one}") == []
    assert long_functions(f"class C:\n    def g(self):\n        '''over 80 lines: a table.'''\n{body}") == []
    assert long_functions(f"def f():\n{''.join(body.splitlines(True)[:LONGEST - 1])}") == []


def test_every_function_of_the_project_is_under_80_lines():
    paths = _project_python()
    assert len(paths) > 200, f"only {len(paths)} Python files found: the walk missed the project"
    found = [problem for path in paths
             for problem in long_functions((REPO / path).read_text(encoding="utf-8"), path)]
    assert found == [], "\n".join(found)


@pytest.mark.parametrize("path", ["verifiers/python/plcvec_verify/runner.py", "generator/plcvec/cli.py"])
def test_the_walk_reaches_the_runner_and_the_generator(path):
    assert path in _project_python()
