"""Where the commands find the spec and vectors, and where `generate` refuses to write.

The installed case (a built wheel or sdist in a fresh virtual environment, run from a temporary
folder) is exercised end to end by .ci/package-check.sh; these tests cover the rules themselves.
"""
import re
import subprocess
import sys
import sysconfig
from pathlib import Path

import pytest

from plcvec_verify import locate

from conftest import REPO


def plcvec(*args, cwd):
    return subprocess.run([sys.executable, "-m", "plcvec", *args], capture_output=True, text=True, cwd=cwd, timeout=300)


def make_checkout(folder, name="plcvec"):
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "pyproject.toml").write_text(f'[project]\nname = "{name}"\nversion = "0"\n', encoding="utf-8")
    return folder


def test_a_checkout_is_found_from_any_folder_inside_it(tmp_path):
    root = make_checkout(tmp_path / "repo")
    deep = root / "a" / "b"
    deep.mkdir(parents=True)
    assert locate.checkout_of(deep) == root.resolve()
    assert locate.checkout_of(root) == root.resolve()


def test_another_project_is_not_a_checkout(tmp_path):
    other = make_checkout(tmp_path / "theirs", name="plcvec-adapter")
    assert locate.checkout_of(other) != other.resolve()
    assert not locate.is_checkout(other)
    assert not locate.is_checkout(tmp_path / "missing")


def test_the_checkout_around_the_current_folder_wins(tmp_path, monkeypatch):
    root = make_checkout(tmp_path / "repo")
    monkeypatch.chdir(root)
    found = locate.default_vectors()
    assert (found.path, found.kind) == (root.resolve() / "vectors", "checkout")
    assert "the checkout" in found.describe()


def test_from_elsewhere_the_source_tree_in_use_is_the_checkout(tmp_path, monkeypatch):
    # This test runs the packages from this repository's source folders (not a built install).
    monkeypatch.chdir(tmp_path)
    assert locate.default_vectors().path == REPO.resolve() / "vectors"


def test_site_packages_is_an_installation():
    purelib = Path(sysconfig.get_paths()["purelib"])
    assert locate.inside_installation(purelib / "somewhere" / "vectors")
    assert locate.inside_installation(purelib)
    assert not locate.inside_installation(REPO / "vectors")


def test_generate_refuses_to_write_into_site_packages(tmp_path):
    target = Path(sysconfig.get_paths()["purelib"]) / "plcvec-test-never-written"
    proc = plcvec("generate", "--out", str(target), cwd=tmp_path)
    assert proc.returncode == 2, proc.stderr
    assert "site-packages" in proc.stderr and "Traceback" not in proc.stderr
    assert not target.exists()


def _unwrapped(text: str) -> str:
    """argparse's help with its wrapping undone: it breaks lines at spaces and after hyphens (a checkout
    at /work/my-checkout may be printed as /work/my-<newline><indent>checkout)."""
    return re.sub(r"(?<=-)\n\s+", "", re.sub(r"(?<![-\s])\n\s+", " ", text))


def test_help_says_which_folders_are_used(tmp_path):
    out = plcvec("generate", "--help", cwd=REPO).stdout
    assert str(REPO.resolve() / "vectors") in _unwrapped(out)
    assert "the checkout" in out
    verify = plcvec("verify", "--help", cwd=REPO).stdout
    assert str(REPO.resolve() / "vectors") in _unwrapped(verify)


@pytest.mark.parametrize("text, want", [
    ("folder (default: /work/my-\n                  checkout/vectors (the checkout))", "/work/my-checkout/vectors"),
    ("folder (default: /tmp/a\n   b/vectors)", "/tmp/a b/vectors"),
])
def test_unwrapping_the_help_undoes_argparses_breaks(text, want):
    assert want in _unwrapped(text)


def test_version_prints_suite_spec_hash_and_schema(tmp_path):
    import json

    proc = plcvec("--version", cwd=REPO)
    assert proc.returncode == 0, proc.stderr
    manifest = json.loads((REPO / "vectors" / "manifest.json").read_text(encoding="utf-8"))
    assert f"suite version {manifest['generator_version']}" in proc.stdout
    assert f"vector schema version {manifest['schema_version']}" in proc.stdout
    assert f"spec sha256 {manifest['spec_sha256']}" in proc.stdout
