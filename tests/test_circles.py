"""`.ci/circles.py`: it finds a circle between modules, a circle between the generator's folders and an
import against the stages' order, and finds none in the project."""
import importlib.util
import subprocess
import sys

from conftest import REPO

spec = importlib.util.spec_from_file_location("circles", REPO / ".ci" / "circles.py")
circles = importlib.util.module_from_spec(spec)
spec.loader.exec_module(circles)


def test_a_circle_at_any_depth_is_found():
    graph = {"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}
    assert circles.circles(graph) == [["a", "b", "c"]]
    assert circles.circles({"a": {"b"}, "b": set()}) == []


def test_folders_that_import_each_other_are_a_circle():
    graph = {"plcvec.spec.loader": {"plcvec.cases.build"}, "plcvec.cases.build": {"plcvec.spec.knobs"},
             "plcvec.spec.knobs": set()}
    stages = circles.stage_graph(graph)
    assert stages == {"plcvec.spec": {"plcvec.cases"}, "plcvec.cases": {"plcvec.spec"}}
    assert circles.circles(stages) == [["plcvec.cases", "plcvec.spec"]]


def test_an_import_of_a_later_stage_and_an_unplaced_stage_are_reported():
    found = circles.upstream_imports({"plcvec.spec": {"plcvec.output"}, "plcvec.output": {"plcvec.spec"},
                                      "plcvec.newstage": {"plcvec.spec"}})
    assert found == ["stage plcvec.newstage is not in STAGES (.ci/circles.py): place it in the order",
                     "stage plcvec.spec imports plcvec.output, which comes after it in STAGES"]
    assert circles.upstream_imports({"plcvec.output": {"plcvec.spec", "plcvec.errors"}}) == []


def test_the_project_has_no_circle():
    proc = subprocess.run([sys.executable, str(REPO / ".ci" / "circles.py")], capture_output=True, text=True,
                          timeout=120)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert "circles: 0 between modules, 0 between folders; 0 against the stages' order" in proc.stdout
