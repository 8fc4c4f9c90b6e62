"""Planner names and commands, checked and resolved before anything runs.

- `check_planner`: is `--planner NAME` Fast Downward or an installed unified-planning
  engine? Read from UP's engine table (`unified_planning/engines/factory.py`, parsed,
  not imported: importing UP costs seconds), so a typo fails at once.
- `PRESETS`: named `--planner-cmd` templates for planners installable from PyPI.
- `resolve_command`: a `--planner-cmd` (preset or template) as the words to run. The
  command runs in a private temporary directory, so the executable is resolved here,
  against the caller's working directory and PATH, and other words naming existing
  files relative to the caller's directory become absolute; `python`/`python3` mean
  the interpreter running foon2pddl (whose environment has the planners installed),
  whether or not a virtual environment is active.
"""

from __future__ import annotations

import ast
import importlib.util
import os
import shlex
import shutil
import sys
from dataclasses import dataclass
from functools import cache
from pathlib import Path

from . import DEFAULT_PLANNER

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


#: Words in the names of UP's engines that are not planners (grounders, validators, compilers).
NOT_PLANNERS = ("grounder", "validator", "simulator", "remover", "replanner", "oversubscription", "compiler",
                "repairer")


@cache
def up_engine_table() -> dict[str, str]:
    """UP's default planning engines: name -> the module that provides it (read from UP's source)."""
    spec = importlib.util.find_spec("unified_planning")
    if spec is None or not spec.submodule_search_locations:
        return {}
    source = Path(next(iter(spec.submodule_search_locations))) / "engines" / "factory.py"
    tree = ast.parse(source.read_text())
    for node in tree.body:
        if (isinstance(node, ast.Assign) and len(node.targets) == 1 and isinstance(node.targets[0], ast.Name)
                and node.targets[0].id == "DEFAULT_ENGINES"):
            table = ast.literal_eval(node.value)
            return {name: module for name, (module, _) in table.items()
                    if not any(word in name for word in NOT_PLANNERS)}
    return {}


def installed_engines() -> list[str]:
    """The engines of `up_engine_table` whose package is installed."""
    return sorted(n for n, m in up_engine_table().items() if importlib.util.find_spec(m.split(".")[0]) is not None)


def check_planner(name: str) -> None:
    """Raise ValueError unless `name` is `fd` or an installed UP engine (no UP import: milliseconds)."""
    if name == DEFAULT_PLANNER:
        return
    table = up_engine_table()
    if name in table and importlib.util.find_spec(table[name].split(".")[0]) is None:
        package = table[name].split(".")[0].replace("_", "-")
        raise ValueError(f"planner {name!r} is a unified-planning engine that is not installed "
                         f"(pip install {package})")
    if name not in table:
        import difflib

        known = [DEFAULT_PLANNER, *installed_engines()]
        close = difflib.get_close_matches(name, known, n=1)
        hint = f"did you mean {close[0]!r}? " if close else ""
        raise ValueError(f"unknown planner {name!r}; {hint}planners here: {', '.join(known)} "
                         "(or --planner-cmd with a command or a preset: " + ", ".join(PRESETS) + ")")
