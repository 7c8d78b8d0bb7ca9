"""User-facing errors: each names the file and line (or vector id) and prints without a traceback."""


class PlcvecError(Exception):
    """An error caused by the user's input, reported as one plain message and exit status 2."""

    exit_code = 2


class SpecError(PlcvecError):
    def __init__(self, path, line, message):
        self.path, self.line, self.message = str(path), line, message
        where = f"{self.path}:{line}" if line else self.path
        super().__init__(f"{where}: {message}")

    def __reduce__(self):
        # Rebuilt from its parts, not from the one message Exception keeps (a worker process that
        # meets it sends it to the parent pickled).
        return SpecError, (self.path, self.line, self.message)
