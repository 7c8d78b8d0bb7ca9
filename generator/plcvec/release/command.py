"""`plcvec release --out DIR`: plcvec-vectors-<version>.tar.gz and .zip, byte-identical on every run.

Bundle (release/bundle.py): the vector files, their JSON Lines form, the CSV, the schemas, the
manifest, the review (HTML and Markdown), CONTRACT.md and PROTOCOL.md, CHANGES.md made by `plcvec
diff` against the previous release (--previous), and SHA256SUMS. The version is the suite version;
CONTRACT.md ("Suite version") says when it moves, and a release that breaks the rule is refused.
"""
import hashlib
from pathlib import Path

from plcvec.errors import PlcvecError
from plcvec.output.workers import add_jobs_option


def register(sub, spec_parent):
    from plcvec_verify.locate import default_vectors_text

    r = sub.add_parser("release", parents=[spec_parent], description=__doc__,
                       help="write the versioned release archives (.tar.gz, .zip) of the golden set")
    r.add_argument("--out", required=True, metavar="DIR", help="folder for the two archives")
    r.add_argument("--previous", metavar="DIR|ARCHIVE|REV",
                   help="the previous release, for CHANGES.md: a vector folder or unpacked release, a release archive, "
                        "or a git revision (e.g. v0.1.0); without it the release says it is the first")
    r.add_argument("--vectors", metavar="DIR",
                   help=f"the committed vector folder, which must match the spec (default: {default_vectors_text()})")
    r.add_argument("--manual-dir", metavar="DIR", help="check the review's quotes against the manual text")
    add_jobs_option(r)
    r.set_defaults(func=run)


def _license_text() -> bytes:
    """The LICENSE to ship: the checkout's, else the one the installed distribution's metadata carries
    (a wheel holds it once, in its .dist-info, not again as package data)."""
    from importlib import metadata

    from plcvec_verify.locate import checkout

    root = checkout()
    try:
        if root is not None:
            return (root / "LICENSE").read_bytes()
        files = metadata.distribution("plcvec").files or ()
        found = next((f for f in files if f.name == "LICENSE" and ".dist-info" in str(f)), None)
        if found is None:
            raise OSError("the installed plcvec's metadata holds no LICENSE")
        return found.read_binary()
    except (OSError, metadata.PackageNotFoundError) as exc:
        raise PlcvecError(f"release: the LICENSE to ship: {exc}") from None


def run(args):
    from plcvec_verify.errors import VerifyError
    from plcvec_verify.locate import default_vectors, inside_installation, locate

    from plcvec import SCHEMA_VERSION, __version__
    from plcvec.output.atomic import write_atomic
    from plcvec.release import archive, bundle, changes
    from plcvec.spec.loader import load_spec

    out = Path(args.out)
    if inside_installation(out):
        raise PlcvecError(f"release: --out {out}: inside the Python installation (site-packages); name a folder of your own")
    if out.exists() and not out.is_dir():
        raise PlcvecError(f"release: --out {out}: not a folder")
    try:
        vectors_dir = Path(args.vectors) if args.vectors else default_vectors().path
        docs_dir = locate("plcvec_verify", "verifiers", "CONTRACT.md").path
    except VerifyError as exc:
        raise PlcvecError(f"release: {exc}") from None
    previous = changes.load_previous(args.previous) if args.previous else None   # a bad name fails before the work

    families = load_spec(args.spec_dir)
    golden, by_family = bundle.golden_checked(families, vectors_dir, args.jobs)
    current = bundle.current_set(golden, __version__)
    try:
        changelog_path = locate("plcvec_verify", ".", "CHANGES.md").path / "CHANGES.md"
        changelog = changelog_path.read_text(encoding="utf-8")
    except (VerifyError, OSError) as exc:
        raise PlcvecError(f"release: the changelog to ship (CHANGES.md): {exc}") from None
    text, report = changes.changes_text(__version__, current, previous, args.previous, changelog)
    if report is not None:
        old_schema = str(previous.manifest.get("schema_version", ""))
        changes.check_version(__version__, previous.manifest.get("suite_version")
                              or previous.manifest.get("generator_version", ""),
                              changes.required_bump(report, old_schema, SCHEMA_VERSION))
    license_text = _license_text()
    files = bundle.bundle(__version__, golden, vectors_dir, _review(families, by_family, args.manual_dir), docs_dir,
                          text, license_text)

    name = bundle.root_name(__version__)
    written = []
    for suffix, make in ((".tar.gz", archive.tar_gz), (".zip", archive.zip_bytes)):
        target = out / f"{name}{suffix}"
        write_atomic(target, make(files))
        written.append(str(target))
    # The C library's source, for CMake's FetchContent (verifiers/c/README.md): from a checkout only.
    from plcvec_verify.locate import checkout

    root = checkout()
    c_files = bundle.c_source(__version__, root) if root is not None else None
    if c_files is None:
        print("plcvec release: no git checkout here, so no C source archive (plcvec-c-<version>.tar.gz)")
    else:
        target = out / f"{bundle.c_root_name(__version__)}.tar.gz"
        write_atomic(target, archive.tar_gz(c_files))
        written.append(str(target))
    # SHA256SUMS beside the archives too, so a download can be checked before it is unpacked; lines
    # for other files already listed there (an earlier release in the same folder) are kept.
    sums = out / "SHA256SUMS"
    lines = {}
    if sums.is_file():
        for line in sums.read_text(encoding="utf-8").splitlines():
            digest, _, fname = line.partition("  ")
            if fname:
                lines[fname] = digest
    for path in written:
        lines[Path(path).name] = hashlib.sha256(Path(path).read_bytes()).hexdigest()
    write_atomic(sums, "".join(f"{lines[n]}  {n}\n" for n in sorted(lines)).encode("utf-8"))
    t = report["totals"] if report else None
    summary = "first release" if report is None else ", ".join(f"{n} {k}" for k, n in t.items() if n) or "no vector differs"
    print(f"plcvec release {__version__}: {len(files)} files, {current.count()} vectors ({summary}); "
          f"wrote {', '.join(written)}")
    return 0


def _review(families, by_family, manual_dir):
    from plcvec.review.model import build_model, run_audit
    from plcvec.review.quotes import check_quotes, read_manual
    from plcvec.review.render import render

    quotes = check_quotes(families, read_manual(manual_dir)) if manual_dir else None
    return render(build_model(families, by_family, quotes=quotes, audit=run_audit(families)))
