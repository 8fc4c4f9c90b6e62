"""A skill plan as text for a reader, as JSON for a robot executive, and as PDDL files for other planners.

Text: one line per macro step (`3. chop [chop] (recipe.txt:42)`), the unit it stands
for (`FOON: onion (whole), knife -> onion (chopped)`), then its skills, indented, in words (`pick knife_1 from workspace`, `chop onion_1 with knife_1`).
JSON (`skill_plan_json`): the verdict, every macro step (1-based `step`, motion,
`unit` file:line, skill, status, reason) and the flat `skills` list, one entry per
skill: `skill`, `hand`, `objects` (trace ids; `workspace` for the table top),
`holders` (what each object was in or on just before the skill: an id, a hand, or
null for the workspace), `macro_step` (1-based) and `unit`. `micro_files`: the
domain (robot costs written in) and one problem per decomposed step, for `-o DIR`.
Deterministic: same plan, same bytes.
"""

from __future__ import annotations

from ..model.words import count
from .decompose import MacroSkills, SkillCall, SkillPlan, StepStatus
from .profile import Robot

__all__ = ["call_text", "micro_files", "skill_plan_json", "skill_plan_text", "with_hand"]

_REL = {"pick": "from", "take-out": "out of", "place": "on", "put-in": "into"}


def with_hand(text: str, call: SkillCall, hands: int) -> str:
    """`text` (a skill in words), then the hand that does it when the robot has several: `... (hand 2)`."""
    return text if hands == 1 else f"{text} ({call.hand.replace('_', ' ')})"


def call_text(call: SkillCall, params: tuple[str, ...] = (), hands: int = 1) -> str:
    """`pick knife_1 from workspace`, `chop onion_1 with knife_1`: a skill in words (`with_hand`: `hands`)."""
    objs, shape = list(call.objects), params[1:]
    if len(shape) != len(objs):
        text = " ".join([call.skill, *objs])
    elif shape == ("?t", "?o"):
        text = f"{call.skill} {objs[1]} with {objs[0]}"
    elif shape == ("?t", "?src", "?dst"):
        text = f"{call.skill} from {objs[1]} into {objs[2]} with {objs[0]}"
    elif shape == ("?src", "?dst"):
        text = f"{call.skill} from {objs[0]} over {objs[1]}"
    elif shape == ("?src", "?into"):
        text = f"{call.skill} from {objs[0]} into {objs[1]}"
    elif shape == ("?o", "?s"):
        text = f"{call.skill} {objs[0]} {_REL.get(call.skill, 'at')} {objs[1]}"
    else:
        text = " ".join([call.skill, *objs])
    return with_hand(text, call, hands)


def _header(step: MacroSkills) -> str:
    skill = f" [{step.skill}]" if step.skill else ""
    where_ = f" ({step.source})" if step.source else ""
    head = f"{step.index + 1}. {step.motion}{skill}{where_}"
    if step.status is StepStatus.DECOMPOSED:
        return head
    return f"{head}: {step.status} step, kept as is: {step.reason}"


def skill_plan_text(plan: SkillPlan, robot: Robot | None = None) -> str:
    """The plan for a reader: a summary line, then each macro step with its skills (each
    naming its hand when the robot has several)."""
    robot = robot or Robot()
    params = {a.name: tuple(v for v, _ in a.params) for a in plan.domain.actions}
    verdict = "valid" if plan.replay.ok else "INVALID: " + "; ".join(plan.replay.problems)
    lines = [f"skill plan ({plan.domain.name}, {count(robot.hands, 'hand')}): "
             f"{count(len(plan.steps), 'macro step')}, {plan.decomposed} decomposed, {count(len(plan.calls), 'skill')}; "
             f"skill replay {verdict}"]
    for step in plan.steps:
        lines.append(_header(step))
        if step.what:
            lines.append(f"   FOON: {step.what}")
        lines += [f"   {call_text(c, params.get(c.skill, ()), robot.hands)}" for c in step.calls]
    return "\n".join(lines) + "\n"


def skill_plan_json(plan: SkillPlan) -> dict:
    """The plan as JSON-ready data (see the module doc)."""
    return {
        "domain": plan.domain.path,
        "ok": plan.ok,
        "replay": {"ok": plan.replay.ok, "problems": list(plan.replay.problems)},
        "macro_steps": len(plan.steps),
        "decomposed": plan.decomposed,
        "steps": [{"step": s.index + 1, "motion": s.motion, "unit": s.source, "skill": s.skill,
                   "status": str(s.status), "reason": s.reason, "skills": len(s.calls),
                   "seconds": round(s.seconds, 4)} for s in plan.steps],
        "skills": [{"skill": c.skill, "hand": c.hand, "objects": list(c.objects), "holders": list(c.holders),
                    "macro_step": c.macro + 1, "unit": plan.steps[c.macro].source} for c in plan.calls],
    }


def micro_files(plan: SkillPlan, robot: Robot | None = None) -> dict[str, str]:
    """File name -> text: `domain.pddl` (every skill, the robot's costs written in) and `step-NNN.pddl` per
    step with a micro problem (a failed step's too: an external planner may do better)."""
    robot = robot or Robot()
    domain = plan.domain
    files = {"domain.pddl": domain.pruned(set(domain.by_name) - set(robot.without), robot.cost_table)}
    width = max(3, len(str(len(plan.steps))))
    for s in plan.steps:
        if s.problem is not None:
            files[f"step-{s.index + 1:0{width}d}.pddl"] = s.problem.text
    return files
