"""The solvers an experiment compares, by name, each prepared once per (trial, network).

A solver is prepared for one network view and one trial kitchen (`prepare`, given a `setting.Setting`), which
does the work shared by the goals of the batch (its time is the batch's `setup`), then answers goals one by one
(`solve`). What each prepares is its class's doc: the native solvers in `native_solver` (the reachability fixpoint
or the network index), the Fast Downward ones in `fd_solvers` (`fd-tree` and `fd-tree-opt`: one translation per
run, goals swapped in; `fd-state`, `fd-instances` and `fd-relational`: compiled per goal, the physical ones may
need a wash or a second bowl where FOON's semantics does not, and solve fewer goals than `native-complete`;
`fd-lifted-gen`: GEN only, one translation per trial). Every tree a solver returns is validated by simulation
from the kitchen the solver was given; a tree that fails is an `error` (`outcomes`).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from enum import StrEnum

from ..errors import UsageError
from .fd_solvers import FdFresh, FdReuse, LiftedGen
from .native_solver import Native
from .networks import lifted_networks
from .setting import Prepared, Setting


class Role(StrEnum):
    """What the report uses a solver for."""

    REFERENCE = "reference"  # counts the successes (exactly the goals some task tree reaches)
    AGREEMENT = "agreement"  # a planner that must solve exactly the reference's goals (cell by cell)
    OPTIMUM = "optimum"  # an optimal solver: tree sizes are compared with its
    PAPER = "paper"  # the seed paper's method: the time beside the paper's
    CONCRETE = "concrete"  # returns concrete (REG) trees whatever network it runs on
    OTHER = "other"


@dataclass(frozen=True)
class Solver:
    """A registered solver: name, what it is, its preparation, the networks it applies to (None: all),
    its role in the report and its cost rank (batches of costlier solvers start first: better load balance)."""

    name: str
    description: str
    prepare: Callable[[Setting], Prepared]
    networks: tuple[str, ...] | None = None
    planner: bool = False
    role: Role = Role.OTHER
    cost: int = 0
    whole_batches: bool = False  # one task per (trial, network): its preparation is too costly to repeat
    encoding: str | None = None  # the encoding it compiles each goal with (`pddl.compile.ENCODINGS`), if one

    def applies_to(self, network: str) -> bool:
        return self.networks is None or network in self.networks


def _fresh(name: str, description: str, encoding: str) -> Solver:
    """A solver compiling and translating each goal afresh with `encoding` (`FdFresh`)."""
    return Solver(name, description, lambda s: FdFresh(s, encoding), planner=True, cost=6, encoding=encoding)


SOLVERS: dict[str, Solver] = {s.name: s for s in (
    Solver("native-greedy", "the seed paper's greedy task tree retrieval", lambda s: Native(s, "greedy"),
           role=Role.PAPER, cost=1),
    Solver("native-complete", "reachability fixpoint, a tree whenever one exists", lambda s: Native(s, "complete"),
           role=Role.REFERENCE, cost=0),
    Solver("native-optimal", "fewest distinct units (branch and bound)", lambda s: Native(s, "optimal"),
           role=Role.OPTIMUM, cost=2),
    Solver("fd-tree", "Fast Downward lama-first, tree encoding, one translation per run (a trial's kitchen is "
                      "its initial state), each goal's relevant operators only",
           lambda s: FdReuse(s, False), planner=True, role=Role.AGREEMENT, cost=3, whole_batches=True),
    Solver("fd-tree-opt", "Fast Downward A* with LM-cut and atom-centric stubborn sets (optimal), tree encoding, "
                          "one translation per run (a trial's kitchen is its initial state), each goal's relevant "
                          "operators only",
           lambda s: FdReuse(s, True), planner=True, role=Role.OPTIMUM, cost=5, whole_batches=True),
    _fresh("fd-state", "Fast Downward lama-first, state encoding, compiled per goal (plans checked under the "
                       "encoding's STRIPS semantics; FOON simulation reported apart)", "state"),
    _fresh("fd-instances", "Fast Downward lama-first, instances encoding (physical objects whose states change, "
                           "counts derived per goal), compiled per goal (plans replayed on the objects and "
                           "validated as FOON trees; goals no task tree reaches are answered from the trial's "
                           "fixpoint)", "instances"),
    _fresh("fd-relational", "Fast Downward lama-first, relational encoding (physical objects and what holds "
                            "what), compiled per goal (plans replayed object by object, holders included; goals "
                            "no task tree reaches are answered from the trial's fixpoint)", "relational"),
    Solver("fd-lifted-gen", "Fast Downward lama-first, lifted GEN (category types, concrete objects), one "
                            "translation per trial",
           LiftedGen, networks=lifted_networks(), planner=True, role=Role.CONCRETE, cost=4, whole_batches=True),
)}


def with_role(role: Role, solvers: tuple[str, ...] | None = None) -> tuple[str, ...]:
    """Names of the registered solvers with `role` (among `solvers` when given), in registry order."""
    return tuple(n for n, s in SOLVERS.items() if s.role == role and (solvers is None or n in solvers))


#: Solvers run when none are named: everything but the slow per-goal encodings.
DEFAULT_SOLVERS = ("native-greedy", "native-complete", "native-optimal", "fd-tree", "fd-lifted-gen")


def get_solver(name: str) -> Solver:
    """The registered solver `name` (ValueError listing the known ones)."""
    try:
        return SOLVERS[name]
    except KeyError:
        raise UsageError(f"unknown solver {name!r} (expected one of {', '.join(SOLVERS)})") from None
