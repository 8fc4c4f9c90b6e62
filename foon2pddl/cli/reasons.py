"""Why a plan failed: words that are true for what they name (which other network would make the goal:
`network_hints`).

A reason never contradicts the planner's status: when FOON's own semantics makes the
goal, the cause is the encoding's extra conditions (for `instances`, counts stated
below what the plan uses; for `relational` and a scene, the step of FOON's task tree that
runs out of the stated objects), never "the planner gave up".
"""

from __future__ import annotations

import re
from pathlib import Path

#: What `compile` says of a task whose goal holds in its initial state (`pddl.task.goal_at_start`).
ALREADY_HELD = "the goal already holds in the kitchen: the plan is empty"


def explained(status, encoding: str) -> bool:
    """Whether a planner's answer without a plan gets FOON's reason (`why_unsolvable`): unsolvable or gave up,
    and a time limit too where the encoding is not complete for FOON's semantics (a tree may exist)."""
    from ..pddl.compile import ENCODINGS
    from ..status import PlanStatus

    info = ENCODINGS[encoding]
    statuses = {PlanStatus.UNSOLVABLE, PlanStatus.GAVE_UP} | (set() if info.complete else {PlanStatus.TIMEOUT})
    return status in statuses and info.foon_semantics


def why_unsolvable(foon, kitchen, goal, cons, encoding: str = "tree",
                   instances: tuple[tuple[str, int], ...] = (), full=None) -> tuple[str, bool]:
    """(FOON's account of a failed plan, whether FOON's semantics makes the goal from `kitchen`).

    Under constraints: the native constrained retrieval's words. Otherwise the missing
    kitchen additions when the fixpoint does not reach the goal; when it does, what in
    the encoding rules it out (a scene's objects, or under `relational` the stated counts, the step of
    FOON's task tree that runs short: `short_step`; under `instances`, the counts stated below what the
    unfolded plan uses; under `relational` at level 1 or 2, with `full`, the network at level 3, the readings
    the level's missing lists change: `level_reason`), else that the planner found no plan.
    """
    from ..analysis.reachability import reachable
    from ..retrieval.explain import explain_unreachable

    if cons.items:
        from ..retrieval.constrained import retrieve_constrained

        found = retrieve_constrained(foon, kitchen, goal, cons).result
        if found.tree is None:
            return found.detail, False
        return "native retrieval finds a tree under the constraints; the planner did not (see its message)" \
            + _try_tree(encoding), True
    reach = reachable(foon, kitchen.nodes)
    if not reach.makes_any(goal.candidates):
        return explain_unreachable(foon, kitchen.nodes, goal), False
    if kitchen.scene:
        short = short_step(foon, kitchen, goal)
        if short:
            return f"FOON's semantics makes the goal, but the scene has too few objects: {short}" + _freed(encoding), True
    if encoding == "relational" and (kitchen.stated_counts() or instances):
        short = short_step(foon, kitchen, goal, dict(instances))
        if short:
            return _too_few(short), True
    if encoding == "instances":
        from ..pddl.instance_counts import count_shortfalls

        short = count_shortfalls(foon, kitchen.nodes, goal.candidates, stated=kitchen.stated_counts(),
                                 overrides=dict(instances))
        if short:
            return _too_few("; ".join(s.describe() for s in short)), True
    if encoding == "relational" and full is not None and foon.level < 3:
        said = level_reason(foon, kitchen, goal, full)
        if said:
            return said, True
    return f"FOON's semantics makes the goal from this kitchen; the planner found no plan for the {encoding} " \
           "encoding (see its message)" + _try_tree(encoding), True


def _freed(encoding: str) -> str:
    """What to try when a scene is short under `instances`, which frees no holder: `relational` takes an object off
    a holder and the holder serves the next step (the guacamole scene with one cutting board plans there)."""
    return ("; under `--encoding relational` (the default) a holder serves again once its object moves off it, "
            "so the scene's objects may do there") if encoding == "instances" else ""


def level_reason(foon, kitchen, goal, full) -> str | None:
    """Why the `relational` planner finds no plan at level 1 or 2 (`foon`; `full`: the network at level 3) where
    FOON's semantics makes the goal: the level leaves out the ingredient lists from which the encoding reads which
    container holds what and whether a pour leaves some behind, and the units of FOON's task tree it reads otherwise
    (`pddl.level_readings`: the milk poured whole out of the measuring cup that level 3 says keeps some). None when
    there is no tree or no unit of it reads otherwise."""
    from ..pddl.level_readings import lost_readings
    from ..retrieval.api import retrieve

    tree = retrieve(foon, kitchen, goal).tree
    if tree is None:
        return None
    by_place = {(s.path, s.line): u for u in full.units for s in u.sources}
    units = dict.fromkeys(by_place[s.path, s.line] for u in tree.units for s in u.sources[:1]
                          if (s.path, s.line) in by_place)
    lost = lost_readings(units, foon.level)
    if not lost:
        return None
    return (f"FOON's semantics makes the goal from this kitchen; the planner found no plan for the relational "
            f"encoding at level {foon.level}, whose nodes leave out the ingredient lists from which it reads which "
            "container holds what and whether a pour leaves some behind; FOON's task tree is read otherwise than at "
            "level 3: " + "; ".join(lost) + "; `--level 3` reads the lists" + _try_tree("relational"))


def _too_few(where: str) -> str:
    """The reason when FOON's semantics makes the goal and a stated count falls short (`where`): one sentence for
    `relational`'s step (`short_step`) and `instances`' shortfalls (`instance_counts.count_shortfalls`)."""
    return (f"FOON's semantics makes the goal, but too few physical objects are given: {where}"
            " (raise the count, or drop it to let the count be derived)")


def _try_tree(encoding: str) -> str:
    """What to try when FOON's semantics makes the goal and the planner found no plan under `encoding`."""
    return "" if encoding == "tree" else "; `--encoding tree` plans under FOON's own semantics (no objects, no holders)"


def unsupported_reason(task) -> str | None:
    """Why a planner error may come from what `task` needs of a planner, and what to try; None when its
    actions are plain STRIPS (then the planner's message is the whole story)."""
    said = []
    if ":conditional-effects" in task.requirements:
        said.append(f"the {task.encoding} encoding's actions have conditional effects (`:conditional-effects`), which "
                    "this planner or search may not support (pyperplan, Tamer, Aries and Fast Downward's LM-cut do not; "
                    "Fast Downward, the default planner, takes them (its `--optimal` search: A* with h^max, not "
                    "LM-cut)); `--encoding tree` (FOON's own semantics) and "
                    "`--encoding instances` have none")
    if ":action-costs" in task.requirements:
        said.append("the task has action costs (`:action-costs`; --costs or a constraints file's rates give them), "
                    "which this planner may not support (pyperplan does not); plan without --costs and without the "
                    "constraints file's rates, or with fd (the default), which takes costs")
    return "; ".join(said) or None


def rejected_reason(problems: tuple[str, ...], notes: tuple[str, ...]) -> str:
    """Why a found plan is no answer: the physical replay rejects it (`problems`, shown on the status line) and no
    count had a right one. Names the first problem's FOON unit (`file:line`) and its label-mismatch `notes` on the
    objects the replay names (else all of them): a recipe that contradicts itself, not a planner that failed."""
    where = problems[0].split(": step ", 1)[0] if ": step " in problems[0] else ""
    said = [n.split(f"{where}: ", 1)[1] for n in notes if where and f"{where}: " in n]
    named = {x.replace("_", " ") for p in problems if p.startswith(where) for x in re.findall(r"([a-z][\w-]*?)_\d+", p)}
    said = [n for n in said if n.split(" is ", 1)[0] in named] or said  # the words on the objects the replay names
    return ("the planner found a plan, but replayed object by object it is physically wrong (docs/pddl.md, Physical "
            "checks), and no count `plan` tried had a physically right one" + (
                f"; FOON's words at {Path(where).name} contradict each other: " + "; ".join(said) if said
                else f"; at {Path(where).name}" if where else ""))


def foreign_reason(status, encoding: str) -> str | None:
    """Why an encoding that is not FOON's semantics (`state`, `ocp`: one object per label, deletes) has no plan,
    where FOON's reason would not apply; None for the other encodings and for a plan or an error."""
    from ..pddl.compile import ENCODINGS
    from ..status import PlanStatus

    if ENCODINGS[encoding].foon_semantics or status not in {PlanStatus.UNSOLVABLE, PlanStatus.GAVE_UP,
                                                            PlanStatus.TIMEOUT}:
        return None
    return (f"the {encoding} encoding is not FOON's semantics: it has one object per label, so a recipe that needs "
            "two of one (two cutting boards, one board twice) has no plan in it (docs/pddl.md); `--encoding "
            "relational` (the default) or `--encoding tree` plans under FOON's semantics")


def failure_reason(status, encoding: str, task, foon, kitchen, goal, cons,
                   instances: tuple[tuple[str, int], ...] = (), full=None, rejected: tuple[str, ...] = (),
                   notes: tuple[str, ...] = ()) -> tuple[str | None, bool]:
    """(the `reason:` of a planner's answer without a plan, whether FOON's semantics makes the goal): one decision
    for a single `plan` and each row of a batch. FOON's reason (`why_unsolvable`) where `explained`; for a plan the
    physical replay rejects (`rejected`: `PlanOutcome.rejected`), where and what FOON's words say there
    (`rejected_reason`, from the outcome's `notes`); for another error, what the encoding needs of a planner; for
    `state`/`ocp`, `foreign_reason` where FOON's semantics makes the goal, else FOON's reason; None (nothing to add)
    otherwise."""
    from ..status import PlanStatus

    if explained(status, encoding):
        return why_unsolvable(foon, kitchen, goal, cons, encoding, instances, full)
    if status == PlanStatus.ERROR:
        return (rejected_reason(rejected, notes) if rejected else unsupported_reason(task)), True
    if (foreign := foreign_reason(status, encoding)) is None:
        return None, True
    fails, makes = why_unsolvable(foon, kitchen, goal, cons, encoding, instances, full)
    return (foreign if makes else fails), makes


def short_step(foon, kitchen, goal, counts: dict[str, int] | None = None) -> str | None:
    """Which step of FOON's task tree runs out of a kitchen's counted objects (`planners.executable.schedule`:
    `step 3 (pour) needs one more bowl in 'bowl (empty)': ...`), None when none does or there is no tree.

    `counts` (label -> N, as `--instances`): only the stated counts and these limit the schedule (`schedule`'s
    `uncounted=None`), so a shortfall is always one the user stated; a label in `counts` is counted by it, not by
    the kitchen (`instance_counts.derive_counts`'s precedence: override, then the kitchen's count). Without
    `counts`, a node the kitchen gives no count has one object (a scene's objects are all counted)."""
    from ..planners.executable import Verdict, schedule
    from ..retrieval.api import retrieve

    tree = retrieve(foon, kitchen, goal).tree
    if tree is None:
        return None
    stated = kitchen.stated_counts()
    if counts is not None:
        stated = {n: k for n, k in stated.items() if n.label not in counts}  # `schedule` takes these first
    done = schedule(tree, kitchen.nodes, counts, stated=stated, uncounted=1 if counts is None else None)
    return done.message if done.verdict is Verdict.SHORT else None


def foon_makes(foon, kitchen, goal) -> bool:
    """Whether FOON's own semantics makes a candidate of the ground `goal` from `kitchen`: the fixpoint over the
    units that can contribute to the candidates, the same answer for them as the whole one (`reachable`);
    O(the goal's relevant units). The one test of `unreachable_reason` and `beyond_foon_note`."""
    from ..analysis.reachability import reachable

    return reachable(foon, kitchen.nodes, goal.candidates).makes_any(goal.candidates)


def unreachable_reason(foon, kitchen, goal, task=None, *, fixpoint: bool = True) -> str | None:
    """Why nothing makes `goal` from `kitchen` (the words `retrieve` gives), or None when something may.

    FOON's fixpoint decides for a ground goal (O(the goal's relevant units)); a compiled `task` with no unit action
    whose goal is not already true at the start is unsolvable too (constraints, the lifted encoding).
    `fixpoint=False` skips the first test: a lifted encoding grounds categories to kitchen objects the
    concrete network's fixpoint does not see (the recipe's lemon, the kitchen's lime).
    """
    from ..retrieval.explain import explain_unreachable

    if fixpoint and hasattr(goal, "candidates") and not foon_makes(foon, kitchen, goal):
        return explain_unreachable(foon, kitchen.nodes, goal)
    if task is not None and not any(a.unit is not None for a in task.actions) and not set(task.goal) <= set(task.init):
        return "no unit of the network is left on a way to it, and the kitchen does not hold it"
    return None


def beyond_foon_note(foon, kitchen, goal, encoding: str) -> str | None:
    """A solved plan's note when FOON's own semantics does not make `goal` from `kitchen`, which `retrieve` and
    `--encoding tree` then answer unreachable: the relational encoding's readings of the data (its `label mismatch:`
    notes, docs/pddl.md) made it. None when the fixpoint reaches a candidate, and for a lifted encoding (it grounds
    categories to kitchen objects the concrete fixpoint does not see). O(the goal's relevant units)."""
    from ..pddl.compile import encoding_named

    if encoding_named(encoding).lifted or not hasattr(goal, "candidates") or foon_makes(foon, kitchen, goal):
        return None
    return (f"FOON's own semantics does not make {goal.describe()!r} from this kitchen (`retrieve` and "
            f"`--encoding tree` answer unreachable): the plan rests on the {encoding} encoding's readings of the "
            "data (its `label mismatch:` notes)")


def gen_reading_note(view, goal: str | None, goal_file: Path | None, made) -> str:
    """For a FOON-GEN tree: how the goal was read, and whether `made` (the tree's goal node) is the
    category image of a node the user's goal names in the concrete network ("" when it is, or when
    the goal is already a category). A category-level goal (`salads`) is met by any salad; this
    says when the tree makes another dish of the category than the one asked for."""
    from ..errors import FoonError
    from ..generalize.compress import abstract_goal
    from ..io.inputs import load_goal_spec
    from ..model.goal import resolve_goal, spec_of_node

    spec = load_goal_spec(goal, goal_file)
    read = view.map_goal(spec)
    if read == spec:
        return ""
    try:
        concrete = resolve_goal(spec, view.concrete).candidates
    except FoonError:
        return ""
    for node in concrete:
        image = abstract_goal(spec_of_node(node), view.index)
        if made.label == image.label and set(image.states or ()) <= set(made.states):
            return ""
    return (f"note: FOON-GEN reads {spec.describe()!r} as {read.describe()!r}: this tree makes "
            f"`{made.describe()}`, the category image of no {spec.describe()!r} node of the network (another "
            f"dish of the category); `plan --network gen` grounds only trees for the dish itself")
