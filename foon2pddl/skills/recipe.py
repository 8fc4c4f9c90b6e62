"""A skill plan in a cook's words: each macro step as a recipe sentence, then what the robot does, in words.

`plan --skills --format recipe`. Per macro step: the FOON step as `--format recipe`
says it (`io.recipe_words.recipe_text`), then one line `robot: ...` with its skills
joined by `; ` (`pick up the knife from the workspace; chop the onion with the
knife; put the knife on the workspace`), or why the step was kept abstract. An
object is named by its FOON label, with its instance number when the trace has more
than one object of that label (`cutting board 2`); a hand is named only when the
robot has several. Linear in the skills; deterministic.
"""

from __future__ import annotations

from collections import Counter

from ..io.recipe_words import recipe_text, surfaces
from ..model.physical import PhysicalTrace
from ..model.words import count
from .decompose import SkillCall, SkillPlan, StepStatus
from .report import with_hand

__all__ = ["object_names", "skill_plan_recipe", "skill_sentence"]

#: Transport skills: (verb phrase before the object, preposition before the holder).
_TRANSPORT = {"pick": ("pick up", "from"), "take-out": ("take", "out of"), "place": ("put", "on"),
              "put-in": ("put", "into")}
_ONTO = {"spread": "onto", "scrape": "into", "scoop": "into", "pour": "into", "sprinkle": "over"}


def object_names(trace: PhysicalTrace) -> dict[str, str]:
    """Trace id -> words: the label, plus the id's number when several objects share the label."""
    shared = Counter(o.label for o in trace.objects)
    names = {"workspace": "workspace"}
    for o in trace.objects:
        number = o.id.rpartition("_")[2]
        names[o.id] = f"{o.label} {number}" if shared[o.label] > 1 and number.isdigit() else o.label
    return names


def skill_sentence(call: SkillCall, params: tuple[str, ...], names: dict[str, str], holds: bool = False) -> str:
    """One skill in words by the shape of its parameters (as the shipped domain's are); any other shape
    is the skill's name and its objects. `holds`: the poured source holds what is poured (a carton)."""
    objs = [f"the {names.get(o, o)}" for o in call.objects]
    shape, verb = params[1:], call.skill.replace("-", " ")
    if len(shape) != len(objs):
        return " ".join([verb, *objs])
    if call.skill in _TRANSPORT and len(objs) == 2:
        phrase, prep = _TRANSPORT[call.skill]
        return f"{phrase} {objs[0]} {prep} {objs[1]}"
    if shape == ("?t", "?o"):
        return f"{verb} {objs[1]} with {objs[0]}"
    if shape == ("?o",):
        return f"{verb.removesuffix(' by hand')} {objs[0]}" + (" by hand" if verb.endswith(" by hand") else "")
    if shape == ("?src", "?dst"):
        source = f"from {objs[0]}" if holds else objs[0]
        return f"{verb} {source} {_ONTO.get(call.skill, 'into')} {objs[1]}"
    if shape == ("?src", "?into") and call.skill == "dip":  # the held object is what is dipped
        return f"{verb} {objs[1]} into {objs[0]}"
    if shape == ("?src", "?into"):
        return f"{verb} from {objs[0]} into {objs[1]}"
    if shape == ("?t", "?src", "?dst"):
        return f"{verb} from {objs[1]} {_ONTO.get(call.skill, 'into')} {objs[2]} with {objs[0]}"
    return " ".join([verb, *objs])


def skill_plan_recipe(plan: SkillPlan, trace: PhysicalTrace, hands: int = 1) -> str:
    """The skill plan as recipe lines (see the module doc)."""
    names = object_names(trace)
    params = {a.name: tuple(v for v, _ in a.params) for a in plan.domain.actions}
    verdict = "valid" if plan.replay.ok else "INVALID: " + "; ".join(plan.replay.problems)
    on = surfaces(s.unit for s in trace.steps)  # the recipe's words, as `retrieve` says them
    lines = [f"skill plan ({plan.domain.name}, {count(hands, 'hand')}): "
             f"{count(len(plan.steps), 'macro step')}, {plan.decomposed} decomposed, {count(len(plan.calls), 'skill')}; skill replay {verdict}"]
    for step in plan.steps:
        lines.append(f"{step.index + 1}. {recipe_text(trace.steps[step.index].unit, on)}")
        if step.status is not StepStatus.DECOMPOSED:
            lines.append(f"   robot: nothing planned ({step.status} step, kept as is): {step.reason}")
            continue
        before = trace.after(step.index - 1)
        said = []
        for c in step.calls:
            holds = bool(c.objects) and any(s.holder == c.objects[0] and s.exists for s in before.values())
            text = skill_sentence(c, params.get(c.skill, ()), names, holds)
            said.append(with_hand(text, c, hands))
        lines.append("   robot: " + ("; ".join(said) if said else "nothing to do"))
    return "\n".join(lines) + "\n"
