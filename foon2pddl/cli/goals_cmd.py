"""`foon2pddl goals`: the goal candidates of a network and whether the kitchen can make each."""

from __future__ import annotations

import json

import click

from ..generalize.network import DEFAULT_NETWORK, NETWORKS
from ..io.jsonio import node_to_dict
from ..model.foon import Foon
from ..model.where import shown_path
from ..model.words import count
from ..retrieval import Reachability, reachable
from . import main
from .loading import load_view
from .options import kitchen_option, level_option, network_option, output_option, paths_argument
from .outputs import emit
from .progress import slow_step


def goal_rows(foon: Foon, reach: Reachability) -> list[dict]:
    """One row per node some unit produces (sorted): reachable, its round, whether it is a recipe's dish."""
    dishes = foon.dishes
    rows = []
    for node in sorted(foon.producers):
        r = reach.round_of(node)
        rows.append({"goal": node.describe(), "node": node_to_dict(node), "reachable": r is not None,
                     "round": r, "dish": node in dishes})
    return rows


def _which_foon(word: str, network: str) -> str:
    """` on FOON-EXP` (`word`, then the network's name) for a network not taken as read; nothing for the one as read:
    the table's legend and the slow step name the network alike."""
    kind = NETWORKS[network]
    return "" if kind.as_read else f" {word} FOON-{kind.label}"


def format_rows(rows: list[dict], kitchen_source: str, network: str = DEFAULT_NETWORK,
                counted: tuple[int, int, str] | None = None) -> str:
    """Text table: the legend and a column header first, then `yes      3  *    node` per goal. The legend counts
    `counted` (made, of how many, what: `goal candidates`, `dishes`) when the rows are only the reachable ones."""
    made, total, what = counted or (sum(r["reachable"] for r in rows), len(rows), "goal candidates")
    net = _which_foon("on", network)
    listed = "; only those are listed" if counted and len(rows) < total else ""
    lines = [f"reachable: {made} of {total} {what} can be made from {kitchen_source}{net}{listed} "
             "(round = sequential steps needed; * = a recipe's dish)",
             f"{'made':<5}{'round':>5}  {'dish':<5}goal"]
    lines += [f"{'yes' if r['reachable'] else 'no':<5}{'' if r['round'] is None else r['round']:>5}  "
              f"{'*' if r['dish'] else '':<5}{r['goal']}" for r in rows]
    return "\n".join(lines) + "\n"


@main.command("goals")
@paths_argument
@kitchen_option
@level_option
@network_option
@click.option("--json", "as_json", is_flag=True, help="Machine-readable JSON output.")
@click.option("--reachable", "only_reachable", is_flag=True,
              help="Only the goals the kitchen can make (pipe into `retrieve --goals -`).")
@click.option("--dishes", "only_dishes", is_flag=True, help="Only the recipes' dishes (the * rows).")
@output_option
def goals(paths, kitchen, level, network, as_json, only_reachable, only_dishes, output) -> None:
    """List the goal candidates (nodes some unit produces) and whether the kitchen can make each.

    With --network exp or gen, the goals of FOON-EXP or FOON-GEN (GEN goals are category-level).
    """
    _, view = load_view(paths, kitchen, level, network)
    foon, kit = view.foon, view.kitchen
    of = _which_foon("of", network)
    # FOON-EXP of the shared subgraphs: 2.3-2.5 s silent after its build at load 8 (stop 58's pass)
    with slow_step(f"finding which of the {count(len(foon.producers), 'goal candidate', grouped=True)}{of} "
                   "the kitchen can make"):
        rows = goal_rows(foon, reachable(foon, kit.nodes))
    if only_dishes:
        rows = [r for r in rows if r["dish"]]
        if not foon.dishes:  # `0 of 0 dishes` alone reads as if none could be made
            click.echo("note: no node of this network is marked as a recipe's dish (an O line's 4th field); "
                       "`goals` without --dishes lists every goal candidate", err=True)
    counted = (sum(r["reachable"] for r in rows), len(rows), "dishes" if only_dishes else "goal candidates")
    if only_reachable:  # the legend still counts every candidate (or dish)
        rows = [r for r in rows if r["reachable"]]
    source = shown_path(kit.source) if kit.source else "the kitchen"  # the embedded one by its path in the package
    what = count(len(rows), "dish" if only_dishes else "goal candidate", grouped=True)
    with slow_step(f"writing the {what}{' as JSON' if as_json else ''}"):  # FOON-EXP's 7,334: 2.3 s at load 9
        if as_json:
            data = {"level": level, "network": network, "kitchen": source,
                    "reachable": counted[0], "total": counted[1], "goals": rows}
            emit(json.dumps(data, indent=2, ensure_ascii=False) + "\n", output)
        else:
            emit(format_rows(rows, source, network, counted), output)
