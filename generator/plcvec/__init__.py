"""plcvec: conformance test vectors for PLC clock and calendar instructions."""

__version__ = "0.2.0"
# Bumped when the vector file format changes incompatibly (see verifiers/CONTRACT.md).
SCHEMA_VERSION = "1.0.0"
