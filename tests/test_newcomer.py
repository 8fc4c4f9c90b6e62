"""What a new user hit on real FOON files: hints and reasons that are true, goals that mean the dish,
kitchens from scratch, wrong inputs named, no silent waits. Each test is one finding; small FOONs
are built here for the cases found on files the test corpus does not hold."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from click.testing import CliRunner
from conftest import SUBGRAPHS

from foon2pddl.cli import main
from foon2pddl.io.inputs import example_path
from foon2pddl.io.kitchen_files import read_kitchen


def run(*args: str, stdin: str | None = None):
    return CliRunner().invoke(main, [str(a) for a in args], input=stdin)


def kitchen_lines(drop=(), counts=None) -> str:
    """The example kitchen as one node per line, without the labels in `drop`, with `counts` (label -> N)."""
    counts = counts or {}
    out = []
    for n in read_kitchen(example_path("example_kitchen.txt")).sorted_nodes():
        if n.label in drop:
            continue
        line = n.label + (": " + ", ".join(s.describe() for s in n.states) if n.states else "")
        out.append(f"{counts[n.label]} x {line}" if n.label in counts else line)
    return "\n".join(out) + "\n"


def write(path: Path, text: str) -> Path:
    path.write_text(text)
    return path


#: Two salads: the greek one needs olive oil, which no kitchen object of its category replaces.
SALADS = """//
O\tbowl\t0
S\tempty
O\tfeta cheese\t1
S\tcrumbled
O\tolive oil\t1
S\tliquid
M\tmix
O\tgreek salad\t0
S\tcontains\t{feta cheese,olive oil}
S\tin\t[bowl]
//
O\tbowl\t0
S\tempty
O\tlettuce\t1
S\tchopped
O\tcrouton\t1
S\twhole
M\tmix
O\tcaesar salad\t0
S\tcontains\t{crouton,lettuce}
S\tin\t[bowl]
//
"""
SALAD_KITCHEN = "bowl: empty\nlettuce: chopped\ncrouton: whole\nfeta cheese: crumbled\n"


# -- 1. a hint is true for the command it suggests ----------------------------------------------------


def test_gen_hint_only_when_plan_network_gen_makes_it(tmp_path):
    foon = write(tmp_path / "salads.txt", SALADS)
    kit = write(tmp_path / "k.txt", SALAD_KITCHEN)
    planned = run("plan", foon, "--goal", "greek salad", "--kitchen", kit)
    assert planned.exit_code == 1 and "olive oil" in planned.stderr
    hints = [line for line in planned.stderr.splitlines() if line.startswith("hint:")]
    assert not any("--network gen" in line for line in hints)  # the category fixpoint makes *a* salad, not this one
    gen = run("plan", foon, "--goal", "greek salad", "--kitchen", kit, "--network", "gen")
    assert gen.exit_code == 1  # the oracle: the command the old hint suggested fails
    # where the hint is given, the command it names succeeds
    hinted = run("plan", "--goal", "lemonade")
    assert "--network gen" in hinted.stderr and "--network exp" in hinted.stderr
    assert run("plan", "--goal", "lemonade", "--network", "gen").exit_code == 0


def test_gen_retrieval_says_when_its_tree_is_another_dish(tmp_path):
    foon = write(tmp_path / "salads.txt", SALADS)
    kit = write(tmp_path / "k.txt", SALAD_KITCHEN)
    r = run("retrieve", foon, "--goal", "greek salad", "--kitchen", kit, "--network", "gen")
    assert r.exit_code == 0
    assert "reads 'greek salad' as 'salads'" in r.stderr and "no 'greek salad' node" in r.stderr
    same = run("retrieve", "--goal", "lemonade", "--network", "gen")
    assert same.exit_code == 0 and "no 'lemonade' node" not in same.stderr


# -- 2. too few instances: the cause, no contradicting hint -------------------------------------------


def test_instances_counts_too_low_are_named(tmp_path):
    kit = write(tmp_path / "k.txt", kitchen_lines(counts={"cutting board": 1}))
    r = run("plan", "--goal", "guacamole", "--encoding", "instances", "--kitchen", kit)
    assert r.exit_code == 1 and "unsolvable" in r.stderr
    assert "1 x `cutting board (empty)` (the kitchen's count)" in r.stderr
    assert "gave up" not in r.stderr and "hint:" not in r.stderr
    # the oracle: the counts the reason points to solve it
    fixed = write(tmp_path / "k2.txt", kitchen_lines())
    assert run("plan", "--goal", "guacamole", "--encoding", "instances", "--kitchen", fixed).exit_code == 0


def test_instances_override_too_low_is_named():
    r = run("plan", "--goal", "guacamole", "--encoding", "instances", "--instances", "cutting board=1")
    if r.exit_code == 1:  # one board may do when the plan can reuse it; if not, the reason names it
        assert "(the count stated for the label)" in r.stderr
    else:
        assert r.exit_code == 0


# -- 3. constraints: "even without the constraints" only when true -------------------------------------


def test_without_under_exp_does_not_claim_unreachable_without_constraints():
    r = run("retrieve", "--goal", "guacamole", "--without", "cilantro", "--network", "exp")
    assert r.exit_code == 1
    assert "even without the constraints" not in r.stderr
    assert "without them the kitchen makes it" in r.stderr
    assert run("retrieve", "--goal", "guacamole", "--network", "exp").exit_code == 0  # the oracle


# -- 4. kitchen additions past the old limit of 3 ----------------------------------------------------


def test_four_missing_things_are_found_not_a_wrong_list(tmp_path):
    kit = write(tmp_path / "k.txt", kitchen_lines(drop=("avocado", "cilantro", "juicer", "lime")))
    r = run("retrieve", "--goal", "guacamole", "--kitchen", kit)
    assert r.exit_code == 1
    assert ("smallest kitchen additions that make it: add `avocado (whole)`, `cilantro (fresh)`, "
            "`juicer (empty)` and `lime (whole)`") in r.stderr
    assert "missing" not in r.stderr
    # the oracle: adding them back solves it
    assert run("retrieve", "--goal", "guacamole", "--kitchen", write(tmp_path / "k2.txt", kitchen_lines())).exit_code == 0


def test_the_limit_is_said_when_reached():
    from foon2pddl.io.inputs import load_kitchen, load_network
    from foon2pddl.model.goal import GoalSpec, resolve_goal
    from foon2pddl.model.kitchen import Kitchen
    from foon2pddl.retrieval.explain import explain_unreachable

    net = load_network([])
    kit = load_kitchen(None, net, 3)
    drop = {"avocado", "cilantro", "juicer", "lime"}
    less = Kitchen(frozenset(n for n in kit.nodes if n.label not in drop), 3)
    goal = resolve_goal(GoalSpec("guacamole"), net.at(3))
    text = explain_unreachable(net.at(3), less.nodes, goal, max_size=3)
    assert "it needs more than 3 kitchen additions (no set of up to 3 makes it)" in text
    assert "smallest kitchen additions" not in text


# -- 5. a batch explains as a single goal does ---------------------------------------------------------


def test_batch_plan_explains_unreachable_goals():
    r = run("plan", "--goal", "guacamole", "--goal", "lemonade")
    assert r.exit_code == 1
    assert "smallest kitchen additions that make it: add `lemon (whole)`" in r.stdout


# -- 8. one goal grammar: the node text the tools print is a goal ------------------------------------

GUACAMOLE = "guacamole (contains {avocado, cilantro, lime juice, onion, salt, tomato}, in [bowl])"


def test_goal_accepts_the_node_text_the_tools_print(tmp_path):
    printed = run("retrieve", "--goal", GUACAMOLE)
    assert printed.exit_code == 0, printed.stderr
    colon = run("retrieve", "--goal", "guacamole: contains {avocado, cilantro, lime juice, onion, salt, tomato}, "
                "in [bowl]")
    assert printed.stdout == colon.stdout
    goals = write(tmp_path / "goals.txt", GUACAMOLE + "\n")
    assert run("retrieve", "--goals", goals).exit_code == 0
    assert run("plan", "--goal", GUACAMOLE).exit_code == 0
    # kitchen lines too, with counts
    kit = write(tmp_path / "k.txt", kitchen_lines().replace("cutting board: empty", "2 x cutting board (empty)"))
    assert read_kitchen(kit).stated_counts() and run("retrieve", "--goal", "guacamole", "--kitchen", kit).exit_code == 0


# -- 10. --instances typos and misuse are errors ------------------------------------------------------


def test_instances_typo_is_an_error_with_close_matches():
    r = run("plan", "--goal", "guacamole", "--encoding", "instances", "--instances", "cuting board=1")
    assert r.exit_code == 2 and "no object of the network is labelled 'cuting board'" in r.stderr
    assert "close matches: cutting board" in r.stderr and "Traceback" not in r.output
    c = run("compile", "--goal", "guacamole", "--encoding", "instances", "--instances", "cuting board=1")
    assert c.exit_code == 2 and "cuting board" in c.stderr


@pytest.mark.parametrize("command", ["plan", "compile"])
def test_instances_with_an_encoding_without_objects_is_an_error(command):
    r = run(command, "--goal", "guacamole", "--encoding", "tree", "--instances", "cutting board=2")
    assert r.exit_code == 2 and "--instances counts the objects of --encoding instances or relational" in r.stderr
    batch = run(command, "--goal", "guacamole", "--goal", "lemonade", "--encoding", "tree", "--instances",
                "cutting board=2",
                *(["-o", "/tmp/nu-never"] if command == "compile" else []))
    assert batch.exit_code == 2 and "--instances" in batch.stderr


# -- 9. what `goals --network gen` lists, `--network gen` plans; a one-goal --goals works ------------


def test_gen_goals_listed_are_goals_of_plan_network_gen(tmp_path):
    listed = run("goals", "--network", "gen")
    rows = [line for line in listed.stdout.splitlines() if line.startswith("yes")]
    beverage = next(line for line in rows if "beverages (" in line)
    r = run("plan", "--network", "gen", "--goal", "beverages")
    assert r.exit_code == 0, r.stderr
    assert "lemonade" in r.stdout  # the one beverage the kitchen makes, grounded
    # a row of the table as the goal (the node text `goals` printed)
    node = beverage[17:]  # the goal column (made 5, round 5, 2 blanks, dish 5)
    assert run("plan", "--network", "gen", "--goal", node).exit_code == 0
    assert run("compile", "--network", "gen", "--goal", "beverages", "-o", tmp_path / "c").exit_code == 0
    one = run("plan", "--network", "gen", "--goals", "-", stdin="lemonade\n")
    assert one.exit_code == 0 and "1 goal: 1 solved" in one.stderr
    many = run("compile", "--network", "gen", "--goal", "lemonade", "--goal", "beverages", "-o", tmp_path / "d")
    assert many.exit_code == 0 and (tmp_path / "d" / "beverages" / "domain.pddl").exists()
    unknown = run("plan", "--network", "gen", "--goal", "beveragez")
    assert unknown.exit_code == 2 and "unknown object label" in unknown.stderr


def test_a_bare_gen_category_goal_means_the_dish_goals_marks():
    """Stop 46's pass, item 9 tried again: `goals --network gen` marks the lemonade in a drinking vessel as the
    dish and `retrieve --network gen --goal beverages` reads the bare category so (item 6), but `plan --network
    gen --goal beverages` planned the pitcher's lemonade (7 units, the cheaper candidate) without a word."""
    listed = run("goals", "--network", "gen")
    dish = next(line for line in listed.stdout.splitlines()
                if line.startswith("yes") and line.split()[2:4] == ["*", "beverages"])
    assert "in [drinking vessels]" in dish
    retrieved = run("retrieve", "--network", "gen", "--goal", "beverages")
    assert "in [drinking vessels]): 9 units" in retrieved.stdout
    for command in ("plan", "compile"):
        r = run(command, "--network", "gen", "--goal", "beverages", *(["-o", "out"] if command == "compile" else []))
        assert r.exit_code == 0, r.stderr
        assert "note: goal 'beverages' read as the recipe's dish: `lemonade (contains {lemon juice, sugar, water}, " \
               "in [drinking glass])`" in r.stderr, r.stderr
    planned = run("plan", "--network", "gen", "--goal", "beverages")
    assert "in [drinking glass]): 9 units" in planned.stdout, planned.stdout


# -- 6. a bare label means the dish ------------------------------------------------------------------

#: Salmon thawed in a bowl (one unit) on the way to the recipe's dish, salmon baked on a plate.
SALMON = """//
O\tsalmon\t1
S\tfrozen
O\tbowl\t0
S\tempty
M\tplace
O\tsalmon\t1
S\tfrozen
S\tin\t[bowl]
//
O\tsalmon\t1
S\tfrozen
S\tin\t[bowl]
M\tthaw
O\tsalmon\t1
S\tthawed
S\tin\t[bowl]
//
O\tsalmon\t1
S\tthawed
S\tin\t[bowl]
O\tplate\t0
S\tempty
M\tbake
O\tsalmon\t1\t0
S\tbaked
S\ton\t[plate]
//
"""


def test_bare_label_is_the_dish_and_says_so(tmp_path):
    foon = write(tmp_path / "salmon.txt", SALMON)
    kit = write(tmp_path / "k.txt", "salmon: frozen\nbowl: empty\nplate: empty\n")
    r = run("retrieve", foon, "--goal", "salmon", "--kitchen", kit)
    assert r.exit_code == 0 and "3 units" in r.stderr
    assert "salmon (baked, on [plate])" in r.stdout.splitlines()[0]
    assert "note: goal 'salmon' read as the recipe's dish: `salmon (baked, on [plate])`" in r.stderr
    assert "`salmon (frozen, in [bowl])`" in r.stderr  # the others are listed
    # states still ask for a node exactly
    exact = run("retrieve", foon, "--goal", "salmon: frozen, in [bowl]", "--kitchen", kit)
    assert exact.exit_code == 0 and "1 unit" in exact.stderr and "note:" not in exact.stderr


def test_bare_label_on_the_corpus_picks_a_dish():
    # both black-bean recipes start from half-made beans no unit makes: only the default kitchen has them
    r = run("retrieve", SUBGRAPHS, "--goal", "black bean", "--kitchen", "default")
    assert r.exit_code == 0
    assert "read as the recipes' dishes" in r.stderr
    first = r.stdout.splitlines()[0]
    assert "black bean (contains {" in first and "cooked, in [bowl]" in first


def test_goals_dishes_lists_the_dishes_only():
    r = run("goals", "--dishes")
    rows = r.stdout.splitlines()[2:]
    assert rows and all("  *  " in row for row in rows)
    assert len(rows) == 9  # one dish per recipe of the example
    every = run("goals").stdout.splitlines()[2:]
    assert {row for row in every if "  *  " in row} == set(rows)


def test_more_than_the_limit_is_said_without_a_missing_list(tmp_path):
    kit = write(tmp_path / "k.txt", "knife\n")
    r = run("retrieve", "--goal", "guacamole", "--kitchen", kit)
    assert r.exit_code == 1
    assert "it needs more than 6 kitchen additions" in r.stderr
    assert "missing (no unit makes them)" not in r.stderr


# -- 11. wrong inputs are named ------------------------------------------------------------------------


def test_a_rates_file_as_kitchen_is_an_input_error():
    from conftest import SEARCH_INPUTS

    r = run("retrieve", "--goal", "guacamole", "--kitchen", SEARCH_INPUTS / "motion.txt")
    assert r.exit_code == 2
    assert "motion.txt:1: error: this is a motion success-rates file" in r.stderr
    assert "warning" not in r.stderr


def test_stats_of_a_kitchen_json_says_it_is_a_kitchen():
    from conftest import SEARCH_INPUTS

    r = run("stats", SEARCH_INPUTS / "kitchen.json")
    assert r.exit_code == 2 and "is a kitchen or a goal list" in r.stderr


@pytest.mark.parametrize("command", ["stats", "plan"])
def test_a_scene_given_as_a_network_says_it_is_a_scene_kitchen(command):
    """`plan tests/data/scene/whipped_cream_scene.json --goal ...` (the scene as PATHS, not --kitchen) said only
    "FOON JSON document lacks the required field 'format'"."""
    scene = Path(__file__).parent / "data" / "scene" / "whipped_cream_scene.json"
    r = run(command, scene, *(["--goal", "whipped cream"] if command == "plan" else []))
    assert r.exit_code == 2 and "is a scene kitchen (docs/scene.md), not a network: give it with `--kitchen`" in r.stderr


def test_stats_skips_plainly_non_foon_files_and_invalid_ones_on_request(tmp_path):
    from conftest import SEARCH_INPUTS

    (tmp_path / "net").mkdir()
    (tmp_path / "net" / "a.foon").write_text((example_path() / "07-guacamole.foon").read_text())
    (tmp_path / "net" / "rates.txt").write_text((SEARCH_INPUTS / "motion.txt").read_text())
    (tmp_path / "net" / "notes.txt").write_text("shopping list\nlimes\n")
    plain = run("stats", tmp_path / "net")
    assert plain.exit_code == 0, plain.stderr
    assert "rates.txt: warning: skipped: a motion success-rates file" in plain.output
    assert "notes.txt: warning: skipped: no FOON text" in plain.output
    (tmp_path / "net" / "broken.foon").write_text("O\tbowl\t0\nM\tmix\nX\tnonsense\n")
    stops = run("stats", tmp_path / "net")
    assert stops.exit_code == 2 and "broken.foon:3: error" in stops.stderr
    skips = run("stats", tmp_path / "net", "--skip-invalid")
    assert skips.exit_code == 0 and "broken.foon:3: warning: skipped (not a valid network)" in skips.output
    assert "units" in skips.stdout


def test_paths_accept_standard_input():
    merged = run("merge")
    assert merged.exit_code == 0
    piped = run("stats", "-", stdin=merged.stdout)
    assert piped.exit_code == 0, piped.stderr
    assert piped.stdout.splitlines()[:4] == run("stats").stdout.splitlines()[:4]


# -- 12. no silent waits ------------------------------------------------------------------------------


def test_a_slow_step_says_what_it_does_and_a_fast_one_is_silent(capsys):
    import time

    from foon2pddl.cli.progress import slow_step

    with slow_step("building something big", after=0.05):
        time.sleep(0.3)
    assert capsys.readouterr().err == "building something big ...\n"
    with slow_step("quick", after=5):
        pass
    assert capsys.readouterr().err == ""


def test_a_slow_plan_announces_itself(monkeypatch):
    from foon2pddl.cli import progress

    monkeypatch.setattr(progress, "AFTER", 0.0)  # every step counts as slow: each says what it is
    r = run("plan", "--goal", "guacamole")
    assert r.exit_code == 0
    assert "planning 'guacamole' (fd, relational encoding, planner time limit 300 s) ..." in r.stderr  # plan's default
    assert "reading the embedded example ..." in r.stderr
    monkeypatch.setattr(progress, "AFTER", 60.0)
    quiet = run("plan", "--goal", "guacamole")
    # only stderr changes: no progress line (`... `-ended); a note's cut list says `... (N more)` either way
    assert r.stdout == quiet.stdout
    assert not [line for line in quiet.stderr.splitlines() if line.endswith("...")]


def test_experiment_eta_waits_for_enough_cells():
    from foon2pddl.experiment.progress import LINES, Progress

    clock = iter([0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0]).__next__
    p = Progress(100, LINES, clock=clock)
    p.done = 1
    assert "ETA after 5 cells" in p.line()
    p.done = 5
    assert "ETA after" not in p.line() and "ETA " in p.line()
    big = Progress(1000, LINES, clock=iter([0.0, 10.0, 20.0]).__next__)
    big.done = 20
    assert "ETA after 50 cells" in big.line()


# -- 15. what the docs say about --optimal with a UP engine ---------------------------------------------


def test_optimal_up_result_names_the_engine_that_ran():
    r = run("plan", "--goal", "whipped cream", "--encoding", "tree", "--planner", "pyperplan", "--optimal",
            "--time-limit", "120")  # FOON's semantics: pyperplan takes no conditional effects (relational's)
    assert r.exit_code == 0, r.stderr
    assert "solved (up:pyperplan-opt)" in r.stderr
    assert "`up:pyperplan-opt`" in (Path(__file__).resolve().parent.parent / "docs" / "planning.md").read_text()


# -- 7. a kitchen from scratch ------------------------------------------------------------------------

#: Lemonade from a pitcher of sweetened juice no unit makes (one recipe starts there) or from a lemon.
LEMONADE = """//
O\tpitcher\t0
S\tcontains\t{lemon juice,sugar}
O\twater\t1
S\tcold
M\tpour
O\tlemonade\t0\t0
S\tcontains\t{lemon juice,sugar,water}
S\tin\t[pitcher]
//
O\tlemon\t1
S\twhole
O\tpitcher\t0
S\tempty
M\tsqueeze
O\tpitcher\t0
S\tcontains\t{lemon juice}
O\tlemon juice\t1
S\tin\t[pitcher]
//
O\tpitcher\t0
S\tcontains\t{lemon juice}
O\twater\t1
S\tcold
M\tpour
O\tlemonade\t0\t0
S\tcontains\t{lemon juice,water}
S\tin\t[pitcher]
//
"""


def test_base_kitchen_starts_from_raw_ingredients(tmp_path):
    foon = write(tmp_path / "lemonade.txt", LEMONADE)
    # two recipes merged, one starting from a pitcher of juice another squeezes: the base kitchen by default
    chosen = run("retrieve", foon, "--goal", "lemonade")
    assert chosen.exit_code == 0 and "complete: 2 units" in chosen.stderr
    assert "note: kitchen: base (raw ingredients and tools in their base states, 3 nodes" in chosen.stderr
    assert "`--kitchen default` for the network's default kitchen (4 nodes, 1 half-made dish included)" \
        in chosen.stderr
    assert "pitcher (contains" not in chosen.stdout.splitlines()[1]  # no half-made dish on hand at the start
    base = run("retrieve", foon, "--goal", "lemonade", "--kitchen", "base")
    assert base.exit_code == 0 and base.stdout == chosen.stdout and "note: kitchen" not in base.stderr
    default = run("retrieve", foon, "--goal", "lemonade", "--kitchen", "default")
    assert default.exit_code == 0 and "complete: 1 unit" in default.stderr and "note: kitchen" not in default.stderr
    assert "pitcher (contains {lemon juice, sugar})" in default.stdout.splitlines()[1]
    listed = run("goals", foon, "--json")
    assert '"kitchen": "base kitchen"' in listed.stdout
    # a file named `base` is still a file
    (tmp_path / "base").write_text("lemon: whole\npitcher: empty\nwater: cold\n")
    from_file = CliRunner().invoke(main, ["retrieve", str(foon), "--goal", "lemonade", "--kitchen", "base"],
                                   catch_exceptions=False)
    assert from_file.exit_code == 0


#: One recipe (one dish mark) that starts from a pitcher of lemon juice and also squeezes a lemon.
ONE_RECIPE = LEMONADE.split("//\nO\tpitcher\t0\nS\tcontains\t{lemon juice}\n")[0].replace("\t0\t0\n", "\t0\n")
ONE_RECIPE += "//\nO\tpitcher\t0\nS\tcontains\t{lemon juice}\nO\twater\t1\nS\tcold\nM\tpour\n" \
              "O\tlemonade\t0\t0\nS\tcontains\t{lemon juice,water}\nS\tin\t[pitcher]\n//\n"


def test_a_single_recipe_keeps_its_default_kitchen(tmp_path):
    foon = write(tmp_path / "one.txt", ONE_RECIPE)
    r = run("retrieve", foon, "--goal", "lemonade: contains {lemon juice, sugar, water}, in [pitcher]")
    assert r.exit_code == 0 and "complete: 1 unit" in r.stderr  # the recipe's own start, as written
    assert "note: kitchen: default (the network's default kitchen, 4 nodes" in r.stderr
    assert "`--kitchen base` leaves out its 1 half-made dish" in r.stderr
    # from the base kitchen nothing makes it; the hint names the kitchen that does
    b = run("retrieve", foon, "--goal", "lemonade: contains {lemon juice, sugar, water}, in [pitcher]",
            "--kitchen", "base")
    assert b.exit_code == 1 and "hint: `--kitchen default` can make it" in b.stderr


def test_half_made_dishes_are_what_a_unit_creates_not_packaging():
    from foon2pddl.io.parser import parse_text
    from foon2pddl.model.foon import make_node, make_state
    from foon2pddl.model.kitchen import base_kitchen, chosen_kitchen, default_kitchen, half_made

    foon = parse_text(LEMONADE, "lemonade.txt").foon
    assert sorted(n.describe() for n in half_made(foon)) == ["pitcher (contains {lemon juice, sugar})"]
    assert chosen_kitchen(foon) == base_kitchen(foon) != default_kitchen(foon)
    # milk in its carton: no unit creates milk, so it stays in the base kitchen
    carton = parse_text("//\nO\tmilk\t1\nS\tin\t[carton]\nO\tbowl\t0\nS\tempty\nM\tpour\n"
                        "O\tmilk\t1\nS\tin\t[bowl]\nO\tbowl\t0\nS\tcontains\t{milk}\n//\n", "milk.txt").foon
    assert half_made(carton) == frozenset() and base_kitchen(carton).nodes == default_kitchen(carton).nodes
    # water a faucet gives is drawn, not made; a unit that outputs bread it never took in (a quirk of the
    # public data) does not make the loose loaf's label half-made
    tap = parse_text("//\nO\tfaucet\t0\nS\toff\nM\tturn on\nO\tfaucet\t0\nS\ton\nO\twater\t1\n"
                     "S\tfrom\t[faucet]\n//\nO\tpitcher\t0\nS\tcontains\t{water}\nO\tbasket\t0\nS\tcontains\t{bread}\n"
                     "O\tbread\t1\nS\tloaf\n"
                     "M\tslice\nO\tbread\t1\nS\tsliced\nS\ton\t[plate]\nO\tpitcher\t0\nS\tcontains\t{water}\n"
                     "//\nO\tplate\t0\nS\tempty\nM\tserve\nO\tbread\t1\nS\ton\t[plate]\n//\n", "tap.txt").foon
    assert half_made(tap) == frozenset()
    kept = base_kitchen(tap)
    assert make_node("pitcher", [make_state("contains", "", ["water"])]) in kept
    assert make_node("basket", [make_state("contains", "", ["bread"])]) in kept


def test_the_kitchen_a_run_uses_on_the_corpus(universal):
    from foon2pddl.io.files import load
    from foon2pddl.model.kitchen import BASE_SOURCE, chosen_kitchen, default_kitchen

    foon, _ = universal  # a merge of recipes whose default kitchen holds other recipes' half-made dishes
    kit = chosen_kitchen(foon)
    assert kit.source == BASE_SOURCE and len(kit.nodes) < len(default_kitchen(foon).nodes)
    assert not any(n.label == "pitcher" and "lemon juice" in n.ingredients for n in kit.nodes)
    for path in sorted(SUBGRAPHS.iterdir())[:20]:  # one recipe each: its default kitchen, as before
        single, _ = load([path])
        assert chosen_kitchen(single) == default_kitchen(single)


# -- 13. what plan and the experiment leave out, said -------------------------------------------------


def _summary_counts(stderr: str) -> tuple[int, int]:
    summary = next(line for line in stderr.splitlines() if line.startswith("solved"))
    return int(summary.split(": ")[1].split()[0]), int(summary.split(", ")[1].split()[0])


def test_plan_names_the_steps_it_left_out(tmp_path):
    import json

    r = run("plan", "--goal", "guacamole", "--encoding", "tree", "--format", "json", "--plan-file",
            tmp_path / "sas_plan")  # FOON's semantics: only there does the tree leave steps out
    assert r.exit_code == 0
    data = json.loads(r.stdout)
    raw, used = data["planner_plan"], data["plan"]
    assert len(raw) > len(used)  # lama-first's plan has detours here: they are named, with their step numbers
    note = next(n for n in data["validation"]["notes"] if n.startswith("the planner's plan has "))
    assert note.startswith(f"the planner's plan has {len(raw)} steps; ")
    numbered = [int(part.split(" (")[0]) for part in note.split(": ", 1)[1].split("; ")]
    assert len(numbered) == int(note.split()[6]) == len(raw) - len(used)
    assert all(raw[n - 1] not in used for n in numbered)
    assert (tmp_path / "sas_plan").read_text().splitlines()[:-1] == [f"({s})" for s in used]


def test_plan_steps_printed_are_the_ones_that_make_the_goal():
    # lama-first fires both the lemon-juice chain (a lime squeezed where the recipe squeezed a lemon) and
    # guacamole's lime-juice chain; the tree uses one: the plan printed, counted and written is that one
    r = run("plan", "--goal", "lemonade", "--network", "gen")
    assert r.exit_code == 0, r.output
    steps, units = _summary_counts(r.stderr)
    assert steps == units == 9, r.stderr
    # the left-out squeeze is guacamole's own (the kept one is the lemonade recipe's, its lemon a lime)
    assert ("note: the planner's plan has 14 steps; 5 the goal does not need are left out: "
            "4 (squeeze at 07-guacamole.foon:77: ") in r.stderr
    # the lifted plan names what the squeezed lime made as the recipe does; the tree renames it, and says so
    assert "lemon juice -> lime juice" in r.stderr and "lemon juice" not in r.stdout


def test_another_protocol_is_said_in_words():
    from foon2pddl.experiment.protocol import identity_difference

    old = {"seed": 0, "level": 3, "inputs": "ab12"}
    new = {"seed": 5, "level": 3, "inputs": "cd34", "threshold": 0.8}
    text = identity_difference(old, new)
    assert text == ("the input files differ (other FOON files or other contents); seed 0 there, 5 here; "
                    "threshold 0.8 here, not set there")
    assert identity_difference(None, new) == "its protocol file names no identity"


def test_a_cycle_points_to_check(tmp_path):
    # dough needs starter, starter needs dough: nothing enters the cycle
    cycle = write(tmp_path / "cycle.txt", "//\nO\tdough\t1\nS\tmixed\nM\tferment\nO\tstarter\t1\nS\tactive\n"
                                          "//\nO\tstarter\t1\nS\tactive\nM\tmix\nO\tdough\t1\nS\tmixed\n//\n")
    kit = write(tmp_path / "k.txt", "bowl: empty\n")
    r = run("retrieve", cycle, "--goal", "dough", "--kitchen", kit)
    assert r.exit_code == 1 and "`foon2pddl check` names the cycle" in r.stderr
    checked = run("check", cycle)
    assert "cycle" in checked.output


# -- 14. steps in a cook's words ------------------------------------------------------------------------


def test_plan_prints_steps_in_recipe_words_by_default():
    r = run("plan", "--goal", "lemonade", "--network", "gen")
    assert r.exit_code == 0
    lines = r.stdout.splitlines()
    assert "pour sugar (granulated) into the pitcher (contains {lime juice})" in lines[7]
    assert "pour lime juice from the juicer into the pitcher (empty)" in lines[6]
    assert lines[4].endswith("cut lime (whole), with the knife, on the cutting board")  # the place said once
    assert run("plan", "--goal", "lemonade", "--network", "gen", "--format", "recipe").stdout == r.stdout
    # the FOON node form stays one option away, same tree, same numbering
    steps = run("plan", "--goal", "lemonade", "--network", "gen", "--format", "steps").stdout.splitlines()
    assert lines[:2] == steps[:2] and len(lines) == len(steps)
    assert steps[7].startswith("6. pour pitcher (contains {lime juice}), sugar (granulated) -> ")


def test_retrieve_prints_steps_in_recipe_words_by_default():
    r = run("retrieve", "--goal", "guacamole")
    assert r.exit_code == 0
    assert "3. scoop avocado (halved) from the cutting board into the bowl (empty), with the spoon" in r.stdout
    assert " -> " not in r.stdout
    assert " -> " in run("retrieve", "--goal", "guacamole", "--format", "steps").stdout


def test_a_plans_physical_objects_follow_its_recipe_steps():
    r = run("plan", "--goal", "guacamole", "--encoding", "instances")
    assert r.exit_code == 0
    out = r.stdout
    assert "physical objects, step by step (instances encoding):" in out
    assert out.index("20. mix bowl (contains") < out.index("physical objects, step by step")


def test_recipe_text_on_every_unit_of_the_corpus_names_its_motion_and_movers(universal):
    from foon2pddl.io.recipe_words import _place, aliases, recipe_text

    foon, _ = universal
    for unit in foon.units[:600]:
        text = recipe_text(unit)
        assert text.startswith(unit.motion.label + " ")
        new = {o.label: o for o in unit.outputs if o not in unit.inputs}
        named = aliases(unit)  # `bread` read as the unit's `garlic bread`
        for i in unit.inputs:
            o = new.get(i.label)
            if o is not None and _place(o, named) not in (None, _place(i, named)):
                assert f" the {_place(o, named)[1]}" in text  # where a moved object goes is said


def test_a_pour_into_a_container_whose_contents_list_it_says_what_is_poured_from_where(universal):
    """0001's `pour*` lists the cream and the sugar only in the mixing bowl's new contents (no output of their
    own): the step says what goes from where into what, not `pour mixing bowl ..., with the ... heavy cream`."""
    from foon2pddl.io.recipe_words import recipe_text
    from foon2pddl.model.places import listed

    foon, _ = universal
    pour = next(u for u in foon.units if u.motion.label == "pour" and any(
        o.label == "mixing bowl" and {"heavy cream", "refined sugar"} <= listed(o) for o in u.outputs)
        and not any(o.label == "heavy cream" for o in u.outputs))
    assert recipe_text(pour) == (
        "pour heavy cream from the measuring cup and refined sugar (granulated) from the spoon into the mixing bowl"
        " (attached to [mixer], empty), with the mixer (on, with [mixing bowl])")


def test_an_input_two_containers_newly_list_goes_into_the_inner_one_said_once(universal):
    """0071:245 `scoop and pour`: the baking tray and the pudding in it both newly list the whipped cream. The
    cream goes into the pudding (which is in the tray), and the step says so once."""
    from foon2pddl.io.recipe_words import recipe_text

    foon, _ = universal
    scoop = next(u for u in foon.units if u.motion.label == "scoop and pour"
                 and {"baking tray", "pudding", "whipped cream", "jar"} <= {i.label for i in u.inputs})
    text = recipe_text(scoop)
    assert text.count("whipped cream") == 1, text
    assert text.startswith("scoop and pour whipped cream (chilled) from the jar into the pudding (in [baking tray]"), text



def test_a_tool_the_step_soils_is_said_with_with_not_as_a_second_thing_worked(universal):
    """Stop 56's newcomer pass: where FOON records the knife becoming `dirty`, the greek salad's step read `cut lemon
    (whole), knife (clean), on the cutting board` (the knife a second thing cut; 85 steps of the shared subgraphs),
    beside `slice sweet pepper (whole), with the knife (clean), ...`. A tool is a tool, soiled or not."""
    from foon2pddl.io.recipe_words import recipe_text

    foon, _ = universal
    units = {(u.motion.label, tuple(sorted(i.label for i in u.inputs))): u for u in foon.units}
    cut = units[("cut", ("cutting board", "knife", "lemon"))]
    assert recipe_text(cut) == "cut lemon (whole), with the knife (clean), on the cutting board"
    peel = next(u for u in foon.units if u.motion.label == "peel" and {i.label for i in u.inputs} == {
        "cucumber", "peeler"})
    assert recipe_text(peel) == "peel cucumber (whole), with the peeler (clean)"
    mix = next(u for u in foon.units if u.motion.label == "mix" and "whisk" in {i.label for i in u.inputs}
               and any(o.label == "pancake batter" for o in u.outputs))  # was `mix whisk (clean), with the egg ...`
    assert recipe_text(mix) == ("mix bowl (contains {egg white, egg yolk, flour, milk}), with the whisk (clean), "
                                "making pancake batter (raw) in the bowl")


#: A spread as FOON writes it (0082's cheese pizza): the sauce the spoon holds ends `on {pizza dough}`, its holder in
#: braces, then the mozzarella from its bag goes onto the sauced dough.
SPREADS = (
    "//\nO\tpizza pan\t0\nS\tcontains\t{pizza dough}\nS\ton\t[surface]\nO\tpizza dough\t0\nS\tflattened\n"
    "S\ton\t[pizza pan]\nO\tserving spoon\t1\nS\tcontains\t{pizza sauce}\nO\tpizza sauce\t1\nS\tin\t[bowl]\n"
    "O\tbowl\t0\nS\tcontains\t{pizza sauce}\nM\tpour and spread\nO\tpizza dough\t0\nS\tcontains\t{pizza sauce}\n"
    "S\tflattened\nS\ton\t[pizza pan]\nO\tpizza sauce\t1\nS\ton\t{pizza dough}\n"
    "//\nO\tpizza pan\t0\nS\tcontains\t{pizza dough}\nS\ton\t[surface]\nO\tpizza dough\t0\n"
    "S\tcontains\t{pizza sauce}\nS\ton\t[pizza pan]\nO\tpizza sauce\t0\nS\ton\t{pizza dough}\nO\tbag\t0\n"
    "S\tcontains\t{mozzarella}\nO\tmozzarella\t1\nS\tshredded\nS\tin\t[bag]\nM\tspread\nO\tpizza dough\t0\n"
    "S\tcontains\t{mozzarella,pizza sauce}\nS\ton\t[pizza pan]\nO\tmozzarella\t1\nS\tshredded\n"
    "S\ton\t{pizza dough}\n//\n")


def test_a_place_foon_writes_in_braces_is_where_the_object_goes_not_a_tool():
    """Stop 57's newcomer pass (0082's cheese pizza): FOON writes where a spread thing ends in braces (`pizza sauce
    (on {pizza dough})`), and the steps read `pour and spread pizza dough (flattened), pizza sauce, with the serving
    spoon ..., in the bowl` and `spread pizza dough ..., mozzarella (shredded), with the pizza sauce (on {pizza
    dough}), ..., in the bag`: the sauce a tool, the bowl and the bag places the step happens in. A place state
    naming one object is that place, `[...]` or `{...}`: the sauce and the mozzarella move onto the dough."""
    from foon2pddl.io.parser import parse_text
    from foon2pddl.io.recipe_words import recipe_text

    pour, spread = parse_text(SPREADS, "pizza.txt").foon.units
    assert recipe_text(pour) == (
        "pour and spread pizza sauce from the serving spoon onto the pizza dough (flattened, on [pizza pan]), on the"
        " pizza pan (on [surface])")
    assert recipe_text(spread) == (
        "spread mozzarella (shredded) from the bag onto the pizza dough (contains {pizza sauce}, on [pizza pan]),"
        " on the pizza pan (on [surface])")


def test_what_moves_leaves_the_holder_that_lists_it_not_the_one_its_own_node_still_names():
    """Stop 57's newcomer pass, left then: 0082's cheese pizza scoops the sauce into the serving spoon, and the next
    step read `pour and spread pizza sauce from the bowl ..., with the serving spoon (contains {pizza sauce})`. FOON
    lists the sauce in the spoon (0082-homemade_cheese_pizza.txt:380) but leaves the sauce's own node `in [bowl]`
    (:382): the scoop changed only the spoon. Another input listing what moves (not its own holder, not where it
    goes) is where it is then: the step pours it from the spoon, which is then no tool as well. Its own holder
    listing it alone leaves the words as they were."""
    from foon2pddl.io.parser import parse_text
    from foon2pddl.io.recipe_words import recipe_text

    alone = SPREADS.split("//\n")[1].replace("O\tserving spoon\t1\nS\tcontains\t{pizza sauce}\n", "")
    (pour,) = parse_text("//\n" + alone + "//\n", "pizza.txt").foon.units
    assert recipe_text(pour) == (
        "pour and spread pizza sauce from the bowl onto the pizza dough (flattened, on [pizza pan]), on the pizza pan"
        " (on [surface])")



def test_what_holds_where_a_thing_goes_is_no_source_under_the_name_a_place_gives_it():
    """The end-of-stop re-read (stop 58): dbd1282's `_carrier` (another input listing what moves is where it is
    then, but not what holds where it goes) read holders without the unit's aliases, where every other place of
    the step's words reads them through `aliases`. A tortilla `on [tray]` beside the `baking tray` that lists the
    sauce (as 0053's tray lists the sauce poured onto the tortilla in it) read `pour sauce from the baking tray
    onto the tortilla`: the sauce is in the bowl, and the tray holds the tortilla it goes onto."""
    from foon2pddl.io.parser import parse_text
    from foon2pddl.io.recipe_words import recipe_text

    (pour,) = parse_text(
        "//\nO\tbowl\t1\nS\tcontains\t{sauce}\nO\tsauce\t1\nS\tin\t[bowl]\nO\ttortilla\t0\nS\ton\t[tray]\n"
        "O\tbaking tray\t0\nS\tcontains\t{sauce,tortilla}\nM\tpour\nO\tbowl\t1\nS\tempty\nO\tsauce\t1\n"
        "S\ton\t[tortilla]\nO\ttortilla\t0\nS\tcontains\t{sauce}\nS\ton\t[tray]\n//\n", "tray.txt").foon.units
    assert recipe_text(pour) == "pour sauce from the bowl onto the tortilla (on [tray]), on the baking tray"

def test_things_moved_from_one_holder_say_it_once():
    """0085's breakfast pizza read `sprinkle onion (peeled, sliced) from the cutting board and bacon (chopped,
    defrosted) from the cutting board onto the pizza dough ...` (0085-mini_bacon_egg_breakfast_pizza.txt:472: both
    `on [cutting board]`, the unit lists no board). Things moved from one holder to one place say it once: the
    unit's only input of that label, or with none a surface they are on. Two holders of one label, each listing
    one of them (0082's salt and olive oil, each in its own bowl), stay two, and so do things `in [bottle]` with
    no bottle node (the embedded greek salad's olive oil and vinegar: one bottle each)."""
    from foon2pddl.io.parser import parse_text
    from foon2pddl.io.recipe_words import recipe_text

    sprinkle, pour = parse_text(
        "//\nO\tonion\t1\nS\tsliced\nS\ton\t[cutting board]\nO\tpizza dough\t0\nS\tflattened\nO\tbacon\t1\n"
        "S\tchopped\nS\ton\t[cutting board]\nM\tsprinkle\nO\tonion\t1\nS\tsliced\nS\ton\t{pizza dough}\n"
        "O\tbacon\t1\nS\tchopped\nS\ton\t{pizza dough}\nO\tpizza dough\t0\nS\tflattened\n"
        "S\tcontains\t{bacon,onion}\n"
        "//\nO\tcontainer\t0\nS\tcontains\t{flour}\nO\tbowl\t1\nS\tcontains\t{salt}\nO\tsalt\t1\nS\tin\t[bowl]\n"
        "O\tbowl\t1\nS\tcontains\t{olive oil}\nO\tolive oil\t1\nS\tin\t[bowl]\nM\tpour\nO\tcontainer\t0\n"
        "S\tcontains\t{flour,olive oil,salt}\nO\tsalt\t1\nS\tin\t[container]\nO\tolive oil\t1\n"
        "S\tin\t[container]\n//\n", "moves.txt").foon.units
    (bottles,) = parse_text(
        "//\nO\tbowl\t0\nS\tcontains\t{onion}\nO\tolive oil\t1\nS\tin\t[bottle]\nO\tvinegar\t1\nS\tin\t[bottle]\n"
        "M\tpour\nO\tbowl\t0\nS\tcontains\t{olive oil,onion,vinegar}\nO\tolive oil\t1\nS\tin\t[bowl]\n"
        "O\tvinegar\t1\nS\tin\t[bowl]\n//\n", "bottles.txt").foon.units
    assert recipe_text(sprinkle) == (
        "sprinkle onion (sliced) and bacon (chopped) from the cutting board onto the pizza dough (flattened)")
    assert recipe_text(pour) == "pour salt from the bowl and olive oil from the bowl into the container (contains {flour})"
    assert recipe_text(bottles) == "pour olive oil from the bottle and vinegar from the bottle into the bowl (contains {onion})"


def test_a_thing_named_only_in_lists_moves_from_the_holder_that_lists_it():
    """0085's breakfast pizza names its sour cream only in lists (0085-mini_bacon_egg_breakfast_pizza.txt:427,
    :435), and the steps read `scoop scraper (clean), with the bottle (contains {sour cream})` and `spread pizza
    dough (flattened), with the scraper (contains {sour cream}), ...`. A container's new node newly lists it, and
    another input lists it: it moves from that one. A pan listing what is cooked in it is no source of the dish
    it holds (0060's black beans stirred in the pan), and `rice` beside a `white rice` node is that node."""
    from foon2pddl.io.parser import parse_text
    from foon2pddl.io.recipe_words import recipe_text

    scoop, spread, stir, pour = parse_text(
        "//\nO\tscraper\t1\nS\tclean\nO\tbottle\t0\nS\tcontains\t{sour cream}\nM\tscoop\nO\tscraper\t1\n"
        "S\tcontains\t{sour cream}\n"
        "//\nO\tpizza dough\t0\nS\tflattened\nO\tscraper\t1\nS\tcontains\t{sour cream}\nM\tspread\n"
        "O\tpizza dough\t0\nS\tflattened\nS\tcontains\t{sour cream}\n"
        "//\nO\tblack bean\t0\nS\tuncooked\nS\tin\t[pan]\nO\tcooking pan\t0\nS\tcontains\t{black bean,garlic}\n"
        "O\tspoon\t1\nM\tstir\nO\tblack bean\t0\nS\tcontains\t{garlic}\nS\tin\t[pan]\n"
        "//\nO\tbowl\t0\nS\tempty\nO\tcooker\t0\nS\tcontains\t{rice,water}\nO\twhite rice\t1\nS\tcooked\n"
        "S\tin\t[cooker]\nM\tpour\nO\tbowl\t0\nS\tcontains\t{rice,water}\nO\twhite rice\t1\nS\tcooked\n"
        "S\tin\t[bowl]\n//\n", "lists.txt").foon.units
    assert recipe_text(scoop) == "scoop sour cream from the bottle into the scraper (clean)"
    assert recipe_text(spread) == "spread sour cream from the scraper into the pizza dough (flattened)"
    assert recipe_text(stir) == "stir black bean (uncooked), with the spoon, in the cooking pan (contains {black bean, garlic})"
    assert recipe_text(pour) == "pour white rice (cooked) and water from the cooker into the bowl (empty)"


def test_what_a_step_uses_up_goes_onto_a_container_it_is_made_on():
    """0082's breakfast pizza cracks an egg whose white and yolk end `on {pizza dough}`: the step read `crack egg
    (uncracked) into the pizza dough`, where the omelette's egg goes `into the bowl (empty)` it is made in. What
    a step uses up goes into or onto its container by the word FOON gives what it makes there."""
    from foon2pddl.io.parser import parse_text
    from foon2pddl.io.recipe_words import recipe_text

    crack = parse_text(
        "//\nO\tpizza dough\t0\nS\tflattened\nO\tegg\t1\nS\tuncracked\nM\tcrack\nO\tpizza dough\t0\n"
        "S\tflattened\nS\tcontains\t{egg white and yolk}\nO\tegg white and yolk\t0\nS\ton\t{pizza dough}\n//\n"
        "O\tbowl\t0\nS\tempty\nO\tegg\t1\nS\tuncracked\nM\tcrack\nO\tbowl\t0\nS\tcontains\t{egg white and yolk}\n"
        "O\tegg white and yolk\t0\nS\tin\t[bowl]\n//\n", "crack.txt").foon.units
    assert [recipe_text(u) for u in crack] == [
        "crack egg (uncracked) onto the pizza dough (flattened), making egg white and yolk on the pizza dough",
        "crack egg (uncracked) into the bowl (empty), making egg white and yolk in the bowl"]


def test_the_objects_account_says_a_soiled_tool_with_with_too():
    """The relational account under the tree had the same reading: `peel cucumber_1, peeler_1`, `cut lemon_1,
    knife_1 with cutting_board_1` (the greek salad of the shared subgraphs, whose plan the physical replay now
    rejects: issue 21; the coleslaw peels and chops as it does); a tool the step only soils is one the step uses, as
    in the recipe words above."""
    r = run("plan", SUBGRAPHS / "0022-better_than_kfc_coleslaw.txt", "--goal", "coleslaw")
    assert r.exit_code == 0, r.stderr
    account = r.stdout.split("objects, step by step (relational encoding):")[1].splitlines()
    assert any(line.endswith("peel carrot_1 with peeler_1") for line in account), account
    assert any(line.endswith("chop onion_1 with knife_1") for line in account), account
    assert not any(", peeler_1" in line or ", knife_1 with" in line for line in account), account


def _step(unit_in, motion, unit_out, bindings, before, after):
    """step_words of one step: `bindings` (id, node before, node after), `before`/`after` (id -> (node, holder,
    relation, consumed))."""
    from foon2pddl.model.foon import FunctionalUnit, Motion
    from foon2pddl.model.physical import Binding, ObjectState, TraceStep
    from foon2pddl.pddl.relational_replay import step_words

    step = TraceStep(0, FunctionalUnit(unit_in, Motion(motion), unit_out),
                     tuple(Binding(x, b, a) for x, b, a in bindings), ())
    snap = lambda states: {x: ObjectState(x, *v) for x, v in states.items()}  # noqa: E731
    return step_words(step, snap(before), snap(after))


def test_the_objects_account_sets_what_a_move_changes_off_from_where_it_goes():
    """Issue 24's tried-again pass: the greek salad's last step read `pick-and-place feta_cheese_2 from spoon_1
    into bowl_4 greek_salad_1` (ACT-0034-greek_salad.txt, 24 such steps on the 100 shared subgraphs: `sprinkle milk_2
    from spoon_1 into bowl_1 tomato_soup_2`): the salad the feta goes to is no part of the bowl's name."""
    from node_words import contains, inside, n

    from foon2pddl.model.physical import Relation

    feta, salad, bowl = n("feta cheese", inside("spoon")), n("salad", contains("tomato"), inside("bowl")), n(
        "bowl", contains("salad"))
    feta2, salad2 = n("feta cheese", inside("bowl")), n("salad", contains("feta cheese", "tomato"), inside("bowl"))
    words = _step((bowl, salad, feta), "pick-and-place", (salad2, feta2),
                  [("feta_1", feta, feta2), ("salad_1", salad, salad2)],
                  {"feta_1": (feta, "spoon_1", Relation.IN), "salad_1": (salad, "bowl_1", Relation.IN),
                   "spoon_1": (n("spoon"),), "bowl_1": (bowl,)},
                  {"feta_1": (feta2, "bowl_1", Relation.IN), "salad_1": (salad2, "bowl_1", Relation.IN),
                   "spoon_1": (n("spoon"),), "bowl_1": (bowl,)})
    assert words == "pick-and-place feta_1 from spoon_1 into bowl_1, changing salad_1"


def test_the_objects_account_says_what_a_step_uses_up_without_making_anything():
    """The same pass: `pour onion_1 from cutting_board_2 into cooking_pan_1 butter_2 -> ` (an arrow to nothing, 14
    steps on the 100 shared subgraphs): the butter the onion is fried in is used up, and the step makes nothing."""
    from node_words import contains, inside, n

    from foon2pddl.model.foon import make_state
    from foon2pddl.model.physical import Relation

    onion, butter = n("onion", "chopped", make_state("on", "cutting board")), n("butter", inside("pan"))
    pan = n("pan", contains("butter"))
    onion2, pan2 = n("onion", "chopped", inside("pan")), n("pan", contains("onion"))
    words = _step((pan, butter, onion), "pour", (pan2, onion2),
                  [("onion_1", onion, onion2), ("butter_1", butter, None), ("pan_1", pan, pan2)],
                  {"onion_1": (onion, "board_1", Relation.ON), "butter_1": (butter, "pan_1", Relation.IN),
                   "pan_1": (pan,), "board_1": (n("cutting board"),)},
                  {"onion_1": (onion2, "pan_1", Relation.IN), "butter_1": (butter, "pan_1", Relation.IN, True),
                   "pan_1": (pan2,), "board_1": (n("cutting board"),)})
    assert words == "pour onion_1 from board_1 into pan_1, using up butter_1"


def test_the_objects_account_says_the_board_an_object_is_cut_on_as_a_place():
    """The same pass: `cut avocado_1 with cutting_board_1, knife_1` (the guacamole, every cut and chop on a board):
    the board the avocado lies on is where it is cut, not a tool, as the recipe's words say (`cut avocado (whole),
    with the knife, on the cutting board`)."""
    r = run("plan", "--goal", "guacamole")
    assert r.exit_code == 0, r.stderr
    account = r.stdout.split("objects, step by step (relational encoding):")[1].splitlines()
    assert "2. cut avocado_1 on cutting_board_1 with knife_1" in account, account
    assert not any("with cutting_board" in line for line in account), account


def test_the_objects_account_says_where_a_changed_object_sits_outward():
    """Issue 24's account read `heat butter_2, microwave_1 in bowl_1` (the garlic bread of the shared subgraphs:
    FOON heats the butter in the bowl in the microwave, the microwave going off): the appliance read as a second
    thing heated, in the bowl. A changed object holding another's place is that place, said outward from it."""
    r = run("plan", SUBGRAPHS / "0016-easy_garlic_bread-one-pot-chef.txt", "--goal", "garlic bread")
    assert r.exit_code == 0, r.stderr
    account = r.stdout.split("objects, step by step (relational encoding):")[1].splitlines()
    assert "6. heat butter_2 in bowl_1 in microwave_1" in account, account
    assert not any("microwave_1 in" in line for line in account), account


def test_the_objects_account_says_a_pan_and_what_it_cooks_as_contents_and_place():
    """The same shape on a stove: `cook skillet_1, french_toast_1 on stove_1` (0037, and the omelettes' `cook
    cooking_pan_1, omelette_1 on stove_1`): the toast cooks in the skillet on the stove, both changing; and an
    unchanged holder's holder the step names is a place too (`heat peanut_mixture_1 in bowl_4 with microwave_2`)."""
    from node_words import contains, inside, n

    from foon2pddl.model.foon import make_state
    from foon2pddl.model.physical import Relation

    toast, toast2 = n("french toast", inside("skillet")), n("french toast", "cooked", inside("skillet"))
    pan, pan2 = n("skillet", contains("french toast"), make_state("on", "stove")), n(
        "skillet", "hot", contains("french toast"), make_state("on", "stove"))
    stove = n("stove", "on", contains("skillet"))
    words = _step((toast, pan, stove), "cook", (toast2, pan2),
                  [("skillet_1", pan, pan2), ("toast_1", toast, toast2), ("stove_1", stove, stove)],
                  {"toast_1": (toast, "skillet_1", Relation.IN), "skillet_1": (pan, "stove_1", Relation.ON),
                   "stove_1": (stove,)},
                  {"toast_1": (toast2, "skillet_1", Relation.IN), "skillet_1": (pan2, "stove_1", Relation.ON),
                   "stove_1": (stove,)})
    assert words == "cook toast_1 in skillet_1 on stove_1"
    mix, mix2 = n("peanut mixture", inside("bowl")), n("peanut mixture", "hot", inside("bowl"))
    bowl, oven = n("bowl", contains("peanut mixture"), inside("microwave")), n("microwave", contains("bowl"))
    words = _step((mix, bowl, oven), "heat", (mix2, bowl, oven),
                  [("mix_1", mix, mix2), ("bowl_4", bowl, bowl), ("microwave_2", oven, oven)],
                  {"mix_1": (mix, "bowl_4", Relation.IN), "bowl_4": (bowl, "microwave_2", Relation.IN),
                   "microwave_2": (oven,)},
                  {"mix_1": (mix2, "bowl_4", Relation.IN), "bowl_4": (bowl, "microwave_2", Relation.IN),
                   "microwave_2": (oven,)})
    assert words == "heat mix_1 in bowl_4 in microwave_2"


def test_no_objects_account_line_runs_two_parts_together():
    """The greek salad of the shared subgraphs had both glitches above; its plan the physical replay now rejects
    (issue 21), and the tomato soup's last steps move an ingredient into the bowl of the soup they change."""
    import re

    r = run("plan", SUBGRAPHS / "0011-easy_tomato_soup.txt", "--goal", "tomato soup")
    assert r.exit_code == 0, r.stderr
    account = r.stdout.split("objects, step by step (relational encoding):")[1].splitlines()
    assert account[-1] == ("24. sprinkle coriander_2 (a portion of coriander_1) from container_1 into bowl_3, "
                           "changing tomato_soup_1")
    assert not [line for line in account if re.search(r"(into|onto) \w+_\d+ \w+_\d+|-> *$|->  ", line)]

# -- -o: one convention for every output ---------------------------------------------------------------

#: Every command's output options, each with its kind: a file, a PNG file (`--plot`), or a directory of files.
OUTPUTS = [
    (("stats", "-o"), "file"), (("merge", "-o"), "file"), (("goals", "-o"), "file"), (("check", "-o"), "file"),
    (("analyze", "-o"), "file"), (("analyze", "--plot"), "png"), (("analyze", "--graphml"), "dir"),
    (("similarity", "lemon", "lime", "-o"), "file"), (("generalize", "-o"), "file"),
    (("categories", "--extend", SUBGRAPHS / "0001-whipped_cream.txt", "-o"), "file"),
    (("retrieve", "--goal", "guacamole", "-o"), "file"), (("retrieve", "--goal", "guacamole", "--goal", "pancake", "-o"),
                                                         "dir"),
    (("compile", "--goal", "guacamole", "-o"), "dir"), (("plan", "--goal", "guacamole", "-o"), "file"),
    (("plan", "--goal", "guacamole", "--plan-file"), "file"), (("plan", "--goal", "whipped cream", "--skills", "-o"),
                                                               "dir"),
    (("experiment", "--trials", "1", "--goals", "1", "--networks", "reg", "--solvers", "native-greedy",
      "--no-progress", "-o"), "dir"),
]


@pytest.mark.parametrize(("args", "kind"), OUTPUTS, ids=[" ".join(map(str, a)) for a, _ in OUTPUTS])
def test_every_output_option_creates_its_missing_parent_directories(tmp_path, args, kind):
    """`plan -o missing/dir/file` creates `missing/dir`: so does every other output of every command
    (README, common options), as `compile -o DIR` and `experiment -o DIR` must."""
    target = tmp_path / "missing" / "dir" / {"dir": "out", "png": "out.png"}.get(kind, "out.txt")  # --plot: a PNG
    r = run(*args, target)
    assert r.exit_code == 0, r.stderr
    assert target.is_dir() if kind == "dir" else target.is_file()
    if kind == "dir":
        assert any(target.iterdir())


@pytest.mark.parametrize("option", ["--kitchen", "--constraints", "--rates", "--goals"])
def test_a_missing_input_file_is_named_without_a_line(tmp_path, option):
    missing = tmp_path / "nope.json"
    r = run("plan", "--goal", "guacamole", option, missing) if option != "--goals" else run("plan", option, missing)
    assert r.exit_code == 2 and r.stderr == f"{missing}: error: no such file\n", r.output


def test_a_missing_network_path_and_a_whole_file_problem_have_no_line(tmp_path):
    r = run("stats", tmp_path / "nope.txt")
    assert r.exit_code == 2 and r.stderr == f"{tmp_path / 'nope.txt'}: error: no such file or directory\n", r.output
    r = run("plan", "--goal", "guacamole", "--kitchen", tmp_path)
    assert r.exit_code == 2 and r.stderr == f"{tmp_path}: error: cannot read file: Is a directory\n", r.output


def test_a_batch_table_at_a_terminal_gives_its_total_once(monkeypatch):
    from foon2pddl.cli import batch

    piped = run("retrieve", "--goal", "guacamole", "--goal", "lemonade")
    assert piped.exit_code == 1 and piped.stdout.splitlines()[-1] == "2 goals: 1 solved, 1 unreachable"  # for files
    monkeypatch.setattr(batch, "_stdout_is_terminal", lambda: True)
    shown = run("retrieve", "--goal", "guacamole", "--goal", "lemonade")
    assert shown.exit_code == 1 and "goals:" not in shown.stdout, shown.stdout
    assert shown.stderr.count("2 goals: 1 solved, 1 unreachable") == 1, shown.stderr


def test_batch_retrieve_and_batch_plan_say_what_an_unreachable_goal_needs_in_the_same_words():
    # one wording for one fact: the smallest kitchen additions, as the single-goal commands give them
    words = "smallest kitchen additions that make it: add `lemon (whole)`"
    for command in ("retrieve", "plan"):
        r = run(command, "--goal", "guacamole", "--goal", "lemonade")
        assert r.exit_code == 1 and words in r.stdout, (command, r.stdout)
        assert "missing (no unit makes them)" not in r.stdout
    single = run("retrieve", "--goal", "lemonade")
    assert words in single.stderr


def test_a_category_typed_wrong_under_gen_plan_names_the_close_categories():
    """Issue 24's tried-again pass: `plan --network gen --goal beverage` (the singular) said `unknown object label
    'beverage'` with no close match, where `retrieve --network gen --goal beverage` says `close matches: beverages`
    and `plan --network gen --goal beverages` plans (docs/format.md: an unknown label lists its close matches)."""
    r = run("plan", "--network", "gen", "--goal", "beverage")
    assert r.exit_code == 2, r.output
    assert "unknown object label 'beverage'" in r.stderr and "close categories: beverages" in r.stderr, r.stderr
    assert "close categories" not in run("plan", "--network", "gen", "--goal", "unicorn").stderr


def test_the_objects_account_says_where_the_thing_poured_onto_stands():
    """After 60cd616 the pancake's last step read `pour maple_syrup_2 (a portion of maple_syrup_1) from bottle_1 onto
    pancake_1, changing plate_1` (the soup's basil, the fruit salad's cream the same): the plate the pancake lies on
    is where the syrup goes, said as the place of what it is poured onto."""
    r = run("plan", "--goal", "pancake")
    assert r.exit_code == 0, r.stderr
    account = r.stdout.split("objects, step by step (relational encoding):")[1].splitlines()
    assert account[-1] == ("14. pour maple_syrup_2 (a portion of maple_syrup_1) from bottle_1 onto pancake_1 on "
                           "plate_1"), account


def test_an_unknown_goal_on_paths_names_the_listing_of_those_paths(tmp_path):
    """Stop 60's pass: `plan 0024-peanut_butter_and_jelly.txt --goal "peanut butter and jelly"` said '`foon2pddl
    goals` lists every goal', which lists the embedded example's goals, not the file's; a batch row said the same.
    The listing the error names is run on the same PATHS (and network), so it lists the goals asked about."""
    recipe = SUBGRAPHS / "0024-peanut_butter_and_jelly.txt"
    single = run("plan", recipe, "--goal", "peanut butter and jelly")
    assert single.exit_code == 2, single.output
    listing = f"`foon2pddl goals {recipe}` lists every goal"
    assert listing in single.stderr, single.stderr
    batch = run("retrieve", recipe, "--goal", "peanut butter and jelly", "--goal", "sandwich")
    assert listing in batch.stdout, batch.stdout
    compiled = run("compile", recipe, "--network", "gen", "--goal", "peanut butter and jelly", "--goal", "sandwich",
                   "-o", tmp_path / "out")
    assert f"`foon2pddl goals {recipe} --network gen` lists" in compiled.stdout, compiled.stdout
    listed = run("goals", recipe)
    assert listed.exit_code == 0 and "sandwich (contains {jelly, peanut butter}, on [plate])" in listed.stdout


def test_the_objects_account_at_level_1_says_what_a_step_makes_as_made():
    """Stop 60's pass: `plan --goal guacamole --level 1` printed the tree's `squeeze lime, juicer, making lime juice`,
    then the account `squeeze lime_juice_1 with lime_1, juicer_1` and `mix guacamole_1 with bowl_1, avocado_1, ...`:
    lime juice squeezed with a lime. At level 1 no object changes state, so nothing was worked and every input read
    as a tool; a step that only makes something names its objects, then what it makes, as the recipe's words do."""
    r = run("plan", "--goal", "guacamole", "--level", "1")
    assert r.exit_code == 0, r.stderr
    tree, account = r.stdout.split("objects, step by step (relational encoding):")
    assert "1. squeeze lime, juicer, making lime juice" in tree.splitlines(), tree
    assert account.splitlines()[1:] == [
        "1. squeeze lime_1, juicer_1, making lime_juice_1",
        "2. mix bowl_1, avocado_1, lime_juice_1, onion_1, tomato_1, cilantro_1, salt_1, fork_1, making guacamole_1"]


def test_a_plan_of_a_goal_foons_semantics_does_not_make_says_so():
    """Stop 60's pass: `retrieve tests/data/foon-subgraphs --goal ramen` (docs/format.md's base-kitchen example)
    says it cannot be made (add `soup broth (in [pot])`), while `plan` on the same network and kitchen said
    `solved: ..., valid` with no word on the difference: the relational encoding read the scoop's `soup broth (in
    [pot])` as the stirred broth (one of its `label mismatch:` notes). The plan now says FOON's own semantics does
    not make the goal, and on what it rests; a goal FOON's semantics makes gets no such note."""
    recipe = SUBGRAPHS / "0054-quick_ramen_noodles.txt"
    native = run("retrieve", recipe, "--goal", "ramen", "--kitchen", "base")
    assert native.exit_code == 1 and "add `soup broth (in [pot])`" in native.stderr, native.stderr
    planned = run("plan", recipe, "--goal", "ramen", "--kitchen", "base")
    assert planned.exit_code == 0, planned.stderr
    assert ("note: FOON's own semantics does not make 'ramen' from this kitchen (`retrieve` and `--encoding tree` "
            "answer unreachable): the plan rests on the relational encoding's readings of the data (its "
            "`label mismatch:` notes)") in planned.stderr, planned.stderr
    made = run("plan", recipe, "--goal", "ramen")
    assert made.exit_code == 0 and "FOON's own semantics does not make" not in made.stderr, made.stderr


def test_the_json_of_a_plan_foons_semantics_does_not_make_says_so_too():
    """rv60 on 388532d: the note reached the text output only; `plan --format json` carries its words as
    `beyond_foon` (null where FOON's semantics makes the goal), as 1e1516c's `hints` carry the `hint:` lines."""
    recipe = SUBGRAPHS / "0054-quick_ramen_noodles.txt"
    beyond = json.loads(run("plan", recipe, "--goal", "ramen", "--kitchen", "base", "--format", "json").stdout)
    assert beyond["status"] == "solved" and beyond["beyond_foon"].startswith(
        "FOON's own semantics does not make 'ramen' from this kitchen"), beyond["beyond_foon"]
    made = json.loads(run("plan", recipe, "--goal", "ramen", "--format", "json").stdout)
    assert made["status"] == "solved" and made["beyond_foon"] is None


def test_the_objects_account_says_a_vessel_poured_from_is_taken_off_its_place_not_poured():
    """Issue 24's pass at stop 61: the orange juice (0073-orange_juice.txt:86, the juice poured from the squeezer,
    whose output `squeezer (dirty)` no longer says `on [surface]`) read `pour squeezer_1 from surface_1,
    orange_juice_1 from squeezer_1 into drinking_glass_1`: the squeezer poured into the glass. It is lifted off the
    surface to pour from, as a scene's sugar is taken out of its fridge (docs/scene.md)."""
    from node_words import contains, inside, n

    from foon2pddl.model.foon import make_state
    from foon2pddl.model.physical import Relation

    squeezer = n("squeezer", contains("orange juice"), make_state("on", "surface"))
    juice, glass = n("orange juice", inside("squeezer")), n("drinking glass", "empty")
    squeezer2, juice2, glass2 = n("squeezer", "dirty"), n("orange juice", inside("cup")), n(
        "drinking glass", contains("orange juice"))
    words = _step((squeezer, juice, glass), "pour", (squeezer2, glass2, juice2),
                  [("squeezer_1", squeezer, squeezer2), ("juice_1", juice, juice2), ("glass_1", glass, glass2),
                   ("surface_1", n("surface"), None)],
                  {"squeezer_1": (squeezer, "surface_1", Relation.ON), "juice_1": (juice, "squeezer_1", Relation.IN),
                   "glass_1": (glass,), "surface_1": (n("surface"),)},
                  {"squeezer_1": (squeezer2,), "juice_1": (juice2, "glass_1", Relation.IN),
                   "glass_1": (glass2,), "surface_1": (n("surface"),)})
    assert words == "take squeezer_1 off surface_1, pour juice_1 from squeezer_1 into glass_1"
    r = run("plan", SUBGRAPHS / "0073-orange_juice.txt", "--goal", "orange juice")
    assert r.exit_code == 0, r.stderr
    account = r.stdout.split("objects, step by step (relational encoding):")[1].splitlines()
    assert "7. take squeezer_1 off surface_1, pour orange_juice_1 from squeezer_1 into drinking_glass_1" in account, \
        account


def test_plan_network_gen_warns_only_of_kitchen_items_its_lifted_encoding_cannot_use(tmp_path):
    """Issue 24's pass at stop 61: `plan 0073-orange_juice.txt --network gen --kitchen K` with `cup: empty` in K
    warned `kitchen item `cup: empty` matches no node of the network`, then poured the juice into that cup (the
    cup is a drinking vessel, GEN's category of the recipe's glass); `retrieve --network gen` gave no warning."""
    kitchen = write(tmp_path / "oj.txt", "orange: whole\ncolander: empty\nfaucet: off\ncutting board: empty, on "
                    "[surface]\nknife: clean\nsqueezer: clean, on [surface]\ncup: empty\nunicorn: whole\n")
    args = (SUBGRAPHS / "0073-orange_juice.txt", "--kitchen", kitchen, "--goal", "orange juice", "--network", "gen")
    planned, retrieved = run("plan", *args), run("retrieve", *args)
    assert planned.exit_code == 0 and retrieved.exit_code == 0, planned.stderr + retrieved.stderr
    assert "cup (empty)" in planned.stdout.split("\n")[1], planned.stdout
    for r in (planned, retrieved):
        warned = [line for line in r.stderr.splitlines() if "matches no node" in line]
        assert warned == [f"{kitchen}:8: warning: kitchen item `unicorn: whole` matches no node of the network"], \
            r.stderr


@pytest.mark.parametrize("command", ["plan", "compile"])
def test_a_constraint_that_matches_nothing_is_warned_by_plan_and_compile_too(tmp_path, command):
    """Issue 24's pass at stop 61: `retrieve --goal guacamole --without-motion scop` (scoop typed wrong) warns that no
    unit mentions 'scop'; `plan` and `compile` said nothing and planned the scoop (docs/constraints.md: a constraint
    that matches nothing in the network gets a warning)."""
    out = ("-o", tmp_path / "out") if command == "compile" else ()
    r = run(command, "--goal", "guacamole", "--without-motion", "scop", "--without", "avocadoo", *out)
    assert r.exit_code == 0, r.stderr
    assert "warning: no unit of the network mentions 'scop' (`without-motion scop`, from <options>)" in r.stderr
    assert "warning: no unit of the network mentions 'avocadoo' (`without avocadoo`, from <options>)" in r.stderr
    kept = run(command, "--goal", "guacamole", "--without-motion", "whisk", *out)
    assert "warning:" not in kept.stderr, kept.stderr


def test_a_goal_file_in_the_goal_syntax_names_the_options_that_take_it(tmp_path):
    """Issue 24's pass at stop 61: `plan --goal-file g.txt` with `guacamole` in it (one goal a line, as `--goals` and
    kitchens take them) said only `g.txt:1: error: expected an 'O' or 'S' line, '//' or a '#' comment`; a JSON list
    there names the options that take it since stop 56, and so does a list in the goal syntax now."""
    goals = write(tmp_path / "g.txt", "# my goal\nguacamole\n")
    r = run("plan", "--goal-file", goals)
    assert r.exit_code == 2 and "Traceback" not in r.output, r.output
    assert f"{goals}:2: error: 1 goal in the goal syntax, one a line, not the one goal node in FOON O/S lines a goal " \
           "file holds: give it with `--goals`" in r.stderr, r.stderr
    assert run("plan", "--goals", goals).exit_code == 0
    broken = write(tmp_path / "b.txt", "O\tguacamole\t1\nX\tin\t[bowl]\n")  # FOON lines with a mistake: the parser's
    assert "expected an 'O' or 'S' line" in run("plan", "--goal-file", broken).stderr


def test_a_scene_too_small_for_instances_names_the_relational_encoding(tmp_path):
    """newcomer60: `plan --kitchen my_scene.json --goal guacamole --encoding instances` (a scene with one cutting
    board) said the scene has too few objects (step 5 needs one more cutting board), true of `instances`, which
    frees no holder; the default `relational` plans the same scene with its one board (the avocado is scooped off
    it first). The reason names that encoding, and the hint is true here."""
    objects = [{"id": n.label.replace(" ", "_") + "_1", "label": n.label,
                "states": [s.describe() for s in n.states]}
               for n in read_kitchen(example_path("example_kitchen.txt")).sorted_nodes()
               if not any(s.related for s in n.states)]  # the carton's and the bottle's contents left out
    scene = tmp_path / "scene.json"
    scene.write_text(json.dumps({"objects": objects}))
    short = run("plan", "--kitchen", scene, "--goal", "guacamole", "--encoding", "instances")
    assert short.exit_code == 1, short.stderr
    reason = next(line for line in short.stderr.splitlines() if line.startswith("reason: "))
    assert "the scene has too few objects" in reason and "needs one more cutting board" in reason, reason
    assert "`--encoding relational`" in reason, reason
    relational = run("plan", "--kitchen", scene, "--goal", "guacamole", "--encoding", "relational")
    assert relational.exit_code == 0, relational.stderr


def test_a_weighted_batch_in_csv_keeps_each_goals_success_probability():
    """Issue 24's pass at stop 61: `retrieve --goal guacamole --goal lemonade --method weighted --rates motion.txt
    --format jsonl` gives each row its `probability` (3.669e-09 for the guacamole); `--format csv`, the same table,
    had no such column, so a weighted batch in CSV lost what the method maximizes (docs/retrieval.md)."""
    import csv
    import io

    from conftest import SEARCH_INPUTS

    args = ("retrieve", "--goal", "guacamole", "--goal", "lemonade", "--method", "weighted", "--rates",
            SEARCH_INPUTS / "motion.txt")
    rows = [json.loads(line) for line in run(*args, "--format", "jsonl").stdout.splitlines()]
    table = list(csv.DictReader(io.StringIO(run(*args, "--format", "csv").stdout)))
    assert [r["goal"] for r in table] == ["guacamole", "lemonade"], table
    assert float(table[0]["probability"]) == pytest.approx(rows[0]["probability"]) and rows[0]["probability"] > 0
    assert table[1]["probability"] == "" and rows[1]["probability"] is None


def test_a_step_with_no_free_tool_names_the_one_lying_on_a_place_the_step_names(tmp_path):
    """Issue 24's pass at stop 61: a scene for the orange juice (0073-orange_juice.txt, whose board stands `on
    [surface]`) with its knife on the counter, labelled `surface`: `plan --skills` kept the cut abstract, saying `the
    step lists no tool to cut with (none stands free on the table)`, above the FOON line `..., knife (clean) -> ...`.
    The knife is on a place the step names, so it is no tool (docs/skills.md); the reason now says so."""
    objects = [{"id": "counter_1", "label": "surface"}, {"id": "fridge_1", "label": "fridge"},
               {"id": "orange_a", "label": "orange", "states": ["whole"], "in": "fridge_1"},
               {"id": "colander_1", "label": "colander", "states": ["empty"], "on": "counter_1"},
               {"id": "tap", "label": "faucet", "states": ["off"]},
               {"id": "board_1", "label": "cutting board", "states": ["empty"], "on": "counter_1"},
               {"id": "knife_1", "label": "knife", "states": ["clean"], "on": "counter_1"},
               {"id": "squeezer_1", "label": "squeezer", "states": ["clean"], "on": "counter_1"},
               {"id": "glass_1", "label": "drinking glass", "states": ["empty"], "on": "counter_1"}]
    scene = write(tmp_path / "scene.json", json.dumps({"objects": objects}))
    r = run("plan", SUBGRAPHS / "0073-orange_juice.txt", "--kitchen", scene, "--goal", "orange juice", "--skills")
    assert r.exit_code in (0, 1), r.stderr
    cut = next(line for line in r.stdout.splitlines() if line.startswith("5. cut"))
    assert "(none stands free on the table: knife_1 is on counter_1, a place the step names, so not taken as a " \
           "tool)" in cut, cut
