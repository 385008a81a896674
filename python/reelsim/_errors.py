"""The exceptions: the library's rs_status classes that a caller handles differently."""


class Error(Exception):
    """A reelsim failure. `status` is the library's status name ("input", "solver", ...)."""

    def __init__(self, message, status=None):
        super().__init__(message)
        self.message = message
        self.status = status


class InputError(Error, ValueError):
    """Bad input (the CLI's exit status 2): the message names the file, key and line where
    it can ("scene.yaml:7: winding.tension: must be > 0 ...")."""


class SolverError(Error, ArithmeticError):
    """A solver could not converge or gave no finite answer (the CLI's exit status 3)."""
