"""Shared fixtures: the test corpus (tests/data) and the merged universal FOON."""

from __future__ import annotations

from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
#: The test corpus shipped in the repository (tests/data/README.md): no file outside the checkout is read.
SHARED = ROOT / "tests" / "data"
SUBGRAPHS = SHARED / "foon-subgraphs"
SEARCH_INPUTS = SHARED / "foon-search-inputs"


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
