"""`bench.pddl_relational`'s plan length per encoding on the dishes every encoding solves (issue 21's note: "plan
length against `instances` and `tree`"), which docs/pddl.md quotes: before, the summary gave each encoding's median
over the dishes it solved, so a dish one encoding misses moved the others' figures, and no total was printed."""

from __future__ import annotations

from bench.pddl_relational import Row, common_steps, summary

ENCODINGS = ("tree", "instances", "relational")


def _row(file: str, encoding: str, steps: int, status: str = "solved") -> Row:
    return Row(file, encoding, status, steps, 0, 0, (), 0.1)


def test_lengths_are_compared_on_the_dishes_every_encoding_solves():
    rows = [_row("a", "tree", 5), _row("a", "instances", 6), _row("a", "relational", 7),
            _row("b", "tree", 9), _row("b", "instances", 11), _row("b", "relational", 12),
            _row("c", "tree", 3), _row("c", "instances", 3), _row("c", "relational", 40, "timeout"),
            _row("d", "tree", 8), _row("d", "instances", 10), _row("d", "relational", 10)]
    assert common_steps(rows, ENCODINGS) == (
        "unit steps on the 3 dishes every encoding solves: tree median 8, total 22; "
        "instances median 10, total 27; relational median 10, total 29")
    assert summary(rows, ENCODINGS).splitlines()[-1] == common_steps(rows, ENCODINGS)


def test_one_encoding_alone_prints_no_comparison_and_none_solved_says_so():
    rows = [_row("a", "relational", 7)]
    assert "every encoding solves" not in summary(rows, ("relational",))
    assert common_steps([_row("a", "tree", 5, "unsolvable"), _row("a", "relational", 7)], ("tree", "relational")) == (
        "on the dishes every encoding solves (0): no plan length to compare")
