"""Where derived data (assembled WordNet corpus, similarity matrices) is cached, and cache keys."""

from __future__ import annotations

import hashlib
import os
from pathlib import Path


def cache_dir() -> Path:
    """`$FOON2PDDL_CACHE`, else `$XDG_CACHE_HOME/foon2pddl`, else `~/.cache/foon2pddl`."""
    explicit = os.environ.get("FOON2PDDL_CACHE")
    if explicit:
        return Path(explicit).expanduser()
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(base) / "foon2pddl"


def digest(*parts: str) -> str:
    """A short stable hash of text parts (separated so that ("ab", "c") != ("a", "bc"))."""
    h = hashlib.sha256()
    for p in parts:
        data = p.encode("utf-8")
        h.update(len(data).to_bytes(8, "big"))
        h.update(data)
    return h.hexdigest()[:24]
