"""Stop 48's newcomer pass (issue 24, items 11 and the JSON inputs): a file given to the wrong option is told
which option takes it, by the option's name, and the items of a JSON list are counted as a user counts them."""

from __future__ import annotations

import pytest
from click.testing import CliRunner
from conftest import ROOT, SEARCH_INPUTS

from foon2pddl.cli import main
from foon2pddl.errors import FoonSyntaxError
from foon2pddl.io.jsonio import read_json

SCENE = ROOT / "tests" / "data" / "scene" / "whipped_cream_scene.json"
DIET = ROOT / "docs" / "examples" / "diet-no-egg.json"
RATES = SEARCH_INPUTS / "motion.txt"
UTENSILS = SEARCH_INPUTS / "utensils.txt"


def run(*args):
    return CliRunner().invoke(main, [str(a) for a in args])


@pytest.mark.parametrize(("text", "says"), [
    ('[{"label": "bowl"},\n {"label": "cup", "states": "empty"}]', ":2: error: item 2 (cup): 'states' must be"),
    ('[{"states": []}]', ":1: error: item 1: expected an object with a non-empty string 'label'"),
])
@pytest.mark.parametrize("option", ["--kitchen", "--goals"])
def test_json_list_items_are_counted_from_one(tmp_path, text, says, option):
    """A kitchen (or goal list) whose second item is bad said `item 1 (cup)`: counted from 0, where docs/format.md
    shows `item 3 (cup)` and a user counts from 1."""
    document = tmp_path / "k.json"
    document.write_text(text)
    r = run("retrieve", option, document, *(["--goal", "guacamole"] if option == "--kitchen" else []))
    assert r.exit_code == 2 and f"{document}{says}" in r.stderr


@pytest.mark.parametrize("option", ["--kitchen", "--goals"])
def test_a_json_item_key_typed_wrong_is_an_error(tmp_path, option):
    """Issue 24's tried-again pass: a kitchen item `{"label": "avocado", "state": ["whole"]}` (`state` for `states`)
    was read as a bare avocado, its states dropped without a word (the one hint a `matches no node` warning); a
    scene's or a constraints file's unknown key is an error, as a typo must be."""
    document = tmp_path / "k.json"
    document.write_text('[{"label": "bowl", "states": ["empty"]},\n {"label": "avocado", "state": ["whole"]}]')
    r = run("retrieve", option, document, *(["--goal", "guacamole"] if option == "--kitchen" else []))
    assert r.exit_code == 2, r.output
    assert (f"{document}:2: error: item 2 (avocado): unknown key 'state' (expected one of label, states, "
            "ingredients, container)") in r.stderr


def test_scene_objects_are_counted_from_one(tmp_path):
    """The scene reader said `object 1: 'id' must be ...` of the scene's second object."""
    scene = tmp_path / "s.json"
    scene.write_text('{"objects": [\n {"id": "bowl_1", "label": "bowl"},\n {"label": "cup"}\n]}\n')
    r = run("retrieve", "--goal", "guacamole", "--kitchen", scene)
    assert r.exit_code == 2 and f"{scene}:3: error: object 2: 'id' must be a non-empty string" in r.stderr


@pytest.mark.parametrize(("args", "says"), [
    (["stats", SEARCH_INPUTS / "kitchen.json"], "not a network: give it with `--kitchen` or with `--goals`"),
    (["stats", SCENE], "not a network: give it with `--kitchen`"),
    (["retrieve", DIET, "--goal", "guacamole"], "not a network: give it with `--constraints`"),
    (["stats", RATES], "this is a motion success-rates file (`motion<TAB>rate` lines), not a network: give it "
                       "with `--rates`"),
    (["retrieve", "--goal", "guacamole", "--kitchen", DIET], "not a kitchen: give it with `--constraints`"),
    (["retrieve", "--goal", "guacamole", "--kitchen", RATES], "not a kitchen: give it with `--rates`"),
    (["retrieve", "--goal", "guacamole", "--constraints", SEARCH_INPUTS / "kitchen.json"],
     "not a constraints file: give it with `--kitchen` or with `--goals`"),
    # stop 55's pass (nc55b): the rates file as a goal list was 129 `unmatched` goals (`chop 0.10`), exit 1, and as
    # a utensils list `expected one object label a line`; as a kitchen and as PATHS it was named
    (["retrieve", "--goals", RATES], "this is a motion success-rates file (`motion<TAB>rate` lines), not a goal list: "
                                     "give it with `--rates`"),
    (["retrieve", "--goal", "guacamole", "--utensils", RATES], "this is a motion success-rates file "
                                                               "(`motion<TAB>rate` lines), not a utensils list: give it with `--rates`"),
    (["retrieve", "--goal", "guacamole", "--constraints", RATES], "this is a motion success-rates file "
                                                                  "(`motion<TAB>rate` lines), not a constraints file: give it with `--rates`"),
    # stop 55's pass: a utensils list (one label a line) as PATHS said only `expected an 'O', 'S' or 'M' line`
    (["stats", UTENSILS], f"{UTENSILS}:1: error: it reads as a list of objects, one a line (no `O`, `S`, `M` or `//` "
                          "line), not a network: give it with `--utensils` or with `--kitchen` or with `--goals`"),
    (["plan", UTENSILS, "--goal", "cup"], "it reads as a list of objects, one a line (no `O`, `S`, `M` or `//` line), "
                                          "not a network: give it with `--utensils` or with `--kitchen`"),
])
def test_a_file_of_another_kind_names_the_option_that_takes_it(args, says):
    """`stats kitchen.json` said `give it as the kitchen or the goal list`, a scene `give it as the kitchen`, a
    rates file given as PATHS only `expected an 'O', 'S' or 'M' line`: none named the option to use."""
    r = run(*args)
    assert r.exit_code == 2 and says in r.stderr, r.stderr
    assert "Traceback" not in r.output


def test_a_kitchen_of_one_node_a_line_given_as_paths_names_the_kitchen_and_goal_options(tmp_path):
    """Objects with states (`onion: whole`, docs/format.md's node-per-line kitchen) are no utensils list: the
    error names `--kitchen` and `--goals` only; text that is no list of objects keeps the parser's error."""
    kitchen = tmp_path / "k.txt"
    kitchen.write_text("# on hand\nonion: whole\n2 x bowl: empty\nknife\n")
    r = run("stats", kitchen)
    assert r.exit_code == 2, r.output
    assert (f"{kitchen}:1: error: it reads as a list of objects, one a line (no `O`, `S`, `M` or `//` line), not a "
            "network: give it with `--kitchen` or with `--goals`\n") in r.stderr
    for text in ("Onion: whole, in [bowl: empty\n", "Hello world, this is a note.\nSee the README.\n",
                 "# notes\nThis file lists: the inputs.\n", "nonsense\tline\n"):
        prose = tmp_path / "notes.txt"
        prose.write_text(text)
        r = run("stats", prose)
        assert r.exit_code == 2 and "not a network" not in r.stderr, (text, r.stderr)
        assert "expected an 'O', 'S' or 'M' line" in r.stderr, (text, r.stderr)


@pytest.mark.parametrize(("given", "says"), [
    (RATES, "<stdin>:1: error: this is a motion success-rates file (`motion<TAB>rate` lines), not a network: give it "
            "with `--rates`"),
    (UTENSILS, "<stdin>:1: error: it reads as a list of objects, one a line (no `O`, `S`, `M` or `//` line), not a "
               "network: give it with `--utensils` or with `--kitchen` or with `--goals`"),
])
def test_a_file_of_another_kind_on_standard_input_is_named_too(given, says):
    """`cat utensils.txt | stats -` (and the rates file) said only `expected an 'O', 'S' or 'M' line`, where the
    same file named as PATHS says what it is."""
    r = CliRunner().invoke(main, ["stats", "-"], input=given.read_text())
    assert r.exit_code == 2 and says in r.stderr, r.stderr


def test_the_library_says_where_a_file_goes_in_words():
    """Python callers have no options: the same error names the input in words."""
    with pytest.raises(FoonSyntaxError) as info:
        read_json(SEARCH_INPUTS / "kitchen.json")
    assert info.value.belongs == ("kitchen", "goals")
    assert str(info.value).endswith("not a network: give it as the kitchen or as the goal list")


def test_a_directory_of_no_foon_file_says_what_was_skipped():
    """`stats tests/data/foon-search-inputs` said only `no FOON file to read: every file was skipped`, where
    docs/format.md says each skipped file gets a warning: the error names them and why."""
    r = run("stats", SEARCH_INPUTS)
    assert r.exit_code == 2
    assert "every file was skipped; motion.txt: a motion success-rates file" in r.stderr
    assert "; utensils.txt: no FOON text" in r.stderr


@pytest.mark.parametrize("command", [["retrieve", "--goal", "whipped cream"], ["goals"]])
def test_every_command_says_which_files_under_a_directory_it_skipped(tmp_path, command):
    """docs/format.md says a file under a directory that is plainly not FOON is skipped with a warning; `retrieve`,
    `plan`, `goals` and `compile` on such a directory skipped the rates file and the notes without a word (only
    `stats`, in its stdout report, and `merge` said so: stop 49's third newcomer pass)."""
    (tmp_path / "0001-whipped_cream.txt").write_text(
        (ROOT / "tests" / "data" / "foon-subgraphs" / "0001-whipped_cream.txt").read_text())
    (tmp_path / "motion.txt").write_text(RATES.read_text())
    (tmp_path / "notes.txt").write_text("shopping list\n")
    r = run(*command[:1], tmp_path, *command[1:])
    assert r.exit_code == 0, r.output
    assert f"{tmp_path / 'motion.txt'}: warning: skipped: a motion success-rates file" in r.stderr
    assert f"{tmp_path / 'notes.txt'}: warning: skipped: no FOON text" in r.stderr


def test_stats_says_each_skipped_file_once_in_its_report(tmp_path):
    """`stats DIR` said a skipped file twice: in its report's warnings (stdout) and on stderr. Its report lists
    every warning of the files read (parse warnings too, and `--json`'s `warnings`), so that is the one place."""
    (tmp_path / "0001-whipped_cream.txt").write_text(
        (ROOT / "tests" / "data" / "foon-subgraphs" / "0001-whipped_cream.txt").read_text())
    (tmp_path / "motion.txt").write_text(RATES.read_text())
    r = run("stats", tmp_path)
    assert r.exit_code == 0, r.output
    assert "motion.txt: warning: skipped" not in r.stderr, r.stderr
    assert r.stdout.count(f"{tmp_path / 'motion.txt'}: warning: skipped: a motion success-rates file") == 1, r.stdout


def test_merge_says_each_skipped_file_once(tmp_path):
    """`merge` prints every warning on stderr: a skipped file's is not said twice."""
    (tmp_path / "0001-whipped_cream.txt").write_text(
        (ROOT / "tests" / "data" / "foon-subgraphs" / "0001-whipped_cream.txt").read_text())
    (tmp_path / "motion.txt").write_text(RATES.read_text())
    r = run("merge", tmp_path)
    assert r.exit_code == 0 and r.stderr.count("motion.txt: warning: skipped") == 1, r.stderr


@pytest.mark.parametrize(("text", "skipped"), [
    ("O\tonion\t0\nS\twhole\nM\tchop\n", "unit has no output objects after its motion line"),
    ("M\tchop\nO\tonion\t0\nS\tchopped\n", "unit has no input objects before its motion line"),
])
def test_a_recipe_whose_every_block_is_skipped_is_not_called_a_kitchen(tmp_path, text, skipped):
    """nc54a's pass: a recipe of one block with its motion line but no outputs (a truncated file) said `no functional
    units in file: it lists objects and no motion ('M') line, as a kitchen or a goal file does`: false (line 3 is the
    motion line), and the warning saying why its one block was skipped was not shown."""
    recipe = tmp_path / "r.txt"
    recipe.write_text(text)
    r = run("stats", recipe)
    assert r.exit_code == 2 and "Traceback" not in r.stderr
    assert r.stderr.startswith(f"{recipe}:3: error: no functional units in file: every block was skipped"), r.stderr
    assert f"line 1: {skipped}" in r.stderr and "no motion ('M') line" not in r.stderr and "--kitchen" not in r.stderr


@pytest.mark.parametrize("given", [SEARCH_INPUTS / "goal_nodes.json", SEARCH_INPUTS / "kitchen.json"])
def test_a_json_goal_list_as_goal_file_says_it_goes_with_goals(given):
    """Stop 56's newcomer pass: the shared goal list given as `--goal-file` (one node in FOON O/S lines) said only
    `goal_nodes.json:1: error: expected an 'O' or 'S' line, '//' or a '#' comment`."""
    r = run("plan", "--goal-file", given)
    assert r.exit_code == 2 and "Traceback" not in r.output
    first = r.stderr.splitlines()[0]
    assert first.startswith(f"{given}:1: error: a JSON list of ") and "not the one goal node" in first, r.stderr
    assert first.endswith("give it with `--kitchen` or with `--goals`"), first  # kitchen.json is a kitchen
    assert "(s)" not in first and " objects, not" in first, first  # `model.words.count`, never `object(s)`


def test_a_broken_goal_file_keeps_the_parsers_error(tmp_path):
    bad = tmp_path / "goal.txt"
    bad.write_text("onion\twhole\n")
    r = run("retrieve", "--goal-file", bad)
    assert r.exit_code == 2 and "expected an 'O' or 'S' line" in r.stderr, r.stderr
