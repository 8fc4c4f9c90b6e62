"""The experiment's solvers, one module per job: experiment/solvers.py had reached the 400-line limit
(tests/test_layering.py) holding the registry, the solver interface, the outcome builders and every prepared
solver."""

from __future__ import annotations

import ast

from conftest import ROOT

from foon2pddl.experiment import fd_solvers, native_solver, outcomes, solvers
from foon2pddl.experiment.setting import Prepared


def test_the_registry_module_only_names_solvers():
    """solvers.py holds the registry (`Role`, `Solver`, `SOLVERS`); the preparations are classes of
    native_solver and fd_solvers, and an Outcome is made in outcomes, all below the registry."""
    tree = ast.parse((ROOT / "foon2pddl" / "experiment" / "solvers.py").read_text())
    assert {n.name for n in tree.body if isinstance(n, ast.ClassDef)} == {"Role", "Solver"}
    ours = {c.__module__ for c in Prepared.__subclasses__() if c.__module__.startswith("foon2pddl.")}
    assert ours == {native_solver.__name__, fd_solvers.__name__}
    assert outcomes.Outcome.__module__ == outcomes.__name__
    assert set(solvers.SOLVERS) >= {"native-complete", "fd-tree", "fd-relational", "fd-lifted-gen"}
