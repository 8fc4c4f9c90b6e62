"""Output files: a regular file is either written whole or not at all.

A regular file (or a new one) is written to a hidden temporary file beside it and
renamed over it, keeping an existing file's permission bits (a new file gets the
umask's). A symbolic link is followed: its target is replaced, the link stays.
Character devices, FIFOs and sockets (`-o /dev/stdout`, `-o /dev/null`, a named
pipe) cannot be replaced atomically and must not be: they are written through.
Text is encoded as UTF-8, lone surrogates (undecodable bytes of file names) as
`\\udcff` escapes, so no output ever fails to encode.

Missing parent directories are created (every `-o` of the CLI works so); those a failed
write created are removed again.

Several files written as a unit (`atomic_write_many`, compile's domain/problem
pair, a batch's `-o DIR`) are all staged before any is renamed (a target that is a
directory fails the staging; directories made for the set are removed again when it
fails, so a failed set leaves nothing), then renamed while holding an exclusive `flock` on their directory, so
concurrent writers into one directory end with one writer's complete pair;
readers that take a shared lock on the directory (`read_locked`) never see a
mixed pair.
"""

from __future__ import annotations

import fcntl
import os
import stat
import tempfile
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

from .interrupts import signals_deferred

#: Paths that name an open file descriptor of this process: always written through.
_FD_PATHS = ("/dev/stdout", "/dev/stderr", "/dev/fd/", "/proc/self/fd/")


def encode(data: str | bytes) -> bytes:
    """UTF-8 bytes of output text; a lone surrogate becomes its `\\udcXX` escape."""
    return data.encode("utf-8", "backslashreplace") if isinstance(data, str) else data


def _umask_mode() -> int:
    """Mode a plainly created file would get (mkstemp's 0600 is too strict for outputs)."""
    mask = os.umask(0)
    os.umask(mask)
    return 0o666 & ~mask


def _target(path: Path) -> tuple[Path, os.stat_result | None]:
    """Where to write `path`: itself, or its final symlink target; with its stat (None if absent)."""
    real = Path(os.path.realpath(path)) if path.is_symlink() else path
    try:
        return real, os.stat(real)
    except FileNotFoundError:
        return real, None


def _writes_through(path: Path, info: os.stat_result | None) -> bool:
    if str(path).startswith(_FD_PATHS):
        return True
    return info is not None and not stat.S_ISREG(info.st_mode) and not stat.S_ISDIR(info.st_mode)


def _write_through(path: Path, data: bytes) -> None:
    with open(path, "wb") as fh:  # O_TRUNC is ignored by devices and FIFOs
        fh.write(data)


#: Temporary files staged and not yet renamed or removed (removed on every exit path).
_STAGED: set[str] = set()


def _discard(tmp: str) -> None:
    Path(tmp).unlink(missing_ok=True)
    _STAGED.discard(tmp)


def _make_parents(directory: Path, created: list[Path] | None) -> None:
    """`directory` and its missing ancestors; each one this call creates is appended to `created`."""
    missing = []
    for d in (directory, *directory.parents):
        if d.exists() or d.is_symlink():
            break
        missing.append(d)
    for d in reversed(missing):
        try:
            d.mkdir()
        except FileExistsError:
            continue  # another writer made it: not ours to remove
        if created is not None:
            created.append(d)
    if not directory.is_dir():
        raise NotADirectoryError(20, "Not a directory", str(directory))


def _remove_dirs(created: list[Path]) -> None:
    """Remove the directories a failed write created, deepest first, where still empty."""
    for d in reversed(created):
        try:
            d.rmdir()
        except OSError:
            pass


def _stage(path: Path, data: bytes, info: os.stat_result | None, created: list[Path] | None = None) -> str:
    """A hidden temporary file beside `path` holding `data`, with the mode `path` should get
    (the directories made for it are appended to `created`)."""
    if info is not None and stat.S_ISDIR(info.st_mode):
        raise IsADirectoryError(21, "Is a directory", str(path))
    _make_parents(path.parent, created)
    with signals_deferred():  # an interrupt between mkstemp and the caller's cleanup would leak it
        fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", dir=path.parent)
        _STAGED.add(tmp)
    try:
        with os.fdopen(fd, "wb") as fh:
            fh.write(data)
        os.chmod(tmp, stat.S_IMODE(info.st_mode) if info is not None else _umask_mode())
    except BaseException:
        _discard(tmp)
        raise
    return tmp


def discard_staged() -> None:
    """Remove every staged temporary file still present (called when a command ends abnormally)."""
    for tmp in list(_STAGED):
        _discard(tmp)


def atomic_write(path: str | Path, data: str | bytes) -> None:
    """Write `data` to `path` (see the module doc: atomic for regular files, through for devices)."""
    target, info = _target(Path(path))
    if _writes_through(Path(path), info):
        _write_through(Path(path), encode(data))
        return
    tmp = None
    created: list[Path] = []  # directories made for the file: removed again when the write fails
    try:
        tmp = _stage(target, encode(data), info, created)
        os.replace(tmp, target)
        _STAGED.discard(tmp)
    except BaseException:
        if tmp is not None:
            _discard(tmp)
        _remove_dirs(created)
        raise


@contextmanager
def locked_dir(directory: Path, shared: bool = False) -> Iterator[None]:
    """Hold an advisory `flock` on a directory (exclusive for writers, shared for readers)."""
    fd = os.open(directory, os.O_RDONLY | os.O_DIRECTORY)
    try:
        fcntl.flock(fd, fcntl.LOCK_SH if shared else fcntl.LOCK_EX)
        yield
    finally:
        os.close(fd)


def atomic_write_many(files: dict[Path, str | bytes]) -> None:
    """Write several files as a unit: all staged first (none replaced if any fails), then renamed
    under an exclusive lock on each directory, so concurrent writers never leave a mixed set."""
    staged: list[tuple[str, Path]] = []
    created: list[Path] = []  # directories made for the files: removed again when the set fails
    try:
        for path, data in files.items():
            target, info = _target(path)
            staged.append((_stage(target, encode(data), info, created), target))
        dirs = sorted({target.parent for _, target in staged})
        with _locked_all(dirs):
            for tmp, target in staged:
                os.replace(tmp, target)
                _STAGED.discard(tmp)
    except BaseException:
        for tmp, _ in staged:
            _discard(tmp)
        _remove_dirs(created)
        raise


def check_writable(path: str | Path, directory: bool = False) -> None:
    """Raise OSError unless `atomic_write` could create `path` (or files in it, when `directory`).

    Checked before long work (a planner run) so that a bad `-o` fails first, not after.
    The nearest existing ancestor must be a directory in which a file can be created
    (probed with a temporary file, removed at once: `os.access` says yes to root on
    read-only or virtual file systems); an existing `path` must be a file (a directory
    when `directory`). Devices and FIFOs, written through, need only be writable; a
    symlink is checked at its target.
    """
    p = Path(path)
    if p.exists() and p.is_dir() != directory:
        raise IsADirectoryError(21, "is a directory") if not directory else NotADirectoryError(20, "not a directory")
    if not directory:
        p, info = _target(p)
        if _writes_through(Path(path), info):
            if not os.access(path, os.W_OK):
                raise PermissionError(13, "Permission denied")
            return
    base = p if directory else p.parent
    while not base.exists():
        base = base.parent
    if not base.is_dir():
        raise NotADirectoryError(20, f"{base} is not a directory")
    with signals_deferred():  # an interrupt must not leave the probe behind
        fd, tmp = tempfile.mkstemp(prefix=".foon2pddl-probe.", dir=base)
        os.close(fd)
        os.unlink(tmp)


@contextmanager
def _locked_all(dirs: list[Path]) -> Iterator[None]:
    if not dirs:
        yield
        return
    with locked_dir(dirs[0]), _locked_all(dirs[1:]):
        yield


def read_locked(paths: list[Path]) -> list[bytes]:
    """Read files written together by `atomic_write_many` (same directory) as one consistent set."""
    with locked_dir(paths[0].parent, shared=True):
        return [p.read_bytes() for p in paths]
