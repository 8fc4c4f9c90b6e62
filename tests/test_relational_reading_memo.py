"""`relational_reading.read_units`' memo holds every network its count keys name (`_as_now`'s networks live in a
cache of `NOWS_KEPT`): a network evicted there and freed while the memo lives could leave its id to another
network, which would then be handed the first one's counts."""

from __future__ import annotations

import gc
import weakref

from test_relational_count_as_now import BAKE, FILL, KITCHEN, MUFFIN, PUT

from foon2pddl.model.foon import Foon
from foon2pddl.model.goal import Goal, GoalSpec
from foon2pddl.model.kitchen import Kitchen
from foon2pddl.pddl import relational_objects, relational_reading
from foon2pddl.pddl.compile import compile_goal


def test_a_network_evicted_from_the_as_now_cache_stays_alive_while_a_memo_names_it(monkeypatch):
    seen = []

    def recording(inp, st, scene, stated, overrides, narrow=None, memo=None, through=False, placed=False,
                  other_makers=True, refill=True):
        seen.append((inp, memo))
        return relational_reading.read_units(inp, st, scene, stated, overrides, narrow, memo, through, placed,
                                             other_makers, refill)

    monkeypatch.setattr(relational_objects, "read_units", recording)
    foon = Foon((FILL, PUT, BAKE))
    compile_goal(foon, Kitchen(frozenset(KITCHEN)), Goal(GoalSpec("muffin"), (MUFFIN,)), "relational", narrow=True)
    (inp, memo), *_ = seen
    made = relational_reading._nows(inp.foon)
    refs = [weakref.ref(net) for net in made.values()]
    assert refs  # counted small, the bake's stitch made a network (`_as_now`)
    made.clear()  # evicted, as by eight other networks
    gc.collect()
    assert all(r() is not None for r in refs)
    assert memo  # the memo lives on
