"""The verifier's one error type: a user's or an adapter's mistake, reported without a traceback."""


class VerifyError(Exception):
    """A usage or harness error: bad vector path, bad expectations file, adapter that cannot start.

    The command prints the message and exits 2 (failing vectors exit 1).
    """

    exit_code = 2
