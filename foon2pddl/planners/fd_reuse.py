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

Only the goal may change: the translator prunes by reachability from the
initial state, so a new kitchen needs a new translation. Build from a task
compiled without goal-directed pruning, or goals outside its pruned part will
wrongly come out unsolvable.
"""

from __future__ import annotations

import hashlib
import os
import tempfile
import time
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, replace
from pathlib import Path

from ..pddl.task import Action, Atom, PlanningTask, Predicate
from . import fd
from .result import PlanResult, step_action

ANCHOR = "foon2pddl-reuse-anchor"
GOAL_OP = "foon2pddl-reuse-goal-"


def sas_fact_name(atom: Atom) -> str:
    """How FD's translator names a fact: `Atom p(a, b)`."""
    return f"Atom {atom.predicate}({', '.join(atom.args)})".lower()


def _anchored(task: PlanningTask) -> PlanningTask:
    """The task with its goal replaced by a fresh anchor atom one auxiliary action makes true."""
    taken = {p.name.lower() for p in task.predicates} | {a.name.lower() for a in task.actions}
    if ANCHOR in taken:
        raise ValueError(f"task already uses the name {ANCHOR!r}")
    anchor = Atom(ANCHOR)
    return replace(
        task,
        predicates=(*task.predicates, Predicate(ANCHOR)),
        actions=(*task.actions, Action(ANCHOR, (), (anchor,), cost=0 if task.uses_costs else None)),
        goal=(anchor,),
    )


Fact = tuple[int, int]


@dataclass(frozen=True)
class _Op:
    """What backward relevance needs of an operator: the facts it needs and the facts it makes."""

    needs: tuple[Fact, ...]  # prevail conditions and effect preconditions (value != -1)
    makes: tuple[Fact, ...]  # effect values
    conditional: bool  # some effect has a condition


def _parse_op(block: str) -> _Op:
    lines = block.split("\n")
    i = 2
    n_prevail = int(lines[i])
    needs = [tuple(map(int, lines[i + 1 + k].split())) for k in range(n_prevail)]
    i += 1 + n_prevail
    n_effects = int(lines[i])
    makes, conditional = [], False
    for k in range(n_effects):
        parts = list(map(int, lines[i + 1 + k].split()))
        n_cond = parts[0]
        conditional = conditional or n_cond > 0
        needs.extend((parts[1 + 2 * c], parts[2 + 2 * c]) for c in range(n_cond))
        var, pre, post = parts[1 + 2 * n_cond:4 + 2 * n_cond]
        if pre != -1:
            needs.append((var, pre))
        makes.append((var, post))
    return _Op(tuple(needs), tuple(makes), conditional)


@dataclass(frozen=True)
class _Sas:
    """A translated SAS task cut into the parts a goal swap keeps."""

    head: str  # version .. end_state (variables, mutexes, initial state)
    operators: tuple[str, ...]  # operator blocks without the anchor's
    tail: str  # axioms section
    facts: dict[str, tuple[int, int]]  # "Atom p(a)" -> (variable, value)
    anchor: tuple[int, int]
    parsed: tuple[_Op, ...] = ()  # `operators`, parsed for relevance
    makers: dict[Fact, tuple[int, ...]] | None = None  # fact -> indexes of the operators that make it
    prunable: bool = False  # no conditional effects, no axioms: backward relevance is exact

    def relevant(self, goal_facts: Iterable[Fact]) -> list[int]:
        """Indexes of the operators that can contribute to making `goal_facts` (backward relevance, O(task)).

        An operator none of whose effects is a relevant fact never helps: dropping it from a plan
        leaves every later precondition and the goal satisfied (no conditional effects, no axioms),
        so optimal plan costs are unchanged and the search sees only the goal's part of the network.
        """
        if not self.prunable or self.makers is None:
            return list(range(len(self.operators)))
        needed = set(goal_facts)
        stack = list(needed)
        keep: set[int] = set()
        while stack:
            fact = stack.pop()
            for op in self.makers.get(fact, ()):
                if op not in keep:
                    keep.add(op)
                    for f in self.parsed[op].needs:
                        if f not in needed:
                            needed.add(f)
                            stack.append(f)
        return sorted(keep)


def _parse_sas(text: str) -> _Sas:
    lines = text.split("\n")
    facts: dict[str, tuple[int, int]] = {}
    i = 0
    var = -1
    while lines[i] != "begin_goal":
        if lines[i] == "begin_variable":
            var += 1
            count = int(lines[i + 3])
            for value in range(count):
                facts.setdefault(lines[i + 4 + value].lower(), (var, value))
            i += 4 + count
        else:
            i += 1
    head = "\n".join(lines[:i]) + "\n"
    while lines[i] != "end_goal":
        i += 1
    i += 1
    n_ops = int(lines[i])
    i += 1
    ops = []
    for _ in range(n_ops):
        j = lines.index("end_operator", i)
        if lines[i + 1].strip().lower() != ANCHOR:
            ops.append("\n".join(lines[i:j + 1]) + "\n")
        i = j + 1
    tail = "\n".join(lines[i:])
    anchor = facts[sas_fact_name(Atom(ANCHOR))]
    parsed = tuple(_parse_op(op) for op in ops)
    makers: dict[Fact, list[int]] = {}
    for k, op in enumerate(parsed):
        for fact in op.makes:
            makers.setdefault(fact, []).append(k)
    prunable = not any(op.conditional for op in parsed) and tail.strip().split("\n")[0].strip() == "0"
    return _Sas(head, tuple(ops), tail, facts, anchor, parsed, {f: tuple(v) for f, v in makers.items()}, prunable)


@dataclass(frozen=True)
class TranslatedTask:
    """A task translated once; `solve` searches it for any goal over its atoms."""

    task: PlanningTask
    sas: _Sas
    translate_seconds: float
    optimal: bool = False
    search: tuple[str, ...] | None = None  # search options (default: the alias for `optimal`)

    @classmethod
    def build(cls, task: PlanningTask, *, optimal: bool = False, time_limit: float | None = None,
              search: tuple[str, ...] | None = None, cache: Path | None = None) -> TranslatedTask:
        """Translate `task` (its goal is ignored). Raises RuntimeError when the translator fails.

        `cache`: a directory of translations by the SHA-256 of the PDDL text and translator options
        (`cached_sas`); a task translated before, by this process or another, is read, not translated.
        """
        from ..pddl.render import render

        domain_text, problem_text = render(_anchored(task))
        options = ("--keep-unimportant-variables", *fd.translate_options_for(task))
        t0 = time.perf_counter()
        text = cached_sas(cache, domain_text, problem_text, options) if cache is not None else None
        if text is not None:
            return cls(task, _parse_sas(text), time.perf_counter() - t0, optimal, search)
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
        return cls(task, _parse_sas(text), run.seconds, optimal, search)

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
                if not facts:
                    return PlanResult("solved", (), self.name, "goal holds in the initial state")
                reachable.append(sorted(set(facts)))
        if not reachable:
            return PlanResult("unsolvable", (), self.name, "no goal atom is reachable from the initial state")
        ops = [self.sas.operators[k] for k in self.sas.relevant(f for alt in reachable for f in alt)]
        if len(reachable) == 1:
            goal = reachable[0]
        else:
            var, val = self.sas.anchor
            for k, facts in enumerate(reachable):
                prevail = "".join(f"{v} {x}\n" for v, x in facts)
                ops.append(f"begin_operator\n{GOAL_OP}{k}\n{len(facts)}\n{prevail}1\n0 {var} -1 {val}\n0\nend_operator\n")
            goal = [self.sas.anchor]
        goal_text = f"begin_goal\n{len(goal)}\n" + "".join(f"{v} {x}\n" for v, x in goal) + "end_goal\n"
        return self.sas.head + goal_text + f"{len(ops)}\n" + "".join(ops) + self.sas.tail

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

