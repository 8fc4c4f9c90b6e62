"""`plan`'s default encoding is `relational`; `plan --encoding tree` prints what `plan` printed before the switch.

The files in `tests/data/plan-tree/` are `plan`'s output at 3fbb13a, when `tree` was its default, captured with
`normalised` below (stdout, then stderr without the `phases:` timing line; the JSON without its `timings`).
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from click.testing import CliRunner
from conftest import SHARED, SUBGRAPHS

from foon2pddl.cli import main

GOLDEN = SHARED / "plan-tree"
WHIPPED = str(SUBGRAPHS / "0001-whipped_cream.txt")
APPLE = str(SUBGRAPHS / "0086-apple_turnover.txt")
PIZZA = str(SUBGRAPHS / "0082-homemade_cheese_pizza.txt")

#: name -> the `plan` arguments whose output (then, with the default encoding) the golden file holds.
CASES = {
    "guacamole-recipe": ["--goal", "guacamole"],
    "guacamole-steps": ["--goal", "guacamole", "--format", "steps"],
    "guacamole-json": ["--goal", "guacamole", "--format", "json"],
    "whipped-foon": ["--goal", "whipped cream", "--format", "foon", WHIPPED],
    "batch-jsonl": ["--goal", "guacamole", "--goal", "lemonade", "--goal", "tomato soup", "--format", "jsonl"],
    "lemonade-unsolvable": ["--goal", "lemonade"],
    "lemonade-gen": ["--goal", "lemonade", "--network", "gen"],
    "guacamole-constraints": ["--goal", "guacamole", "--without-motion", "squeeze"],
}


def run(*args: str):
    result = CliRunner().invoke(main, ["plan", *args])
    assert result.exception is None or isinstance(result.exception, SystemExit), result.exception
    return result


def normalised(result) -> str:
    """Exit status, stdout and stderr, without what depends on the machine's speed (phase timings, a batch
    row's seconds) or on its caches (a notice of work not cached yet, such as FOON-EXP's similarity matrix,
    ends in ` ...`: an empty cache, as in CI, prints it, a warm one does not)."""
    out = result.stdout
    if out.startswith("{\n"):
        data = json.loads(out)
        data.pop("timings")
        out = json.dumps(data, indent=2) + "\n"
    elif out.startswith("{"):
        rows = [json.loads(line) for line in out.splitlines()]
        out = "".join(json.dumps({k: v for k, v in row.items() if k != "seconds"}) + "\n" for row in rows)
    err = "".join(line for line in result.stderr.splitlines(keepends=True)
                  if not line.startswith("phases: ") and not line.rstrip("\n").endswith(" ..."))
    return f"exit {result.exit_code}\n--- stdout\n{out}--- stderr\n{err}"


#: Cases whose network has its own encoding (`gen`: gen-lifted), the default then and now: asked without
#: `--encoding` (`--encoding tree` there plans FOON's tree over GEN's nodes, tested below).
OWN_ENCODING = {"lemonade-gen"}


@pytest.mark.parametrize("name", sorted(CASES))
def test_encoding_tree_prints_what_the_old_default_printed(name):
    encoding = () if name in OWN_ENCODING else ("--encoding", "tree")
    assert normalised(run(*CASES[name], *encoding)) == (GOLDEN / f"{name}.txt").read_text()


def capture(directory: Path) -> None:
    """Write the golden files from `plan` as it is now (run once, at the commit the module docstring names)."""
    directory.mkdir(parents=True, exist_ok=True)
    for name, args in CASES.items():
        (directory / f"{name}.txt").write_text(normalised(run(*args)))


def test_plan_without_encoding_plans_the_relational_encoding():
    text = run("--goal", "guacamole")
    assert text.exit_code == 0, text.output
    assert "objects, step by step (relational encoding):" in text.stdout
    assert "pour lime_juice_1 from juicer_1 into bowl_1" in text.stdout  # the objects, each in its holder
    data = json.loads(run("--goal", "guacamole", "--format", "json").stdout)
    assert data["encoding"] == "relational" and data["validation"]["relational"]["ok"]


def test_a_scene_kitchen_plans_with_its_ids_without_naming_the_encoding():
    scene = SHARED / "scene" / "whipped_cream_scene.json"
    result = run("--kitchen", str(scene), "--goal", "whipped cream: whipped, in [bowl]")
    assert result.exit_code == 0, result.output
    assert "take sugar_1 out of fridge_1, pour it into mixing_bowl_1" in result.stdout


def test_a_batch_plans_the_relational_encoding():
    result = run("--goal", "guacamole", "--goal", "tomato soup", "--format", "jsonl")
    assert result.exit_code == 0, result.output
    assert "(relational encoding, planner fd)" in result.stderr
    assert [json.loads(line)["status"] for line in result.stdout.splitlines()] == ["solved", "solved"]


def test_restore_and_instances_need_no_encoding_option():
    result = run("--goal", "guacamole", "--restore", "--instances", "knife=1", "--format", "json")
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    assert data["encoding"] == "relational"
    assert {o["id"] for o in data["relational"]["initial"] if o["label"] == "knife"} == {"knife_1"}


def test_the_gen_network_keeps_its_lifted_encoding():
    result = run("--goal", "lemonade", "--network", "gen", "--format", "json")
    assert result.exit_code == 0, result.output
    assert json.loads(result.stdout)["encoding"] == "gen-lifted"
    other = run("--goal", "lemonade", "--network", "gen", "--encoding", "instances")
    assert other.exit_code == 2 and "--network gen compiles the gen-lifted encoding" in other.stderr


def test_the_gen_network_with_encoding_tree_plans_foons_tree_over_its_categories():
    """`--network gen --encoding tree` compiled the lifted encoding over the concrete network, silently (review
    rv42): it plans FOON's tree encoding over GEN's nodes, as the experiment's fd-tree does on GEN."""
    result = run("--goal", "lemonade", "--network", "gen", "--encoding", "tree", "--format", "json")
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    assert data["encoding"] == "tree"
    assert data["tree"]["goal"]["label"] == "beverages"
    refused = run("--goal", "lemonade", "--network", "gen", "--encoding", "tree", "--without", "sugars")
    assert refused.exit_code == 2
    assert "not supported by --network gen here" in refused.stderr and "lifted" in refused.stderr


def test_no_relational_plan_where_foon_has_a_tree_says_so_and_what_to_try():
    # from raw ingredients and tools, the cheese pizza's pour (0082:240) needs the bowl of fermented dough, which
    # no reachable state holds (the apple turnover, the example before, plans since its two readings)
    pizza = ("--goal", "cheese pizza", PIZZA, "--kitchen", "base")
    result = run(*pizza)
    assert result.exit_code == 1 and result.stdout == ""
    reason = next(line for line in result.stderr.splitlines() if line.startswith("reason: "))
    assert "FOON's semantics makes the goal" in reason and "relational encoding" in reason
    assert "--encoding tree" in reason
    data = json.loads(run(*pizza, "--format", "json").stdout)
    assert data["status"] == "unsolvable" and "--encoding tree" in data["reason"]
    assert run(*pizza, "--encoding", "tree").exit_code == 0  # FOON's own tree
    assert run("--goal", "apple pie", APPLE).exit_code == 0


def test_a_search_without_conditional_effects_says_why_and_what_to_try():
    result = run("--goal", "guacamole", "--planner", "pyperplan")
    assert result.exit_code == 2 and result.stdout == ""
    reason = next(line for line in result.stderr.splitlines() if line.startswith("reason: "))
    assert "conditional effects" in reason and "--encoding tree" in reason
    assert "Traceback" not in result.output


def test_a_planner_refusing_action_costs_says_why_and_what_to_try():
    """Stop 45's pass: `plan --encoding tree --costs unit --planner pyperplan` printed the engine's "does not
    support this task's features" and no reason (docs/pddl.md: pyperplan rejects action costs)."""
    result = run("--goal", "guacamole", "--encoding", "tree", "--costs", "unit", "--planner", "pyperplan")
    assert result.exit_code == 2 and result.stdout == ""
    reason = next((line for line in result.stderr.splitlines() if line.startswith("reason: ")), result.stderr)
    assert "action costs (`:action-costs`" in reason and "without --costs" in reason
    assert "without the constraints file's rates" in reason  # rates give costs too (review rv45: no --costs there)
    assert "conditional effects" not in reason  # the tree encoding has none


def test_optimal_plans_the_default_encoding_with_an_admissible_search_that_takes_conditional_effects():
    # LM-cut (seq-opt-lmcut) refuses the relational actions' `forall ... when`; A* with h^max is admissible and
    # takes them, so its plan is no longer than lama's (an independent bound) and passes the relational replay
    optimal = json.loads(run("--goal", "guacamole", "--optimal", "--format", "json").stdout)
    lama = json.loads(run("--goal", "guacamole", "--format", "json").stdout)
    assert (optimal["status"], optimal["planner"], optimal["encoding"]) == ("solved", "fd (astar(hmax()))",
                                                                           "relational")
    assert optimal["validation"]["relational"]["ok"] and len(optimal["plan"]) <= len(lama["plan"])
    tree = json.loads(run("--goal", "guacamole", "--optimal", "--encoding", "tree", "--format", "json").stdout)
    assert tree["planner"] == "fd (seq-opt-lmcut)"  # no conditional effects: LM-cut as before


def test_compile_keeps_the_tree_encoding_as_its_default(tmp_path):
    result = CliRunner().invoke(main, ["compile", "--goal", "guacamole", "-o", str(tmp_path)])
    assert result.exit_code == 0, result.output
    assert "(tree encoding" in result.stdout


def test_batch_rows_give_the_reasons_a_single_goal_prints():
    """Under the relational default a batch row for a planner that refuses conditional effects, or for a time
    limit, gave only the planner's words (review rv42): it gives the reason the single-goal run prints."""
    refused = run("--goal", "guacamole", "--goal", "lemonade", "--planner", "pyperplan", "--format", "jsonl")
    row = json.loads(refused.stdout.splitlines()[0])
    assert row["status"] == "error"
    assert "conditional effects (`:conditional-effects`)" in row["reason"]
    timed = run("--goal", "guacamole", "--goal", "lemonade", "--time-limit", "0.01", "--format", "jsonl")
    row = json.loads(timed.stdout.splitlines()[0])
    assert row["status"] == "timeout"
    assert "FOON's semantics makes the goal from this kitchen" in row["reason"]
    single = run("--goal", "guacamole", "--time-limit", "0.01")
    assert "reason: FOON's semantics makes the goal from this kitchen" in single.stderr


def test_the_conditional_effects_reason_says_which_planner_takes_them():
    """Stop 48's newcomer pass: `plan --goal 'whipped cream' --planner pyperplan --optimal` failed with the reason
    "(pyperplan, Tamer, Aries and Fast Downward's LM-cut do not; `--optimal` takes A* with h^max there)": read
    after an `--optimal` run with pyperplan, as if `--optimal` were the way out. The reason says that Fast
    Downward (the default planner) takes them, and that its `--optimal` search does."""
    from types import SimpleNamespace

    from foon2pddl.cli.reasons import unsupported_reason

    reason = unsupported_reason(SimpleNamespace(requirements=(":strips", ":conditional-effects"),
                                                encoding="relational"))
    assert "`--optimal` takes A* with h^max there" not in reason
    assert ("Fast Downward, the default planner, takes them (its `--optimal` search: A* with h^max, not LM-cut)"
            in reason)
