"""Generate `domains/` and `problems/` from the embedded example network (`make pddl`).

`make pddl` (`python -m foon2pddl.cli.examples_cmd [ROOT]`, which says each step on
stderr) writes, for every encoding and every goal in `GOALS`, the domain and problem
that `foon2pddl compile --goal G --encoding E` writes for the example network and
kitchen (level 3, pruned):
`domains/<encoding>/<goal>.pddl` and `problems/<encoding>/<goal>.pddl`.
A pruned domain depends on its goal, hence one pair per goal. `.pddl` files
under those directories that are no longer generated are removed.
"""

from __future__ import annotations

from pathlib import Path

from ..io.steps import Step, silent_step

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
