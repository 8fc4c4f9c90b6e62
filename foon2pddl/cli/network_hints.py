"""Which other network, kitchen or recipe file would make a goal REG cannot make: the `hint: ` lines `retrieve` and
`plan` print (and their `--format json` holds), out of `reasons`. A hint names a network only when the command it
suggests succeeds there: EXP by FOON's fixpoint on FOON-EXP, GEN by the lifted planner (what `plan --network gen`
runs), not by the category-level fixpoint, which also "makes" a dish from other categories' ingredients.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator
from pathlib import Path

import click

__all__ = ["GEN_HINT_TIME_LIMIT", "HINT", "hint_lines", "hint_words", "networks_hint"]

#: Seconds the lifted planner may take to confirm a `--network gen` hint.
GEN_HINT_TIME_LIMIT = 30.0


def networks_hint(net, kitchen, goal: str | None, goal_file: Path | None, level: int) -> None:
    """After REG cannot make a goal: say (stderr) which of `--network exp`/`gen` would, for retrieve and plan (or that
    neither would); `plan --format json` holds the same lines' words instead (`hint_lines`, `hint_words`)."""
    for line in hint_lines(net, kitchen, goal, goal_file, level):  # each as found: the network check takes seconds
        click.echo(line, err=True)


#: How a hint's line starts: what would make the goal (the lines `hint_lines` gives that do not are what was checked).
HINT = "hint: "


def hint_words(lines: Iterable[str]) -> list[str]:
    """The words of the `hint: ` lines among `lines` (`hint_lines`), without that prefix: what `--format json` holds."""
    return [line.removeprefix(HINT) for line in lines if line.startswith(HINT)]


def hint_lines(net, kitchen, goal: str | None, goal_file: Path | None, level: int) -> Iterator[str]:
    """The lines `networks_hint` says, each as soon as it is known: `hint: ` the default kitchen or a recipe file
    alone, `hint: ` the networks that make the goal, else which were checked and which were not."""
    from ..generalize.hints import hinted_kinds, networks_that_reach, slow_hint
    from ..generalize.network import NETWORKS
    from ..io.inputs import load_goal_spec
    from .progress import slow_step

    spec = load_goal_spec(goal, goal_file)
    first = _default_kitchen_hint(net, kitchen, spec, level) or _recipe_file_hint(net, kitchen, spec, level)
    if first:
        yield first
    slow = slow_hint(net, kitchen)  # known to take seconds: said at once, not after the silence budget
    with slow_step(slow or "checking which other network makes it (for a hint)",
                   after=0 if slow else None) as said:  # WordNet opens (slow), or FOON-GEN is built and planned
        kinds = networks_that_reach(net, kitchen, spec, level,
                                    confirm={k.name: lambda k=k: _lifted_solves(net, kitchen, spec, level, k.encoding)
                                             for k in NETWORKS.values() if k.encoding is not None})
    if kinds:
        yield (HINT + " and ".join(f"--network {k}" for k in kinds) + " can make it: "
               + "; ".join(NETWORKS[k].hint for k in kinds))
    elif said.is_set():  # the check was announced: close it (no `hint:` line, as README says)
        hinted = hinted_kinds(net)
        checked = [f"--network {k.name}" for k in hinted]
        units = len(net.foon.units)
        parts = [f"neither {' nor '.join(checked)} makes it" if len(checked) > 1 else
                 f"{checked[0]} does not make it either"] if checked else []
        parts += [f"--network {k.name} is not checked (FOON-{k.label} of a {units:,}-unit network is too large to build "
                  "for a hint: run it to see)" for k in NETWORKS.values() if k.hint and k not in hinted]
        yield "; ".join(parts)


def _default_kitchen_hint(net, kitchen, spec, level: int) -> str:
    """From the base kitchen: the hint line when the network's default kitchen makes the goal (FOON's fixpoint);
    "" when it does not."""
    from ..analysis.reachability import reachable
    from ..errors import FoonError
    from ..model.goal import resolve_goal
    from ..model.kitchen import BASE_SOURCE, default_kitchen

    if kitchen.source != BASE_SOURCE:
        return ""
    foon = net.at(level)
    try:
        goal = resolve_goal(spec, foon)
    except FoonError:
        return ""
    reach = reachable(foon, default_kitchen(foon).nodes)
    if reach.makes_any(goal.candidates):
        return (HINT + "`--kitchen default` can make it: the network's default kitchen holds the half-made "
                "dishes the base kitchen leaves out")
    return ""


def _recipe_file_hint(net, kitchen, spec, level: int) -> str:
    """On a merge of recipe files, from a kitchen the run chose (base or default): the hint line naming the file
    that makes the goal alone, from its own default kitchen, with the command ("" for none). In a merge another
    recipe may make a file's starting node (`maple syrup (in [bowl])`) by units that never fire: then no kitchen of
    the merge holds it. Files tried: those of the goal's makers, sorted, at most 5 (one fixpoint each)."""
    import shlex

    from ..analysis.reachability import reachable
    from ..errors import FoonError
    from ..model.foon import Foon
    from ..model.goal import resolve_goal
    from ..model.kitchen import BASE_SOURCE, default_kitchen

    foon = net.at(level)
    if kitchen.source not in (BASE_SOURCE, default_kitchen(foon).source):
        return ""
    try:
        goal = resolve_goal(spec, foon)
    except FoonError:
        return ""
    if len({s.path for u in foon.units for s in u.sources[:1]}) < 2:
        return ""
    makers = {u for c in goal.candidates for u in foon.producers.get(c, ())}
    for path in sorted({s.path for u in makers for s in foon.units[u].sources})[:5]:
        alone = Foon(tuple(u for u in foon.units if any(s.path == path for s in u.sources)), foon.level)
        reach = reachable(alone, default_kitchen(alone).nodes, goal.candidates)
        if reach.makes_any(goal.candidates):
            command = shlex.join(["foon2pddl", click.get_current_context().info_name, path, "--goal", spec.describe()])
            return (HINT + f"{path} alone makes it from its own starting nodes (`{command}`); in this merge "
                    "other recipes' units make some of them, so no kitchen of the merge holds them")
    return ""


def _lifted_solves(net, kitchen, spec, level: int, encoding: str) -> bool:
    """Whether `plan --network gen` (a kind's own `encoding`, lifted, over the concrete network) solves the goal."""
    from ..errors import FoonError
    from ..model.goal import resolve_goal
    from ..planners.solve import plan
    from ..status import PlanStatus

    foon = net.at(level)
    try:
        goal = resolve_goal(spec, foon)
        outcome = plan(foon, kitchen, goal, encoding, level, time_limit=GEN_HINT_TIME_LIMIT)
    except FoonError:
        return False
    return outcome.status == PlanStatus.SOLVED
