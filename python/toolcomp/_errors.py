"""The exception classes of toolcomp. Every error carries a stable ``code`` and the
``line`` and ``column`` (1-based; 0 when unknown) of the program or table text it is about,
and ``file``: the called program or subprogram file that line is in (None: the main
program, or the table read)."""


class Error(Exception):
    """Base class of every toolcomp error."""

    def __init__(self, message, code="error", line=0, column=0, file=None):
        super().__init__(message)
        self.message = message
        self.code = code
        self.line = line
        self.column = column
        self.file = file

    def __str__(self):
        where = f"line {self.line}" if self.line else ""
        if where and self.file:
            where += f" of {self.file}"
        if where and self.column:
            where += f", column {self.column}"
        return f"{self.message} [{self.code}{', ' + where if where else ''}]"

    def __reduce__(self):
        return (type(self), (self.message, self.code, self.line, self.column, self.file))


class ParseError(Error):
    """The program text is not valid in its dialect."""


class ProgramError(Error):
    """The control would refuse to run the program (an interpreter error)."""


class CompensationError(Error):
    """Tool compensation cannot be applied (gouge, radius too large, ...)."""


class ToolTableError(Error):
    """A tool table cannot be read, written or used."""
