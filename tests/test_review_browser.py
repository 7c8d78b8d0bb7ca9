"""The review as a reviewer sees it: opened in headless Chromium, photographed, and read through its DOM.

Chromium is Debian's `chromium` package (.ci/run installs it). Without it the test is skipped on a
workstation, but fails under CI (the CI environment variable set): CI must never skip it silently.
"""
import os
import shutil
import struct
import subprocess
import zlib

import pytest

from review_dom import disagreeing_cells, parse

# End to end through a browser, so in CI's slow lane (`-m slow`): the default run reads the same page's
# DOM in test_review.py (the rules, the findings, the disagreeing cells) without starting Chromium.
pytestmark = pytest.mark.slow

FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync"]
TIMEOUT = 60


def chromium_binary():
    found = shutil.which("chromium") or ("/usr/bin/chromium" if os.path.exists("/usr/bin/chromium") else None)
    if found is None:
        if os.environ.get("CI"):
            pytest.fail("chromium is not installed: CI must install Debian's chromium package (apt-get install -y chromium)")
        pytest.skip("chromium is not installed (Debian: apt-get install -y chromium)")
    return found


def chromium(tmp_path, profile, *args):
    """Run headless Chromium with a fresh profile folder; returns the finished process."""
    return subprocess.run([chromium_binary(), *FLAGS, f"--user-data-dir={tmp_path / profile}", *args],
                          capture_output=True, text=True, timeout=TIMEOUT)


@pytest.fixture(scope="module")
def page(real_review):
    chromium_binary()
    done, out = real_review
    assert done.returncode == 0, done.stderr
    return out / "review.html"


@pytest.fixture(scope="module")
def rendered(page, tmp_path_factory):
    """The DOM Chromium built from the page, by element id."""
    tmp = tmp_path_factory.mktemp("chromium")
    done = chromium(tmp, "profile", "--dump-dom", page.as_uri())
    assert done.returncode == 0, done.stderr[-2000:]
    assert "</html>" in done.stdout
    return parse(done.stdout)[1]


def png_pixels(data):
    """(width, height, decompressed scanlines) of a PNG, read with the standard library."""
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG file"
    pos, idat, size = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            size = struct.unpack(">II", body[:8])
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    return size[0], size[1], zlib.decompress(idat)


def test_screenshot(page, tmp_path):
    shot = tmp_path / "review.png"
    done = chromium(tmp_path, "profile", f"--screenshot={shot}", "--window-size=1280,2000", page.as_uri())
    assert done.returncode == 0, done.stderr[-2000:]
    data = shot.read_bytes()
    width, height, pixels = png_pixels(data)
    assert (width, height) == (1280, 2000)
    # A page of text and tables, not a blank or single-colour frame.
    assert len(data) > 20_000
    assert len(set(pixels[::101])) > 16


def test_rendered_rules(rendered):
    row = rendered["clause-fx5-time-add-carry-and-zero"]
    rule, words = row.find_all("td")
    assert rule.text().startswith("carry-and-zero")
    # The manual's own sentence, beside the rule.
    assert words.first("blockquote").text() == \
        "If 1 second is added to 23:59:59, the result will be 0:00:00. This turns on both the carry flag and the zero flag."
    row = rendered["clause-fx5-time-compare-s3.bit.hour"]
    assert row.first("blockquote").text() == '(3) Set "hour" as comparison target.'
    # CP1E: one word holds two BCD bytes; A351 bits 08-15 the minute, bits 00-07 the second.
    cells = [td.text() for td in rendered["layout-cp1e-time-compare-word0"].find_all("td")]
    assert len(cells) == 2 and cells[0].startswith("minute") and cells[1].startswith("second")
    assert [td.attrs["colspan"] for td in rendered["layout-cp1e-time-compare-word0"].find_all("td")] == ["8", "8"]


def test_rendered_audit_findings(rendered):
    # Printed × where the rule gives continuity: day 29 < 31 (B<C) and month 2 < 3 (A<B).
    assert disagreeing_cells(rendered, "fx5-date-compare", "nonexistent") == {"Day, B<C": ("×", "○"), "Month, A<B": ("×", "○")}
    prose = [n for a, n in rendered.items() if a.startswith("audit-fx5-time-add-carry-prose-vs-table")]
    assert len(prose) == 1 and "14:30:30" in prose[0].text() and "14:20:30" in prose[0].text()
    assert "TADD-CARRY-EXAMPLE-PROSE" in prose[0].text()
