"""`foon2pddl goals`: the goal candidates of a network and whether the kitchen can make each."""

from __future__ import annotations

import json

import click

from ..io.inputs import load_kitchen, load_network
from ..io.jsonio import node_to_dict
from ..model.foon import Foon
from ..retrieval import Reachability, reachable
from . import main
from .options import emit, kitchen_option, level_option, output_option, paths_argument


def goal_rows(foon: Foon, reach: Reachability) -> list[dict]:
    """One row per node some unit produces (sorted): reachable, its round, whether it is a recipe's dish."""
    dishes = {n for u in foon.units for n in u.outputs if n.dish is not None}
    rows = []
    for node in sorted(foon.producers):
        r = reach.round_of(node)
        rows.append({"goal": node.describe(), "node": node_to_dict(node), "reachable": r is not None,
                     "round": r, "dish": node in dishes})
    return rows


def format_rows(rows: list[dict], kitchen_source: str) -> str:
    """Text table: `yes   3  * node` (round; `*` marks a dish), then a summary line."""
    lines = [f"{'yes' if r['reachable'] else 'no':<4}{'' if r['round'] is None else r['round']:>4}  "
             f"{'*' if r['dish'] else ' '} {r['goal']}" for r in rows]
    made = sum(r["reachable"] for r in rows)
    lines.append(f"{made} of {len(rows)} goal candidates can be made from {kitchen_source} "
                 "(round = sequential steps needed; * = a recipe's dish)")
    return "\n".join(lines) + "\n"


@main.command("goals")
@paths_argument
@kitchen_option
@level_option
@click.option("--json", "as_json", is_flag=True, help="Machine-readable JSON output.")
@output_option
def goals(paths, kitchen, level, as_json, output) -> None:
    """List the goal candidates (nodes some unit produces) and whether the kitchen can make each."""
    net = load_network(paths)
    foon = net.at(level)
    kit = load_kitchen(kitchen, net, level)
    rows = goal_rows(foon, reachable(foon, kit.nodes))
    source = kit.source or "the kitchen"
    if as_json:
        data = {"level": level, "kitchen": source, "reachable": sum(r["reachable"] for r in rows),
                "total": len(rows), "goals": rows}
        emit(json.dumps(data, indent=2, ensure_ascii=False) + "\n", output)
    else:
        emit(format_rows(rows, source), output)
