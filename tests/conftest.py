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

# A vector file found valid is remembered in a cache folder (plcvec_verify/validate.py), found from
# HOME unless PLCVEC_CACHE_DIR names it. pytester gives each in-process session a HOME of its own,
# so without this every such session validated the whole golden set again (several seconds each),
# which no user's second run does. The folder named here is the one this session's HOME gives;
# tests of the cache itself set their own.
if not os.environ.get("PLCVEC_CACHE_DIR"):
    from plcvec_verify.validate import _cache_dir

    _valid_files = _cache_dir()
    if _valid_files is not None:
        os.environ["PLCVEC_CACHE_DIR"] = str(_valid_files.parent)

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
def real_review(tmp_path_factory):
    """`plcvec review --check` of the real spec against the manual, run once per worker as a user runs
    it: (the finished process, its out folder). The review, provenance, wording-note, accounting and
    browser tests only read it (about 1.5 s a run); a test that needs the review of an edited spec or
    other options runs that itself."""
    import subprocess

    if not MANUAL_DIR.is_dir():
        pytest.fail(f"{MANUAL_DIR} is missing: the review tests read the manual beside the repository")
    out = tmp_path_factory.mktemp("review")
    done = subprocess.run([sys.executable, "-m", "plcvec", "review", "--check", "--manual-dir", str(MANUAL_DIR),
                           "--out", str(out)], capture_output=True, text=True, timeout=120,
                          env=dict(os.environ, PYTHONHASHSEED="0"))
    return done, out


@pytest.fixture(scope="session")
def generated(families):
    """The golden set generated once per test session from spec/: ({file name: text}, {family: vectors}).

    Tests only read it; a test that needs the vectors of an edited spec generates those itself.
    """
    from plcvec.output.golden import build_golden

    return build_golden(list(families.values()))


# Under `pytest -n` (pytest-xdist) these run on one worker each, one test after another: their module
# fixtures are costly (a release, the review, a build of the whole set, every mutant's report) and would
# otherwise be made again in every worker that runs some of their tests. Keys are a module or a test;
# everything else is spread test by test, as xdist's default (`--dist load`) does.
ONE_WORKER = {
    "tests/test_mutants.py": "each mutant's in-process report; the coverage cells of the whole set",
    "tests/test_release.py": "two `plcvec release` runs",
    "tests/test_review.py": "`plcvec review --check` of the real spec",
    "tests/test_review_browser.py": "the review page and Chromium's rendering of it",
    "tests/test_diff.py": "edited copies of vectors/, the HEAD copy",
    "tests/test_exhaustive.py": "cp1e's exhaustive tier",
    "tests/test_audit.py": "the audit of the real spec",
    "tests/test_fuzz.py::test_pulse_form_on_every_scan_is_shrunk_to_two_scans": "the every-scan fuzz run",
    "tests/test_fuzz.py::test_the_printed_vector_is_ready_to_run": "the every-scan fuzz run",
}


def one_worker_group(nodeid):
    """The ONE_WORKER key `nodeid` falls under (its test, else its module), or None."""
    test = nodeid.split("[", 1)[0]
    if test in ONE_WORKER:
        return ONE_WORKER[test]
    module = nodeid.split("::", 1)[0]
    return module if module in ONE_WORKER else None


@pytest.hookimpl(optionalhook=True)
def pytest_xdist_make_scheduler(config, log):
    """xdist's load scheduling with the ONE_WORKER groups kept together. (Its own `--dist loadgroup`
    marks no group under pytest 9, whose node ids it can no longer suffix.) An explicit `--dist` other
    than the default `load` is followed as given."""
    if config.getoption("dist") != "load":
        return None
    from xdist.scheduler import LoadScopeScheduling

    class OneWorkerGroups(LoadScopeScheduling):
        def _split_scope(self, nodeid):
            return one_worker_group(nodeid) or nodeid

    return OneWorkerGroups(config, log)


def pytest_collection_finish(session):
    """Tune the cyclic garbage collector for this session: a worker holds many loaded vector sets
    (fixtures, caches), and with CPython's default thresholds each of the many collections that
    loading or generating triggers walks them all again, which took about 40% of the suite's CPU.
    One pass now leaves what the modules and collection built in the oldest generation, and the
    collector runs less often; the vectors are trees of plain JSON values, which free themselves
    without it. Nothing is frozen (gc.freeze): with nothing frozen, each load of a vector set
    (plcvec_verify.collector.collector_paused) moves what it built to the oldest generation at once,
    instead of leaving it to the young generations' next passes (the collector's time in a whole
    run: 9.4 to 9.9 s of CPU with the modules frozen, 7.8 to 8.7 s so)."""
    import gc

    gc.collect()
    gc.set_threshold(50_000, 20, 20)
