import json
import os
import sys
from pathlib import Path

import pytest

# The suite starts about a hundred Python processes (the CLI, stdio adapters, pytest itself). Where
# the environment forbids bytecode caches (PYTHONDONTWRITEBYTECODE, common in CI images), each of
# them compiled every module it imported, and pytest rewrote every test module in every worker:
# about a second a process. The caches (__pycache__, ignored by git) are written as Python
# normally does for the processes this session starts.
os.environ.pop("PYTHONDONTWRITEBYTECODE", None)
sys.dont_write_bytecode = False

REPO = Path(__file__).resolve().parents[1]
MANUAL_DIR = REPO.parent / "shared" / "manual"


@pytest.fixture(scope="session")
def repo():
    return REPO


@pytest.fixture(scope="session")
def families():
    from plcvec.spec.loader import load_spec

    return {f.name: f for f in load_spec(REPO / "spec")}


@pytest.fixture(scope="session")
def golden():
    """The committed vector files, {family: parsed file}."""
    manifest = json.loads((REPO / "vectors" / "manifest.json").read_text())
    return {name: json.loads((REPO / "vectors" / entry["file"]).read_text())
            for name, entry in manifest["families"].items()}


@pytest.fixture(scope="session")
def all_vectors(golden):
    return [v for f in golden.values() for v in f["vectors"]]


@pytest.fixture(scope="session")
def generated(families):
    """The golden set generated once per test session from spec/: ({file name: text}, {family: vectors}).

    Tests only read it; a test that needs the vectors of an edited spec generates those itself.
    """
    from plcvec.output.golden import build_golden

    return build_golden(list(families.values()))
