"""What a newcomer meets first: warnings and hints that say what to do next (issue 12)."""

from __future__ import annotations

import json

import pytest
from click.testing import CliRunner

from foon2pddl.cli import main


def run(*args: str):
    return CliRunner().invoke(main, list(args))


# -- level 1/2 drop parts of a goal: say so ---------------------------------------------------------


def test_level_1_warns_that_goal_states_are_ignored():
    r = run("retrieve", "--goal", "onion: chopped, in [bowl]", "--level", "1")
    assert "warning: level 1 ignores" in r.stderr
    assert "'onion: chopped, in [bowl]' is read as 'onion'" in r.stderr


def test_level_2_warns_that_ingredients_are_ignored_and_level_3_is_silent():
    two = run("retrieve", "--goal", "mixing bowl: contains {whipped cream}", "--level", "2")
    assert "warning: level 2 ignores" in two.stderr and "ingredients" in two.stderr
    three = run("retrieve", "--goal", "onion: chopped", "--level", "3")
    assert "warning" not in three.stderr
    plain = run("retrieve", "--goal", "guacamole", "--level", "1")
    assert plain.exit_code == 0 and "warning" not in plain.stderr


# -- similarity of a label WordNet does not know ----------------------------------------------------


def test_similarity_warns_about_labels_not_in_wordnet():
    r = run("similarity", "xyzzy", "lemon")
    assert r.exit_code == 0 and float(r.stdout) == 0.0
    assert "warning: 'xyzzy' is not in WordNet" in r.stderr and "similarity to any other label is 0" in r.stderr
    assert "lemon" not in r.stderr
    known = run("similarity", "lemon", "lime")
    assert known.stderr == ""
    # in WordNet, but in no kitchen-relevant sense: a different message
    abstract = run("similarity", "democracy", "lemon")
    assert "warning: 'democracy' has no kitchen sense in WordNet" in abstract.stderr


# -- unknown goal label: where to look --------------------------------------------------------------


def test_unknown_goal_points_to_goals_command_and_closest_labels():
    r = run("retrieve", "--goal", "guacamol")
    assert r.exit_code == 2
    assert "close matches: guacamole" in r.stderr and "foon2pddl goals" in r.stderr
    # a word of a produced label is a hint too (difflib alone misses it)
    cream = run("retrieve", "--goal", "cream")
    assert cream.exit_code == 2 and "whipped cream" in cream.stderr


# -- goals: header first, legend first, --network ---------------------------------------------------


def test_goals_prints_legend_and_header_before_rows():
    lines = run("goals").stdout.splitlines()
    assert lines[0].startswith("reachable")  # legend line
    assert "round = sequential steps" in lines[0] and "* = a recipe's dish" in lines[0]
    assert lines[1].split() == ["made", "round", "dish", "goal"]
    assert lines[2].startswith(("yes", "no"))
    assert "of" in lines[0] and "goal candidates" in lines[0]


@pytest.mark.parametrize(("network", "lemonade"), [("exp", "lemonade"), ("gen", "beverages")])
def test_goals_takes_network(network, lemonade):
    reg = json.loads(run("goals", "--json").stdout)
    other = run("goals", "--json", "--network", network)
    assert other.exit_code == 0, other.output
    data = json.loads(other.stdout)
    assert data["network"] == network
    # lemonade (GEN: a beverage) can be made: a lime stands in for the lemon; on REG it cannot
    assert any(g["reachable"] for g in data["goals"] if g["dish"] and g["node"]["label"] == lemonade)
    assert not any(g["reachable"] for g in reg["goals"] if g["node"]["label"] == "lemonade")


# -- kitchen items that match no node ---------------------------------------------------------------


def test_kitchen_typos_are_warned_with_close_matches(tmp_path):
    kitchen = tmp_path / "k.txt"
    kitchen.write_text("onoin: whole\nonion whole\nknife\ncutting board: empty\n")
    r = run("retrieve", "--goal", "onion: chopped", "--kitchen", str(kitchen))
    assert r.exit_code == 1
    warned = [line for line in r.stderr.splitlines() if line.startswith(f"{kitchen}:") and "warning: kitchen item" in line]
    assert len(warned) == 2  # knife and the cutting board are nodes of the network
    assert all("close: `onion: whole`" in line for line in warned)
    assert any("`onoin: whole`" in line for line in warned) and any("`onion whole`" in line for line in warned)


KITCHEN_FORMS = {
    "k.txt": "# my kitchen\ncutting board: empty\nonoin: whole\n\n2 x knife\nonion: whole\nknfie\n",
    "k.foon": "//\nO\tcutting board\nS\tempty\n//\nO\tonoin\nS\twhole\n//\nO\tknife\n//\nO\tonion\nS\twhole\n"
              "//\nO\tknfie\n",
    "k.json": '[\n  {"label": "cutting board", "states": ["empty"]},\n  {"label": "onoin", "states": ["whole"]},\n'
              '  {"label": "knife"},\n  {"label": "onion",\n   "states": ["whole"]},\n  {"label": "knfie"}\n]\n',
    "scene.json": '{"objects": [\n  {"id": "board_1", "label": "cutting board", "states": ["empty"]},\n'
                  '  {"id": "x_1", "label": "onoin", "states": ["whole"]},\n  {"id": "knife_1", "label": "knife"},\n'
                  '  {"id": "onion_1", "label": "onion",\n   "states": ["whole"]},\n  {"id": "k_2", "label": "knfie"}\n]}\n',
}


@pytest.mark.parametrize(("name", "lines"), [("k.txt", (3, 7)), ("k.foon", (5, 13)), ("k.json", (3, 7)),
                                             ("scene.json", (3, 7))])
@pytest.mark.parametrize("level", ["3", "2"])
def test_kitchen_warnings_name_the_line_of_the_item(tmp_path, name, lines, level):
    """An error in a kitchen file names file:line; a warning about an item of it did not (`k.txt: warning:
    kitchen item ...`, stop 48's pass), and listed the items by label. Each names its line, in file order."""
    kitchen = tmp_path / name
    kitchen.write_text(KITCHEN_FORMS[name])
    r = run("retrieve", "--goal", "onion: chopped", "--kitchen", str(kitchen), "--level", level)
    assert r.exit_code == 0, r.stderr
    warned = [line for line in r.stderr.splitlines() if "warning" in line]
    assert [w.split(" matches")[0] for w in warned] == [
        f"{kitchen}:{lines[0]}: warning: kitchen item `onoin: whole`",
        f"{kitchen}:{lines[1]}: warning: kitchen item `knfie`"], r.stderr


def test_example_kitchen_given_explicitly_raises_no_warning():
    from foon2pddl.io.inputs import example_path

    for network in ("reg", "exp", "gen"):
        r = run("retrieve", "--goal", "lemonade", "--network", network, "--kitchen",
                str(example_path("example_kitchen.txt")))
        assert "warning" not in r.stderr, (network, r.stderr)


def test_many_stray_kitchen_items_are_summarized(tmp_path):
    from foon2pddl.io.inputs import load_network
    from foon2pddl.model.foon import make_node
    from foon2pddl.model.kitchen import unmatched_items

    foon = load_network([]).foon
    strays = [make_node(f"thing {i}") for i in range(25)]
    messages, total = unmatched_items([*strays, foon.nodes[0]], foon, limit=10)
    assert total == 25 and len(messages) == 10


# -- an unreachable goal that EXP or GEN would make ---------------------------------------------------


def test_unreachable_goal_names_the_networks_that_make_it(tmp_path, monkeypatch):
    monkeypatch.setenv("FOON2PDDL_CACHE", str(tmp_path / "cache"))
    cold = run("retrieve", "--goal", "lemonade")
    assert cold.exit_code == 1
    # EXP's similarity matrix is not cached: it is computed, with a notice first (the answer is the same)
    assert "computing its WordNet similarity matrix" in cold.stderr
    assert "hint: --network exp and --network gen can make it" in cold.stderr
    assert run("retrieve", "--goal", "lemonade", "--network", "exp").exit_code == 0  # caches the matrix
    warm = run("retrieve", "--goal", "lemonade")
    assert "hint: --network exp and --network gen can make it" in warm.stderr
    planned = run("plan", "--goal", "lemonade")
    assert planned.exit_code == 1 and "hint: --network exp and --network gen" in planned.stderr


def test_no_network_hint_when_no_network_makes_it(tmp_path):
    kitchen = tmp_path / "k.txt"
    kitchen.write_text("knife\n")
    r = run("retrieve", "--goal", "guacamole", "--kitchen", str(kitchen))
    assert r.exit_code == 1 and "hint:" not in r.stderr  # a slow check may say `(for a hint) ...`, then what it found


# -- output paths are checked before the work ---------------------------------------------------------


@pytest.mark.parametrize("command", [["plan", "--goal", "guacamole"], ["retrieve", "--goal", "guacamole"]])
def test_unwritable_output_fails_before_planning(tmp_path, command):
    blocker = tmp_path / "file"
    blocker.write_text("x")
    for bad in ("/proc/nope/x.txt", str(blocker / "x.txt"), str(tmp_path)):
        r = run(*command, "-o", bad)
        assert r.exit_code == 2, (bad, r.output)
        assert f"{bad}: error: cannot write" in r.stderr
        assert "phases:" not in r.stderr and "units" not in r.stderr  # nothing ran
    ok = tmp_path / "new" / "dir" / "tree.txt"
    assert run(*command, "-o", str(ok)).exit_code == 0 and ok.is_file()



@pytest.mark.parametrize("command", ["retrieve", "plan", "compile"])
@pytest.mark.parametrize(("goal", "problem"), [
    ("onoin", "unknown object label 'onoin'; close matches: onion"),
    ("onion: in [bowl", "unbalanced bracket in goal states ' in [bowl': 'onion: in [bowl'"),  # named before too
    ("onion: boiled", "no produced 'onion' node is in states 'onion: boiled'"),
])
def test_a_goal_nothing_makes_is_a_usage_error_naming_the_option(tmp_path, command, goal, problem):
    """README: a bad command-line value is 'a usage error naming the option'; `--goal onoin` said `Error: unknown
    object label 'onoin'; ...` with no option (stop 49's pass), where `--time-limit nan` names its option."""
    extra = ["-o", str(tmp_path / "out")] if command == "compile" else []
    r = run(command, "--goal", goal, *extra)
    assert r.exit_code == 2
    assert f"Error: Invalid value for '--goal': {problem}" in r.stderr, r.stderr


def test_goals_legend_counts_every_candidate_when_only_some_are_listed():
    """`goals --reachable` said `reachable: 171 of 171 goal candidates can be made` (1853 of 1853 on the subgraphs),
    counting only the rows it kept, where `goals` says 171 of 187 (stop 49's pass); `--dishes` counts dishes."""
    every = run("goals").stdout.splitlines()[0]
    assert every.startswith("reachable: 171 of 187 goal candidates can be made from ")
    kept = run("goals", "--reachable")
    assert kept.stdout.splitlines()[0].startswith("reachable: 171 of 187 goal candidates can be made from ")
    assert "; only those are listed" in kept.stdout.splitlines()[0]
    assert len(kept.stdout.splitlines()) == 2 + 171
    dishes = run("goals", "--dishes").stdout.splitlines()[0]
    assert dishes.startswith("reachable: 8 of 9 dishes can be made from "), dishes
    both = run("goals", "--dishes", "--reachable", "--json")
    data = json.loads(both.stdout)
    assert (data["reachable"], data["total"], len(data["goals"])) == (8, 9, 8)


@pytest.mark.parametrize("only", ["--dishes", "--reachable"])
def test_goals_output_with_its_legend_pipes_into_retrieve(only):
    listed = run("goals", only).stdout
    r = CliRunner().invoke(main, ["retrieve", "--goals", "-"], input=listed)
    assert "unmatched" not in r.stdout, r.stdout
