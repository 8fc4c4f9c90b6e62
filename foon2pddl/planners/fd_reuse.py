"""Many goals on one domain and kitchen: translate once with Fast Downward, search per goal.

FD's translator takes ~99 % of a plan's time on FOON tasks, and only the goal
changes between goals on one network and kitchen. `TranslatedTask.build`
translates the task's actions and initial state once, with a fresh anchor goal
(so the translator's relaxed-reachability and empty-goal shortcuts never fire)
and `--keep-unimportant-variables` (so every reachable fact stays a variable).
`solve` then writes a goal section for each goal into that SAS text and runs the
search binary on it.

A goal is a disjunction of alternatives, each a conjunction of atoms (a FOON
goal is reached by any of its candidate nodes). One alternative becomes the SAS
goal directly; several get one zero-cost auxiliary operator each that sets the
anchor variable, and the goal is the anchor (those operators are removed from
the returned plan). A goal atom absent from the SAS text is either always true
(the translator compiles away facts no action changes, e.g. kitchen atoms of
the delete-free `tree` encoding) or unreachable: the task's initial state
decides which.

The translator prunes by reachability from the initial state, so a new
kitchen would need a new translation, unless the task was translated with its
initial atoms made forgettable (`build(..., forgettable=True)`: one auxiliary
operator per initial atom deletes it, so no initial atom is compiled away as
static). Such a translation serves any initial state that is a subset of the
one translated (`TranslatedTask.at_init`: the SAS initial state is rewritten,
the auxiliary operators dropped, and the operators and facts a relaxed
reachability fixpoint from the new state cannot reach are dropped too, as the
translator would: goals out of reach are answered without a search). Build from
a task compiled without goal-directed pruning, or goals outside its pruned part
will wrongly come out unsolvable.
"""

from __future__ import annotations

import hashlib
import os
import tempfile
import time
from collections.abc import Sequence
from dataclasses import dataclass, replace
from pathlib import Path

from ..pddl.task import Action, Atom, PlanningTask, Predicate
from . import fd
from .result import PlanResult, step_action
from .sas import Sas, parse_sas

RESERVED = "foon2pddl-reuse-"  # the prefix of every auxiliary name
ANCHOR = "foon2pddl-reuse-anchor"
GOAL_OP = "foon2pddl-reuse-goal-"
FORGET_OP = "foon2pddl-reuse-forget-"


def sas_fact_name(atom: Atom) -> str:
    """How FD's translator names a fact: `Atom p(a, b)`."""
    return f"Atom {atom.predicate}({', '.join(atom.args)})".lower()


def _anchored(task: PlanningTask, forgettable: bool = False) -> PlanningTask:
    """The task with its goal replaced by a fresh anchor atom one auxiliary action makes true; `forgettable`:
    and one auxiliary action per initial atom that deletes it (see the module doc)."""
    taken = {p.name.lower() for p in task.predicates} | {a.name.lower() for a in task.actions}
    if any(n.startswith(RESERVED) for n in taken):  # `parse_sas` skips operators by these prefixes
        raise ValueError(f"task already uses a name starting {RESERVED!r}")
    anchor = Atom(ANCHOR)
    cost = 0 if task.uses_costs else None
    forget = tuple(Action(f"{FORGET_OP}{k}", (), (), (a,), cost=cost) for k, a in enumerate(task.init)) \
        if forgettable else ()
    return replace(
        task,
        predicates=(*task.predicates, Predicate(ANCHOR)),
        actions=(*task.actions, Action(ANCHOR, (), (anchor,), cost=cost), *forget),
        goal=(anchor,),
    )


@dataclass(frozen=True)
class TranslatedTask:
    """A task translated once; `solve` searches it for any goal over its atoms."""

    task: PlanningTask
    sas: Sas
    translate_seconds: float
    optimal: bool = False
    search: tuple[str, ...] | None = None  # search options (default: the alias for `optimal`)
    forgettable: bool = False  # built so that `at_init` may start from any subset of the initial state

    @classmethod
    def build(cls, task: PlanningTask, *, optimal: bool = False, time_limit: float | None = None,
              search: tuple[str, ...] | None = None, cache: Path | None = None,
              forgettable: bool = False) -> TranslatedTask:
        """Translate `task` (its goal is ignored). Raises RuntimeError when the translator fails.

        `cache`: a directory of translations by the SHA-256 of the PDDL text and translator options
        (`cached_sas`); a task translated before, by this process or another, is read, not translated.
        `forgettable`: translate so that `at_init` can start from any subset of the task's initial state.
        """
        from ..pddl.render import render

        domain_text, problem_text = render(_anchored(task, forgettable))
        options = ("--keep-unimportant-variables", *fd.translate_options_for(task))
        t0 = time.perf_counter()
        text = cached_sas(cache, domain_text, problem_text, options) if cache is not None else None
        if text is not None:
            return cls(task, parse_sas(text, sas_fact_name(Atom(ANCHOR)), (ANCHOR, FORGET_OP)), time.perf_counter() - t0,
                       optimal, search, forgettable)
        with tempfile.TemporaryDirectory(prefix="foon2pddl-fdr-") as tmp:
            work = Path(tmp)
            (work / "domain.pddl").write_text(domain_text)
            (work / "problem.pddl").write_text(problem_text)
            run = fd.translate(work / "domain.pddl", work / "problem.pddl", work / "output.sas", work, time_limit,
                               options)
            failed = fd.translation_failure(run, "fd-reuse")
            if failed is not None:
                raise RuntimeError(f"translation for reuse failed ({failed.status}): {failed.message}")
            text = (work / "output.sas").read_text()
        if cache is not None:
            store_sas(cache, domain_text, problem_text, options, text)
        return cls(task, parse_sas(text, sas_fact_name(Atom(ANCHOR)), (ANCHOR, FORGET_OP)), run.seconds, optimal,
                   search, forgettable)

    def at_init(self, task: PlanningTask) -> TranslatedTask:
        """This translation for `task`, the translated task with another initial state (built `forgettable`,
        see the module doc; ValueError when its state cannot be written here, or it was not built so)."""
        if not self.forgettable:
            raise ValueError("at_init needs a translation built forgettable (a dropped static atom would go unseen)")
        sas = self.sas.at_init(sas_fact_name(a) for a in task.init)
        return replace(self, task=task, sas=sas)

    def goal_sas(self, alternatives: Sequence[Sequence[Atom]]) -> str | PlanResult:
        """SAS text for a goal, or the result when no search is needed (goal true at start or unreachable)."""
        init = set(self.task.init)
        reachable: list[list[tuple[int, int]]] = []
        for alt in alternatives:
            facts = []
            for atom in alt:
                fact = self.sas.facts.get(sas_fact_name(atom))
                if fact is not None:
                    facts.append(fact)
                elif atom not in init:
                    break  # never reachable from this initial state
            else:
                if all(self.sas.state[v] == x for v, x in facts):
                    return PlanResult("solved", (), self.name, "goal holds in the initial state")
                reachable.append(sorted(set(facts)))
        if not reachable:
            return PlanResult("unsolvable", (), self.name, "no goal atom is reachable from the initial state")
        kept = self.sas.relevant(f for alt in reachable for f in alt)
        ops = [self.sas.operators[k] for k in kept]
        used = {v for k in kept for v, _ in (*self.sas.parsed[k].needs, *self.sas.parsed[k].makes)}
        if len(reachable) == 1:
            goal = reachable[0]
        else:
            var, val = self.sas.anchor
            for k, facts in enumerate(reachable):
                prevail = "".join(f"{v} {x}\n" for v, x in facts)
                ops.append(f"begin_operator\n{GOAL_OP}{k}\n{len(facts)}\n{prevail}1\n0 {var} -1 {val}\n0\nend_operator\n")
                used.update(v for v, _ in facts)
            goal = [self.sas.anchor]
        return self.sas.task_text(goal, ops, used)

    @property
    def name(self) -> str:
        if self.search is not None:
            return f"fd-reuse ({' '.join(self.search)})"
        return "fd-reuse " + fd.planner_name(self.optimal)[3:]

    def solve(self, alternatives: Sequence[Sequence[Atom]], time_limit: float | None = None) -> PlanResult:
        """Search for a plan reaching any alternative (a conjunction of atoms)."""
        t0 = time.perf_counter()
        sas = self.goal_sas(alternatives)
        if isinstance(sas, PlanResult):
            return sas.with_timings(translate=0.0, search=time.perf_counter() - t0)
        translate_s = time.perf_counter() - t0
        with tempfile.TemporaryDirectory(prefix="foon2pddl-fdr-") as tmp:
            options = self.search if self.search is not None else fd.search_options(self.optimal)
            result = fd.search(Path(tmp), options, time_limit, self.name, sas_text=sas)
        plan = tuple(s for s in result.plan if not step_action(s).startswith(GOAL_OP))
        return replace(result, plan=plan).with_timings(translate=translate_s)


def sas_key(domain_text: str, problem_text: str, options: Sequence[str]) -> str:
    """The cache name of a translation: SHA-256 over the PDDL texts and the translator options."""
    h = hashlib.sha256()
    for part in (domain_text, problem_text, *options):
        h.update(part.encode() + b"\0")
    return h.hexdigest() + ".sas"


def cached_sas(cache: Path, domain_text: str, problem_text: str, options: Sequence[str]) -> str | None:
    """The SAS text `store_sas` kept for these inputs, or None."""
    try:
        return (cache / sas_key(domain_text, problem_text, options)).read_text()
    except OSError:
        return None


def store_sas(cache: Path, domain_text: str, problem_text: str, options: Sequence[str], text: str) -> None:
    """Keep a translation in `cache` (written whole under a private name, then renamed: a reader in
    another process never sees half a file); a failed write only loses the reuse."""
    path = cache / sas_key(domain_text, problem_text, options)
    part = path.with_name(f"{path.name}.{os.getpid()}.part")
    try:
        part.write_text(text)
        os.replace(part, path)
    except OSError:
        part.unlink(missing_ok=True)

