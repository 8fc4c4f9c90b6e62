"""An experiment cell whose plan the physical replay rejects is `rejected`, not a returned tree that fails to
validate: no tree, its steps and the replay's words kept, and `make experiment` does not call it INVALID (issue 21:
FOON's words contradict each other where the plan works, so no physically right plan exists; not a bug)."""

from __future__ import annotations

from test_relational_mixed_before import KITCHEN, SALAD, UNITS

from foon2pddl.experiment.outcomes import plan_outcome
from foon2pddl.experiment.records import RETRIED, Record
from foon2pddl.experiment.render import statuses_md
from foon2pddl.experiment.tables import invalid_trees
from foon2pddl.model.foon import Foon
from foon2pddl.model.goal import Goal, GoalSpec
from foon2pddl.model.kitchen import Kitchen
from foon2pddl.planners.solve import plan
from foon2pddl.status import CellStatus


def _rejected_outcome():
    goal = Goal(GoalSpec("caesar salad"), (SALAD,))
    outcome = plan(Foon(UNITS), Kitchen(frozenset(KITCHEN)), goal, "relational")
    assert outcome.rejected, outcome.message  # the planner found a plan; the replay rejects it
    return outcome, plan_outcome(outcome, outcome.result.plan, frozenset(KITCHEN))


def test_a_plan_the_replay_rejects_is_a_rejected_cell_with_no_tree():
    outcome, cell = _rejected_outcome()
    assert cell.status is CellStatus.REJECTED
    assert cell.units is None and cell.validated is None
    assert cell.plan_length == len(outcome.result.plan)
    assert "[consumed-elsewhere]" in cell.reason
    assert CellStatus.REJECTED not in RETRIED  # a rerun gives the same answer


def test_rejected_cells_are_no_invalid_trees_and_get_a_status_column():
    _, cell = _rejected_outcome()
    fields = {k: v for k, v in vars(cell).items() if k in Record.__dataclass_fields__}
    record = Record(trial=1, goal=0, network="reg", solver="fd-relational", goal_label="caesar salad", **fields)

    class Data:  # the ReportData members invalid_trees and statuses_md read
        records = (record,)
        networks, solvers = ("reg",), ("fd-relational",)

        def cells(self, network, solver):
            return [r for r in self.records if (r.network, r.solver) == (network, solver)]

    assert invalid_trees(Data()) == []
    header, _, row = statuses_md(Data()).splitlines()
    columns = [c.strip() for c in header.strip("|").split("|")]
    values = [c.strip() for c in row.strip("|").split("|")]
    assert values[columns.index("rejected")] == "1" and values[columns.index("trees returned")] == "0"
    assert "lost" not in columns  # shown only when some cell has it, as `rejected` is
