"""A batch of goals as one table (text, CSV, JSON lines) and safe, collision-free file names for its trees."""

from __future__ import annotations

import csv
import io
import json
import re
from collections import Counter
from collections.abc import Iterable, Sequence

from ..model.words import count

TABLE_FORMATS = ("text", "csv", "jsonl")
CSV_COLUMNS = ("goal", "status", "units", "inferred", "seconds", "reason", "probability", "source", "file")

#: Longest file name stem derived from a goal.
STEM_MAX = 80


def summary(rows: Sequence[dict]) -> str:
    """`25 goals: 20 solved, 5 unreachable`."""
    counts = Counter(r["status"] for r in rows)
    parts = ", ".join(f"{n} {s}" for s, n in sorted(counts.items(), key=lambda kv: (kv[0] != "solved", kv[0])))
    return f"{count(len(rows), 'goal')}: {parts}" if rows else "0 goals"


def format_table(rows: Sequence[dict], fmt: str, total: bool = True) -> str:
    """Rows (`GoalRow.as_dict()`, optionally with `file`) as `text`, `csv` or `jsonl` (one JSON object a line);
    `text` ends with the `summary` line unless `total` is false."""
    if fmt == "jsonl":
        return "".join(json.dumps(r, ensure_ascii=False) + "\n" for r in rows)
    if fmt == "csv":  # the jsonl keys in their order; `probability` where the rows carry it (retrieve's)
        columns = [c for c in CSV_COLUMNS if c != "probability" or any(c in r for r in rows)]
        out = io.StringIO()
        w = csv.writer(out, lineterminator="\n")
        w.writerow(columns)
        for r in rows:
            w.writerow([_cell(r.get(c)) for c in columns])
        return out.getvalue()
    if fmt != "text":
        raise ValueError(f"unknown table format {fmt!r} (expected one of {', '.join(TABLE_FORMATS)})")
    lines = [f"{'status':<17}{'units':>6}{'inferred':>9}{'seconds':>9}  goal"]
    for r in rows:
        units = "-" if r["units"] is None else str(r["units"])
        inferred = "-" if r["units"] is None else str(len(r["inferred"]))
        lines.append(f"{r['status']:<17}{units:>6}{inferred:>9}{r['seconds']:>9.3f}  {r['goal']}")
        if r["status"] != "solved" and r["reason"]:
            lines.append(f"{'':<43}{r['reason']}")
        for node in r["inferred"]:
            lines.append(f"{'':<43}inferred: {node}")
    if total:
        lines.append(summary(rows))
    return "\n".join(lines) + "\n"


def _cell(value) -> str:
    if value is None:
        return ""
    if isinstance(value, list):
        return "; ".join(map(str, value))
    return str(value)


def slug(text: str) -> str:
    """A portable file name stem: lower-case ASCII letters and digits joined by `-` (`goal` when none)."""
    stem = "-".join(re.findall(r"[a-z0-9]+", text.lower()))[:STEM_MAX].strip("-")
    return stem or "goal"


def file_names(goals: Iterable[str], ext: str) -> list[str]:
    """One distinct file name per goal, in order: `slug.ext`, then `slug-2.ext`, ... on collisions."""
    used: set[str] = set()
    names = []
    for g in goals:
        stem = slug(g)
        name, k = f"{stem}.{ext}", 1
        while name in used:
            k += 1
            name = f"{stem}-{k}.{ext}"
        used.add(name)
        names.append(name)
    return names
