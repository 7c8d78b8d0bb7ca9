"""The Python names renamed to the shared vocabulary (verifiers/VOCABULARY.md) in 0.3.0: each old name
still gives the very object of the new one, with a DeprecationWarning naming the new one, until
0.4.0; the new names warn of nothing; and the API check against 0.1.0 sees each old name as the class
it was, not as a name removed or turned into an attribute."""
from __future__ import annotations

import importlib
import shutil
import warnings

import pytest

from conftest import REPO

RENAMED = [
    ("plcvec_verify", "RunReport", "Report"),
    ("plcvec_verify", "VectorResult", "Verdict"),
    ("plcvec_verify.runner", "RunReport", "Report"),
    ("plcvec_verify.runner", "VectorResult", "Verdict"),
    ("plcvec_reference", "FX5CompareMachine", "Fx5Compare"),
    ("plcvec_reference", "TADDMachine", "Fx5TimeAdd"),
    ("plcvec_reference", "HourMeter", "Fc6aHourMeter"),
    ("plcvec_reference", "CP1ETimeCompare", "Cp1eTimeCompare"),
    ("plcvec_reference.fx5_compare", "FX5CompareMachine", "Fx5Compare"),
    ("plcvec_reference.fx5_tadd", "TADDMachine", "Fx5TimeAdd"),
    ("plcvec_reference.fc6a_hour", "HourMeter", "Fc6aHourMeter"),
    ("plcvec_reference.cp1e_dt", "CP1ETimeCompare", "Cp1eTimeCompare"),
]


@pytest.mark.parametrize("module, old, new", RENAMED, ids=[f"{m}.{o}" for m, o, _ in RENAMED])
def test_the_old_name_is_the_new_one_and_warns(module, old, new):
    mod = importlib.import_module(module)
    message = rf"^{module}\.{old} is deprecated since 0\.3\.0 and removed in 0\.4\.0: use {module}\.{new}$"
    with pytest.warns(DeprecationWarning, match=message):
        assert getattr(mod, old) is getattr(mod, new)
    # An import statement warns too, every time (the package never keeps an old name in its globals).
    for _ in range(2):
        space = {}
        with pytest.warns(DeprecationWarning, match=message):
            exec(f"from {module} import {old}", space)
        assert space[old] is getattr(mod, new)
    if "__all__" in vars(mod):      # `import *` still gives the old name (with the warning)
        assert old in mod.__all__ and new in mod.__all__


@pytest.mark.parametrize("module, new", sorted({(m, n) for m, _, n in RENAMED}))
def test_the_new_name_warns_of_nothing(module, new):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        space = {}
        exec(f"from {module} import {new}", space)
        assert space[new].__name__ == new


def test_an_unknown_name_is_still_an_attribute_error():
    for module, _, _ in RENAMED:
        with pytest.raises(AttributeError, match=f"module '{module}' has no attribute 'RunReports'"):
            getattr(importlib.import_module(module), "RunReports")


def test_a_subclass_of_an_old_reference_name_runs_as_the_new_one():
    """A mutant written against 0.2.0 (`class Mine(TADDMachine)`) is built and run as before."""
    from plcvec_reference import make_machine

    with pytest.warns(DeprecationWarning):
        from plcvec_reference.fx5_tadd import TADDMachine

    class Mine(TADDMachine):
        pass

    machine = make_machine("fx5-time-add", {}, {}, None, cls=Mine)
    assert isinstance(machine, Mine)
    from plcvec_reference.fx5_tadd import Fx5TimeAdd
    assert isinstance(machine, Fx5TimeAdd)


def test_describe_is_the_failure_block_the_summary_prints():
    """describe(verdict) (VOCABULARY.md) is, for each failing vector, the block `plcvec verify` prints."""
    from plcvec_reference.mutants.report import run_mutant
    from plcvec_verify import Selection, Suite
    from plcvec_verify.describe import describe
    from plcvec_verify.reports import summary_text

    suite = Suite.load(REPO / "vectors")
    report = run_mutant(suite, "tadd-no-wrap-at-24", Selection(families=("fx5-time-add",)))
    failed = [r for r in report.results if r.status == "fail"]
    assert failed
    defaults = {i: d["default"] for i, d in suite.interpretations().items()}
    followed = {**defaults, **{i: d["alternative"] for i, d in report.interpretations.items()}}
    text = summary_text(report)
    for r in failed[:3]:
        one = describe(r, suite.by_id[r.id], followed, defaults, suite.expectations)
        assert one.startswith(f"FAIL {r.id}\n") and "\n    step " in one
        assert one + "\n" in text, one


@pytest.mark.parametrize("module, line", [
    ("runner.py", "    from ._report import Report as RunReport  # noqa: F401\n"),
    ("runner.py", "    from .verdict import Verdict as VectorResult  # noqa: F401\n"),
], ids=["RunReport", "VectorResult"])
def test_the_api_check_sees_the_old_name_by_its_import(tmp_path, module, line):
    """Without the import static tools read, the old name is gone to the API check against 0.1.0, though
    __getattr__ still gives it at run time: the check is what holds the old name in place."""
    from test_api_check import check

    copy = tmp_path / "python"
    shutil.copytree(REPO / "verifiers" / "python", copy, ignore=shutil.ignore_patterns("__pycache__"))
    path = copy / "plcvec_verify" / module
    text = path.read_text(encoding="utf-8")
    assert line in text
    path.write_text(text.replace(line, "    pass\n"), encoding="utf-8")
    proc = check("--new", str(copy))
    assert proc.returncode == 1
    name = line.split(" as ")[1].split()[0]
    assert f"plcvec_verify.runner.{name}: " in proc.stderr, proc.stderr
