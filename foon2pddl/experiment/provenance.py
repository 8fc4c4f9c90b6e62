"""Which code computed an experiment's cells: the package version and, from a git checkout, its commit.

`runs.jsonl` records `code_version()` with each run and the report prints `describe` of it, so a figure
of the report can be compared with one from another commit. A package installed from a wheel (no `.git`
beside the package) records its version alone.
"""

from __future__ import annotations

import subprocess
from functools import lru_cache
from pathlib import Path

from .. import __version__

#: The directory holding the package: a git checkout's root when installed editable from a clone.
ROOT = Path(__file__).resolve().parent.parent.parent


def _git(*args: str) -> str | None:
    try:
        done = subprocess.run(["git", "-C", str(ROOT), *args], capture_output=True, text=True, timeout=10)
    except (OSError, subprocess.SubprocessError):
        return None
    return done.stdout.strip() if done.returncode == 0 else None


@lru_cache(maxsize=1)
def code_version() -> dict:
    """`{"version"}`, plus `"commit"` (HEAD) and `"modified"` (the package's tracked files differ from it)
    when the package runs from a git checkout."""
    out: dict = {"version": __version__}
    if not (ROOT / ".git").exists():  # a wheel's site-packages, even inside some repository's .venv
        return out
    commit = _git("rev-parse", "HEAD")
    if commit:
        out["commit"] = commit
        out["modified"] = bool(_git("status", "--porcelain", "--untracked-files=no", "--", "foon2pddl"))
    return out


def describe(entry: dict) -> str:
    """`foon2pddl 0.1.0 at commit 3fbb13a` (with uncommitted changes), or says no commit was recorded."""
    if "version" not in entry:
        return "code not recorded (a run logged before runs recorded it)"
    name = f"foon2pddl {entry['version']}"
    if not entry.get("commit"):
        return f"{name} (not run from a git checkout: no commit recorded)"
    return f"{name} at commit {entry['commit'][:7]}" + (" with uncommitted changes" if entry.get("modified") else "")
