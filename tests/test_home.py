"""One home, one version, one licence: every package names the repository written once in
pyproject.toml ([tool.plcvec] home), carries the suite version and the MIT licence text, and no
placeholder for the home is left anywhere."""
import json
import re
import subprocess
import tomllib
import xml.etree.ElementTree as ET

import pytest

from plcvec import __version__

from conftest import REPO

PYPROJECT = tomllib.loads((REPO / "pyproject.toml").read_text(encoding="utf-8"))
HOME = PYPROJECT["tool"]["plcvec"]["home"]
LICENSE = (REPO / "LICENSE").read_bytes()
POM = "{http://maven.apache.org/POM/4.0.0}"


def test_home_is_a_repository_url_and_python_names_it():
    assert re.fullmatch(r"https://github\.com/[\w.-]+/[\w.-]+", HOME)
    urls = PYPROJECT["project"]["urls"]
    assert urls["Homepage"] == urls["Source"] == HOME
    assert all(u.startswith(HOME) for u in urls.values())
    assert PYPROJECT["project"]["license"] == "MIT"


def test_rust_crate():
    cargo = tomllib.loads((REPO / "verifiers" / "rust" / "Cargo.toml").read_text(encoding="utf-8"))["package"]
    assert cargo["repository"] == HOME
    assert cargo["version"] == __version__
    assert cargo["license"] == "MIT"
    assert (REPO / "verifiers" / "rust" / "LICENSE").read_bytes() == LICENSE


def test_npm_package():
    pkg = json.loads((REPO / "verifiers" / "typescript" / "package.json").read_text(encoding="utf-8"))
    repo = pkg["repository"]
    url = repo["url"] if isinstance(repo, dict) else repo
    assert url.removeprefix("git+").removesuffix(".git") == HOME
    assert pkg["homepage"].startswith(HOME) and pkg["bugs"]["url"].startswith(HOME)
    assert pkg["version"] == __version__ and pkg["license"] == "MIT"
    assert (REPO / "verifiers" / "typescript" / "LICENSE").read_bytes() == LICENSE


def test_go_module_path_is_the_home():
    first = (REPO / "verifiers" / "go" / "go.mod").read_text(encoding="utf-8").splitlines()[0]
    assert first == "module " + HOME.removeprefix("https://") + "/verifiers/go"
    assert (REPO / "verifiers" / "go" / "LICENSE").read_bytes() == LICENSE


def _poms():
    return sorted((REPO / "verifiers" / "java").glob("**/pom.xml"))


def test_java_poms():
    poms = _poms()
    assert poms
    root = ET.parse(REPO / "verifiers" / "java" / "pom.xml").getroot()
    assert root.findtext(f"{POM}groupId") == "io.github.plcvec"
    assert root.findtext(f"{POM}version") == __version__
    assert root.findtext(f"{POM}url") == HOME
    assert root.findtext(f"{POM}scm/{POM}url") == HOME
    assert root.findtext(f"{POM}licenses/{POM}license/{POM}name") == "MIT"
    assert root.find(f"{POM}developers") is not None
    relocation = REPO / "verifiers" / "java" / "relocation"
    for pom in poms:
        text = pom.read_text(encoding="utf-8")
        if relocation in pom.parents:
            # 0.1.0's coordinates, kept only to point at the new ones (a Maven relocation).
            tree = ET.parse(pom).getroot()
            assert tree.findtext(f"{POM}groupId") == "org.plcvec", pom
            assert tree.findtext(f"{POM}distributionManagement/{POM}relocation/{POM}groupId") == "io.github.plcvec", pom
            continue
        assert "org.plcvec</groupId>" not in text, pom


def test_cmake_package():
    cmake = (REPO / "verifiers" / "c" / "CMakeLists.txt").read_text(encoding="utf-8")
    m = re.search(r"project\(\s*plcvec\b([^)]*)\)", cmake, re.S)
    assert m, "project(plcvec ...) in verifiers/c/CMakeLists.txt"
    version = re.search(r"VERSION\s+(\S+)", m.group(1)).group(1)
    if version == "${PLCVEC_SUITE_VERSION}":   # rendered by `plcvec export` from the vectors' suite version
        generated = (REPO / "verifiers" / "c" / "src" / "generated" / "families.cmake").read_text(encoding="utf-8")
        version = re.search(r"set\(PLCVEC_SUITE_VERSION\s+\"?([\w.]+)", generated).group(1)
    assert version == __version__
    assert HOME in m.group(1)


def test_no_placeholder_for_the_home_anywhere():
    files = subprocess.run(["git", "ls-files"], cwd=REPO, capture_output=True, text=True, check=True).stdout.split()
    placeholder = re.compile(r"\b(OWNER|HOST)/|<this repository>|example\.com/plcvec|org\.plcvec</groupId>")
    found = []
    for name in files:
        path = REPO / name
        if path.suffix in (".json", ".jsonl", ".csv") or not path.is_file() or name == "tests/test_home.py":
            continue
        if name.startswith(("verifiers/java/relocation/", "verifiers/java/relocation-check")):   # the old coordinates, relocated on purpose
            continue
        try:
            text = path.read_text(encoding="utf-8")
        except UnicodeDecodeError:
            continue
        found += [f"{name}:{text.count(chr(10), 0, m.start()) + 1}: {m.group(0)}" for m in placeholder.finditer(text)]
    assert not found, "\n".join(found)


@pytest.mark.parametrize("lang", ["rust", "typescript", "go"])
def test_each_package_folder_licence_is_the_repository_licence(lang):
    assert (REPO / "verifiers" / lang / "LICENSE").read_bytes() == LICENSE


def test_one_licence_statement():
    """The copyright holder the LICENSE names is the author every package's metadata names."""
    holder = re.search(r"^Copyright \(c\) \d{4} (.+)$", LICENSE.decode(), re.M).group(1)
    assert [a["name"] for a in PYPROJECT["project"]["authors"]] == [holder]
    cargo = tomllib.loads((REPO / "verifiers" / "rust" / "Cargo.toml").read_text(encoding="utf-8"))["package"]
    assert cargo["authors"] == [holder]
    pkg = json.loads((REPO / "verifiers" / "typescript" / "package.json").read_text(encoding="utf-8"))
    assert pkg["author"] == holder
    root = ET.parse(REPO / "verifiers" / "java" / "pom.xml").getroot()
    assert root.findtext(f"{POM}developers/{POM}developer/{POM}name") == holder
