"""The package's one error hierarchy, and warnings that point at a place in an input file.

- `FoonError`: every error reported to users (the CLI exits with status 2);
  it has a location (`path`, `line`) only when the problem is in a file.
- `FoonSyntaxError`, `FoonInputError`: a file that breaks its format, input that
  parses but cannot be used; both name `path:line`, or `path` alone for the file as a whole
  (line 0: missing, unreadable, of the wrong kind).
- `UsageError` (also a `ValueError`): a bad argument or option value, no file.
- `MissingDependencyError`: an optional part that is not installed (Fast
  Downward, WordNet, Graphviz, an extra), with the command that installs it.
- `PlanDecodeError` (also a `ValueError`): a planner's plan that does not map back
  to the task (an unknown action, wrong arguments); `PlanOutcome` reports it as
  its `decode_error`, never raised to the user.

Messages never name command-line flags: only `cli/` knows them. A file of another kind than the input it was
given as (a kitchen given as a network) carries `belongs`, the inputs that take it (`INPUTS`); its message
ends by naming them in words, and the CLI names its options instead.
"""

from __future__ import annotations

import importlib
from dataclasses import dataclass
from types import ModuleType

__all__ = ["INPUTS", "FoonError", "FoonInputError", "FoonSyntaxError", "MissingDependencyError", "ParseWarning",
           "PlanDecodeError", "UsageError", "did_you_mean", "place", "require"]

#: The inputs a file can belong to (`FoonError.belongs`), as the library's messages name them.
INPUTS = {"paths": "as a network (FOON paths)", "kitchen": "as the kitchen", "goals": "as the goal list",
          "constraints": "as the constraints", "rates": "as the motion rates", "utensils": "as the utensils list"}


def place(path: str, line: int) -> str:
    """`path:line`, or `path` alone for line 0 (the file as a whole: a missing file has no line)."""
    return f"{path}:{line}" if line else path


def did_you_mean(name: str, choices) -> str:
    """`; did you mean 'x'?` naming the choice closest to a misspelt `name` (difflib's ratio, cutoff 0.6), or ""."""
    import difflib

    close = difflib.get_close_matches(name, list(choices), n=1)
    return f"; did you mean {close[0]!r}?" if close else ""


class FoonError(Exception):
    """Base of every error this package reports to users (CLI exit status 2).

    `path` and `line` locate the problem in an input file when there is one
    (`line` 0: the file as a whole); `text` is the offending line. `belongs`: for a file of another kind,
    the inputs (`INPUTS` keys) that take it; `what` is then the message without where it goes.
    """

    def __init__(self, message: str, *, path: str | None = None, line: int = 0, text: str | None = None,
                 belongs: tuple[str, ...] = ()) -> None:
        self.path = path
        self.line = line
        self.what = message
        self.belongs = belongs
        self.message = f"{message}: {goes(belongs, INPUTS)}" if belongs else message
        self.text = text
        super().__init__(self.message)

    def location(self) -> str | None:
        """`path:line`, `path` when the problem is the file as a whole (line 0), None when not in a file."""
        return None if self.path is None else place(self.path, self.line)

    def __str__(self) -> str:
        where = self.location()
        text = self.message if where is None else f"{where}: {self.message}"
        if self.text is not None:
            text += f"\n    {self.text!r}"
        return text


def goes(belongs: tuple[str, ...], names: dict[str, str]) -> str:
    """`give it as the kitchen or as the goal list`: where a file of another kind goes, in `names`' words."""
    return "give it " + " or ".join(names[b] for b in belongs)


class FoonSyntaxError(FoonError):
    """A FOON, kitchen, goal or rates file that does not follow its format (or a file of another kind)."""

    def __init__(self, path: str, line: int, message: str, text: str | None = None,
                 belongs: tuple[str, ...] = ()) -> None:
        super().__init__(message, path=path, line=line, text=text, belongs=belongs)


class FoonInputError(FoonError):
    """A file that parses but cannot be used, or cannot be read or written (missing, a directory, ...)."""

    def __init__(self, path: str, line: int, message: str, text: str | None = None) -> None:
        super().__init__(message, path=path, line=line, text=text)


class UsageError(FoonError, ValueError):
    """A bad argument or option value (an unknown method, a threshold out of range, a goal nothing makes)."""

    def __init__(self, message: str) -> None:
        super().__init__(message)


class MissingDependencyError(FoonError):
    """An optional dependency is not installed; `hint` says how to install it."""

    def __init__(self, message: str, hint: str) -> None:
        self.hint = hint
        super().__init__(f"{message}: {hint}")


class PlanDecodeError(FoonError, ValueError):
    """A plan step that does not map back to a functional unit (an unknown action, wrong arguments)."""

    def __init__(self, message: str) -> None:
        super().__init__(message)


def require(module: str, extra: str, purpose: str) -> ModuleType:
    """Import an optional dependency of the `extra` install option, or say how to install it.

    >>> require("json", "gen", "reading JSON").__name__
    'json'
    >>> require("no_such_module_x", "gen", "FOON-EXP").hint
    Traceback (most recent call last):
        ...
    foon2pddl.errors.MissingDependencyError: FOON-EXP needs no_such_module_x: pip install 'foon2pddl[gen]'
    """
    try:
        return importlib.import_module(module)
    except ImportError:
        top = module.split(".")[0]
        raise MissingDependencyError(f"{purpose} needs {top}", f"pip install 'foon2pddl[{extra}]'") from None


@dataclass(frozen=True)
class ParseWarning:
    """Something skipped while reading, with its place."""

    path: str
    line: int
    message: str

    def __str__(self) -> str:
        return f"{place(self.path, self.line)}: warning: {self.message}"
