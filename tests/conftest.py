"""Shared fixtures: the test corpus (tests/data) and the merged universal FOON."""

from __future__ import annotations

from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
#: The test corpus shipped in the repository (tests/data/README.md): no file outside the checkout is read.
SHARED = ROOT / "tests" / "data"
SUBGRAPHS = SHARED / "foon-subgraphs"
SEARCH_INPUTS = SHARED / "foon-search-inputs"


@pytest.fixture(autouse=True)
def _quiet_slow_steps(monkeypatch):
    """A slow step's line (`cli.progress`) depends on the machine's speed and load: none in tests, so
    their stderr is deterministic; a test about the lines sets `progress.AFTER` itself (0: every step), and
    `progress.BEAT` for the seconds a long call's step adds through a pipe."""
    from foon2pddl.cli import progress

    monkeypatch.setattr(progress, "AFTER", 3600.0)
    monkeypatch.setattr(progress, "BEAT", 3600.0)
    monkeypatch.setattr(progress, "_quiet_since", None)


@pytest.fixture(scope="session")
def universal():
    """The universal FOON of the shared subgraphs at level 3 (with parse warnings)."""
    from foon2pddl.io.files import load

    return load([SUBGRAPHS])


@pytest.fixture(scope="session")
def example():
    """The embedded example network."""
    from foon2pddl.io.inputs import load_network

    return load_network([])


@pytest.fixture(scope="session")
def label_similarity():
    """WordNet-backed label similarity (opening WordNet takes a few seconds: once per session)."""
    from foon2pddl.generalize.similarity import LabelSimilarity

    return LabelSimilarity()


def substitution_lines_without_wordnet(monkeypatch, tmp_path, *args: str) -> list[str]:
    """Run the CLI with `args` on an empty cache, then again with WordNet unreadable (a warm run must not open it):
    both succeed with the same stdout and `substitution:` lines, which are returned."""
    from click.testing import CliRunner

    from foon2pddl.cli import main
    from foon2pddl.generalize import wordnet

    monkeypatch.setenv("FOON2PDDL_CACHE", str(tmp_path / "cache"))
    runs = []
    for warm in (False, True):
        if warm:
            monkeypatch.setattr(wordnet, "reader", lambda: pytest.fail("WordNet opened on a warm run"))
        result = CliRunner().invoke(main, list(args))
        assert result.exit_code == 0, result.stderr
        runs.append((result.stdout, [line for line in result.stderr.splitlines() if line.startswith("substitution: ")]))
    assert runs[0] == runs[1]
    return runs[0][1]
