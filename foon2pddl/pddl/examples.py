"""Generate `domains/` and `problems/` from the embedded example network (`make pddl`).

`python -m foon2pddl.pddl.examples [ROOT]` writes, for every encoding and every
goal in `GOALS`, the domain and problem that `foon2pddl compile --goal G
--encoding E` writes for the example network and kitchen (level 3, pruned):
`domains/<encoding>/<goal>.pddl` and `problems/<encoding>/<goal>.pddl`.
A pruned domain depends on its goal, hence one pair per goal. `.pddl` files
under those directories that are no longer generated are removed.
"""

from __future__ import annotations

import sys
from contextlib import AbstractContextManager, nullcontext
from pathlib import Path

from ..io.atomic import atomic_write_many
from ..io.steps import Step, silent_step
from ..model.words import count

#: Goals a reader recognizes: the dishes of the example recipes the example kitchen can make.
GOALS = (
    "whipped cream",
    "scrambled eggs",
    "pancake",
    "french toast",
    "tomato soup",
    "guacamole",
    "greek salad",
    "fruit salad",
)

LEVEL = 3


def generate(step: Step = silent_step) -> dict[Path, str]:
    """Relative path -> text of every generated file (each goal's encodings in one `step`). The encodings are
    imported here, in a step of their own: with jinja2 they take 0.5 s of CPU, seconds of wall time under load,
    which `make pddl` says before they load."""
    with step("loading the PDDL encodings"):
        from ..io.inputs import load_goal, load_kitchen, load_network
        from .compile import GROUND_ENCODINGS, compile_task
        from .names import sanitize
        from .render import render
    net = load_network([])
    foon = net.at(LEVEL)
    kitchen = load_kitchen(None, net, LEVEL)
    files: dict[Path, str] = {}
    for i, goal_text in enumerate(GOALS, 1):
        goal = load_goal(goal_text, None, foon)
        stem = sanitize(goal_text)
        with step(f"compiling '{goal_text}' ({i} of {len(GOALS)}) in {len(GROUND_ENCODINGS)} encodings"):
            for encoding in GROUND_ENCODINGS:
                domain, problem = render(compile_task(foon, kitchen, goal, encoding, LEVEL))
                files[Path("domains") / encoding / f"{stem}.pddl"] = domain
                files[Path("problems") / encoding / f"{stem}.pddl"] = problem
    return files


def stale_files(root: Path, files: dict[Path, str]) -> list[Path]:
    """`.pddl` files under ROOT/domains and ROOT/problems that `files` does not hold."""
    found = [p.relative_to(root) for d in ("domains", "problems") for p in sorted((root / d).rglob("*.pddl"))]
    return [p for p in found if p not in files]


def _said(what: str) -> AbstractContextManager[None]:
    """A step that says what it does on stderr at once (each goal takes ~1 s; all of them ~10 s at load 10)."""
    print(f"{what} ...", file=sys.stderr, flush=True)
    return nullcontext()


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
