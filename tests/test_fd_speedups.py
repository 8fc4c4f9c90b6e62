"""FD's translator with `planners.fd_speedups`' rewrites writes the SAS file it writes without them,
and both translator paths (the warm server's children, a fresh interpreter) run with them."""

from __future__ import annotations

import os
import random
import subprocess
import sys
from pathlib import Path

import pytest

from foon2pddl.io.files import load
from foon2pddl.model.goal import resolve_goal, spec_of_node
from foon2pddl.model.kitchen import default_kitchen
from foon2pddl.pddl.compile import compile_goal
from foon2pddl.pddl.prune import drop_unbindable
from foon2pddl.pddl.render import render
from foon2pddl.pddl.split_actions import split
from foon2pddl.planners import fd, fd_speedups, translator

SUBGRAPHS = Path(__file__).parent / "data" / "foon-subgraphs"
PLANNERS = Path(fd_speedups.__file__).parent


def _env() -> dict[str, str]:
    return {**os.environ, "PYTHONPATH": str(fd.bin_dir())}


def _in_translator(script: str, cwd: Path) -> str:
    """`script`'s output, run with the translator importable and this package's planners directory on sys.path
    (as the server script has it)."""
    out = subprocess.run([sys.executable, "-c", f"import sys; sys.path.insert(0, {str(PLANNERS)!r})\n" + script],
                         cwd=cwd, env=_env(), capture_output=True, text=True, check=True)
    return out.stdout


def test_the_warm_server_installs_both_rewrites(tmp_path):
    out = _in_translator("import translate_server; print(sorted(translate_server.load()))", tmp_path)
    assert out.strip() == str(sorted(fd_speedups.ORIGINALS))


def test_another_translator_version_is_left_as_it_is(tmp_path, monkeypatch):
    script = ("import fd_speedups\n"
              "fd_speedups.ORIGINALS = {k: '0' * 40 for k in fd_speedups.ORIGINALS}\n"
              "from fast_downward.translate import variable_order as v\n"
              "before = v.CausalGraph.calculate_topological_pseudo_sort\n"
              "print(fd_speedups.apply(), v.CausalGraph.calculate_topological_pseudo_sort is before)\n")
    assert _in_translator(script, tmp_path).strip() == "() True"


@pytest.mark.parametrize("seed", range(20))
def test_the_pseudo_sort_orders_as_the_original(seed, tmp_path):
    # random weighted causal graphs with large components (the rewrite's case), goal variables among them
    rng = random.Random(seed)
    n = rng.randint(2, 60)
    edges = {(rng.randrange(n), rng.randrange(n)): rng.randint(1, 5) for _ in range(rng.randint(1, 4 * n))}
    goal = sorted(rng.sample(range(n), rng.randint(0, min(3, n))))
    script = (
        "import fd_speedups\nfrom collections import defaultdict\n"
        "from fast_downward.translate import variable_order as v\n"
        f"edges, goal, n = {edges!r}, {goal!r}, {n}\n"
        "def order():\n"
        "    cg = v.CausalGraph.__new__(v.CausalGraph)\n"
        "    cg.weighted_graph = defaultdict(lambda: defaultdict(int))\n"
        "    for (s, t), w in edges.items():\n"
        "        if s != t: cg.weighted_graph[s][t] += w\n"
        "    cg.predecessor_graph, cg.ordering, cg.num_variables = defaultdict(set), [], n\n"
        "    cg.goal_map = {g: 0 for g in goal}\n"
        "    return cg.get_ordering()\n"
        "before = order(); done = fd_speedups.apply(); print(before == order(), len(before), len(done))\n")
    same, count, installed = _in_translator(script, tmp_path).split()
    assert same == "True" and int(count) == n and int(installed) == len(fd_speedups.ORIGINALS)  # compared with the rewrite


def test_a_ground_action_keeps_the_deletes_the_original_keeps(tmp_path):
    # a delete the same (condition, atom) adds is dropped, one under another condition or unconditional is kept
    script = (
        "import fd_speedups\n"
        "from fast_downward.translate.pddl import actions\nfrom fast_downward.translate.pddl.conditions import Atom\n"
        "p, q, r = Atom('p', ['a']), Atom('q', ['b']), Atom('r', [])\n"
        "effects = [([], p), ([q], p.negate()), ([], p.negate()), ([q], r), ([q], r.negate()), ([r], q.negate()),\n"
        "           ([q, r], p), ([q, r], p.negate()), ([r, q], p.negate())]\n"
        "def lists():\n"
        "    a = actions.PropositionalAction('a', [], effects, 1)\n"
        "    shown = lambda pairs: repr([(list(map(str, c)), str(e)) for c, e in pairs])\n"
        "    return shown(a.add_effects), shown(a.del_effects)\n"
        "before = lists(); done = fd_speedups.apply(); print(before == lists(), len(eval(before[1])), len(done))\n")
    # kept: ([q], p), ([r], q), ([r, q], p) (a condition is a list: its order counts, as in the original)
    assert _in_translator(script, tmp_path).split() == ["True", "3", str(len(fd_speedups.ORIGINALS))]


def _relational_task(name: str) -> tuple[str, str]:
    """The relational task `plan` hands over for `name`'s dish (split, as `plan` splits it)."""
    foon, _ = load([SUBGRAPHS / name])
    dish = min(n for n in foon.nodes if n.dish is not None)
    compiled = compile_goal(foon, default_kitchen(foon), resolve_goal(spec_of_node(dish), foon), "relational", 3)
    return render(split(drop_unbindable(compiled.task)).task)


@pytest.mark.parametrize("name", ["ACT-0034-greek_salad.txt", "0058-chocolate_cake.txt"])
def test_warm_and_fresh_write_the_sas_file_of_the_unchanged_translator(name, tmp_path):
    domain, problem = _relational_task(name)
    (tmp_path / "domain.pddl").write_text(domain)
    (tmp_path / "problem.pddl").write_text(problem)
    plain = subprocess.run([sys.executable, "-m", "fast_downward.translate", "domain.pddl", "problem.pddl",
                            "--sas-file", "plain.sas"], cwd=tmp_path, env=_env(), capture_output=True, check=True)
    assert plain.returncode == 0
    sas = {}
    for warm in (True, False):
        os.environ[translator.SWITCH] = "1" if warm else "0"
        try:
            run = fd.translate(tmp_path / "domain.pddl", tmp_path / "problem.pddl", tmp_path / f"{warm}.sas",
                               tmp_path, 60.0)
        finally:
            os.environ.pop(translator.SWITCH, None)
        assert run.returncode == 0, run.output
        sas[warm] = (tmp_path / f"{warm}.sas").read_bytes()
    assert sas[True] == sas[False] == (tmp_path / "plain.sas").read_bytes()


@pytest.mark.parametrize("entry", ["import fd_speedups; fd_speedups.apply()",
                                   "import translate_server; translate_server.load()"])
def test_both_translator_paths_collect_cycles_rarely(entry, tmp_path):
    # the fresh translator's script and the warm server (whose children inherit it) raise the collector's threshold
    out = _in_translator(entry + "\nimport gc; print(gc.get_threshold()[0])", tmp_path)
    assert int(out) == fd_speedups.GC_THRESHOLD[0] > 700  # CPython's default: a collection every 700 allocations


def test_a_condition_translated_again_is_a_fresh_copy_of_the_original_result(tmp_path):
    # the cache returns what the original returns, as new dicts each time: callers add to them (a delete's guard)
    script = (
        "import fd_speedups\n"
        "from fast_downward.translate import main\nfrom fast_downward.translate.pddl.conditions import Atom\n"
        "p, q, r = Atom('p', ['a']), Atom('q', ['b']), Atom('r', [])\n"
        "dictionary = {p: [(0, 0)], q: [(1, 0)], r: [(1, 1)]}\n"
        "ranges, mutex, mutex_ranges = [2, 3], {p: [(0, 0)], q: [(1, 0)], r: [(2, 0)]}, [2, 2, 2]\n"
        "cases = [[p], [p, q], [q, r], [p, q.negate()], [r.negate()], []]\n"
        "def run():\n"
        "    return [main.translate_strips_conditions(c, dictionary, ranges, mutex, mutex_ranges) for c in cases]\n"
        "before = run(); done = fd_speedups.apply()\n"
        "first = run(); first[1][0][5] = 9; second = run()\n"
        "print(before == second, first[0][0] is not second[0][0], 'main.translate_strips_conditions' in done)\n")
    assert _in_translator(script, tmp_path).split() == ["True", "True", "True"]


@pytest.mark.parametrize("name", ["ACT-0034-greek_salad.txt", "0058-chocolate_cake.txt"])
def test_the_datalog_model_is_the_original_one_in_its_order(name, tmp_path):
    domain, problem = _relational_task(name)
    (tmp_path / "domain.pddl").write_text(domain)
    (tmp_path / "problem.pddl").write_text(problem)
    script = (
        "import io, contextlib, fd_speedups\n"
        "from fast_downward.translate import build_model, normalize, options, pddl_parser, pddl_to_prolog\n"
        "options.set_options(['domain.pddl', 'problem.pddl'])\n"
        "def model():\n"
        "    with contextlib.redirect_stdout(io.StringIO()):\n"
        "        task = pddl_parser.open('domain.pddl', 'problem.pddl'); normalize.normalize(task)\n"
        "        model = build_model.compute_model(pddl_to_prolog.translate(task))\n"
        "    return [(getattr(a.predicate, 'name', a.predicate), a.args) for a in model]  # an action: by name\n"
        "before = model(); done = fd_speedups.apply()\n"
        "print(before == model(), len(before) > 100, 'build_model.JoinRule.fire' in done)\n")
    assert _in_translator(script, tmp_path).split() == ["True", "True", "True"]


def test_each_replacement_is_installed_once_and_keeps_the_function_it_replaces(tmp_path):
    # one way to install all four: each installed function names the translator's own (`original`), and a second
    # apply (the warm server's children import the module again) installs nothing over them
    script = (
        "import fd_speedups\n"
        "from fast_downward.translate import build_model, main, variable_order\n"
        "from fast_downward.translate.pddl import actions\n"
        "places = [(variable_order.CausalGraph, 'calculate_topological_pseudo_sort'),\n"
        "          (actions.PropositionalAction, '__init__'), (build_model.JoinRule, 'fire'),\n"
        "          (main, 'translate_strips_conditions')]\n"
        "before = [owner.__dict__[attr] for owner, attr in places]\n"
        "first = fd_speedups.apply(); installed = [owner.__dict__[attr] for owner, attr in places]\n"
        "second = fd_speedups.apply(); again = [owner.__dict__[attr] for owner, attr in places]\n"
        "print(len(first), first == second, [f.original is b for f, b in zip(installed, before)] == [True] * 4,\n"
        "      [a is f for a, f in zip(again, installed)] == [True] * 4)\n")
    assert _in_translator(script, tmp_path).split() == ["4", "True", "True", "True"]
