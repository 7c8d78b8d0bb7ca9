import sys

from plcvec.cli import main

sys.exit(main())
