"""The native solvers prepared: task tree retrieval by a method (`retrieval.api.retrieve`) on a network view.

The reachability fixpoint (complete, optimal) and the network index (greedy) are built once per batch, its
`setup`.
"""

from __future__ import annotations

import time

from ..model.foon import ObjectNode
from .outcomes import Outcome, native_outcome
from .setting import Prepared, Setting

__all__ = ["Native"]


class Native(Prepared):
    """Native retrieval by `method` on the view's network, kitchen mapped through the view."""

    def __init__(self, setting: Setting, method: str) -> None:
        from ..analysis.index import index_of
        from ..analysis.reachability import reachable

        view = setting.view
        t0 = time.perf_counter()
        self.view = view
        self.method = method
        self.per_item = setting.per_item
        self.kitchen_nodes = view.map_kitchen(setting.kitchen).project(view.foon.level).nodes
        index_of(view.foon)
        self.reach = reachable(view.foon, self.kitchen_nodes)
        self.setup = time.perf_counter() - t0

    def solve(self, node: ObjectNode) -> Outcome:
        from ..retrieval.api import retrieve

        nodes = self.kitchen_nodes
        t0 = time.perf_counter()
        result = retrieve(self.view.foon, nodes, self.view.goal_of(node), self.method, reach=self.reach)
        return native_outcome(result, nodes, time.perf_counter() - t0, self.per_item)
