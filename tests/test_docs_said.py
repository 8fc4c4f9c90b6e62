"""What the docs say in prose a command does, it does (stop 46's newcomer pass).

Each test reads the claim from the page itself, so a page that changes the claim is checked again, and runs
the command as a reader types it (from a scratch directory with `tests/` and `docs/` linked in).
"""

from __future__ import annotations

import re
import shlex

import pytest
from click.testing import CliRunner
from conftest import ROOT

from bench.doc_commands import PAGES, prose
from foon2pddl.cli import main


def _prose(page) -> str:
    """A page's text outside fenced blocks, its whitespace runs read as one space (claims wrap lines)."""
    return " ".join(prose(page.read_text()).split())


def _matches(quote: str, line: str) -> bool:
    """Whether `line` is `quote`, each `...` in it standing for any text."""
    return re.fullmatch(".*".join(re.escape(part) for part in quote.split("...")), line) is not None


@pytest.fixture
def reader_dir(tmp_path, monkeypatch):
    for name in ("tests", "docs"):
        (tmp_path / name).symlink_to(ROOT / name)
    monkeypatch.chdir(tmp_path)
    return tmp_path


#: "A goal that resolves to several nodes (`--goal "X"` matches the N ...)": X resolves to N nodes.
_SEVERAL = re.compile(r"several nodes \(`--goal \"([^\"]+)\"` matches the (\w+) ")
_NUMBERS = {"two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "seven": 7, "eight": 8}


def test_a_goal_the_docs_give_as_several_nodes_resolves_to_several(reader_dir):
    """Stop 46's pass: pddl.md said `--goal "whipped cream"` matches every produced whipped-cream node and so
    gets a `reach-goal-<i>` action per candidate; since a bare label is read as the recipe's dish (issue 24
    item 6) it is one node, and the task has no goal action at all. The page's count is checked as it says it
    (stop 47: the test asked for at least two where the page says three)."""
    goals = [m.groups() for page in PAGES for m in _SEVERAL.finditer(_prose(page))]
    assert goals
    for goal, said in goals:
        r = CliRunner().invoke(main, ["compile", "--goal", goal, "-o", "out"])
        assert r.exit_code == 0, r.stderr
        actions = re.findall(r"\(:action reach-goal-\d+", (reader_dir / "out" / "domain.pddl").read_text())
        assert len(actions) == _NUMBERS.get(said, said), (goal, said, r.stderr)  # what the page says (stop 47)


#: "(`plan ...` exits N: `QUOTE`": the command exits N and prints a line that is QUOTE.
_EXITS = re.compile(r"\(`((?:plan|compile|retrieve) [^`]*)` exits (\d+): `([^`]*)`")


def test_a_commands_exit_and_line_the_docs_quote_are_what_it_gives(reader_dir):
    """Stop 46's pass: pddl.md said `plan --costs unit --planner pyperplan` exits 2 with `reason: the task has
    action costs ...`; as shown it has no goal (a usage error), and with one, under `plan`'s default encoding
    (`relational`), the reason opens with the conditional effects pyperplan also refuses."""
    claims = [m.groups() for page in PAGES for m in _EXITS.finditer(_prose(page))]
    assert claims
    for command, status, quote in claims:
        r = CliRunner().invoke(main, shlex.split(command))
        assert r.exit_code == int(status), (command, r.exit_code, r.stderr)
        lines = r.stdout.splitlines() + r.stderr.splitlines()
        assert any(_matches(quote, line) for line in lines), (command, quote, r.stderr)


def test_the_stove_pddl_md_says_instances_leaves_unbound_is_what_plan_gives(reader_dir, monkeypatch):
    """Stop 46's pass: pddl.md said the physical replay's note "after the plan" says the `instances` plan
    melts and fries with another stove than the pan's; the note comes before the plan (stderr, under the
    `solved` line) and names only the first of its disagreements (the maple syrup's bottle). What the page
    says of that command holds: the pan goes on `stove_1`, the melt uses `stove_2`, the note counts the
    disagreements it says, and the fry's unbound stove is among them."""
    import foon2pddl.planners.instance_physical as physical
    from foon2pddl.planners.physical_replay import replay

    text = _prose(ROOT / "docs/pddl.md")
    m = re.search(r"`plan (--goal \"french toast\" --encoding instances --instances stove=2)` (.*?)\)\.", text)
    assert m, "pddl.md no longer shows the french toast's two stoves"
    claim = m.group(2)
    count = re.search(r"counts (\d+) disagreements", claim)
    fry = re.search(r"`(step \d+: fry: [^`]*)`", claim)
    assert count and fry, claim
    seen = []
    note = physical.replay_note

    def recording(task, trace):
        seen.extend(str(d) for d in replay(physical.physical_trace(task, trace).trace).disagreements)
        return note(task, trace)

    monkeypatch.setattr(physical, "replay_note", recording)
    r = CliRunner().invoke(main, ["plan", *shlex.split(m.group(1))])
    assert r.exit_code == 0, r.stderr
    assert "pick-and-place frying_pan_1 with stove_1" in r.stdout and "melt butter_1 with stove_2" in r.stdout
    assert f"finds {count.group(1)} disagreements" in r.stderr, r.stderr
    assert any(fry.group(1) in d for d in seen), seen


#: Rule 3's examples: "container~spoon (8.2 %), baking tray~pot (cooking utensil, 3.7 %), ...".
_BREADTH = re.compile(r"([a-z][a-z ]*)~([a-z][a-z ]*) \((?:([a-z][a-z ]*), )?(\d+\.\d) %\)")


def test_the_breadths_rule_3_gives_are_what_similarity_senses_says():
    """Stop 47's pass: generalization.md's rule 3 said carrot~strawberry meet under produce covering 10.5 % of
    the vocabulary; `foon2pddl similarity carrot strawberry --senses` says 10.3 % (and did at 820d7bc). Each
    example's breadth, and its ancestor when named, is the command's."""
    rule = _prose(ROOT / "docs" / "generalization.md").split("**Broad ancestors rejected.**", 1)[1][:1500]
    examples = _BREADTH.findall(rule)
    assert len(examples) >= 5, examples
    r = CliRunner().invoke(main, ["similarity", "--pairs", "--senses", *(x.strip() for a, b, _, _ in examples
                                                                          for x in (a, b))])
    assert r.exit_code == 0, r.stderr
    for a, b, ancestor, share in examples:
        first, second = sorted((a.strip(), b.strip()))
        said = re.search(rf"^{first} ~ {second}: \S+ ~ \S+ under (\S+)\.n\.\d+ \((?:rejected: )?(?:the )?ancestor "
                         rf"covers (\d+\.\d)% ", r.stdout, re.M)
        assert said, (a, b, r.stdout)
        assert said.group(2) == share, (a, b, said.group(2), share)
        assert not ancestor or said.group(1).replace("_", " ") == ancestor, (a, b, said.group(1), ancestor)


#: "(`similarity --senses A B` lists `LINE`)": the command prints LINE.
_LISTS = re.compile(r"`(similarity --senses [^`]*)` lists `([^`]*)`")


def test_the_senses_a_label_keeps_are_what_similarity_senses_lists():
    """Stop 49's pass (nc49d): generalization.md's rule 1 said the cook mode reads `pot` as no toilet and no
    potentiometer; `similarity --senses` lists `potentiometer.n.02` among pot's senses (a device, one of the
    kitchen artifacts' roots), and pot~potentiometer scores 1.0. The page quotes the command's line."""
    claims = [m.groups() for page in PAGES for m in _LISTS.finditer(_prose(page))]
    assert claims
    for command, line in claims:
        r = CliRunner().invoke(main, shlex.split(command))
        assert r.exit_code == 0, r.stderr
        assert line in r.stdout.splitlines(), (command, line, r.stdout)


def test_generalization_md_goals_solved_are_what_the_kitchen_it_names_reaches(reader_dir):
    """Stop 49's pass (nc49d): the table of goals solved names the universal FOON's default kitchen of 718
    nodes; since a merge of recipes starts from `base` (693 nodes, issue 24 item 7) the reader's `goals
    tests/data/foon-subgraphs --dishes` counts 54 where REG's row says 59. The page gives the command with
    `--kitchen default`; its REG and GEN-native counts are the table's."""
    section = _prose(ROOT / "docs" / "generalization.md").split("**Goals solved**", 1)[1][:1500]
    command = re.search(r"`(goals tests/data/foon-subgraphs --dishes --kitchen default)( --network gen)?`", section)
    assert command, section[:300]
    for network, row in (("reg", "REG (complete retrieval)"), ("gen", "GEN, native retrieval")):
        said = re.search(rf"\| {re.escape(row)} \| (\d+) \|", section)
        assert said, row
        r = CliRunner().invoke(main, [*shlex.split(command.group(1)), "--network", network])
        assert r.exit_code == 0, r.stderr
        assert f"reachable: {said.group(1)} of 100 dishes " in r.stdout, (row, r.stdout[:200])


def test_pddl_md_counts_the_encodings_make_pddl_writes():
    """Stop 49's pass (nc49d): pddl.md said `make pddl` writes a pair "for each encoding", of which there are
    seven; the generator writes the six ground ones (`gen-lifted` plans FOON-GEN, `compile --network gen`)."""
    from foon2pddl.pddl.compile import GROUND_ENCODINGS
    from foon2pddl.pddl.examples import GOALS

    section = _prose(ROOT / "docs" / "pddl.md").split("## `domains/` and `problems/`", 1)[1][:1200]
    m = re.search(r"for each of the (\w+) encodings .*? and each of (\w+) dishes .*? all (\d+) files", section)
    assert m, section[:300]
    encodings, dishes, files = (_NUMBERS.get(x, x) for x in m.groups())
    assert (int(encodings), int(dishes)) == (len(GROUND_ENCODINGS), len(GOALS))
    assert int(files) == 2 * len(GROUND_ENCODINGS) * len(GOALS)


def test_generalization_md_gives_the_command_of_its_exp_goals_solved_rows(reader_dir):
    """Stop 50's and 51's passes (nc50b, nc51b): the table of goals solved named the commands of its REG and GEN
    rows and none for its EXP rows (`goals --network exp --dishes` counts FOON-EXP's own dishes, copies too). The
    page gives the pipeline that asks FOON-EXP for the recipes' dish nodes: run here on one recipe, `goals`' table
    feeds `retrieve --goals -` on FOON-EXP and the batch's count line is what the table's rows read."""
    section = (ROOT / "docs" / "generalization.md").read_text().split("**Goals solved**", 1)[1][:2500]
    stderr = _goals_pipeline_on_one_recipe(section, "retrieve", "exp")
    assert re.search(r"^1 goal: 1 solved", stderr, re.M), stderr


def _goals_pipeline_on_one_recipe(section: str, command: str, network: str) -> str:
    """Runs the page's `foon2pddl goals ... | foon2pddl COMMAND ... --network NETWORK --goals -` pipeline on one
    recipe instead of the 100, and returns the second command's stderr (its batch count line)."""
    m = re.search(rf"^foon2pddl (goals tests/data/foon-subgraphs [^|\n]+) \| foon2pddl ({command} [^\n]+)$", section,
                  re.M)
    assert m, section[:600]
    listing, asking = (shlex.split(c) for c in m.groups())
    assert asking[asking.index("--network") + 1] == network and asking[asking.index("--goals") + 1] == "-", asking
    one = "tests/data/foon-subgraphs/0001-whipped_cream.txt"
    listing, asking = ([one if w == "tests/data/foon-subgraphs" else w for w in c] for c in (listing, asking))
    listed = CliRunner().invoke(main, listing)
    assert listed.exit_code == 0, listed.stderr
    r = CliRunner().invoke(main, asking, input=listed.stdout)
    assert r.exit_code == 0, r.stderr
    return r.stderr


def test_generalization_md_counts_with_the_search_projects_kitchen_are_what_goals_gives(reader_dir):
    """Stop 51's pass (nc51b): with the search project's `kitchen.json` the page said REG solves 1 dish and
    GEN-native 5, its first reading (c01474a), never measured again; `goals --dishes` with that kitchen gives 1
    and 4. The counts the page gives are what it gives."""
    text = _prose(ROOT / "docs" / "generalization.md").split("**Goals solved**", 1)[1]
    m = re.search(r"`kitchen\.json` .*? REG solves (\d+) dish.*? GEN-native (\d+),", text)
    assert m, text[:300]
    for network, said in (("reg", m.group(1)), ("gen", m.group(2))):
        r = CliRunner().invoke(main, ["goals", "tests/data/foon-subgraphs", "--dishes", "--network", network,
                                      "--kitchen", "tests/data/foon-search-inputs/kitchen.json"])
        assert r.exit_code == 0, r.stderr
        assert f"reachable: {said} of 100 dishes " in r.stdout, (network, r.stdout[:200])


def test_generalization_md_gives_the_command_and_commit_of_its_lifted_gen_row(reader_dir):
    """Stop 52's pass (nc52b): the lifted GEN row of the goals-solved table (67, its times per goal) named no
    command and no commit ("measured before round 3's category refinements", from c01474a). The page gives the
    pipeline that plans the recipes' dish nodes on FOON-GEN's lifted PDDL, run here on one recipe, and the row
    names the commit it was measured at."""
    section = (ROOT / "docs" / "generalization.md").read_text().split("**Goals solved**", 1)[1][:4000]
    stderr = _goals_pipeline_on_one_recipe(section, "plan", "gen")
    assert re.search(r"^1 goal: 1 solved \(gen-lifted encoding", stderr, re.M), stderr
    row = re.search(r"^\| GEN, lifted PDDL \(`absent`\) \| \d+ \| (.*)\|$", section, re.M)
    assert row and re.search(r"\bat [0-9a-f]{7}\b", row.group(1)), row
