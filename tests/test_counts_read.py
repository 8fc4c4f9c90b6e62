"""Counts in messages read as a sentence says them (issue 24, newcomer passes nc51a N5 and nc52a): `1 units`,
`1 files`, `1 node(s)` and `1 connected component(s)` were printed wherever a count happened to be one."""

from __future__ import annotations

import re

import pytest
from click.testing import CliRunner
from conftest import SUBGRAPHS

from foon2pddl.cli import main
from foon2pddl.model.words import count, plural, prose_list

#: A count of one with a plural noun, or a noun hedged with `(s)`.
WRONG = re.compile(r"(?<![\d.,])1 (?:[a-z-]+ )?(?:units|objects|nodes|steps|files|labels|motions|components|goals|"
                   r"skills|categories|candidates|cells|substitutions|additions)\b|\w\(s\)")

ONE_UNIT = "O\tbowl\t0\nS\tempty\nM\tpour\t<Assumed>\t<Assumed>\nO\tbowl\t0\nS\tfull\n//\n"


def run(*args: str):
    return CliRunner().invoke(main, [str(a) for a in args])


@pytest.mark.parametrize(("n", "noun", "said"), [
    (1, "unit", "1 unit"), (0, "unit", "0 units"), (2, "plan step", "2 plan steps"), (3, "category", "3 categories"),
    (2, "day", "2 days"), (2, "match", "2 matches"), (1845, "unit", "1845 units")])
def test_count(n, noun, said):
    assert count(n, noun) == said


def test_grouped_count_and_bare_plural():
    assert count(1845, "unit", grouped=True) == "1,845 units"
    assert plural(1, "node") == "node" and plural(7, "node") == "nodes"


def test_a_list_reads_as_prose_one_way():
    """`a, b and c`: the recipe words (io/recipe_words, dbd1282) and `retrieve`'s kitchen additions
    (retrieval/explain) each wrote this joiner; both now say a list through `prose_list`."""
    assert [prose_list(list("abc")[:n]) for n in (1, 2, 3)] == ["a", "a and b", "a, b and c"]


@pytest.fixture
def one_unit(tmp_path):
    path = tmp_path / "one.foon"
    path.write_text(ONE_UNIT)
    return path


@pytest.mark.parametrize("args", [
    ("retrieve", "--goal", "avocado"),                       # complete: 1 units; task tree ...: 1 units
    ("retrieve", "--goal", "lemonade"),                      # none of the 1 node(s) matching 'lemonade'
    ("plan", "--goal", "avocado", "--encoding", "tree"),     # 1 plan steps, 1 units
    ("merge", "{one}"),                                      # universal FOON: level 3, 1 units, 2 object nodes
    ("stats", "{one}"),                                      # units per source file (1 files)
    ("analyze", "{one}"),                                    # 1 object labels, 1 motions, 1 units; 1 connected component(s)
    ("retrieve", SUBGRAPHS, "--goal", "french toast (in [pan], partly cooked)", "--without-motion", "pour",
     "--explain"),                                           # avoided 1 unit(s) of the unconstrained tree
], ids=["retrieve one unit", "one candidate", "plan one step", "merge", "stats", "analyze", "explain"])
def test_a_count_of_one_reads_singular(one_unit, args):
    r = run(*(str(a).replace("{one}", str(one_unit)) for a in args))
    assert r.exit_code in (0, 1), r.output
    said = r.stdout + r.stderr
    assert not WRONG.findall(said), said
