"""One result per cell (trial, goal, network, solver), stored as JSON lines.

The JSONL file is append-only: a record is written, flushed, as soon as its
cell finishes, so an interrupted run loses at most the line being written.
`read_records` ignores a truncated last line (and `open_for_append` cuts it
off before appending), and keeps the last record of a key when a cell was run
twice. Cells whose status is `error` count as not done, so a rerun retries them.
"""

from __future__ import annotations

import json
from dataclasses import asdict, dataclass, field, fields
from pathlib import Path
from typing import IO

#: Statuses of a cell. `solved` means a task tree was found and validated.
STATUSES = ("solved", "unsolvable", "budget exhausted", "node limit", "timeout", "error")

Key = tuple[int, int, str, str]


@dataclass(frozen=True)
class Record:
    """The result of one solver on one goal of one trial on one network.

    `times` holds this cell's phases in seconds; `setup` is the time shared by
    the cells of its (trial, network, solver) batch (a fixpoint, an FD
    translation), counted once per batch in per-trial totals. `units` counts the
    task tree's functional units, `plan_length` the planner's plan steps
    (auxiliary goal actions included; None for native solvers). `validated`:
    the tree or plan passed every check its solver promises (FOON simulation
    from the kitchen; for the `state` encoding, the plan under the task's own
    STRIPS semantics); `foon_valid`: the tree passed FOON simulation.
    """

    trial: int
    goal: int
    network: str
    solver: str
    goal_label: str
    status: str
    reason: str = ""
    times: dict[str, float] = field(default_factory=dict)
    setup: float = 0.0
    units: int | None = None
    plan_length: int | None = None
    validated: bool | None = None
    proven_optimal: bool | None = None
    foon_valid: bool | None = None

    def __post_init__(self) -> None:
        if self.status not in STATUSES:
            raise ValueError(f"unknown cell status {self.status!r}")

    @property
    def key(self) -> Key:
        return (self.trial, self.goal, self.network, self.solver)

    @property
    def solved(self) -> bool:
        """A tree was found and it validates."""
        return self.status == "solved" and self.validated is True

    @property
    def time(self) -> float:
        """This cell's own time (sum of its phases, without the shared setup)."""
        return sum(self.times.values())

    def to_json(self) -> str:
        data = asdict(self)
        data["solved"] = self.solved
        data["times"] = {k: round(v, 6) for k, v in sorted(self.times.items())}
        data["setup"] = round(self.setup, 6)
        return json.dumps(data, sort_keys=True, ensure_ascii=False)

    @classmethod
    def from_json(cls, text: str) -> Record:
        data = json.loads(text)
        names = {f.name for f in fields(cls)}
        return cls(**{k: v for k, v in data.items() if k in names})


def read_records(path: Path) -> dict[Key, Record]:
    """Records of a JSONL file by key (last one wins); a missing file gives none.

    A line that does not parse is skipped only if it is the last one (a write
    cut short); elsewhere it is an error (ValueError naming the line).
    """
    if not path.exists():
        return {}
    out: dict[Key, Record] = {}
    lines = path.read_text(encoding="utf-8").split("\n")
    for number, line in enumerate(lines, start=1):
        if not line.strip():
            continue
        try:
            record = Record.from_json(line)
        except (ValueError, TypeError) as exc:
            if number == len(lines):  # no newline after it: a write cut short
                continue
            raise ValueError(f"{path}:{number}: not a result record: {exc}") from None
        out[record.key] = record
    return out


def done_keys(records: dict[Key, Record]) -> set[Key]:
    """Keys of cells that need no rerun (everything but errors)."""
    return {k for k, r in records.items() if r.status != "error"}


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
