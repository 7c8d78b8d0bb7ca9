"""The report of a `--check` that found committed files differing from what would be written."""
import sys


def report_drift(command: str, what: str, differ: list[str], fix: str) -> int:
    """Print each differing file under a heading and the command that mends them; 1, or 0 if none."""
    if not differ:
        return 0
    print(f"{command}: {what}:", file=sys.stderr)
    for line in differ:
        print(f"  {line}", file=sys.stderr)
    print(f"run `{fix}` and commit the result", file=sys.stderr)
    return 1
