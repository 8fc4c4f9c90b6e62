"""`categories --extend`: unknown labels join the category of their nearest known label (WordNet)."""

from __future__ import annotations

import json

from click.testing import CliRunner

from foon2pddl.cli import main
from foon2pddl.generalize.categories import Category, CategoryIndex, coverage, parse_index, shipped_index
from foon2pddl.generalize.cook import filing_similarity
from foon2pddl.generalize.extend import assign, by_name, extended_index, file_labels, index_json

FORGOTTEN = ("lime", "strawberry", "salad bowl", "cayenne pepper")


def _without(index: CategoryIndex, labels) -> CategoryIndex:
    return CategoryIndex(tuple(Category(c.name, c.parent, c.description, tuple(m for m in c.members if m not in labels))
                               for c in index.categories))


def test_forgotten_labels_find_their_categories_again(label_similarity):
    full = shipped_index()
    small = _without(full, FORGOTTEN)
    found = {a.label: a for a in file_labels([*FORGOTTEN, "lemon", "xyzzy plorb"], small,
                                             filing_similarity(label_similarity.reader))}
    assert set(found) == {*FORGOTTEN, "xyzzy plorb"}  # known labels are not reassigned
    assert found["lime"].category == full.choose("lime") == "lemons and limes" and found["lime"].how == "name"
    assert found["strawberry"].category == full.choose("strawberry") == "berries"
    assert found["strawberry"].how == "wordnet"
    assert found["salad bowl"].how == "head" and found["salad bowl"].category == full.choose("bowl")
    # WordNet's cayenne pepper (the ground pods, the capsicum) is no kind of the index's pepper, the spice: it joins
    # `peppers` by that category's name, not `ground peppers` by its head (as the cook mode files it, since rv45-5)
    assert (found["cayenne pepper"].category, found["cayenne pepper"].how) == ("peppers", "name")
    assert found["xyzzy plorb"].category is None and found["xyzzy plorb"].how == "none"
    bigger = extended_index(small, found.values())
    assert coverage(FORGOTTEN, bigger).percent == 100.0
    again = parse_index(index_json(bigger), "x.json")  # the written file reads back
    assert again.choose("lime") == "lemons and limes" and len(again) == len(full)


def test_cli_extend_writes_the_index_and_lists_assignments(tmp_path, example):
    small = tmp_path / "small.json"
    small.write_text(index_json(_without(shipped_index(), ("lime", "avocado"))))
    out = tmp_path / "index.json"
    r = CliRunner().invoke(main, ["categories", "--categories", str(small), "--extend", "-o", str(out)])
    assert r.exit_code == 0, r.stderr
    lines = r.stderr.splitlines()
    # the table starts at its header (a loaded machine may print a slow-step line before it)
    lines = lines[lines.index("label\tcategory\tvia\tsimilarity\thow"):]
    rows = {line.split("\t")[0]: line.split("\t") for line in lines[1:-1]}
    assert rows["lime"][1] == "lemons and limes"
    assert "object labels in some category" in lines[-1]
    data = json.loads(out.read_text())
    assert "lime" in data["categories"]["lemons and limes"]["members"]
    check = CliRunner().invoke(main, ["categories", "--categories", str(out), "--check"])
    assert "lime" not in check.stdout.split()


def test_a_hand_is_not_filed_with_the_tools(label_similarity):
    """WordNet's only kitchen-file sense of `hand` is a clock's pointer (an artifact); the cook's overrides
    read it as the body part, which is close to no tool, so an index without a place for it leaves it out
    (listed for review) instead of making it a cutting tool."""
    small = CategoryIndex(tuple(c for c in shipped_index().categories if "hand" not in c.members))
    (found,) = file_labels(["hand"], small, filing_similarity(label_similarity.reader))
    assert found.category is None and found.how == "none"


def test_a_label_ending_in_a_category_name_joins_that_category():
    ix = CategoryIndex((Category("sauces", None, "", ("ketchup",)),
                        Category("pasta and pizza sauces", "sauces", "", ("marinara",)),
                        Category("spices", None, "", ("cumin",)),
                        Category("allium powders", "spices", "", ("garlic powder",)),
                        Category("puddings and custards", None, "", ("flan",)),
                        Category("berries", None, "", ("blueberry",))))
    assert by_name("banana pudding", ix) == "puddings and custards"  # a part's head, singular
    assert by_name("pizza sauce", ix) == "pasta and pizza sauces"  # the longest part it contains
    assert by_name("enchilada sauce", ix) == "sauces"  # no evidence for a refinement: the general one
    assert by_name("curry powder", ix) is None  # `allium powders` needs `allium`
    assert by_name("wild berry", ix) == "berries" and by_name("sauce", ix) == "sauces"
    (found,) = assign(["banana pudding"], ix, sim=lambda a, b: 0.0)
    assert (found.category, found.how) == ("puddings and custards", "name")


def test_cli_extend_files_a_label_as_the_cook_mode_does(tmp_path, label_similarity):
    """`categories --extend` and the cook mode's rule 5 file an unknown label one way (`extend.file_labels`):
    `chili pepper`, a whole WordNet term that is a capsicum, is no kind of the index's `pepper` (the spice),
    so neither files it by its head (review rv45-5: the CLI filed it with ground peppers, the cook mode in
    `peppers`)."""
    from foon2pddl.generalize.cook import CookSimilarity

    foon = tmp_path / "chili.txt"
    foon.write_text("//\nO1\tchili pepper\t1\nS1\twhole\nO2\tknife\t0\nS2\tclean\n"
                    "M1\tslice\tAssumed\tAssumed\nO1\tchili pepper\t0\nS3\tsliced\n//\n", encoding="utf-8")
    out = tmp_path / "index.json"
    r = CliRunner().invoke(main, ["categories", "--extend", str(foon), "-o", str(out)])
    assert r.exit_code == 0, r.stderr
    lines = r.stderr.splitlines()
    rows = {line.split("\t")[0]: line.split("\t") for line in lines[lines.index("label\tcategory\tvia\tsimilarity\thow") + 1:-1]}
    cook = CookSimilarity(label_similarity.reader)
    assert (rows["chili pepper"][1], rows["chili pepper"][4]) == (cook.categories_of("chili pepper")[0], "name") == (
        "peppers", "name")


def test_cli_extend_opens_no_wordnet_when_every_label_has_a_category(tmp_path, monkeypatch):
    """`categories --extend` on a network the index covers said `filing the object labels in no category
    (through WordNet) ...` and opened WordNet for nothing (39 s at load 15; newcomer pass nc50b): with no
    label to file, no WordNet, the index written unchanged and `0 added`."""
    from foon2pddl.generalize import wordnet

    def no_wordnet():
        raise AssertionError("WordNet opened with no label to file")

    monkeypatch.setattr(wordnet, "reader", no_wordnet)
    out = tmp_path / "index.json"
    r = CliRunner().invoke(main, ["categories", "--extend", "-o", str(out)])  # the example: every label filed
    assert r.exit_code == 0, r.output
    assert "through WordNet" not in r.stderr and "(100.0 %; 100.0 % before, 0 added)" in r.stderr, r.stderr
    assert parse_index(out.read_text(), str(out)).categories == shipped_index().categories
