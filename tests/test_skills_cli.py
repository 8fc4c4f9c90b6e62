"""`plan --skills`: skill plans on the command line, robot profiles, micro problem files, bad input."""

from __future__ import annotations

import json
import re
import sys

import pytest
from click.testing import CliRunner

from foon2pddl.cli import main
from foon2pddl.skills.domain import shipped_domain


def run(*args):
    result = CliRunner().invoke(main, ["plan", *args])
    assert result.exception is None or isinstance(result.exception, SystemExit), result.exception
    return result


def test_skills_print_every_macro_step_with_its_skills():
    result = run("--goal", "whipped cream", "--skills")
    assert result.exit_code == 0, result.output
    out = result.stdout.splitlines()
    m = re.match(r"skill plan \(foon-skills, 1 hand\): (\d+) macro steps, (\d+) decomposed", out[0])
    assert m and m.group(1) == m.group(2) and out[0].endswith("skill replay valid")
    heads = [line.split(" [")[0] for line in out if line[:1].isdigit()]
    assert heads[:3] == ["1. pour", "2. pour", "3. whisk"] and len(heads) == int(m.group(1))
    assert "   pick whisk_1 from workspace" in out and "   place whisk_1 on workspace" in out
    assert all(out[k + 1].startswith("   FOON: ") for k, line in enumerate(out) if line[:1].isdigit())
    assert "skills" in result.stderr.splitlines()[-1]


def test_json_gives_a_skill_list_an_executive_can_consume():
    result = run("--goal", "guacamole", "--skills", "--format", "json")
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    assert data["ok"] and data["replay"] == {"ok": True, "problems": []}
    skills = data["skills"]
    names = {a.name for a in shipped_domain().actions}
    assert skills and all(s["skill"] in names for s in skills)
    assert all(len(s["objects"]) == len(s["holders"]) and s["unit"].rsplit(":", 1)[1].isdigit() for s in skills)
    assert [s["macro_step"] for s in skills] == sorted(s["macro_step"] for s in skills)
    assert {s["macro_step"] for s in skills} == set(range(1, data["macro_steps"] + 1))
    pours = [s for s in skills if s["skill"] == "pour"]
    assert pours and all(p["holders"][0] == p["hand"] for p in pours)  # the source is in the hand
    assert data["steps"][0]["status"] == "decomposed"


def test_output_dir_holds_the_domain_and_one_problem_per_step_that_other_parsers_read(tmp_path):
    from pddl import parse_domain, parse_problem
    from unified_planning.io import PDDLReader

    out = tmp_path / "micro"
    result = run("--goal", "whipped cream", "--skills", "-o", str(out))
    assert result.exit_code == 0, result.output
    steps = int(re.search(r"(\d+) macro steps", (out / "skills.txt").read_text()).group(1))
    assert sorted(p.name for p in out.iterdir()) == ["domain.pddl", "skills.txt",
                                                     *(f"step-{k:03d}.pddl" for k in range(1, steps + 1))]
    assert result.stdout == ""
    for step in sorted(out.glob("step-*.pddl")):
        parse_domain(str(out / "domain.pddl"))
        assert parse_problem(str(step)).name.startswith("step-")
        assert PDDLReader().parse_problem(str(out / "domain.pddl"), str(step)) is not None


def _pourless(paths, goal, *network):
    """(native retrieval under --without-motion pour, plan --skills --without-skill pour --format json)."""
    native = CliRunner().invoke(main, ["retrieve", *paths, "--goal", goal, *network, "--without-motion", "pour"])
    return native, run(*paths, "--goal", goal, *network, "--skills", "--without-skill", "pour", "--format", "json")


def _blocking(text, option="without-motion pour"):
    return re.search(rf"every way to make ('[^']+') needs `{option}`", text)


@pytest.mark.parametrize(("goal", "network"), [("whipped cream", ()), ("guacamole", ()),
                                               ("lemonade", ("--network", "exp"))])
def test_a_robot_without_pour_gets_the_blocking_node_native_retrieval_names_under_the_option_given(goal, network):
    native, result = _pourless((), goal, *network)
    assert native.exit_code == 1 and _blocking(native.stderr), native.output  # every example dish pours
    assert result.exit_code == 1 and json.loads(result.stdout)["status"] == "unsolvable"  # one JSON document
    assert _blocking(result.stderr, "without-skill pour").group(1) == _blocking(native.stderr).group(1)
    assert _blocking(json.loads(result.stdout)["reason"], "without-skill pour").group(1) == _blocking(
        native.stderr).group(1)
    assert "without-motion" not in result.stderr  # the user gave --without-skill, not --without-motion
    assert "constraints to relax: `without-skill pour`\n" in result.stderr


def test_a_skill_ban_with_no_way_left_names_the_skill_once():
    result = run("--goal", "french toast", "--skills", "--without-skill", "pour")
    assert result.exit_code == 1, result.output
    excluded = [line for line in result.stderr.splitlines() if "left by the constraints" in line]
    assert not excluded or excluded[0].endswith("(without-skill pour)"), excluded
    assert "without-motion" not in result.stderr, result.stderr


MELT = """O	bowl	0
S	empty
O	water	1
S	in	[cup]
M	pour
O	bowl	0
S	contains	{water}
O	water	1
S	in	[bowl]
//
O	bowl	0
S	empty
O	ice	1
S	frozen
M	pick-and-place
O	bowl	0
S	contains	{ice}
O	ice	1
S	in	[bowl]
S	frozen
//
O	bowl	0
S	contains	{ice}
O	ice	1
S	in	[bowl]
S	frozen
M	sit
O	bowl	0
S	contains	{water}
O	water	1
S	in	[bowl]
//
"""


def test_a_robot_without_pour_gets_a_plan_without_pour_where_native_retrieval_finds_one(tmp_path):
    net = tmp_path / "melt.txt"
    net.write_text(MELT)
    native, result = _pourless((str(net),), "water (in [bowl])")
    assert native.exit_code == 0 and "pour" not in native.stdout and "sit " in native.stdout
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    assert data["ok"] and [s["motion"] for s in data["steps"]] == ["pick-and-place", "sit"]
    assert not [s for s in data["skills"] if s["skill"] == "pour"] and data["skills"]
    with_pour = json.loads(run(str(net), "--goal", "water (in [bowl])", "--skills", "--format", "json").stdout)
    assert "pour" in [s["skill"] for s in with_pour["skills"]]  # the ban, not the network, removes the pour


def test_without_skills_in_a_constraints_file_ban_the_motions_of_plain_plans(tmp_path):
    profile = tmp_path / "robot.json"
    profile.write_text('{"without_skills": ["beat"], "skill_costs": {"pick": 3}}')
    plain = run("--goal", "whipped cream")
    result = run("--goal", "whipped cream", "--constraints", str(profile))
    assert "whisk" in plain.stdout and plain.exit_code == 0
    assert result.exit_code == 0 and "whisk" not in result.stdout  # whisk maps to beat: the electric mixer instead
    assert ". mix " in result.stdout


def test_bad_skill_domain_is_a_located_error_and_no_output_is_written(tmp_path):
    bad = tmp_path / "mine.pddl"
    bad.write_text(shipped_domain().text.replace("(unmade ?o - thing)", ""))
    out = tmp_path / "dir"
    result = run("--goal", "whipped cream", "--skills", "--skill-domain", str(bad), "-o", str(out))
    assert result.exit_code == 2 and f"{bad}:" in result.stderr and "error: " in result.stderr
    assert "Traceback" not in result.output and not out.exists()


def test_skills_need_an_encoding_with_objects_and_one_goal():
    result = run("--goal", "whipped cream", "--skills", "--encoding", "tree")
    assert result.exit_code == 2 and "physical objects" in result.stderr
    result = run("--goals", "whipped cream,guacamole", "--skills")
    assert result.exit_code == 2


def test_the_api_returns_the_skill_list_the_cli_prints():
    import foon2pddl as fp

    net = fp.load_network()
    done = fp.skill_plan(net, fp.load_kitchen(net), "whipped cream")
    cli = json.loads(run("--goal", "whipped cream", "--skills", "--format", "json").stdout)
    assert done.json()["skills"] == cli["skills"] and done.json()["steps"][0]["unit"] == cli["steps"][0]["unit"]
    assert done.trace is not None and len(done.trace.steps) == cli["macro_steps"]


def test_a_lacked_skill_the_domain_does_not_have_is_an_error_with_close_names(tmp_path):
    typo = run("--goal", "whipped cream", "--skills", "--without-skill", "puor")
    assert typo.exit_code == 2
    assert "no such skill" in typo.stderr and "did you mean pour" in typo.stderr
    profile = tmp_path / "robot.json"
    profile.write_text('{"without_skills": ["stirr"]}')
    in_file = run("--goal", "whipped cream", "--skills", "--constraints", str(profile))
    assert in_file.exit_code == 2 and "'stirr'" in in_file.stderr


def test_skills_is_a_flag_so_paths_after_it_are_the_network():
    from conftest import ROOT

    example = ROOT / "foon2pddl" / "data" / "example"
    after = run("--goal", "whipped cream", "--skills", str(example), "--format", "json")
    before = run(str(example), "--goal", "whipped cream", "--skills", "--format", "json")
    assert after.exit_code == 0, after.output
    assert json.loads(after.stdout)["skills"] == json.loads(before.stdout)["skills"]


def test_a_skill_domain_after_skills_is_a_usage_error_naming_skill_domain(tmp_path):
    mine = tmp_path / "mine.pddl"
    mine.write_text(shipped_domain().text)
    result = run("--goal", "whipped cream", "--skills", str(mine))
    assert result.exit_code == 2 and "--skill-domain FILE" in result.stderr and str(mine) in result.stderr
    assert "Traceback" not in result.output
    ok = run("--goal", "whipped cream", "--skills", "--skill-domain", str(mine), "--format", "json")
    assert ok.exit_code == 0 and json.loads(ok.stdout)["domain"] == str(mine)


def test_skill_options_without_skills_are_usage_errors_not_ignored(tmp_path):
    mine = tmp_path / "mine.pddl"
    mine.write_text(shipped_domain().text)
    for extra in (("--skill-domain", str(mine)), ("--hands", "2")):
        result = run("--goal", "whipped cream", *extra)
        assert result.exit_code == 2 and extra[0] in result.stderr and "with --skills" in result.stderr


@pytest.mark.parametrize("fmt", ["dot", "svg", "foon", "csv"])
def test_a_format_the_skill_plan_has_no_form_in_is_a_usage_error_naming_the_supported_ones(fmt, tmp_path):
    out = tmp_path / "dir"
    result = run("--goal", "whipped cream", "--skills", "--format", fmt, "-o", str(out))
    assert result.exit_code == 2 and f"--format {fmt}" in result.stderr
    assert "steps, recipe or json" in result.stderr and not out.exists()


def test_recipe_says_each_step_then_the_robot_skills_in_words():
    result = run("--goal", "whipped cream", "--skills", "--format", "recipe")
    assert result.exit_code == 0, result.output
    out = result.stdout.splitlines()
    data = json.loads(run("--goal", "whipped cream", "--skills", "--format", "json").stdout)
    assert out[0].startswith("skill plan (foon-skills, 1 hand): ") and out[0].endswith("skill replay valid")
    steps, robot = out[1::2], out[2::2]
    assert len(steps) == len(robot) == data["macro_steps"]
    assert steps[0] == "1. pour heavy cream from the carton into the mixing bowl (empty)"
    assert robot[0] == ("   robot: pick up the carton from the workspace; pour from the carton into the mixing bowl; "
                        "put the carton on the workspace")
    assert robot[1].endswith("pour the sugar into the mixing bowl")  # sugar stands free: it is itself poured
    per_step = [sum(s["macro_step"] == k for s in data["skills"]) for k in range(1, data["macro_steps"] + 1)]
    assert [line.count("; ") + 1 for line in robot] == per_step
    assert "_1" not in result.stdout  # labels, not trace ids, where no label is shared


def test_recipe_numbers_objects_that_share_a_label():
    result = run("--goal", "guacamole", "--skills", "--format", "recipe")
    assert result.exit_code == 0, result.output
    out = result.stdout
    assert len(set(re.findall(r"the cutting board (\d+)", out))) >= 2  # several boards, each named by its number
    robot = "\n".join(line for line in out.splitlines() if line.strip().startswith("robot:"))
    assert not re.search(r"the cutting board(?! \d)", robot)  # in the robot's words, always
    for food in ("onion", "tomato", "cilantro"):  # what is put on a board is picked up from that board (which
        put = re.findall(rf"put the {food} on the cutting board (\d+)", out)  # board: the plan's choice)
        took = re.findall(rf"pick up the {food} from the cutting board (\d+)", out)
        assert len(put) == 1 and took == put, (food, put, took)


@pytest.mark.parametrize("encoding", ["relational", "instances"])
def test_french_toast_dips_the_bread_into_the_custard_not_the_custard_into_the_bread(encoding):
    result = run("--goal", "french toast", "--skills", "--encoding", encoding, "--format", "recipe")
    assert result.exit_code == 0 and "skill replay valid" in result.stdout, result.output
    lines = result.stdout.splitlines()
    robot = lines[next(k for k, line in enumerate(lines) if re.match(r"\d+\. dip bread", line)) + 1]
    assert re.fullmatch(r"   robot: pick up the bread from the workspace; dip the bread into the bowl( \d+)?; "
                        r"put the bread on the workspace", robot), robot
    assert "abstract" not in result.stderr, result.stderr  # every step has a skill: melt heats the butter
    melt = lines[next(k for k, line in enumerate(lines) if re.match(r"\d+\. melt butter", line)) + 1]
    assert melt == "   robot: heat the butter", melt


@pytest.mark.parametrize(("code", "status", "exit_code"), [(12, "gave up", 1), (10, "unsolvable", 1), (40, "error", 2)])
def test_skills_exit_as_plan_does_for_a_planner_that_gives_up_proves_or_fails(code, status, exit_code):
    # docs/planning.md: `gave up` exits 1 like `unsolvable` and `timeout`; only `error` exits 2
    planner = f"{sys.executable} -c 'import sys; sys.exit({code})' {{domain}} {{problem}} {{plan}}"
    plain = run("--goal", "guacamole", "--encoding", "instances", "--planner-cmd", planner)
    skills = run("--goal", "guacamole", "--encoding", "instances", "--skills", "--planner-cmd", planner)
    assert plain.exit_code == skills.exit_code == exit_code, (plain.output, skills.output)
    assert skills.stderr.startswith(f"{status} ")
    # the same account of why there is no plan as `plan` gives
    assert [x for x in skills.stderr.splitlines() if x.startswith("reason: ")] == \
        [x for x in plain.stderr.splitlines() if x.startswith("reason: ")]


@pytest.mark.parametrize("encoding", ["relational", "instances"])
def test_the_french_toast_subgraph_cracks_the_egg_not_the_measuring_cup(encoding):
    from conftest import SUBGRAPHS

    path = str(SUBGRAPHS / "0037-make_quick_french_toast.txt")
    result = run(path, "--goal", "french toast", "--skills", "--encoding", encoding)
    assert result.exit_code == 0 and "skill replay valid" in result.stdout, result.output
    lines = result.stdout.splitlines()
    k = next(k for k, line in enumerate(lines) if re.match(r"\d+\. crack ", line))
    assert lines[k + 2] == "   crack egg_1", lines[k:k + 3]  # was `crack measuring_cup_1`


def test_the_default_skill_plan_falls_back_to_instances_when_the_relational_encoding_finds_none_and_says_so():
    # 0082 (cheese pizza) from the base kitchen: the relational task has no plan (the pour at 0082:240 needs the
    # bowl of fermented dough, which no reachable state holds: holder reachability answers unsolvable), the
    # instances one solves; `plan --skills` answered `unsolvable` where `plan --encoding instances --skills` had a
    # skill plan (0036, 0050, ACT-0009, then 0086 were the example until relational readings solved them)
    from conftest import SUBGRAPHS

    path = str(SUBGRAPHS / "0082-homemade_cheese_pizza.txt")
    goal = ("cheese pizza (contains {flour, mozzarella, olive oil, pizza sauce, salt, sugar, water, yeast}, "
            "on [plate])", "--kitchen", "base")
    result = run(path, "--goal", *goal, "--skills", "--time-limit", "20")
    assert result.exit_code == 0 and "skill replay valid" in result.stdout, result.output
    assert "note: the relational encoding found no plan (" in result.stderr, result.stderr
    assert "under the instances encoding" in result.stderr
    asked = run(path, "--goal", *goal, "--skills", "--encoding", "relational", "--time-limit", "5")
    assert asked.exit_code == 1 and "encoding found no plan" not in asked.stderr, asked.output  # asked for: no fallback


def test_the_relational_task_gets_a_share_of_the_time_limit_when_a_fallback_may_follow(monkeypatch):
    from foon2pddl.skills import run as skills_run

    calls = []
    real = skills_run.plan

    def recording(foon, kitchen, goal, encoding, **options):
        calls.append((encoding, options["time_limit"]))
        return real(foon, kitchen, goal, encoding, **options)

    monkeypatch.setattr(skills_run, "plan", recording)
    assert run("--goal", "whipped cream", "--skills", "--time-limit", "40").exit_code == 0
    assert calls == [("relational", 40 * skills_run.FIRST_SHARE)]  # solved: no fallback
    calls.clear()
    assert run("--goal", "whipped cream", "--skills", "--time-limit", "40", "--encoding", "relational").exit_code == 0
    assert calls == [("relational", 40)]


def test_retrieve_reads_a_lacked_skill_as_one_ban_and_warns_only_when_it_bans_nothing(tmp_path):
    """docs/skills.md: a constraints file's `without_skills` bans the skill's motions for `retrieve` too. The
    table maps pour to nine motions (add, drain, fill, ...); the example network has only pour among them: the
    constraints line counts the ban once, as the user gave it, and there is no warning that the network has no
    `add` (the user did not name it). A skill none of whose motions is in the network gets one warning."""
    profile = tmp_path / "robot.json"
    profile.write_text('{"without_skills": ["pour"]}')
    result = CliRunner().invoke(main, ["retrieve", "--goal", "whipped cream", "--constraints", str(profile)])
    assert result.exit_code == 1, result.output
    constraints = [x for x in result.stderr.splitlines() if x.startswith("constraints: ")]
    assert constraints == ["constraints: `without-skill pour` removes 21 of 101 units"], result.stderr
    assert "warning" not in result.stderr, result.stderr
    profile.write_text('{"without_skills": ["grate"]}')
    result = CliRunner().invoke(main, ["retrieve", "--goal", "whipped cream", "--constraints", str(profile)])
    assert result.exit_code == 0, result.output
    warnings = [x for x in result.stderr.splitlines() if x.startswith("warning: ")]
    assert warnings == ["warning: no unit of the network has a motion the table maps to the skill 'grate' "
                        "(`without-skill grate`)"], result.stderr


def test_a_failed_step_is_said_to_be_kept_abstract():
    """Stop 48's newcomer pass: the cheese pizza's skill plan said `skill replay valid`, exit 0, and then
    `note: step 39 (spread, ...) is failed: ...`, which read as a contradiction. The note says the step failed to
    decompose and is kept as an abstract step, the replay going on from FOON's state after it (docs/skills.md)."""
    from conftest import SUBGRAPHS

    pizza = SUBGRAPHS / "0082-homemade_cheese_pizza.txt"
    r = CliRunner().invoke(main, ["plan", str(pizza), "--goal", "cheese pizza", "--kitchen", "base", "--skills",
                                  "--time-limit", "40"])
    assert r.exit_code == 0, r.stderr
    assert ") is failed:" not in r.stderr
    assert ("0082-homemade_cheese_pizza.txt:394) failed to decompose, kept as an abstract step (the replay goes on "
            "from FOON's state after it): the step lists no tool to spread with") in r.stderr


@pytest.mark.parametrize("args", [("--goal", "guacamole", "--without-skill", "pour"), ("--goal", "lemonade")],
                         ids=["a robot without pour", "no lemon in the kitchen"])
def test_no_second_encoding_is_tried_where_foons_semantics_cannot_make_the_goal(args):
    """`plan --goal guacamole --skills --without-skill pour` said `note: the relational encoding found no plan
    (unsolvable: translator: no relaxed solution); planning with the instances encoding ...`, then `unsolvable`
    again (stop 49's pass): where FOON's semantics cannot make the goal, no encoding can; the reason is given at
    once, from the first encoding's outcome."""
    result = run(*args, "--skills")
    assert result.exit_code == 1, result.output
    assert "instances" not in result.stderr, result.stderr
    assert "\nreason: " in "\n" + result.stderr, result.stderr


def test_a_skill_table_error_names_the_shipped_domain_by_a_path_that_opens(tmp_path):
    """newcomer60: `plan --skills --skill-table my.json` with a skill the domain lacks said `motion 'chop' maps to
    skill 'slash', which <shipped>/skills.pddl does not define`: `<shipped>` is no path a user can open. The shipped
    files are named by their path in the package (`model.where.shown_path`, as the embedded example is), and
    the JSON's `domain` says the same."""
    from conftest import ROOT

    table = tmp_path / "my.json"
    table.write_text(json.dumps({"motions": {"chop": "slash"}}))
    result = run("--goal", "whipped cream", "--skills", "--skill-table", str(table))
    assert result.exit_code == 2, result.output
    said = "which foon2pddl/data/skills/skills.pddl does not define"
    assert said in result.stderr and "<shipped>" not in result.stderr, result.stderr
    assert (ROOT / "foon2pddl" / "data" / "skills" / "skills.pddl").is_file()
    ok = run("--goal", "whipped cream", "--skills", "--format", "json")
    assert ok.exit_code == 0 and json.loads(ok.stdout)["domain"] == "foon2pddl/data/skills/skills.pddl"
