"""One result per cell (trial, goal, network, solver, swept parameters), stored as JSON lines.

The JSONL file is append-only: a record is written, flushed, as soon as its
cell (or its task's batch of cells) finishes, so an interrupted run loses at
most what was being computed. `read_records` skips damaged lines (garbage, a
truncated write, wrong field types, NUL bytes, invalid UTF-8), reporting each
as `results.jsonl:N`, so their cells are simply recomputed; it keeps the last
record of a key when a cell was run twice. Cells whose status is `error` or
`lost` count as not done, so a rerun retries them; so do records of another
goal or time limit than the run's (`reusable`).
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass, field, fields
from pathlib import Path
from typing import IO, Any

from ..errors import FoonInputError
from ..status import CellStatus

#: Statuses in report order.
STATUSES = tuple(CellStatus)
#: Statuses a rerun retries.
RETRIED = frozenset({CellStatus.ERROR, CellStatus.LOST})

#: (trial, goal, network, solver, swept parameters as sorted (name, value) pairs).
Key = tuple[int, int, str, str, tuple]


def params_key(params: dict[str, Any]) -> tuple:
    """The hashable, order-free form of a cell's swept parameters."""
    return tuple(sorted(params.items()))


@dataclass(frozen=True)
class Record:
    """The result of one solver on one goal of one trial on one network (at one point of a sweep).

    `times` holds this cell's phases in seconds; `setup` is the time shared by
    the cells of its (trial, network, solver) batch (a fixpoint, an FD
    translation), counted once per batch in per-trial totals. `units` counts the
    task tree's functional units, `plan_length` the planner's plan steps
    (auxiliary goal actions included; None for native solvers). `validated`:
    the tree or plan passed every check its solver promises (FOON simulation
    from the kitchen; for the `state` encoding, the plan under the task's own
    STRIPS semantics); `foon_valid`: the tree passed FOON simulation.
    Anytime optimal solvers fill `bound` (proven lower bound on units), `gap`
    ((units - bound) / units) and `proven_optimal`. `params` holds the values of
    the swept parameters (empty without sweeps); `worker` the engine's worker
    that computed the cell (None in-process); `time_limit` the planner time limit
    it ran under (None in files written before cells recorded it: the run's
    `protocol.json` says which). A returned tree is also scheduled over the
    kitchen's physical objects (`planners.executable.schedule`): `executable`
    is the verdict, `executable_reason` names the label and step that failed,
    `extra_objects` how many objects more a tree that ran `short` needs (None
    when no number of objects would do: a unit must fire again); for a physical plan,
    `repeated` counts its unit steps that fire a unit it fired before.
    """

    trial: int
    goal: int
    network: str
    solver: str
    goal_label: str
    status: CellStatus
    reason: str = ""
    times: dict[str, float] = field(default_factory=dict)
    setup: float = 0.0
    units: int | None = None
    plan_length: int | None = None
    validated: bool | None = None
    proven_optimal: bool | None = None
    foon_valid: bool | None = None
    bound: float | None = None
    gap: float | None = None
    params: dict[str, Any] = field(default_factory=dict)
    worker: str | None = None
    time_limit: float | None = None
    executable: str | None = None  # planners.executable.Verdict of the tree over the kitchen's objects
    executable_reason: str | None = None  # why not (the label and step that failed)
    extra_objects: int | None = None  # a `short` tree: objects beyond the kitchen's it needs (None: more do not help)
    repeated: int | None = None  # a physical plan: its unit steps that fire a unit it fired before

    def __post_init__(self) -> None:
        try:
            object.__setattr__(self, "status", CellStatus(self.status))
        except ValueError:
            raise ValueError(f"unknown cell status {self.status!r}") from None

    @property
    def key(self) -> Key:
        return (self.trial, self.goal, self.network, self.solver, params_key(self.params))

    @property
    def solved(self) -> bool:
        """A tree was found and it validates."""
        return self.status == CellStatus.SOLVED and self.validated is True

    @property
    def time(self) -> float:
        """This cell's own time (sum of its phases, without the shared setup)."""
        return sum(self.times.values())

    def to_json(self) -> str:
        data = {name: getattr(self, name) for name in _FIELDS}  # every field is a scalar or a flat dict
        data["status"] = str(self.status)
        data["solved"] = self.solved
        data["times"] = {k: round(v, 6) for k, v in sorted(self.times.items())}
        data["setup"] = round(self.setup, 6)
        for name in _OPTIONAL:  # optional: absent when unset (old files have none)
            if data[name] is None:
                del data[name]
        if not self.params:
            del data["params"]
        return _ENCODER.encode(data)

    @classmethod
    def from_json(cls, text: str) -> Record:
        """Parse one line; ValueError when it is not a well-formed record."""
        data = json.loads(text)
        if not isinstance(data, dict):
            raise ValueError("not a JSON object")
        data = {k: v for k, v in data.items() if k in _NAMES}
        _check_types(data)
        return cls(**data)


#: Record's fields, in order (`to_json`, `from_json`).
_FIELDS = tuple(f.name for f in fields(Record))
_NAMES = frozenset(_FIELDS)
_ENCODER = json.JSONEncoder(sort_keys=True, ensure_ascii=False)

_INT = ("trial", "goal")
_STR = ("network", "solver", "goal_label")
_OPT_INT = ("units", "plan_length", "extra_objects", "repeated")
_OPT_STR = ("executable", "executable_reason")
_OPT_BOOL = ("validated", "proven_optimal", "foon_valid")
#: Fields left out of a line when unset (added after the first version).
_OPTIONAL = ("bound", "gap", "worker", "time_limit", "executable", "executable_reason", "extra_objects",
             "repeated")
_OPT_NUM = ("bound", "gap", "time_limit")


def _number(x: object) -> bool:
    return isinstance(x, int | float) and not isinstance(x, bool) and math.isfinite(x)


def _check_types(data: dict) -> None:
    """Every field of a parsed line has its type (a damaged line must not become a wrong record)."""
    problems = [k for k in _INT if not (isinstance(data.get(k), int) and not isinstance(data.get(k), bool))]
    problems += [k for k in (*_STR, "status") if not isinstance(data.get(k), str)]
    problems += [k for k in _OPT_INT if data.get(k) is not None and not (
        isinstance(data[k], int) and not isinstance(data[k], bool))]
    problems += [k for k in _OPT_BOOL if data.get(k) is not None and not isinstance(data[k], bool)]
    problems += [k for k in _OPT_STR if data.get(k) is not None and not isinstance(data[k], str)]
    problems += [k for k in _OPT_NUM if data.get(k) is not None and not _number(data[k])]
    times = data.get("times", {})
    if not isinstance(times, dict) or not all(isinstance(k, str) and _number(v) for k, v in times.items()):
        problems.append("times")
    if not isinstance(data.get("reason", ""), str):
        problems.append("reason")
    if not _number(data.get("setup", 0.0)):
        problems.append("setup")
    params = data.get("params", {})
    if not isinstance(params, dict) or not all(isinstance(v, str | int | float) for v in params.values()):
        problems.append("params")
    if data.get("worker") is not None and not isinstance(data["worker"], str):
        problems.append("worker")
    if problems:
        raise ValueError("bad or missing field(s): " + ", ".join(problems))


def read_records(path: Path, warnings: list[str] | None = None) -> dict[Key, Record]:
    """Records of a JSONL file by key (last one wins); a missing file gives none.

    Damaged lines are skipped; unless it is a last line cut short (an
    interrupted write), each adds `path:N: warning: ...` to `warnings`.
    FoonInputError when `path` is not a readable regular file.
    """
    if not path.exists():
        return {}
    if not path.is_file():
        raise FoonInputError(str(path), 0, "not a results file (a directory or a special file); "
                                           "remove it or use another -o directory")
    try:
        data = path.read_bytes()
    except OSError as exc:
        raise FoonInputError(str(path), 0, f"cannot read: {exc.strerror or exc}") from None
    out: dict[Key, Record] = {}
    lines = data.split(b"\n")
    for number, raw in enumerate(lines, start=1):
        if not raw.strip():
            continue
        try:
            if b"\0" in raw:
                raise ValueError("NUL bytes")
            record = Record.from_json(raw.decode("utf-8"))
        except UnicodeDecodeError:
            problem = "invalid UTF-8"
        except (ValueError, TypeError) as exc:
            problem = str(exc)
        except RecursionError:
            problem = "nested too deeply"
        else:
            out[record.key] = record
            continue
        if number == len(lines):  # no newline after it: a write cut short, cut off before the next append
            continue
        if warnings is not None:
            warnings.append(f"{path}:{number}: warning: damaged result line skipped, its cell is recomputed "
                            f"({problem[:120]})")
    return out


def done_keys(records: dict[Key, Record]) -> set[Key]:
    """Keys of cells that need no rerun (everything but errors and lost cells)."""
    return {k for k, r in records.items() if r.status not in RETRIED}


def reusable(records: dict[Key, Record], labels: dict[Key, str], time_limit: float,
             old_limit: float | None = None) -> set[Key]:
    """Keys of the cells of this run (`labels`: key -> the goal's label as drawn now) whose record can
    stand: done (`done_keys`), of the same goal (a record of another goal is recomputed), computed under
    this `time_limit` (a record without one takes `old_limit`, the directory's previous limit). A
    limit changes a cell's answer (a timeout, an anytime solver's bound), so any other limit is rerun."""
    return {k for k in done_keys(records) if k in labels and records[k].goal_label == labels[k]
            and (records[k].time_limit if records[k].time_limit is not None else old_limit) == time_limit}


def open_for_append(path: Path) -> IO[str]:
    """Open the JSONL file for appending, first cutting off a truncated last line."""
    path.parent.mkdir(parents=True, exist_ok=True)
    if path.exists():
        with open(path, "rb+") as fh:
            data = fh.read()
            end = data.rfind(b"\n") + 1
            if end != len(data):
                fh.truncate(end)
    return open(path, "a", encoding="utf-8")


def append(fh: IO[str], record: Record) -> None:
    """Write one record line and flush it (a killed run keeps every line written before)."""
    fh.write(record.to_json() + "\n")
    fh.flush()
