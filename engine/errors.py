"""Errors a user can cause, with the file and line they come from.

Every exception a researcher can trigger with bad input (a malformed model
file, an unknown parameter, a value out of range) derives from
:class:`UserError`. Its ``str()`` is the one line the command line prints
after ``error:``, ``<file>:<line>: <what>``.
"""

from __future__ import annotations

from pathlib import Path


class UserError(Exception):
    """Bad input from the user: reported as one line, never a traceback.

    >>> str(UserError("unknown parameter 'jaw'", file="head.xml", line=12))
    "head.xml:12: unknown parameter 'jaw'"
    """

    def __init__(self, message: str, file: str | Path | None = None, line: int | None = None):
        super().__init__(message)
        self.message = message
        self.file = str(file) if file is not None else None
        self.line = line

    def __str__(self) -> str:
        where = ""
        if self.file is not None:
            where = f"{self.file}:"
            if self.line is not None:
                where += f"{self.line}:"
            where += " "
        return where + self.message


class ModelFileError(UserError):
    """A model file (XML or HDF5) is unreadable, malformed or inconsistent."""


class ParameterError(UserError):
    """An unknown parameter, a value out of range, or an invalid parameter tree."""


class MeshImportError(UserError):
    """A mesh file could not be read as a polygon surface."""


class LibraryError(UserError):
    """A command library file (§2.3 format) is malformed, or does not fit the model."""


class CommandError(UserError):
    """A command file (high- or low-level XML) is malformed, or a command is used wrongly."""
