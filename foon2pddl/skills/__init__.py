"""Robot skills under every FOON step: a macro plan's steps decomposed into pick, place, pour, stir, cut.

Pipeline: `domain` (the skill domain, a PDDL file) and `table` (motion -> skill),
`micro` (one micro problem per macro step of a `model.physical.PhysicalTrace`),
`fd_micro` (Fast Downward on it), `memo` (each shape of micro task solved once), `shorten`
(skills a micro plan does not need dropped),
`replay` (an independent skill-level simulator), `decompose` (all of it for one plan), `profile` (robot profiles), `trace_of`
(a trace from an `instances` plan), `report` (text and JSON). docs/skills.md.
"""

from .decompose import MacroSkills, SkillCall, SkillPlan, StepStatus, decompose
from .domain import SkillDomain, read_domain, shipped_domain
from .profile import Robot, robot_constraints
from .table import MotionTable, read_table, shipped_table

__all__ = ["MacroSkills", "MotionTable", "Robot", "SkillCall", "SkillDomain", "SkillPlan", "StepStatus",
           "read_domain", "read_table", "robot_constraints", "shipped_domain", "shipped_table", "decompose", "domain",
           "fd_micro", "memo", "micro", "profile", "recipe", "replay", "report", "run", "sexpr", "shorten", "source", "table"]
