"""plcvec: conformance test vectors for PLC clock and calendar instructions."""

__version__ = "0.2.0"
# The vector file format (semver): a minor version adds optional keys, a major one changes what a key
# means (see verifiers/CONTRACT.md, Versioning).
SCHEMA_VERSION = "1.1.0"
