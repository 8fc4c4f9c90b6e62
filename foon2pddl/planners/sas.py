"""Fast Downward's translated (SAS) task as text: parsed once, then cut to each goal's part.

`parse_sas` reads the translator's output into a `Sas`: the variables, the
initial state, the operators (their text, and the facts each needs and makes),
the axioms. `Sas.relevant` keeps the operators that can contribute to a goal
(backward relevance); `Sas.at_init` starts the same task from another initial
state, dropping what a relaxed reachability fixpoint from it never reaches;
`Sas.task_text` writes the task for one goal, with only the variables its
operators and goal mention (renumbered) when the task has no mutex groups, so
the search reads the goal's few hundred variables, not the network's thousands.
Used by `planners.fd_reuse`.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass, replace
from functools import cached_property

__all__ = ["Fact", "Op", "Sas", "parse_op", "parse_sas", "reachable", "renumbered"]

Fact = tuple[int, int]


@dataclass(frozen=True)
class Op:
    """What backward relevance needs of an operator: the facts it needs and the facts it makes."""

    needs: tuple[Fact, ...]  # prevail conditions and effect preconditions (value != -1)
    makes: tuple[Fact, ...]  # effect values
    conditional: bool  # some effect has a condition


def parse_op(block: str) -> Op:
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
    return Op(tuple(needs), tuple(makes), conditional)


def renumbered(block: str, var: dict[int, int]) -> str:
    """An operator block with its variables renamed by `var` (old index -> new)."""
    lines = block.split("\n")
    n_prevail = int(lines[2])
    for k in range(3, 3 + n_prevail):
        v, x = lines[k].split()
        lines[k] = f"{var[int(v)]} {x}"
    n_effects = int(lines[3 + n_prevail])
    for k in range(4 + n_prevail, 4 + n_prevail + n_effects):
        parts = lines[k].split()
        n_cond = int(parts[0])
        for c in range(n_cond + 1):  # each condition's variable, then the effect's
            parts[1 + 2 * c] = str(var[int(parts[1 + 2 * c])])
        lines[k] = " ".join(parts)
    return "\n".join(lines)


@dataclass(frozen=True)
class Sas:
    """A translated SAS task cut into the parts a goal swap keeps."""

    prefix: str  # version and metric sections
    blocks: tuple[str, ...]  # each variable's section
    mutexes: str  # the mutex groups section, its count first
    state: tuple[int, ...]  # the initial value of each variable
    operators: tuple[str, ...]  # operator blocks without the auxiliary ones the caller skipped
    tail: str  # axioms section
    facts: dict[str, Fact]  # "atom p(a)" (lower case) -> (variable, value)
    anchor: Fact
    parsed: tuple[Op, ...] = ()  # `operators`, parsed for relevance
    makers: dict[Fact, tuple[int, ...]] | None = None  # fact -> indexes of the operators that make it
    prunable: bool = False  # no conditional effects, no axioms: backward relevance is exact
    values: tuple[tuple[str, ...], ...] = ()  # per variable, its values' names (lower case), for `at_init`

    @cached_property
    def head(self) -> str:
        """Version .. end_state: every variable, the mutex groups, the initial state."""
        return (self.prefix + f"{len(self.blocks)}\n" + "".join(self.blocks) + self.mutexes
                + "begin_state\n" + "".join(f"{v}\n" for v in self.state) + "end_state\n")

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

    def task_text(self, goal: Sequence[Fact], ops: Sequence[str], used: Iterable[int]) -> str:
        """The SAS text with `goal` and the operator blocks `ops`, whose variables (and the goal's) are among
        `used`. Without mutex groups and axioms only those variables are written, renumbered in order
        (a variable no operator and no goal mentions changes nothing a search does); else all of them.
        O(size of `ops` + size of `used`) then."""
        if not self.prunable or self.mutexes != "0\n":
            return self.head + _goal_section(goal) + f"{len(ops)}\n" + "".join(ops) + self.tail
        keep = sorted(set(used) | {v for v, _ in goal})
        var = {v: k for k, v in enumerate(keep)}
        return (self.prefix + f"{len(keep)}\n" + "".join(self.blocks[v] for v in keep) + "0\n"
                + "begin_state\n" + "".join(f"{self.state[v]}\n" for v in keep) + "end_state\n"
                + _goal_section([(var[v], x) for v, x in goal]) + f"{len(ops)}\n"
                + "".join(renumbered(op, var) for op in ops) + self.tail)

    def at_init(self, true: Iterable[str]) -> Sas:
        """This task from another initial state: the facts named in `true` (lower-case SAS names) hold, every
        other variable takes its negated or `<none of those>` value. Operators a relaxed reachability fixpoint
        from that state never enables are dropped, and so are the facts it never reaches (as the translator
        drops them). ValueError when the state cannot be written here (a named fact the translation compiled
        away, two named facts of one variable, a variable with no value for 'none of these'): translate
        afresh then. O(size of the task).
        """
        if not self.prunable or not self.values:
            raise ValueError("only a task without conditional effects and axioms can change its initial state")
        true = set(true)
        state = []
        for names in self.values:
            hit = [k for k, n in enumerate(names) if n in true]
            other = [k for k, n in enumerate(names) if n.startswith("negatedatom ") or n == "<none of those>"]
            if len(hit) > 1 or (not hit and len(other) != 1):
                raise ValueError(f"no single initial value among {', '.join(names)}")
            state.append(hit[0] if hit else other[0])
            true.difference_update(names[k] for k in hit)
        if true:
            raise ValueError(f"initial facts the translation compiled away: {', '.join(sorted(true)[:3])}")
        reached = reachable(set(enumerate(state)), self.parsed)
        keep = [k for k, op in enumerate(self.parsed) if all(f in reached for f in op.needs)]
        makers: dict[Fact, list[int]] = {}
        for new, k in enumerate(keep):
            for fact in self.parsed[k].makes:
                makers.setdefault(fact, []).append(new)
        return replace(self, state=tuple(state), operators=tuple(self.operators[k] for k in keep),
                       facts={n: f for n, f in self.facts.items() if f in reached},
                       parsed=tuple(self.parsed[k] for k in keep),
                       makers={f: tuple(v) for f, v in makers.items()})


def _goal_section(goal: Sequence[Fact]) -> str:
    return f"begin_goal\n{len(goal)}\n" + "".join(f"{v} {x}\n" for v, x in goal) + "end_goal\n"


def reachable(facts: set[Fact], ops: Sequence[Op]) -> set[Fact]:
    """The facts reachable from `facts` when nothing is ever deleted (every operator's needs, then its
    effects; conditional effects count as unconditional, an over-approximation). O(size of the operators)."""
    waiting: dict[Fact, list[int]] = {}
    missing = []
    for k, op in enumerate(ops):
        need = set(op.needs) - facts
        missing.append(len(need))
        for f in need:
            waiting.setdefault(f, []).append(k)
    stack = [k for k, n in enumerate(missing) if n == 0]
    while stack:
        for f in ops[stack.pop()].makes:
            if f not in facts:
                facts.add(f)
                for k in waiting.pop(f, ()):
                    missing[k] -= 1
                    if missing[k] == 0:
                        stack.append(k)
    return facts


def parse_sas(text: str, anchor: str, skip: Sequence[str] = ()) -> Sas:
    """The translator's output `text`; `anchor`, the SAS name of the fact the caller's anchor operators
    set (`atom p()`, lower case); operators whose name starts with one of `skip` are left out. O(text)."""
    lines = text.split("\n")
    facts: dict[str, Fact] = {}
    values: list[tuple[str, ...]] = []
    blocks: list[str] = []
    i = lines.index("end_metric") + 1
    prefix = "\n".join(lines[:i]) + "\n"
    i += 1  # the variable count
    while lines[i] == "begin_variable":
        count = int(lines[i + 3])
        names = tuple(lines[i + 4 + value].lower() for value in range(count))
        for value, name in enumerate(names):
            facts.setdefault(name, (len(values), value))
        values.append(names)
        blocks.append("\n".join(lines[i:i + 5 + count]) + "\n")
        i += 5 + count
    start = lines.index("begin_state", i)
    mutexes = "\n".join(lines[i:start]) + "\n"
    end = lines.index("end_state", start)
    state = tuple(int(v) for v in lines[start + 1:end])
    i = lines.index("end_goal", end) + 1
    n_ops = int(lines[i])
    i += 1
    ops = []
    for _ in range(n_ops):
        j = lines.index("end_operator", i)
        name = lines[i + 1].strip().lower()
        if not name.startswith(tuple(skip)):
            ops.append("\n".join(lines[i:j + 1]) + "\n")
        i = j + 1
    tail = "\n".join(lines[i:])
    parsed = tuple(parse_op(op) for op in ops)
    makers: dict[Fact, list[int]] = {}
    for k, op in enumerate(parsed):
        for fact in op.makes:
            makers.setdefault(fact, []).append(k)
    prunable = not any(op.conditional for op in parsed) and tail.strip().split("\n")[0].strip() == "0"
    return Sas(prefix, tuple(blocks), mutexes, state, tuple(ops), tail, facts, facts[anchor], parsed,
               {f: tuple(v) for f, v in makers.items()}, prunable, tuple(values))
