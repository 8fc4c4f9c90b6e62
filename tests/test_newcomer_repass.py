"""Findings of a newcomer's re-pass over README and docs (issue 24): each test is one thing a new user
read or was told that was not true, written first and watched fail."""

from __future__ import annotations

import json

import pytest
from click.testing import CliRunner
from conftest import ROOT

from foon2pddl.cli import main

POUR_WATER = ROOT / "tests" / "data" / "foon_to_pddl-examples" / "FOON-pour_water.txt"
BOWL = "bowl: contains {water}, on [table]"


def run(*args: str):
    return CliRunner().invoke(main, [str(a) for a in args])


def test_a_cycle_names_the_node_that_breaks_it_not_a_false_count():
    """The converter's pour water: the pour gives back the empty cup the fill takes, so the default kitchen
    lacks it. One node (`cup (empty, on [table])`, docs/pddl.md's kitchen) makes the bowl of water; the
    reason said it "needs more than 6 kitchen additions"."""
    r = run("retrieve", POUR_WATER, "--goal", BOWL)
    assert r.exit_code == 1
    assert "needs more than" not in r.stderr
    assert "`foon2pddl check` names the cycle" in r.stderr
    assert "a kitchen that holds one of the cycle's nodes breaks it: add `cup (empty, on [table])`" in r.stderr


def test_the_named_node_does_make_it(tmp_path):
    """The oracle: the default kitchen plus the node the reason names makes the goal."""
    kitchen = tmp_path / "k.txt"
    kitchen.write_text("bottle: contains {water}, on [table]\nwater: liquid, in [bottle]\nbowl: empty, on [table]\n"
                       "cup: empty, on [table]\n")
    r = run("retrieve", POUR_WATER, "--kitchen", kitchen, "--goal", BOWL)
    assert r.exit_code == 0, r.stderr


def test_a_scene_kitchens_fridge_and_counter_are_no_tools_to_lift():
    """`plan --kitchen SCENE --skills` (docs/scene.md's scene): the robot picked the fridge up and poured the sugar
    from it, and found no whisk to beat with on the counter. A holder the step's unit does not name is where the
    object stands: the sugar is taken out of the fridge and poured, the whisk picked from the counter."""
    r = run("plan", "--kitchen", ROOT / "tests" / "data" / "scene" / "whipped_cream_scene.json", "--goal",
            "whipped cream", "--skills")
    assert r.exit_code == 0, r.output
    assert "4 macro steps, 4 decomposed, 11 skills; skill replay valid" in r.stdout
    lines = r.stdout.splitlines()
    assert "   take-out sugar_1 out of fridge_1" in lines and "   pour from sugar_1 over mixing_bowl_1" in lines
    assert "   pick whisk_1 from counter_1" in lines and "   beat mixing_bowl_1 with whisk_1" in lines
    assert not any("fridge_1 from" in x or "from fridge_1 over" in x for x in lines)


def test_a_gen_goal_note_names_what_the_user_asked_for():
    """`retrieve --goal lemonade --network gen` said "note: goal 'beverages' read as the recipe's dish": the user
    asked for lemonade; the note names it, and the category FOON-GEN reads it as."""
    r = run("retrieve", "--goal", "lemonade", "--network", "gen")
    assert r.exit_code == 0, r.output
    assert "note: goal 'lemonade' (FOON-GEN: 'beverages') read as the recipe's dish: `beverages (" in r.stderr
    assert "note: goal 'beverages'" not in r.stderr


def test_a_gen_goal_naming_a_label_no_category_files_says_which():
    """`retrieve --network gen --goal "butter: melted, in [pan]"` listed GEN's `(in [pans], melted)` beside the
    `in [pan]` it kept, with no reason (review rv42): the index files `pan` in no category; the error says so.
    A goal whose labels all have categories keeps the plain message."""
    r = run("retrieve", "--goal", "butter: melted, in [pan]", "--network", "gen")
    assert r.exit_code == 2
    assert "the category index files 'pan' in no category, so GEN keeps it as written" in r.stderr
    other = run("retrieve", "--goal", "butter: melted, in [bowls]", "--network", "gen")
    assert other.exit_code == 2 and "produced states include" in other.stderr
    assert "in no category" not in other.stderr
    assert run("retrieve", "--goal", "butter: melted, in [frying pan]", "--network", "gen").exit_code == 0


def test_plan_help_says_what_format_a_skill_plan_takes():
    """`plan --help` gave `--format` as "[default: recipe]" for the task tree only; with --skills the default is
    the steps form (docs/skills.md) and only steps, recipe and json are accepted."""
    text = " ".join(run("plan", "--help").stdout.split())
    assert "with --skills, the skill plan: steps (the default there), recipe or json" in text
    default = run("plan", "--goal", "whipped cream", "--skills")
    assert default.exit_code == 0 and default.stdout.splitlines()[1].startswith("1. pour [pour] (")


def test_an_unquoted_goal_of_two_words_is_told_to_be_quoted():
    """`plan --goal whipped cream` said only "cream: error: no such file or directory": the second word was read
    as a FOON path. The error stays (exit 2); a hint shows the quoted goal."""
    r = run("plan", "--goal", "whipped", "cream")
    assert r.exit_code == 2
    assert "cream: error: no such file or directory" in r.stderr
    assert "hint: a goal of several words is one argument: --goal 'whipped cream'" in r.stderr
    other = run("plan", "--goal", "guacamole", "nowhere.txt")  # a path that is plainly a file name: no hint
    assert other.exit_code == 2 and "hint:" not in other.stderr


def test_a_command_without_a_goal_names_every_way_to_give_one():
    """`foon2pddl plan` with no goal said "give exactly one of --goal and --goal-file": a newcomer reading it
    misses `--goals FILE` and that `--goal` repeats (README, "Many goals in one run")."""
    for command in ("plan", "retrieve", "compile"):
        r = run(command, *(["-o", "out"] if command == "compile" else []))
        assert r.exit_code == 2, (command, r.stderr)
        assert "no goal given: --goal G (repeat it for a batch), --goals FILE or --goal-file FILE" in r.stderr
    both = run("plan", "--goal", "guacamole", "--goal-file", POUR_WATER)
    assert both.exit_code == 2 and "--goal and --goal-file: give one of them" in both.stderr


def test_instances_help_names_every_encoding_it_counts_for():
    """`--instances` sets the object counts of `relational` too (docs/pddl.md: same counts as `instances`), but
    plan --help said "instances encoding: N objects of LABEL" and the refusal "--encoding instances" only."""
    assert "instances and relational encodings: N objects of LABEL" in " ".join(run("plan", "--help").output.split())
    counted = run("plan", "--goal", "guacamole", "--encoding", "relational", "--instances", "cutting board=2")
    assert counted.exit_code == 0
    assert ("2 x cutting board (empty): 2 given by `cutting board=2` (the instances stated per label), where FOON's "
            "unfolded plan takes") in counted.stderr



def test_a_count_restoring_units_set_is_not_called_stated():
    """Stop 56's newcomer pass: `plan --goal guacamole --restore` noted `3 x cutting board (empty): the count stated
    for it`, a count the user never stated (--restore set it: docs/pddl.md, Restoring units)."""
    r = run("plan", "--goal", "guacamole", "--restore")
    assert r.exit_code == 0, r.stderr
    note = next(line for line in r.stderr.splitlines() if line.startswith("note: objects: 3 x cutting board (empty)"))
    assert "3 set by the restoring units' peak, where FOON's unfolded plan takes 5" in note, note
    assert "the count stated" not in note


def test_the_objects_note_names_who_gave_a_count(tmp_path):
    """newcomer60: the note on a count FOON's plan does not take said `k given, where FOON's unfolded plan takes n
    (a stated count, restoring units' peak, or the relational encoding's own counting)`: three sources, never the
    one that applies. It names it: the kitchen file's line, the scene, `--instances` (above), the restoring units
    (above), or the encoding itself, in text and in `plan --format json`'s notes."""
    from foon2pddl.io.inputs import load_goal, load_kitchen, load_network
    from foon2pddl.pddl.compile import compile_goal

    example = ROOT / "foon2pddl" / "data" / "example_kitchen.txt"
    lines = []
    for node in load_kitchen(example, load_network([]), 3).sorted_nodes():
        line = node.label + (": " + ", ".join(s.describe() for s in node.states) if node.states else "")
        lines.append(("2 x " if node.label == "cutting board" else "") + line)
    kitchen = tmp_path / "k.txt"
    kitchen.write_text("\n".join(lines) + "\n")
    at = 1 + next(i for i, line in enumerate(lines) if line.startswith("2 x "))
    r = run("plan", "--goal", "guacamole", "--kitchen", kitchen)
    assert r.exit_code == 0, r.stderr
    said = f"note: objects: 2 x cutting board (empty): 2 given by the kitchen file (k.txt:{at}), where FOON's"
    assert said in r.stderr, r.stderr
    notes = json.loads(run("plan", "--goal", "guacamole", "--kitchen", kitchen, "--format", "json").stdout)[
        "validation"]["notes"]
    assert any(n.startswith(said.removeprefix("note: ")) for n in notes), notes
    # a scene's three bowls, where the whipped cream's plan takes one
    objects = json.loads((ROOT / "tests" / "data" / "scene" / "whipped_cream_scene.json").read_text())["objects"]
    objects += [{"id": f"bowl_{k}", "label": "bowl", "states": ["empty"], "on": "counter_1"} for k in (2, 3)]
    scene = tmp_path / "scene.json"
    scene.write_text(json.dumps({"objects": objects}))
    net = load_network([])
    foon = net.at(3)
    goal = load_goal("whipped cream: whipped, in [bowl]", None, foon)
    compiled = compile_goal(foon, load_kitchen(scene, net, 3), goal, "instances")
    said = compiled.task.comments  # the problem file's header
    assert any(n.startswith("objects: 3 x bowl (empty): 3 given by the scene, where FOON's unfolded plan takes 1")
               for n in said), said
    assert not any("a stated count" in n for n in said)

PHYSICAL_OPTIONS = (("--restore",), ("--instances", "bowl=2"), ("--instances", "bowl=x"), ("--category-types",))


@pytest.mark.parametrize("command", ["plan", "compile"])
@pytest.mark.parametrize("option", PHYSICAL_OPTIONS, ids=" ".join)
def test_an_option_over_physical_objects_is_refused_before_anything_is_read(command, option, tmp_path):
    """`plan --goal "whipped cream" --restore` (the `tree` encoding) printed the goal's note, then the usage
    error; on the shared subgraphs the kitchen's note too, after 2 s of loading. A usage error comes first.
    And `--category-types` under `tree` was ignored without a word (`--instances` there is refused)."""
    out = ["-o", tmp_path / "out"] if command == "compile" else []
    r = run(command, "--goal", "whipped cream", "--encoding", "tree", *option, *out)  # plan's default has objects
    assert r.exit_code == 2, r.output
    assert option[0] in r.stderr and "note:" not in r.stderr, r.stderr
    gen = run(command, "--goal", "whipped cream", "--network", "gen", *option, *out)
    assert gen.exit_code == 2 and "gen-lifted" in gen.stderr and "note:" not in gen.stderr, gen.stderr


def test_category_types_help_names_every_encoding_it_types():
    """`--category-types` changes the `relational` domain as it does `instances`' (both declare the category
    chain as supertypes), but --help said "instances encoding:"."""
    assert "instances and relational encodings: declare" in " ".join(run("plan", "--help").output.split())


@pytest.mark.parametrize("option", ["--kitchen", "--goal-file"])
def test_a_recipe_file_given_as_a_list_of_objects_is_told_to_be_a_network(option):
    """A FOON recipe given where a list of objects is read (`--kitchen`, `--goal-file`) stopped at its first
    motion line with `expected an 'O' or 'S' line`, never saying the file is a network that goes in PATHS."""
    recipe = ROOT / "tests" / "data" / "foon-subgraphs" / "0001-whipped_cream.txt"
    extra = ["--goal", "guacamole"] if option == "--kitchen" else []
    r = run("retrieve", option, recipe, *extra)
    assert r.exit_code == 2
    assert f"{recipe}:8: error: a motion line ('M'): this file is a FOON network of functional units, " in r.stderr
    assert "give it as a PATHS argument" in r.stderr
    assert "Traceback" not in r.output


@pytest.mark.parametrize(("where", "extra"), [
    ("foon2pddl.planners.solve", ["--goal", "whipped cream", "--goal", "guacamole"]),  # a batch
    ("foon2pddl.skills.run", ["--goal", "whipped cream", "--skills"]),
])
def test_category_types_reach_the_planner_in_a_batch_and_under_skills(where, extra, monkeypatch):
    """`--category-types` was read, then dropped without a word by a batch of goals and by `--skills`:
    every task they planned had no category types."""
    import importlib

    module = importlib.import_module(where)
    real, seen = module.plan, []

    def spy(*args, **kwargs):
        seen.append(kwargs.get("categories", ()))
        return real(*args, **kwargs)

    monkeypatch.setattr(module, "plan", spy)
    r = run("plan", "--encoding", "relational", "--category-types", *extra)
    assert r.exit_code == 0, r.output
    assert seen and all(dict(chains).get("bowl", ())[:1] == ("bowls",) for chains in seen)


@pytest.mark.parametrize(("document", "says"), [
    ("docs/examples/robot-no-pour.json", "this is a constraints file (docs/constraints.md), not a kitchen: "
                                         "give it with `--constraints`"),
    ("docs/examples/diet-no-egg.json", "this is a constraints file (docs/constraints.md), not a kitchen: "
                                       "give it with `--constraints`"),
    ("network", "this is a FOON network (JSON, docs/json-schema.md), not a kitchen: give it as a PATHS argument"),
])
def test_a_json_document_given_as_a_kitchen_says_what_it_is_and_where_it_goes(document, says, tmp_path):
    """A constraints file or a network's JSON export given as `--kitchen` got the generic `expected a JSON
    list of objects, or a scene`, never saying what the file is or which option takes it."""
    if document == "network":
        document = tmp_path / "net.json"
        assert run("merge", "--format", "json", "-o", document).exit_code == 0
    else:
        document = ROOT / document
    r = run("retrieve", "--goal", "guacamole", "--kitchen", document)
    assert r.exit_code == 2
    assert f"{document}:1: error: {says}" in r.stderr
    assert "Traceback" not in r.output


def test_a_constraints_file_given_as_a_network_says_to_give_it_with_constraints():
    """`retrieve docs/examples/robot-no-pour.json --goal ...` said only "FOON JSON document lacks the required
    field 'format'"."""
    document = ROOT / "docs" / "examples" / "robot-no-pour.json"
    r = run("retrieve", document, "--goal", "guacamole")
    assert r.exit_code == 2
    assert ("error: top level: this is a constraints file (docs/constraints.md), not a network: give it with "
            "`--constraints`") in r.stderr


@pytest.mark.parametrize("encoding", ["state", "ocp"])
def test_an_encoding_that_is_not_foons_semantics_says_why_it_has_no_plan(encoding):
    """Stop 43's re-pass: `plan --goal guacamole --encoding state` (and `ocp`) exited 1 with only `search proved the
    task unsolvable`, where README promises the reason is printed; the guacamole needs the one cutting board twice,
    and these encodings have one object per label (docs/pddl.md). The reason says so and what to use."""
    r = run("plan", "--goal", "guacamole", "--encoding", encoding)
    assert r.exit_code == 1
    reason = next(line for line in r.stderr.splitlines() if line.startswith("reason: "))
    assert f"the {encoding} encoding is not FOON's semantics" in reason and "--encoding relational" in reason
    data = json.loads(run("plan", "--goal", "guacamole", "--encoding", encoding, "--format", "json").stdout)
    assert data["reason"] == reason.removeprefix("reason: ")
    missing = run("plan", "--goal", "lemonade", "--encoding", encoding)  # review rv43: no lemon in the kitchen
    assert missing.exit_code == 1
    reason = next(line for line in missing.stderr.splitlines() if line.startswith("reason: "))
    assert "add `lemon (whole)`" in reason and "not FOON's semantics" not in reason


@pytest.mark.parametrize("encoding", ["state", "ocp"])
def test_a_batch_row_gives_the_reason_a_single_plan_gives(encoding):
    """Stop 44's leftover: a single `plan --encoding state|ocp` names why there is no plan (one object per label;
    FOON's reason where the kitchen lacks an ingredient), but a batch row gave only the planner's words. One
    decision serves both: each row's reason ends with the reason line the single run prints."""
    r = run("plan", "--goal", "guacamole", "--goal", "lemonade", "--encoding", encoding, "--format", "jsonl")
    assert r.exit_code == 1
    rows = {row["goal"].split(" (")[0]: row for row in map(json.loads, r.stdout.splitlines())}
    for goal, says in (("guacamole", f"the {encoding} encoding is not FOON's semantics"),
                       ("lemonade", "add `lemon (whole)`")):
        single = run("plan", "--goal", goal, "--encoding", encoding)
        reason = next(line for line in single.stderr.splitlines() if line.startswith("reason: "))
        assert says in reason and rows[goal]["reason"].endswith(": " + reason.removeprefix("reason: "))


def test_a_directory_file_that_fails_to_parse_names_the_way_to_skip_it(tmp_path):
    """Stop 44's re-pass: `stats tests/data` stopped at a test fixture under the directory
    (`plan-tree/whipped-foon.txt:1: error: expected an 'O', 'S' or 'M' line`) and said nothing of
    `--skip-invalid`, which no page names either (issue 24 item 11: "no way to skip")."""
    (tmp_path / "net").mkdir()
    (tmp_path / "net" / "a.foon").write_text((ROOT / "foon2pddl" / "data" / "example" / "07-guacamole.foon").read_text())
    (tmp_path / "net" / "broken.foon").write_text("O\tbowl\t0\nM\tmix\nX\tnonsense\n")
    stops = run("stats", tmp_path / "net")
    assert stops.exit_code == 2 and "broken.foon:3: error" in stops.stderr
    assert "`--skip-invalid` skips the files that fail to parse" in stops.stderr
    named = run("stats", tmp_path / "net" / "broken.foon")  # one file named: nothing else to read, no hint
    assert named.exit_code == 2 and "--skip-invalid" not in named.stderr
    assert run("stats", tmp_path / "net", "--skip-invalid").exit_code == 0


def test_a_kitchen_list_given_as_a_network_says_where_it_goes():
    """Stop 44's re-pass of issue 24 item 11 (`stats kitchen.json` should suggest the kitchen): the error said what
    the file is but not where it goes, where a scene or a constraints file given as a network is told both."""
    from conftest import SEARCH_INPUTS

    r = run("stats", SEARCH_INPUTS / "kitchen.json")
    assert r.exit_code == 2
    assert "is a kitchen or a goal list (docs/format.md), not a network: give it with `--kitchen` or with `--goals`" \
        in r.stderr


def test_results_of_another_protocol_give_each_way_out_once(tmp_path):
    """Stop 44's re-pass of issue 24 item 13: the experiment's 'another protocol' error said 'use another output
    directory, start afresh, or the same parameters and inputs; use another -o directory, or --fresh to discard
    them': the library's advice and then the command's, one of them twice. Each way out is said once."""
    args = ["experiment", "--trials", "1", "--goals", "2", "--networks", "reg", "--solvers", "native-complete",
            "-o", str(tmp_path), "--sensitivity", "none", "--no-progress"]
    assert run(*args).exit_code == 0
    r = run(*args, "--seed", "5")
    assert r.exit_code == 2 and "seed 0 there, 5 here" in r.stderr
    assert r.stderr.split("error: ", 1)[1].count("another") == 2  # 'another protocol', 'another -o directory'
    assert "the same parameters and inputs resume them; use another -o directory, or --fresh to discard them" \
        in r.stderr


def test_optimal_help_names_the_search_the_default_encoding_gets():
    """`plan --help` said `--optimal` is "Fast Downward: A* with LM-cut"; on plan's default encoding
    (`relational`, whose conditional effects LM-cut refuses) it runs A* with h^max (docs/planning.md)."""
    r = run("plan", "--goal", "whipped cream", "--optimal")
    assert r.exit_code == 0 and "solved (fd (astar(hmax())))" in r.stderr, r.stderr
    text = " ".join(run("plan", "--help").stdout.split())
    assert "A* with h^max on a task with conditional effects (relational)" in text


def test_a_misspelt_json_field_is_named_as_the_typo(tmp_path):
    """docs/json-schema.md: "Unknown fields are an error (they are most often typos, e.g. `stats` for `states`)".
    A node written with `stats` was reported as "object node lacks the required field 'states'", never naming
    the field the file does have."""
    export = run("merge", "--format", "json")
    assert export.exit_code == 0
    bad = tmp_path / "net.json"
    bad.write_text(export.stdout.replace('"states"', '"stats"', 1))
    r = run("stats", bad)
    assert r.exit_code == 2 and "Traceback" not in r.output
    assert ("units[0].inputs[0].stats: unknown key 'stats' in object node: did you mean 'states'? (expected one of "
            "label, states, motion_flag, goal, dish)") in r.stderr, r.stderr


def test_a_misspelt_command_names_the_closest_one():
    """A newcomer's typo of a command (`foon2pddl retrive`) said only "No such command 'retrive'." where a misspelt
    option, planner or alias names the closest: the command now does too, and lists the commands."""
    r = CliRunner().invoke(main, ["retrive", "--goal", "guacamole"])
    assert r.exit_code == 2
    assert "Error: No such command 'retrive'; did you mean 'retrieve'? (commands: analyze, categories," in r.stderr
    assert "Traceback" not in r.output


@pytest.mark.parametrize(("lines", "bad", "says"), [
    # a node-per-line kitchen with a FOON object pasted in: each O/S line was read as a label, one warning each
    ("onion: whole\nO1\tbowl\t1\nS1\tempty\n", 2, "a FOON `O` line, but line 1 lists a node in the goal syntax"),
    ("# kitchen\nknife\n\nS12\tempty\n", 4, "a FOON `S` line, but line 2 lists a node in the goal syntax"),
    ("onion: whole\nO278 mixing bowl 1\n", 2, "a FOON `O` line, but line 1 lists a node in the goal syntax"),
    ("onion: whole\n//\n", 2, "a FOON `//` line, but line 1 lists a node in the goal syntax"),
    # a FOON recipe whose first line is a bare title: its motion line says it is a network
    ("whipped cream\nO1\tbowl\t1\nS1\tempty\nM1\tpour\t1\t2\n", 2, "a FOON `O` line"),
])
def test_a_kitchen_that_mixes_foon_lines_into_node_lines_is_one_error(lines, bad, says, tmp_path):
    """Stop 46's leftover: a kitchen of one node per line that also holds FOON `O`/`S` lines (a FOON file, or a
    FOON-style kitchen, pasted after a node line) read each O/S line as a label: one `matches no node` warning
    per line (69 on a recipe), then a run from the wrong kitchen. One error names the file, the line and the
    two forms instead."""
    kitchen = tmp_path / "k.txt"
    kitchen.write_text(lines)
    r = run("retrieve", "--goal", "guacamole", "--kitchen", kitchen)
    assert r.exit_code == 2, r.output
    assert f"{kitchen}:{bad}: error: {says}" in r.stderr
    assert "one form throughout" in r.stderr and "docs/format.md" in r.stderr
    assert "warning" not in r.stderr and "Traceback" not in r.output


@pytest.mark.parametrize("command", ["plan", "compile"])
@pytest.mark.parametrize("value, says", [
    ("cuting board=1", "no object of the network is labelled 'cuting board'; close matches: cutting board"),
    ("cutting board", "'cutting board' is not LABEL=N (a label, then a count N >= 0)"),
    ("cutting board=x", "'cutting board=x' is not LABEL=N (a label, then a count N >= 0)"),
])
def test_an_instances_value_error_names_the_option_as_every_other_option_error(command, value, says, tmp_path):
    """`--instances` errors read `Error: --instances: ...` where `--goal`, `--time-limit`, `--planner` and the
    experiment's options read click's `Invalid value for '--option': ...` (issue 24, stop 50's leftover)."""
    r = run(command, "--goal", "guacamole", "--encoding", "instances", "--instances", value,
            *(["-o", tmp_path / "out"] if command == "compile" else []))
    assert r.exit_code == 2
    assert f"Error: Invalid value for '--instances': {says}" in r.stderr, r.stderr
    assert not (tmp_path / "out").exists()


def test_the_omelettes_steps_say_what_moves_from_where_into_what_with_which_tool():
    """Issue 24 item 14 on the shared data's omelette: `crack bowl (empty), with the egg (uncracked)`, `sprinkle
    bowl (...), bowl (...)`, `pour egg mixture ... into the pan, with the cooking pan`, `heat cooking pan (...),
    stove (...)` and `cook cooking pan (...), omelette (...)` read as if the bowl were cracked and the pan a tool."""
    from conftest import SUBGRAPHS

    r = run("retrieve", SUBGRAPHS, "--goal", "omelette")
    assert r.exit_code == 0, r.stderr
    steps = {line.split(". ", 1)[1] for line in r.stdout.splitlines() if line[:1].isdigit()}
    assert "crack egg (uncracked) into the bowl (empty), making egg white and yolk in the bowl" in steps, steps
    assert "mix egg white and yolk, with the fork (clean), in the bowl" in steps  # not `on the bowl`
    assert "heat cooking pan (empty), on the stove (off, with [pan])" in steps
    assert "pour egg mixture from the bowl into the cooking pan (heated, on [stove])" in steps
    assert "sprinkle salt (granulated) from the bowl (contains {salt}) into the bowl (contains {egg white and yolk})" in steps
    assert ("cook omelette (contains {black pepper, salt}, partly cooked), in the cooking pan (contains {egg mixture},"
            " on [stove]), on the stove (on, with [pan])") in steps
    assert ("mix egg mixture (contains {black pepper, salt}), with the whisk (clean), in the cooking pan (on [stove]),"
            " making omelette (contains {black pepper, salt}, partly cooked) in the cooking pan") in steps
    assert ("pick-and-place omelette (contains {black pepper, salt}, cooked) from the cooking pan onto the plate "
            "(empty), with the turner (clean)") in steps
    assert not any(s.startswith("crack bowl") or "with the cooking pan" in s or "with the egg" in s for s in steps)


def test_a_kitchen_of_object_lines_given_as_a_network_names_the_option_that_takes_it():
    """nc52a's pass: `stats foon2pddl/data/example_kitchen.txt` (the kitchen README names, FOON-style O/S lines)
    said only `...:148: error: no functional units in file`, where a JSON kitchen given so names `--kitchen`."""
    kitchen = ROOT / "foon2pddl" / "data" / "example_kitchen.txt"
    r = run("stats", kitchen)
    assert r.exit_code == 2
    assert r.stderr.startswith(f"{kitchen}:148: error: no functional units in file: it lists objects and no "
                               "motion ('M') line, as a kitchen or a goal file does"), r.stderr
    assert "give it with `--kitchen` or with `--goals`" in r.stderr and "Traceback" not in r.stderr


CYCLE_AND_LEAF = ("//\nO\tstarter\t1\nS\tactive\nO\ttopping\t1\nS\tready\nM\tmix\nO\tdough\t1\nS\tmixed\n"
                  "//\nO\tdough\t1\nS\tmixed\nM\tferment\nO\tstarter\t1\nS\tactive\n"
                  "//\nO\tnut\t1\nS\twhole\nM\tchop\nO\ttopping\t1\nS\tready\n//\n")


def test_a_goal_behind_a_cycle_is_said_to_be_so_when_the_kitchen_also_lacks_a_leaf():
    """The base kitchen's apple cake on the shared subgraphs (nc53a's pass): every way to the dough needs the
    starter the dough makes, and the kitchen lacks the nut too. The reason said "it needs more than 6 kitchen
    additions" and listed the nut, where no set of any size helps: docs/retrieval.md says such a goal gets the
    cycle's words and the cycle's nodes that break it."""
    from foon2pddl.io.parser import parse_text
    from foon2pddl.model.goal import GoalSpec, resolve_goal
    from foon2pddl.retrieval.explain import explain_unreachable

    foon = parse_text(CYCLE_AND_LEAF, "cycle.txt").foon
    text = explain_unreachable(foon, [], resolve_goal(GoalSpec("dough"), foon))
    assert "needs more than" not in text
    assert "every way to make it needs a node that itself needs it" in text
    assert "breaks it: add `nut (whole)` and `starter (active)`" in text


def test_the_shared_apple_cake_from_the_base_kitchen_names_its_cycle_and_what_breaks_it():
    from conftest import SUBGRAPHS

    from foon2pddl.analysis.reachability import reachable
    from foon2pddl.io.inputs import load_network
    from foon2pddl.model.goal import GoalSpec, resolve_goal
    from foon2pddl.model.kitchen import base_kitchen

    r = run("retrieve", SUBGRAPHS, "--goal", "apple cake")
    assert r.exit_code == 1
    assert "needs more than" not in r.stderr
    assert "`foon2pddl check` names the cycle" in r.stderr
    named = r.stderr.split("breaks it: add ", 1)[1].split(";", 1)[0]
    foon = load_network([SUBGRAPHS]).at(3)
    added = {n for n in foon.nodes if f"`{n.describe()}`" in named}
    assert len(added) == named.count("`") // 2 > 0
    goal = resolve_goal(GoalSpec("apple cake"), foon)
    reach = reachable(foon, base_kitchen(foon).nodes | added, goal.candidates)
    assert any(reach.can_make(c) for c in goal.candidates)  # the oracle: the named nodes do make it


def test_the_nodes_no_unit_makes_are_counted_when_not_all_are_named():
    """Stop 55's pass: a kitchen of a knife, a board and `onoin: whole` (a typo) for the guacamole. The reason listed
    10 nodes no unit makes (avocado ... lime) as if they were all, leaving out the onion the typo lost, the salt,
    the spoon and the tomato: `blockers` returns its first 10. The list says how many it leaves out."""
    from foon2pddl.analysis.reachability import blockers, reachable
    from foon2pddl.api import kitchen_of
    from foon2pddl.io.inputs import load_network
    from foon2pddl.model.goal import GoalSpec, resolve_goal
    from foon2pddl.retrieval.explain import explain_unreachable

    net = load_network([]).at(3)
    kit = kitchen_of("onoin: whole", "knife", "cutting board: empty")
    goal = resolve_goal(GoalSpec("guacamole"), net)
    every = blockers(reachable(net, kit.nodes, goal.candidates), goal.candidates, limit=10**6)
    assert len(every) > 10 and "onion (whole)" in {n.describe() for n in every}
    text = explain_unreachable(net, kit.nodes, goal)
    listed = text.split("each needed on some way to it: ", 1)[1]
    assert listed == "; ".join(n.describe() for n in every[:10]) + f"; ... ({len(every) - 10} more)"


def _typo_guacamole():
    """The guacamole with a kitchen of a knife, a board and `onoin: whole` (a typo): 17 nodes no unit makes."""
    from foon2pddl.analysis.reachability import blockers, reachable
    from foon2pddl.api import kitchen_of
    from foon2pddl.io.inputs import load_network
    from foon2pddl.model.goal import GoalSpec, resolve_goal

    net = load_network([]).at(3)
    kit = kitchen_of("onoin: whole", "knife", "cutting board: empty")
    goal = resolve_goal(GoalSpec("guacamole"), net)
    every = blockers(reachable(net, kit.nodes, goal.candidates), goal.candidates, limit=10**6)
    assert len(every) > 10
    return net, kit, goal, "; ".join(n.describe() for n in every[:10]) + f"; ... ({len(every) - 10} more)"


def test_the_librarys_unreachable_reason_counts_the_missing_nodes_it_leaves_out():
    """Stop 55's pass: `complete`'s reason (the library's and the experiment's text) cut the missing nodes at 10
    with no count of the rest, as `explain_unreachable` did before 439d090."""
    from foon2pddl.retrieval.complete import complete

    net, kit, goal, listed = _typo_guacamole()
    detail = complete(net, kit.nodes, goal).detail
    assert detail.endswith("; missing (no unit makes them): " + listed)


def test_the_blocking_reason_counts_the_missing_nodes_it_leaves_out():
    """The same cut in the constrained retrieval's `... even without the constraints` reason."""
    from foon2pddl.api import constraints_of
    from foon2pddl.retrieval.constrained import retrieve_constrained

    net, kit, goal, listed = _typo_guacamole()
    done = retrieve_constrained(net, kit, goal, constraints_of(without=["cilantro"]))
    assert "even without the constraints" in done.result.detail
    assert done.result.detail.endswith("; missing (no unit makes them): " + listed)


# -- stop 57's re-pass -------------------------------------------------------------------------------------

LETTUCE = ROOT / "tests" / "data" / "scene" / "dressed_lettuce.foon"
DRESSED = "bowl: contains {dressing, lettuce}"


@pytest.mark.parametrize("given", [
    ("--instances", "bowl=1"),  # the count option, on the recipe that whisks the dressing while the lettuce waits
    ("--kitchen", "one_bowl.txt"),  # the same count in a kitchen file
])
def test_a_relational_plan_short_of_stated_objects_names_the_step(tmp_path, given):
    """`plan` (relational, the default) with one bowl stated where the recipe needs two at once said only "the
    planner found no plan for the relational encoding ... `--encoding tree`"; the `instances` encoding and a scene
    name the count. The reason names the step that needs the object the stated count leaves out."""
    (tmp_path / "one_bowl.txt").write_text("1 x bowl: empty\nbottle: contains {olive oil}\nolive oil: in [bottle]\n"
                                           "bottle: contains {vinegar}\nvinegar: in [bottle]\nwhisk\nlettuce: chopped\n")
    option, value = given
    value = tmp_path / value if option == "--kitchen" else value
    r = run("plan", LETTUCE, "--goal", DRESSED, option, value)
    assert r.exit_code == 1, r.output
    assert ("reason: FOON's semantics makes the goal, but too few physical objects are given: step 4 (pick-and-place) "
            "needs one more bowl in 'bowl (empty)': the kitchen has 1 there, none free") in r.stderr
    assert "the planner found no plan" not in r.stderr
    # the oracle: one more bowl plans
    assert run("plan", LETTUCE, "--goal", DRESSED, "--instances", "bowl=2").exit_code == 0


def test_a_relational_plan_with_no_object_of_a_needed_label_names_it():
    """`--instances knife=0`: the guacamole cannot be cut (a kitchen file's `0 x knife` is an error naming its line)."""
    r = run("plan", "--goal", "guacamole", "--instances", "knife=0")
    assert r.exit_code == 1, r.output
    assert "too few physical objects are given: step " in r.stderr and "needs one more knife in 'knife'" in r.stderr



def test_a_network_on_standard_input_may_be_the_json_export():
    """`foon2pddl merge --format json | foon2pddl retrieve - --goal guacamole` said `<stdin>:1: error: expected an
    'O', 'S' or 'M' line`, while the same JSON in a `.json` file reads (docs/json-schema.md): `-` reads either."""
    exported = run("merge", "--format", "json")
    assert exported.exit_code == 0
    r = CliRunner().invoke(main, ["retrieve", "-", "--goal", "guacamole"], input=exported.stdout)
    assert r.exit_code == 0, r.output
    assert "task tree for guacamole (contains {avocado, cilantro, lime juice, onion, salt, tomato}, in [bowl]): " \
           "20 units" in r.stdout
    bad = CliRunner().invoke(main, ["stats", "-"], input='{"format": "foon2pddl.foon", "version": 1, "units": [1]}')
    assert bad.exit_code == 2 and bad.stderr.startswith("<stdin>:1: error: units[0]")


def test_an_instances_count_beats_the_kitchen_count_in_the_relational_reason(tmp_path):
    """`--instances` is stated after the kitchen's count and wins over it (`instance_counts.derive_counts`: override,
    then the kitchen's count): with `1 x bowl` in the kitchen file, `bowl=2` and `lettuce=0`, the reason named the
    kitchen's one bowl at step 4, which the option had raised, not the lettuce the option left out."""
    (tmp_path / "one_bowl.txt").write_text("1 x bowl: empty\nbottle: contains {olive oil}\nolive oil: in [bottle]\n"
                                           "bottle: contains {vinegar}\nvinegar: in [bottle]\nwhisk\nlettuce: chopped\n")
    r = run("plan", LETTUCE, "--goal", DRESSED, "--kitchen", tmp_path / "one_bowl.txt",
            "--instances", "bowl=2", "--instances", "lettuce=0")
    assert r.exit_code == 1, r.output
    assert "too few physical objects are given: step " in r.stderr and "needs one more lettuce in " in r.stderr
    assert "one more bowl" not in r.stderr


@pytest.mark.parametrize(("goal", "said"), [
    ("onion: choped", "state 'choped' is on no produced 'onion' node (close: chopped)"),
    ("guacamole: in [bowel]", "state 'in [bowel]' is on no produced 'guacamole' node (close: in [bowl])"),
])
def test_a_goal_state_typed_slightly_wrong_names_the_close_state(goal, said):
    """`plan --goal "onion: choped"` listed eight produced state combinations and left the reader to spot
    `chopped` among them; a label typed wrong gets `close matches:`. A state typed wrong gets them too."""
    r = run("plan", "--goal", goal)
    assert r.exit_code == 2
    assert said in r.stderr and "produced states include: " in r.stderr
    assert "Traceback" not in r.output


def test_retrieve_json_says_where_a_goal_it_cannot_make_goes():
    """`retrieve --goal lemonade --format json` (no lemon in the example kitchen) printed nothing on standard output,
    exit 1, the reason on stderr; `plan --format json` prints a document with `status` and `reason`. A script reading
    the JSON got empty input, and retrieval.md's `json` named only a tree's fields. Since stop 61 it prints a
    document of its own (tests/test_newcomer_json.py); the page names its keys, and `--format jsonl` gives the row."""
    r = run("retrieve", "--goal", "lemonade", "--format", "json")
    assert r.exit_code == 1 and json.loads(r.stdout)["status"] == "unreachable"
    row = json.loads(run("retrieve", "--goal", "lemonade", "--format", "jsonl").stdout)
    assert row["status"] == "unreachable" and "add `lemon (whole)`" in row["reason"]
    page = " ".join((ROOT / "docs" / "retrieval.md").read_text().split())
    assert ("A goal with no tree gives a document of its own (exit 1): `goal`, `status` and `reason` (the batch "
            "row's, below: the words the text output prints after `cannot make ...:`), `method`, `hints` (the words "
            "of the text output's `hint:` lines) and `additions`") in page
    assert "`--format jsonl` gives its row for one goal too" in page


def test_scene_md_says_which_scene_objects_the_compiled_problem_declares(tmp_path):
    """scene.md said the relational task's `:init` is the scene, "with `(in h x)` / `(on h x)` for every `in`/`on`";
    `compile --kitchen whipped_cream_scene.json --encoding relational` wrote a problem with five objects, no fridge,
    no counter and no holder fact (docs/pddl.md, "Objects the problem leaves out"); `--no-prune` writes them all.
    The page says so, and both halves hold."""
    page = " ".join((ROOT / "docs" / "scene.md").read_text().split())
    assert ("the PDDL problem `compile` writes declares only the objects an action can touch (the whipped cream's: "
            "`bowl_1`, `mixing_bowl_1`, `sugar_1` and the two the plan makes), with their facts") in page
    scene = ROOT / "tests" / "data" / "scene" / "whipped_cream_scene.json"
    goal = "whipped cream: whipped, in [bowl]"
    for extra, out in (((), "pruned"), (("--no-prune",), "whole")):
        r = run("compile", "--kitchen", scene, "--goal", goal, "--encoding", "relational", *extra, "-o", tmp_path / out)
        assert r.exit_code == 0, r.output
    pruned = (tmp_path / "pruned" / "problem.pddl").read_text()
    objects = pruned.split("(:objects")[1].split(")")[0].split()
    assert [o for o in objects if o != "-"][::2] == ["bowl_1", "mixing_bowl_1", "sugar_1", "heavy_cream_2",
                                                      "whipped_cream_1"]
    whole = (tmp_path / "whole" / "problem.pddl").read_text()
    assert "(in fridge_1 sugar_1)" not in pruned and "(in fridge_1 sugar_1)" in whole


def test_retrieval_md_says_what_a_compile_rows_units_count(tmp_path):
    """`compile --goals FILE -o DIR` printed `compiled 37 ... guacamole` beside `plan`'s `solved 20`: its `units` are
    the compiled task's unit actions (`compile --goal guacamole` says `37 unit actions`), retrieval.md said only
    "functional units". The page says what a `compile` row counts, and it is what `compile` says for one goal."""
    (tmp_path / "goals.txt").write_text("guacamole\n")
    row = json.loads(run("compile", "--goals", tmp_path / "goals.txt", "--format", "jsonl", "-o", tmp_path / "set").stdout)
    one = run("compile", "--goal", "guacamole", "-o", tmp_path / "one")
    assert row["status"] == "compiled" and f"level 3: {row['units']} unit actions" in one.output
    page = " ".join((ROOT / "docs" / "retrieval.md").read_text().split())
    assert "status `compiled`, `units` the task's unit actions, as `compile` says for one goal" in page


@pytest.mark.parametrize("encoding", ["relational", "instances"])
def test_a_count_stated_short_says_one_sentence_under_either_encoding(encoding):
    """`relational` names the step the count runs short at, `instances` the count against the derived one: each in the
    one sentence (`cli.reasons._too_few`), which ends saying what to do about it."""
    r = run("plan", "--goal", "guacamole", "--instances", "knife=0", "--encoding", encoding)
    assert r.exit_code == 1, r.output
    said = next(line for line in r.stderr.splitlines() if line.startswith("reason: "))
    assert said.startswith("reason: FOON's semantics makes the goal, but too few physical objects are given: "), said
    assert "knife" in said and said.endswith(" (raise the count, or drop it to let the count be derived)"), said
