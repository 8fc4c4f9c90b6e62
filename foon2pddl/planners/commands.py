"""Planner commands, resolved before anything runs (planner names: `planners.registry`).

- `PRESETS`: named `--planner-cmd` templates for planners installable from PyPI.
- `resolve_command`: a `--planner-cmd` (preset or template) as the words to run. The
  command runs in a private temporary directory, so the executable is resolved here,
  against the caller's working directory and PATH, and other words naming existing
  files relative to the caller's directory become absolute; `python`/`python3` mean
  the interpreter running foon2pddl (whose environment has the planners installed),
  whether or not a virtual environment is active.
"""

from __future__ import annotations

import os
import shlex
import shutil
import sys
from dataclasses import dataclass
from pathlib import Path

PLACEHOLDERS = ("{domain}", "{problem}", "{plan}", "{time}")


@dataclass(frozen=True)
class Preset:
    """A named planner command: its template and where the planner comes from."""

    name: str
    template: str
    source: str


#: `{python}` is this interpreter; `{fd_driver}` the driver script of the up-fast-downward wheel.
PRESETS: dict[str, Preset] = {p.name: p for p in (
    Preset("fd-driver", "{python} {fd_driver} --alias lama-first --plan-file {plan} {domain} {problem}",
           "Fast Downward's own driver script from the up-fast-downward wheel (lama-first)"),
    Preset("fd-driver-opt", "{python} {fd_driver} --alias seq-opt-lmcut --plan-file {plan} {domain} {problem}",
           "the same driver, A* with LM-cut (optimal)"),
    Preset("pyperplan", "{python} -m pyperplan -s gbf -H hff {domain} {problem}",
           "pyperplan (PyPI `pyperplan`, installed with up-pyperplan): greedy best-first with h_FF; "
           "its plan is read from problem.pddl.soln"),
)}


def fd_driver() -> Path:
    """`fast-downward.py` inside the up-fast-downward wheel (located without importing it)."""
    from .fd import downward_dir

    return downward_dir() / "fast-downward.py"


def expand_preset(cmd: str) -> str:
    """The template of preset `cmd` with `{python}` and `{fd_driver}` filled in, else `cmd` unchanged."""
    preset = PRESETS.get(cmd.strip())
    if preset is None:
        return cmd
    text = preset.template.replace("{python}", shlex.quote(sys.executable))
    if "{fd_driver}" in text:
        text = text.replace("{fd_driver}", shlex.quote(str(fd_driver())))
    return text


def _absolute(word: str, cwd: Path) -> str:
    """A word naming an existing file or directory relative to `cwd`, made absolute; others unchanged."""
    if word.startswith("-") or any(p in word for p in PLACEHOLDERS) or os.path.isabs(word):
        return word
    path = cwd / word
    return os.path.abspath(path) if path.exists() else word


def resolve_command(cmd: str, cwd: str | Path | None = None) -> list[str]:
    """The words of a planner command (preset name or template), resolved against `cwd` and PATH.

    Raises ValueError for an empty or unbalanced command, or an executable that is found nowhere.
    """
    here = Path.cwd() if cwd is None else Path(cwd)
    words = shlex.split(expand_preset(cmd))
    if not words:
        raise ValueError("empty planner command")
    exe = words[0]
    if exe in ("python", "python3"):
        words[0] = sys.executable
    elif os.sep in exe or (os.altsep and os.altsep in exe):
        path = Path(os.path.abspath(here / exe))  # symlinks kept: a venv's python must stay the venv's
        if not path.is_file():
            raise ValueError(f"no executable {exe!r} (relative to {here})")
        words[0] = str(path)
    else:
        found = shutil.which(exe)
        if found is None:
            raise ValueError(f"{exe!r} is not on PATH; presets: {', '.join(PRESETS)}")
        words[0] = found
    return [words[0], *(_absolute(w, here) for w in words[1:])]
