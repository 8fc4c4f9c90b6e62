"""Micro plans without skills that do nothing: greedy action elimination, checked by the skill replay.

A micro plan can hold a skill the step does not need: `lama-first` (greedy, not
optimal; `fd_micro` falls back to it on large tasks) sometimes applies a step's skill
at a site where it changes nothing (it pours from the salt packet over the pepper
mill, then over the bowl) or carries an object to the workspace and back.
`irredundant` drops such skills: for each skill in turn it drops the skill and every
later skill that then no longer applies, and keeps the shorter plan when it ends in
exactly the state the whole plan ends in (greedy action elimination: Fink and Yang
1992, Nakhost and Mueller 2010). Every candidate is run by `replay.Replayer` on the
domain's own actions, so a kept plan is valid by the same rules the end-to-end replay
checks, and ends where the found plan ends (not merely somewhere that satisfies the
goal: the end-to-end replay compares every changing fact). The result is never
longer and, with costs >= 0, never costlier; a plan the replay does not accept, or
that misses the goal, is returned as it is (the end-to-end replay then reports it).
Skills are tried first to last, so the result is a function of the plan alone.
O(n^2) skill applications for an n-skill plan.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence

from ..pddl.task import Atom
from .domain import SkillDomain
from .replay import Replayer, SkillError

__all__ = ["irredundant"]


def _run(rep: Replayer, start: set, plan: Sequence[str]) -> list[str]:
    """Apply `plan` from state `start`, skipping the skills that do not apply; the ones applied."""
    rep.state = set(start)
    kept = []
    for line in plan:
        name, *args = line.split()
        try:
            rep.apply(name, args)
        except SkillError:
            continue
        kept.append(line)
    return kept


def irredundant(plan: Sequence[str], domain: SkillDomain, objects: Mapping[str, str], init: Iterable[Atom],
                goal: Iterable[Atom]) -> tuple[str, ...]:
    """`plan` (PDDL plan lines over `objects`: name -> type) with the skills the goal does not need dropped."""
    rep = Replayer(domain, objects, init)
    start = set(rep.state)
    wanted = {(a.predicate, *a.args) for a in goal}
    lines = list(plan)
    if len(_run(rep, start, lines)) != len(lines) or not wanted <= rep.state:
        return tuple(plan)
    end = set(rep.state)
    k = 0
    while k < len(lines):
        rest = _run(rep, start, lines[k + 1:])
        if rep.state == end:
            lines = lines[:k] + rest  # skill k (and what only it enabled) dropped; try the new k-th
            continue
        _run(rep, start, lines[k:k + 1])  # kept: the prefix state moves past it
        start = set(rep.state)
        k += 1
    return tuple(lines)
