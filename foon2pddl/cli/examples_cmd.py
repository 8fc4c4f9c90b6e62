"""`make pddl`: write `domains/` and `problems/` from the embedded example network, saying each step on stderr.

`python -m foon2pddl.cli.examples_cmd [ROOT]` writes what `pddl.examples.generate` gives under ROOT (default
`.`), atomically, and removes the `.pddl` files no longer generated. It lives in `cli` because it speaks: each
step is a `progress.slow_step` said at once, which through a pipe adds its seconds every `progress.BEAT` s while
it runs (a goal took 2.2-2.7 s at load 30, the encodings' import 5.3 s, with no line between).
"""

from __future__ import annotations

import sys
from contextlib import AbstractContextManager
from pathlib import Path

from ..io.atomic import atomic_write_many
from ..model.words import count
from ..pddl.examples import generate, stale_files
from .progress import slow_step


def _said(what: str, *, series: str | None = None) -> AbstractContextManager[object]:
    """A step said at once (each goal takes about 1 s, all of them about 10 s at load 10), beating while it runs
    (`io.steps.Step`: a step of a `series` shares one redrawn line on a terminal)."""
    return slow_step(what, 0.0, series=series)


def main(argv: list[str] | None = None) -> None:
    """Write every file under ROOT (default `.`), remove stale ones; say on stderr which goal it compiles."""
    args = sys.argv[1:] if argv is None else argv
    root = Path(args[0]) if args else Path(".")
    files = generate(_said)
    atomic_write_many({root / p: text for p, text in files.items()})
    for p in stale_files(root, files):
        (root / p).unlink()
        print(f"removed stale {p}")
    print(f"wrote {count(len(files), 'file')} under {root / 'domains'} and {root / 'problems'}")


if __name__ == "__main__":
    main()
