"""The options over physical objects (`--instances`, `--category-types`, `--restore` of compile and plan):
read and checked once, before anything is loaded, so none is ignored under an encoding without objects."""

from __future__ import annotations

import click

from ..errors import UsageError

#: How a bad `--instances` value is reported: `Invalid value for '--instances': ...`, as every option's value is.
_HINT = "'--instances'"

instances_option = click.option("--instances", "instances", multiple=True, metavar="LABEL=N",
                                help="instances and relational encodings: N objects of LABEL in each place one "
                                     "can start (overrides the derived count; repeatable).")
category_types_option = click.option("--category-types", "category_types", is_flag=True,
                                     help="instances and relational encodings: declare each label's type under its "
                                          "categories from the shipped category index (FOON-GEN's).")


def parse_instances(items) -> tuple[tuple[str, int], ...]:
    """`--instances LABEL=N` values as (normalized label, N), sorted; click's bad-parameter error when malformed."""
    from ..model.foon import normalize_label

    out: dict[str, int] = {}
    for item in items:
        label, sep, count = item.rpartition("=")
        if not sep or not normalize_label(label) or not count.strip().isdigit():
            raise click.BadParameter(f"{item!r} is not LABEL=N (a label, then a count N >= 0)", param_hint=_HINT)
        out[normalize_label(label)] = int(count)
    return tuple(sorted(out.items()))


def check_physical_options(encoding: str, restore: bool, instances: tuple[str, ...], category_types: bool) -> None:
    """`--restore`, `--instances` and `--category-types` refused (UsageError) under an encoding without physical
    objects (they would be ignored), and `--instances` read (`parse_instances`), all before a note is printed."""
    from ..pddl.compile import encoding_named

    if encoding_named(encoding).physical:
        parse_instances(instances)
    elif restore:
        raise UsageError(f"--restore needs a physical encoding (relational, instances), not {encoding}")
    elif instances:
        raise UsageError(f"--instances counts the objects of --encoding instances or relational; {encoding} has none")
    elif category_types:
        raise UsageError(f"--category-types types the objects of --encoding instances or relational; {encoding} "
                         "has none")


def checked_instances(items, encoding: str, foon) -> tuple[tuple[str, int], ...]:
    """`parse_instances` of `items` (the encoding is checked by `check_physical_options`), refused (click's
    bad-parameter error) for a label no node of `foon` has (a typo would otherwise be ignored), naming close labels."""
    import difflib

    if not items:
        return ()
    parsed = parse_instances(items)
    labels = sorted({n.label for n in foon.nodes})
    for label, _ in parsed:
        if label not in labels:
            close = difflib.get_close_matches(label, labels, n=3)
            raise click.BadParameter(f"no object of the network is labelled {label!r}"
                                     + (f"; close matches: {', '.join(close)}" if close else ""), param_hint=_HINT)
    return parsed


def category_chains(foon) -> tuple[tuple[str, tuple[str, ...]], ...]:
    """Label -> its category chain (most specific first) from the shipped category index, for PDDL supertypes."""
    from ..generalize.categories import load_index

    index = load_index()
    labels = sorted({n.label for n in foon.nodes})
    return tuple((label, (cat, *index.ancestors(cat))) for label in labels if (cat := index.choose(label)))
