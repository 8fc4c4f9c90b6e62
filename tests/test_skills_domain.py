"""The skill domain and the motion table: what the decomposer relies on, checked on the shipped files."""

from __future__ import annotations

import re
from collections import Counter

import pytest
from conftest import SUBGRAPHS

from foon2pddl.errors import FoonSyntaxError
from foon2pddl.skills.domain import PREDICATES, TRANSPORT, parse_domain, shipped_domain
from foon2pddl.skills.sexpr import SexprError, parse
from foon2pddl.skills.table import coverage, motion_key, parse_table, shipped_table


def test_sexpr_lines_spans_and_errors():
    (top,) = parse("; c\n(a (B c)\n  d)")
    assert top.line == 2 and top.items[1].items == ("b", "c") and top.items[2] == "d"
    assert "(a (B c)\n  d)" == "; c\n(a (B c)\n  d)"[top.start:top.end]
    with pytest.raises(SexprError) as exc:
        parse("(a\n(b)")
    assert exc.value.line == 1
    with pytest.raises(SexprError):
        parse("(a))")


def test_shipped_domain_declares_the_vocabulary_and_every_required_skill():
    d = shipped_domain()
    names = set(d.by_name)
    required = {"pick", "place", "pour", "put-in", "take-out", "stir", "mix", "cut", "chop", "slice", "dice",
                "spread", "open", "close", "turn-on", "turn-off", "wash"}
    assert required <= names
    assert set(d.skills) == {d.constant(a) for a in names}
    assert all(a.params[0][1] == "hand" and a.cost_span is not None for a in d.actions)


def test_shipped_domain_parses_with_the_pddl_package_and_unified_planning(tmp_path):
    from pddl import parse_domain as pddl_domain
    from unified_planning.io import PDDLReader

    path = tmp_path / "skills.pddl"
    path.write_text(shipped_domain().text)
    assert len(pddl_domain(str(path)).actions) == len(shipped_domain().actions)
    reader = PDDLReader()
    assert reader.parse_problem(str(path)) is not None


def test_pruned_domain_keeps_the_exact_text_of_kept_actions_and_writes_costs():
    d = shipped_domain()
    text = d.pruned({*TRANSPORT, "pour"}, {"pour": 7})
    kept = parse_domain(text, "pruned")
    assert [a.name for a in kept.actions] == [*TRANSPORT, "pour"]
    pour = kept.by_name["pour"]
    assert text[pour.cost_span[0]:pour.cost_span[1]] == "(increase (total-cost) 7)"
    pick = d.by_name["pick"]
    assert d.text[pick.span[0]:pick.span[1]] in text


@pytest.mark.parametrize("cut, message", [
    ("(unmade ?o - thing)", "predicate unmade"),
    ("sk-pour ", "sk-pour - skill"),
    ("(:types hand thing phase skill)", "types hand, thing, phase, skill"),
])
def test_a_domain_missing_what_the_decomposer_writes_is_rejected_with_its_line(cut, message):
    text = shipped_domain().text
    assert cut in text
    with pytest.raises(FoonSyntaxError) as exc:
        parse_domain(text.replace(cut, "", 1), "my.pddl")
    assert message in str(exc.value) and exc.value.path == "my.pddl" and exc.value.line > 1


def test_a_domain_without_a_transport_skill_is_rejected():
    d = shipped_domain()
    with pytest.raises(FoonSyntaxError, match="transport skill take-out"):
        parse_domain(d.pruned(set(d.by_name) - {"take-out"}), "x.pddl")


def test_predicates_match_the_shipped_declarations():
    text = shipped_domain().text
    for name, arity in PREDICATES.items():
        decl = re.search(rf"\({re.escape(name)}((?: \?\w+ - \w+)*)\)", text)
        assert decl is not None and decl.group(1).count("?") == arity, name


def test_table_normalizes_labels_and_rejects_bad_entries():
    t = parse_table('{"motions": {"Pour ": "pour", "mix*": "Mix"}}', "t.json")
    assert t.skill_of("pour*") == "pour" and t.skill_of("MIX") == "mix" and t.skill_of("fold") is None
    assert motion_key(" Scoop  and pour* ") == "scoop and pour"
    with pytest.raises(FoonSyntaxError, match="unknown key"):
        parse_table('{"motions": {}, "motion": 1}', "t.json")
    with pytest.raises(FoonSyntaxError) as exc:
        parse_table('{"motions": {\n"pour": ""}}', "t.json")
    assert exc.value.line == 2
    with pytest.raises(FoonSyntaxError, match="mapped twice"):
        parse_table('{"motions": {"pour": "pour", "Pour": "sprinkle"}}', "t.json")


def test_every_skill_of_the_shipped_table_is_in_the_shipped_domain():
    shipped_table().check(shipped_domain())
    bad = parse_table('{"motions": {"juggle": "juggle"}}', "t.json")
    with pytest.raises(FoonSyntaxError, match="juggle"):
        bad.check(shipped_domain())


def _subgraph_motions():
    out = []
    for path in sorted(SUBGRAPHS.glob("*.txt")):
        out += [line.split("\t")[1] for line in path.read_text().splitlines() if line.startswith("M")]
    return out


def test_table_covers_the_shared_subgraphs_motions_by_frequency():
    motions = _subgraph_motions()
    cov = coverage(motions, shipped_table())
    assert cov.total == len(motions) > 1900
    # independent count: the ten most frequent motions (composite marks dropped) all map
    top = Counter(m.strip().lower().removesuffix("*") for m in motions).most_common(10)
    assert all(shipped_table().skill_of(m) is not None for m, _ in top)
    assert cov.share >= 0.99 and cov.counts[0] == ("pour", top[0][1])
