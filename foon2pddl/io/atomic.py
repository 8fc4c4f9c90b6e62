"""Atomic output: a file is either written whole or not at all."""

from __future__ import annotations

import os
import tempfile
from pathlib import Path


def _umask_mode() -> int:
    """Mode a plainly created file would get (mkstemp's 0600 is too strict for outputs)."""
    mask = os.umask(0)
    os.umask(mask)
    return 0o666 & ~mask


def atomic_write(path: str | Path, data: str | bytes) -> None:
    """Write `data` to `path` through a temporary file in the same directory and a rename."""
    p = Path(path)
    p.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(prefix=f".{p.name}.", dir=p.parent)
    try:
        with os.fdopen(fd, "wb") as fh:
            fh.write(data.encode("utf-8") if isinstance(data, str) else data)
        os.chmod(tmp, _umask_mode())
        os.replace(tmp, p)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


def atomic_write_many(files: dict[Path, str | bytes]) -> None:
    """Write several files; if any cannot be prepared, none is replaced."""
    staged: list[tuple[str, Path]] = []
    try:
        for path, data in files.items():
            path.parent.mkdir(parents=True, exist_ok=True)
            fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", dir=path.parent)
            staged.append((tmp, path))
            with os.fdopen(fd, "wb") as fh:
                fh.write(data.encode("utf-8") if isinstance(data, str) else data)
            os.chmod(tmp, _umask_mode())
        for tmp, path in staged:
            os.replace(tmp, path)
    except BaseException:
        for tmp, _ in staged:
            Path(tmp).unlink(missing_ok=True)
        raise


def check_writable(path: str | Path, directory: bool = False) -> None:
    """Raise OSError unless `atomic_write` could create `path` (or files in it, when `directory`).

    Checked before long work (a planner run) so that a bad `-o` fails first, not after.
    The nearest existing ancestor must be a directory in which a file can be created
    (probed with a temporary file, removed at once: `os.access` says yes to root on
    read-only or virtual file systems); an existing `path` must be a file (a directory
    when `directory`).
    """
    p = Path(path)
    if p.exists() and p.is_dir() != directory:
        raise IsADirectoryError(21, "is a directory") if not directory else NotADirectoryError(20, "not a directory")
    base = p if directory else p.parent
    while not base.exists():
        base = base.parent
    if not base.is_dir():
        raise NotADirectoryError(20, f"{base} is not a directory")
    fd, tmp = tempfile.mkstemp(prefix=".foon2pddl-probe.", dir=base)
    os.close(fd)
    os.unlink(tmp)
