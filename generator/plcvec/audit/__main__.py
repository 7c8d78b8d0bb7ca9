"""python3 -m plcvec.audit [--spec-dir DIR] [--json]: print the audit of the manual's tables."""
import argparse
import sys

from plcvec.audit import audit_families
from plcvec.errors import PlcvecError
from plcvec.spec.files import default_spec_help
from plcvec.spec.loader import load_spec


def main(argv=None):
    p = argparse.ArgumentParser(prog="python3 -m plcvec.audit", description=__doc__.split(":")[1].strip())
    p.add_argument("--spec-dir", help=f"folder of spec *.yaml files (default: {default_spec_help()})")
    p.add_argument("--json", action="store_true", help="print the findings as JSON")
    args = p.parse_args(argv)
    try:
        report = audit_families(load_spec(args.spec_dir))
    except PlcvecError as exc:
        print(f"plcvec audit: {exc}", file=sys.stderr)
        return exc.exit_code
    sys.stdout.write(report.to_json() if args.json else report.text())
    return 0


if __name__ == "__main__":
    sys.exit(main())
