"""Fast Downward's translator with four of its functions rewritten to do the same with less work (two of them in
linear time), its garbage collector run rarely: the SAS file is the same.

Imports nothing of foon2pddl: it runs inside translator processes (`planners/translate_server.py` applies it
before forking; a fresh translator runs this file as its script, `python fd_speedups.py ARGS`, which applies it and
then runs `fast_downward.translate` as `python -m` would).

- variable_order.CausalGraph.calculate_topological_pseudo_sort tests each causal-graph edge's target for
  membership in its strongly connected component, a list: O(edges x component). A relational task whose split
  chains and holder sweeps put thousands of variables in one component spent 6.9 of its 19.4 s of translation
  CPU there (the odd-index universal FOON's chocolate cake, 5,047 variables); a set makes it 0.7 s.
- pddl/actions.py's PropositionalAction.__init__ keeps a delete unless the same (condition, atom) is added, testing
  each delete against the list of adds: O(effects^2) per ground action (FD's own comment says so), with
  hundreds of conditional effects per action on a holder sweep. A set of the adds gives the same lists.
- build_model.JoinRule.fire (the Datalog model's join, run once per atom a rule's condition matches: 174,516 times on
  the chocolate cake's small task below) tested every argument of every joined atom with isinstance to find the
  effect positions it binds; the rewrite lists them once per rule. main.translate_strips_conditions translated each
  effect condition of each ground action anew, and a quantified effect's branches and a ground action's parts
  repeat them (41,490 non-empty conditions there, 10,416 distinct); the rewrite caches the answer and returns new
  dicts each time (callers add to them). At f5bff79, side by side: the model 1.30 -> 1.10 s of CPU (medians of 5 in
  one process, load 21), the whole translation 4.93 -> 4.69 s (medians of 10 runs each, interleaved, load 17-22).
- The cyclic garbage collector: CPython collects every 700 net allocations, and the translator allocates millions
  of objects that live to its end (atoms, conditions, ground effects), so each collection walks them again for
  little garbage (the process is short-lived and ends with the task). `apply` raises the threshold
  (`GC_THRESHOLD`): the odd-index universal FOON's chocolate cake, its small task's translation 5.17 -> 4.43 s of
  CPU (medians of 6 runs each, side by side, load 14-18), peak memory the same (144 MB), the SAS file byte-identical.

Each replacement is installed only when the translator file it replaces a function of is the one it was written
against (sha1 below); another translator version is left as it is. Each keeps every order the original produces, so the SAS
file is byte-identical (tests/test_fd_speedups.py checks on relational tasks).
"""

from __future__ import annotations

import gc
import hashlib
import os
import runpy
import sys
from collections import defaultdict

#: Each replacement, by the name it replaces, with the sha1 of the translator file it was written against (the
#: up-fast-downward 1.0.0 wheel's): a file's bytes are read and hashed in well under a millisecond, where
#: `inspect.getsource` cost a fresh translator ~25 ms of CPU.
ORIGINALS = {
    "variable_order.CausalGraph.calculate_topological_pseudo_sort": "95826d3b74439d488f7712d581604666476d208c",
    "pddl.actions.PropositionalAction.__init__": "f8cf5885859734873f4a80335e220392c1d92232",
    "build_model.JoinRule.fire": "ff68ed4954032f06ac526832300e34be7524ad13",
    "main.translate_strips_conditions": "a5f12332d684873f84b8756f86f9935cea87571f",
}

#: The collector's thresholds in a translator (generation 0 every 100,000 net allocations: CPython's default 700).
GC_THRESHOLD = (100_000, 50, 100)


def _pseudo_sort(self, sccs) -> None:
    """As the original, with each component's members in a set: O(edges) instead of O(edges x component)."""
    from fast_downward.translate.variable_order import MaxDAG

    for scc in sccs:
        if len(scc) > 1:
            members = set(scc)
            subgraph = defaultdict(list)
            for var in scc:
                subgraph_edges = subgraph[var]
                for target, cost in sorted(self.weighted_graph[var].items()):
                    if target in members:
                        if target in self.goal_map:
                            subgraph_edges.append((target, 100000 + cost))
                        subgraph_edges.append((target, cost))
            self.ordering.extend(MaxDAG(subgraph, scc).get_result())
        else:
            self.ordering.append(scc[0])


def _action_init(self, name, precondition, effects, cost) -> None:
    """As the original, testing each delete against a set of the adds (conditions as tuples): O(effects)."""
    self.name = name
    self.precondition = precondition
    self.add_effects = [(condition, effect) for condition, effect in effects if not effect.negated]
    added = {(tuple(condition), effect) for condition, effect in self.add_effects}
    self.del_effects = []
    for condition, effect in effects:
        if effect.negated:
            atom = effect.negate()
            if (tuple(condition), atom) not in added:
                self.del_effects.append((condition, atom))
    self.cost = cost


def _join_fire(self, new_atom, cond_index, enqueue_func) -> None:
    """As the original, with each condition's (effect position, argument position) pairs listed once per rule
    instead of found by an isinstance test per argument of every atom joined (the Datalog model's inner loop)."""
    binds = self.__dict__.get("_binds")
    if binds is None:
        binds = self._binds = tuple(tuple((var, pos) for pos, var in enumerate(cond.args) if isinstance(var, int))
                                    for cond in self.conditions)
    args = new_atom.args
    effect_args = list(self.effect.args)
    for var, pos in binds[cond_index]:
        effect_args[var] = args[pos]
    key = tuple([args[pos] for pos in self.common_var_positions[cond_index]])
    other = binds[1 - cond_index]
    predicate = self.effect.predicate
    for atom in self.atoms_by_key[1 - cond_index].get(key, ()):
        other_args = atom.args
        for var, pos in other:
            effect_args[var] = other_args[pos]
        enqueue_func(predicate, effect_args)


def _cached_conditions(original):
    """`main.translate_strips_conditions` answering a condition it translated before from a cache (each ground action
    translates the conditions of its effects, and a quantified effect's branches repeat them: 41,490 non-empty
    conditions, 10,416 distinct, in the chocolate cake's small task), as new dicts each time: callers add to them."""
    cache: dict = {}

    def translate_strips_conditions(conditions, dictionary, ranges, mutex_dict, mutex_ranges):
        if not conditions:
            return [{}]
        key = (tuple(conditions), id(dictionary), id(ranges), id(mutex_dict), id(mutex_ranges))
        hit = cache.get(key)
        if hit is None:  # the objects are kept with the answer, so no other object takes their ids while it is cached
            hit = cache[key] = ((dictionary, ranges, mutex_dict, mutex_ranges),
                                original(conditions, dictionary, ranges, mutex_dict, mutex_ranges))
        return None if hit[1] is None else [dict(c) for c in hit[1]]

    translate_strips_conditions.original = original
    return translate_strips_conditions


def _as_is(function):
    """The maker of a replacement that needs nothing of the function it replaces: `function` itself, naming it."""
    def install(original):
        function.original = original
        return function
    return install


def _sha1(module) -> str | None:
    try:
        with open(module.__file__, "rb") as source:
            return hashlib.sha1(source.read()).hexdigest()
    except (OSError, TypeError):
        return None


def apply() -> tuple[str, ...]:
    """Install each replacement whose translator file is the expected one, and collect cycles rarely (`GC_THRESHOLD`:
    in the translator's process only); the names installed (none when the translator is another version or is
    missing)."""
    gc.set_threshold(*GC_THRESHOLD)
    try:
        from fast_downward.translate import build_model, main, variable_order
        from fast_downward.translate.pddl import actions
    except ImportError:
        return ()
    targets = {  # each replacement's maker, given the function it replaces (kept as the replacement's `original`)
        "variable_order.CausalGraph.calculate_topological_pseudo_sort":
            (variable_order, variable_order.CausalGraph, "calculate_topological_pseudo_sort", _as_is(_pseudo_sort)),
        "pddl.actions.PropositionalAction.__init__":
            (actions, actions.PropositionalAction, "__init__", _as_is(_action_init)),
        "build_model.JoinRule.fire": (build_model, build_model.JoinRule, "fire", _as_is(_join_fire)),
        "main.translate_strips_conditions": (main, main, "translate_strips_conditions", _cached_conditions),
    }
    done = []
    for name, (module, owner, attr, make) in targets.items():
        current = owner.__dict__.get(attr)
        if hasattr(current, "original"):  # installed before: left as it is
            done.append(name)
        elif current is not None and _sha1(module) == ORIGINALS[name]:
            setattr(owner, attr, make(current))
            done.append(name)
    return tuple(done)


if __name__ == "__main__":  # a fresh translator: `python fd_speedups.py ARGS` is `python -m fast_downward.translate ARGS`
    sys.path[0] = os.getcwd()  # as under `python -m`: the working directory, not this file's
    apply()
    sys.argv = ["translate", *sys.argv[1:]]
    runpy.run_module("fast_downward.translate", run_name="__main__", alter_sys=True)
