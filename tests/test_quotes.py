"""Every provenance quote in the spec is found, verbatim up to white space, in the manual text."""
import os
import re

import pytest

from conftest import MANUAL_DIR


def squash(text):
    return re.sub(r"\s+", "", text)


def quotes(doc):
    def walk(node, where):
        if isinstance(node, dict):
            if "quote" in node and isinstance(node["quote"], str):
                yield where, node.get("file"), node["quote"]
            for k, v in node.items():
                yield from walk(v, where + (k,))
        elif isinstance(node, list):
            for i, v in enumerate(node):
                yield from walk(v, where + (i,))
    yield from walk(doc, ())


def test_every_quote_is_in_the_manual(families):
    if not MANUAL_DIR.is_dir():
        if os.environ.get("CI"):
            pytest.fail(f"{MANUAL_DIR} is missing: CI must run with shared/ beside the repository")
        pytest.skip("the manual excerpts (../shared/manual) are not beside this checkout")
    texts = {p.name: squash(p.read_text(encoding="utf-8")) for p in MANUAL_DIR.iterdir() if p.is_file()}
    missing, count = [], 0
    for fam in families.values():
        for where, file, quote in quotes(fam.doc):
            count += 1
            source = file or fam.doc["manual"]
            if squash(quote) not in texts[source]:
                missing.append(f"{fam.path.name}:{fam.line_of(*where)}: not in {source}: {quote[:80]!r}")
    assert count > 100
    assert not missing, "\n".join(missing)
