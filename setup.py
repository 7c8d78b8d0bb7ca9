"""The build step pyproject.toml cannot declare: copy the spec and the vectors into the packages.

The spec (`spec/`: family files, schemas, regressions) and the golden vectors (`vectors/`: family
files, manifest, CSV, schema) live at the top of the repository, outside any package. A built
wheel carries a copy of each as package data, where the commands find them with importlib.resources
(plcvec_verify/locate.py):

    plcvec/_data/spec/...            the spec, for generate --check, lint, review, fuzz, exhaustive
    plcvec_verify/_data/vectors/...  the golden vectors, for verify and the pytest plugin
    plcvec_verify/_data/verifiers/   CONTRACT.md, PROTOCOL.md and parity/ (TEXT.md, text/), for release

An editable install copies nothing: it runs from the checkout, whose own folders are used.
Everything else is declared in pyproject.toml.
"""
import shutil
from pathlib import Path

from setuptools import setup
from setuptools.command.build_py import build_py

HERE = Path(__file__).resolve().parent
DATA = "_data"
# (source relative to the repository, package, destination inside the package's data folder)
COPIES = [
    ("spec", "plcvec", "spec"),
    ("vectors", "plcvec_verify", "vectors"),
    ("verifiers/CONTRACT.md", "plcvec_verify", "verifiers/CONTRACT.md"),
    ("verifiers/PROTOCOL.md", "plcvec_verify", "verifiers/PROTOCOL.md"),
    ("verifiers/parity/TEXT.md", "plcvec_verify", "verifiers/parity/TEXT.md"),
    ("verifiers/parity/text", "plcvec_verify", "verifiers/parity/text"),
    ("CHANGES.md", "plcvec_verify", "CHANGES.md"),   # the changelog a release bundle carries
]
SKIP = ("__pycache__", ".*", "*.pyc", "*.tmp")


class build_py_with_data(build_py):
    def run(self):
        super().run()
        if getattr(self, "editable_mode", False):
            return
        for source, package, name in COPIES:
            src, dst = HERE / source, Path(self.build_lib) / package / DATA / name
            if not src.exists():
                raise SystemExit(f"setup.py: {src} is missing; a plcvec distribution needs it")
            if dst.exists():
                shutil.rmtree(dst) if dst.is_dir() else dst.unlink()
            dst.parent.mkdir(parents=True, exist_ok=True)
            if src.is_dir():
                shutil.copytree(src, dst, ignore=shutil.ignore_patterns(*SKIP))
            else:
                shutil.copyfile(src, dst)


setup(cmdclass={"build_py": build_py_with_data})
