"""python3 -m plcvec_reference.mutants [VECTORS_DIR]: print the table of MUTANTS.md from a fresh run."""
import sys
from pathlib import Path

from plcvec_verify import Suite

from .report import table

if __name__ == "__main__":
    sys.stdout.write(table(Suite.load(Path(sys.argv[1] if len(sys.argv) > 1 else "vectors"))))
