"""The command that lists the goals of this run's network, which an unknown goal's error names."""

from __future__ import annotations

import shlex

import click


def goals_listing(network: str | None = None) -> str:
    """`foon2pddl goals` with the running command's PATHS and `--network` (or `network`: the lifted encoding's
    categories are listed on GEN whatever the run's network): without them it would list the embedded example's
    goals, not those of the network the goal was looked up in (stop 60's newcomer pass)."""
    from ..generalize.network import DEFAULT_NETWORK

    ctx = click.get_current_context(silent=True)
    params = ctx.params if ctx is not None else {}
    network = network or params.get("network") or DEFAULT_NETWORK
    words = ["foon2pddl", "goals", *map(str, params.get("paths") or ())]
    return shlex.join(words + ([] if network == DEFAULT_NETWORK else ["--network", network]))
