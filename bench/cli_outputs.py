"""Byte-identical CLI outputs across a refactor: every command, two checkouts, every difference reported.

Runs each CLI command (stats, merge, goals, retrieve with each method and format,
compile with each encoding, plan with Fast Downward, similarity, expand, generalize,
categories) on the embedded example network and on `SHARED/foon-subgraphs`, once
with a baseline commit (exported with `git archive` into a temporary directory) and
once with the current tree, and compares stdout, stderr, exit status and every file
a command writes. Lines that report elapsed time (`phases: ...`, JSON `timings`) and
the checkout's own path are masked before comparing.

    python -m bench.cli_outputs --shared ../shared/data [--baseline ce6cbbc] [--against COMMIT] [--only retrieve,plan]

`--against COMMIT` compares two commits (both exported) instead of the baseline and this
checkout: one commit's effect alone, with `--baseline COMMIT^`.

Exit status 0 when every output is identical, 1 otherwise (each difference is printed
as a unified diff).
"""

from __future__ import annotations

import argparse
import difflib
import os
import re
import subprocess
import sys
import tarfile
import tempfile
from concurrent.futures import ThreadPoolExecutor
from io import BytesIO
from pathlib import Path

from .harness import run_main, shared_data

ROOT = Path(__file__).resolve().parent.parent
DEFAULT_BASELINE = "ce6cbbc"  # the last commit before the issue-9 refactor

EXAMPLE_GOALS = ("guacamole", "lemonade", "tomato soup: pureed, garnished {basil}, in [bowl]")
SHARED_GOAL = "whipped cream"
METHODS = ("greedy", "complete", "optimal")
FORMATS = ("steps", "foon", "json", "dot", "svg")
ENCODINGS = ("tree", "state", "foon-compat")


def commands(shared: Path) -> list[tuple[str, tuple[str, ...]]]:
    """(name, arguments) of every command compared; `{out}` stands for a fresh output directory."""
    subgraphs = str(shared / "foon-subgraphs")
    rates = str(shared / "foon-search-inputs" / "motion.txt")
    out: list[tuple[str, tuple[str, ...]]] = []
    for where, paths in (("example", ()), ("subgraphs", (subgraphs,))):
        out += [
            (f"stats {where}", ("stats", *paths)),
            (f"stats --json {where}", ("stats", "--json", *paths)),
            (f"merge {where}", ("merge", *paths)),
            (f"merge --ids --provenance {where}", ("merge", "--ids", "--provenance", *paths)),
            (f"merge --format json {where}", ("merge", "--format", "json", *paths)),
            (f"goals {where}", ("goals", *paths)),
            (f"goals --json --level 2 {where}", ("goals", "--json", "--level", "2", *paths)),
            (f"categories --check {where}", ("categories", "--check", *paths)),
            (f"generalize {where}", ("generalize", *paths)),
            (f"generalize --format json {where}", ("generalize", "--format", "json", *paths)),
        ]
    out.append(("expand example", ("expand", "--provenance")))
    out.append(("expand example json", ("expand", "--format", "json")))
    for goal in EXAMPLE_GOALS:
        for method in METHODS:
            for fmt in FORMATS if method == "complete" else ("steps",):
                out.append((f"retrieve {method} {fmt} {goal}", ("retrieve", "--goal", goal, "--method", method,
                                                                  "--format", fmt)))
        out.append((f"retrieve weighted {goal}", ("retrieve", "--goal", goal, "--method", "weighted",
                                                  "--rates", rates)))
        for network in ("exp", "gen"):
            out.append((f"retrieve --network {network} {goal}", ("retrieve", "--goal", goal, "--network", network)))
        for enc in ENCODINGS:
            out.append((f"compile {enc} {goal}", ("compile", "--goal", goal, "--encoding", enc, "-o", "{out}")))
        out.append((f"compile --no-prune --costs unit {goal}", ("compile", "--goal", goal, "--no-prune", "--costs",
                                                                "unit", "-o", "{out}")))
        out.append((f"compile --network gen {goal}", ("compile", "--goal", goal, "--network", "gen", "-o", "{out}")))
        out.append((f"plan tree {goal}", ("plan", "--goal", goal)))
        out.append((f"plan --network gen {goal}", ("plan", "--goal", goal, "--network", "gen")))
    out += [
        ("plan state json guacamole", ("plan", "--goal", "guacamole", "--encoding", "state", "--format", "json")),
        ("plan foon-compat level 2 guacamole", ("plan", "--goal", "guacamole", "--encoding", "foon-compat",
                                                "--level", "2")),
        ("plan --optimal guacamole", ("plan", "--goal", "guacamole", "--optimal", "--format", "foon")),
        ("retrieve subgraphs", ("retrieve", subgraphs, "--goal", SHARED_GOAL, "--method", "optimal")),
        ("retrieve subgraphs json", ("retrieve", subgraphs, "--goal", SHARED_GOAL, "--format", "json")),
        ("compile subgraphs", ("compile", subgraphs, "--goal", SHARED_GOAL, "-o", "{out}")),
        ("compile subgraphs state", ("compile", subgraphs, "--goal", SHARED_GOAL, "--encoding", "state", "-o",
                                     "{out}")),
        ("compile subgraphs gen", ("compile", subgraphs, "--goal", SHARED_GOAL, "--network", "gen", "-o", "{out}")),
        ("plan subgraphs", ("plan", subgraphs, "--goal", SHARED_GOAL)),
        ("plan subgraphs gen", ("plan", subgraphs, "--goal", SHARED_GOAL, "--network", "gen")),
        ("similarity two", ("similarity", "lemon", "lime")),
        ("similarity matrix", ("similarity", "lemon", "lime", "onion", "bowl", "--json")),
        ("similarity pairs senses", ("similarity", "--pairs", "--senses", "lemon", "lime", "cup", "mug")),
        ("bad option", ("retrieve", "--goal", "guacamole", "--method", "weighted")),
        ("unknown goal", ("retrieve", "--goal", "xyzzy")),
    ]
    return out


#: Elapsed-time reports: the `phases:` line and the `timings` object of `plan --format json`.
_TIMING = re.compile(r'^phases: .*$|"timings": \{[^}]*\}', re.M)


def _mask(text: str, checkout: Path, work: Path) -> str:
    text = text.replace(str(work), "<OUT>").replace(str(checkout), "<ROOT>")
    text = re.sub(r"/tmp/foon2pddl-baseline-[^/]+/(?:baseline|current)", "<ROOT>", text)
    return _TIMING.sub("<timing>", text)


def run_one(checkout: Path, args: tuple[str, ...], python: str) -> str:
    """Everything one command shows: exit status, stdout, stderr and the files it wrote (masked)."""
    with tempfile.TemporaryDirectory(prefix="foon2pddl-cli-") as tmp:
        work = Path(tmp)
        argv = [a.replace("{out}", str(work / "out")) for a in args]
        env = {**os.environ, "PYTHONPATH": str(checkout), "COLUMNS": "100"}
        done = subprocess.run([python, "-m", "foon2pddl", *argv], cwd=work, env=env, capture_output=True,
                              text=True, timeout=900, check=False)
        parts = [f"exit {done.returncode}", "--- stdout", done.stdout, "--- stderr", done.stderr]
        for path in sorted((work / "out").glob("*")) if (work / "out").is_dir() else ():
            parts += [f"--- file {path.name}", path.read_text()]
        return _mask("\n".join(parts), checkout, work)


def export(commit: str, into: Path, repo: Path = ROOT) -> Path:
    """The tree of `commit` (from the git repository `repo`) written under `into` (no git worktree to clean up)."""
    data = subprocess.run(["git", "archive", commit], cwd=repo, capture_output=True, check=True).stdout
    with tarfile.open(fileobj=BytesIO(data)) as tar:
        tar.extractall(into, filter="data")
    return into


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--shared", type=Path, default=ROOT.parent / "shared" / "data")
    ap.add_argument("--baseline", default=DEFAULT_BASELINE, help="commit to compare against")
    ap.add_argument("--only", default="", help="comma-separated words; run the commands whose name has one")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--python", default=sys.executable)
    ap.add_argument("--against", default=None, help="a commit to compare instead of this checkout")
    ap.add_argument("--repo", type=Path, default=ROOT, help="git repository holding the baseline commit")
    args = ap.parse_args(argv)
    shared_data(args.shared)
    todo = commands(args.shared.resolve())
    if args.only:
        words = [w.strip() for w in args.only.split(",") if w.strip()]
        todo = [c for c in todo if any(w in c[0] for w in words)]
    with tempfile.TemporaryDirectory(prefix="foon2pddl-baseline-") as tmp:
        base = export(args.baseline, Path(tmp) / "baseline", args.repo)
        current = ROOT if args.against is None else export(args.against, Path(tmp) / "current", args.repo)
        jobs = [(name, checkout, cmd) for name, cmd in todo for checkout in (base, current)]
        with ThreadPoolExecutor(args.jobs) as pool:
            outs = list(pool.map(lambda j: run_one(j[1], j[2], args.python), jobs))
    differ = 0
    for k, (name, _) in enumerate(todo):
        before, after = outs[2 * k], outs[2 * k + 1]
        if before != after:
            differ += 1
            print(f"DIFFERENT: {name}")
            sys.stdout.writelines(difflib.unified_diff(before.splitlines(True), after.splitlines(True),
                                                       f"{args.baseline}", "current", n=2))
    print(f"{len(todo) - differ} of {len(todo)} commands identical to {args.baseline}")
    return 1 if differ else 0


if __name__ == "__main__":
    run_main(main)
