"""The parameters an experiment can sweep, one registry entry each.

A sweep (`--sweep NAME=V1,V2,...`, repeatable) runs the whole grid once per
combination of values (the cartesian product, in the order given); every
cell records the values of the swept parameters (`Record.params`), and the
report gets one table and one plot per swept parameter.

A parameter is either a field of `Protocol` (kitchen fraction, hierarchy level,
FOON-EXP threshold and similarity mode: consumed where trials and networks are built), or carries
hooks: `network` transforms the network read from the inputs before the
REG/EXP/GEN views are built, `kitchen` transforms each trial's kitchen. Adding
a parameter is one entry in `PARAMS` below. `stage` says what a value change
invalidates: `network` parameters get their own network views (cached per
worker by value), `trial` parameters only redraw the trials.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, fields, replace
from typing import Any

from ..errors import UsageError, did_you_mean
from ..model.foon import Foon
from ..model.kitchen import Kitchen
from .bans import ban_motions, exclude_objects
from .protocol import Protocol

NETWORK = "network"
TRIAL = "trial"


def _fraction(text: str) -> float:
    value = float(text)
    if not 0 < value <= 1:
        raise ValueError("must be in (0, 1]")
    return value


def _count(text: str) -> int:
    value = int(text)
    if value < 0:
        raise ValueError("must be 0 or more")
    return value


def _positive(text: str) -> int:
    value = int(text)
    if value < 1:
        raise ValueError("must be 1 or more")
    return value


def _mode(text: str) -> str:
    from ..errors import UsageError
    from ..generalize.modes import check_mode

    try:
        return check_mode(text.strip().lower())
    except UsageError as exc:
        raise ValueError(exc.message) from None


def _level(text: str) -> int:
    value = int(text)
    if value not in (1, 2, 3):
        raise ValueError("must be 1, 2 or 3")
    return value


@dataclass(frozen=True)
class Param:
    """A sweepable parameter: its name on the command line and in records, how to read a value, what it changes."""

    name: str  # as written in --sweep and in records, reports and plots
    parse: Callable[[str], Any]  # text -> value (ValueError on a bad value)
    stage: str  # NETWORK or TRIAL
    description: str
    field: str | None = None  # the Protocol field it sets, if any
    network: Callable[[Foon, Any], Foon] | None = None  # transforms the network read, before views are built
    kitchen: Callable[[Kitchen, Any], Kitchen] | None = None  # transforms each trial's kitchen


PARAMS: dict[str, Param] = {p.name: p for p in (
    Param("kitchen-fraction", _fraction, TRIAL, "fraction of the default kitchen a trial keeps",
          field="kitchen_fraction"),
    Param("threshold", _fraction, NETWORK, "FOON-EXP Wu-Palmer similarity threshold", field="threshold"),
    Param("similarity", _mode, NETWORK, "FOON-EXP similarity mode (cook, paper)", field="similarity"),
    Param("level", _level, NETWORK, "hierarchy level of goals, kitchens and networks", field="level"),
    Param("objects-per-item", _positive, TRIAL, "physical objects per kitchen item when trees are scheduled",
          field="objects_per_item"),
    Param("banned-motions", _count, NETWORK, "motions the robot cannot perform (drawn at random, bans.py)",
          network=ban_motions),
    Param("excluded-objects", _count, NETWORK, "kitchen objects that must not appear (drawn at random, bans.py)",
          network=exclude_objects),
)}

_PROTOCOL_FIELDS = {f.name for f in fields(Protocol)}
assert all(p.field is None or p.field in _PROTOCOL_FIELDS for p in PARAMS.values())

#: A point of a sweep: swept parameter name -> value, in sweep order.
Point = tuple[tuple[str, Any], ...]
#: Most points a sweep's grid may have (each point is a whole run of the grid: trials, goals, networks).
MAX_POINTS = 1000


def get_param(name: str) -> Param:
    """The registered parameter `name` (ValueError listing the known ones)."""
    try:
        return PARAMS[name]
    except KeyError:
        raise ValueError(f"unknown sweep parameter {name!r}{did_you_mean(name, PARAMS)} (expected one of {', '.join(PARAMS)})") from None


def parse_sweep(text: str) -> tuple[str, tuple[Any, ...]]:
    """`NAME=V1,V2,...` -> (name, distinct values in order); ValueError naming the problem."""
    name, sep, values = text.partition("=")
    param = get_param(name.strip().lower())
    items = [v.strip() for v in values.split(",") if v.strip()]
    if not sep or not items:
        raise ValueError(f"expected {param.name}=V1,V2,... not {text!r}")
    parsed = []
    for item in items:
        try:
            parsed.append(param.parse(item))
        except ValueError as exc:
            raise ValueError(f"{param.name}={item}: {exc}") from None
    return param.name, tuple(dict.fromkeys(parsed))


def check_grid(sweeps: Sequence[tuple[str, tuple[Any, ...]]]) -> None:
    """UsageError when the sweep's grid has more than MAX_POINTS points (counted, not built)."""
    size = math.prod(len(v) for _, v in sweeps)
    if size > MAX_POINTS:
        shape = " x ".join(f"{len(v)} {n}" for n, v in sweeps)
        raise UsageError(f"the sweep's grid has {size:,} points ({shape}); at most {MAX_POINTS:,} are run")


def points(sweeps: Sequence[tuple[str, tuple[Any, ...]]]) -> tuple[Point, ...]:
    """Every combination of the swept values (one empty point without sweeps); see `check_grid`."""
    names = [n for n, _ in sweeps]
    return tuple(tuple(zip(names, combo, strict=True)) for combo in itertools.product(*(v for _, v in sweeps)))


def protocol_at(protocol: Protocol, point: Point) -> Protocol:
    """The protocol with the point's Protocol-field parameters set."""
    changes = {PARAMS[n].field: v for n, v in point if PARAMS[n].field is not None}
    return replace(protocol, **changes) if changes else protocol


def network_hooks(point: Point) -> Point:
    """The part of the point that transforms the network read (parameters with a `network` hook)."""
    return tuple((n, v) for n, v in point if PARAMS[n].network is not None)


def network_key(protocol: Protocol, point: Point) -> tuple:
    """What a network view depends on at this point (its cache key beside the inputs and the network name)."""
    at = protocol_at(protocol, point)
    return (at.level, at.threshold, at.similarity, network_hooks(point))


def _apply(hook: str, value, point: Point):
    """`value` through the point's `hook` ("network" or "kitchen") of each parameter, in sweep order."""
    for name, v in point:
        fn = getattr(PARAMS[name], hook)
        if fn is not None:
            value = fn(value, v)
    return value


def transform_network(foon: Foon, point: Point) -> Foon:
    """Apply the point's network hooks (in sweep order)."""
    return _apply("network", foon, point)


def transform_kitchen(kitchen: Kitchen, point: Point) -> Kitchen:
    """Apply the point's kitchen hooks (in sweep order)."""
    return _apply("kitchen", kitchen, point)


def label(point: Point) -> str:
    """`kitchen-fraction=0.5, level=2` (empty without sweeps)."""
    return ", ".join(f"{n}={v:g}" if isinstance(v, float) else f"{n}={v}" for n, v in point)
