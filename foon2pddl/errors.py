"""Errors and warnings that point at a place in an input file."""

from __future__ import annotations

from dataclasses import dataclass


class FoonError(Exception):
    """Base of every error this package reports to users (CLI exit status 2)."""

    def __init__(self, path: str, line: int, message: str, text: str | None = None) -> None:
        self.path = path
        self.line = line
        self.message = message
        self.text = text
        super().__init__(self.location() + ": " + message)

    def location(self) -> str:
        """`path:line`; line 0 when the problem is not on a line (a directory, a missing file)."""
        return f"{self.path}:{self.line}"

    def __str__(self) -> str:
        text = f"{self.location()}: {self.message}"
        if self.text is not None:
            text += f"\n    {self.text!r}"
        return text


class FoonSyntaxError(FoonError):
    """A FOON, kitchen, goal or rates file that does not follow its format."""


class FoonInputError(FoonError):
    """Input that parses but cannot be used (unknown goal label, missing file, ...)."""


@dataclass(frozen=True)
class ParseWarning:
    """Something skipped while reading, with its place."""

    path: str
    line: int
    message: str

    def __str__(self) -> str:
        return f"{self.path}:{self.line}: warning: {self.message}"
