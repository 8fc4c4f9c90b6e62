"""Extension points are registries: network kinds are named only in theirs, and a new kind plugs in everywhere."""

from __future__ import annotations

import ast
from pathlib import Path

from click.testing import CliRunner

from foon2pddl.generalize.network import (
    DEFAULT_NETWORK,
    NETWORKS,
    NetworkKind,
    NetworkView,
    get_network,
    network_view,
    register,
)

PACKAGE = Path(__file__).resolve().parent.parent / "foon2pddl"
REGISTRY = PACKAGE / "generalize" / "network.py"


def _kind_literals(path: Path) -> list[str]:
    """`path:line` of every string constant naming a network kind, outside the extra names given to `require`."""
    tree = ast.parse(path.read_text(), str(path))
    extras = {id(call.args[1]) for call in ast.walk(tree)
              if isinstance(call, ast.Call) and getattr(call.func, "id", None) == "require" and len(call.args) > 1}
    return [f"{path.relative_to(PACKAGE)}:{node.lineno}: {node.value!r}" for node in ast.walk(tree)
            if isinstance(node, ast.Constant) and node.value in NETWORKS and id(node) not in extras]


def test_no_network_kind_literal_outside_the_registry():
    found = [hit for p in sorted(PACKAGE.rglob("*.py")) if p != REGISTRY for hit in _kind_literals(p)]
    assert not found, found
    assert _kind_literals(REGISTRY)  # the scan does see literals where they are


def test_every_kind_builds_its_view_and_names_itself(example):
    from foon2pddl.model.kitchen import default_kitchen

    kitchen = default_kitchen(example.at(3))
    for name, kind in NETWORKS.items():
        if kind.slow_step is not None and kind.slow_step(example, kitchen) is not None:
            continue  # a similarity matrix not cached yet: seconds of WordNet, tested in the generalize tests
        view = network_view(example, name, 3, kitchen)
        assert view.name == name and kind.label and kind.description and kind.summary
    assert NETWORKS[DEFAULT_NETWORK].as_read and sum(k.as_read for k in NETWORKS.values()) == 1


def test_a_registered_kind_is_a_network_for_every_command(example, tmp_path):
    """A kind keeping only the units whose motion is not `pour` (a toy): retrieve, goals and the experiment
    accept it once registered; its hint, label and summary come from its entry."""
    from foon2pddl.cli import main
    from foon2pddl.experiment.tables import net_name
    from foon2pddl.experiment.worker import build_view
    from foon2pddl.model.foon import Foon
    from foon2pddl.model.kitchen import default_kitchen

    def no_pouring(net, level, kitchen, options) -> NetworkView:
        reg = net.at(level)
        foon = Foon(tuple(u for u in reg.units if u.motion.label != "pour"), reg.level)
        return NetworkView("nopour", foon, kitchen, lambda spec: spec, reg, note="no pouring")

    register(NetworkKind("nopour", "NOPOUR", "the network without pouring", no_pouring, "without pour units"))
    try:
        assert get_network("nopour").build is no_pouring
        view = network_view(example, "nopour", 3, default_kitchen(example.at(3)))
        assert all(u.motion.label != "pour" for u in view.foon.units) and view.note == "no pouring"
        assert len(view.foon.units) < len(example.at(3).units)
        assert build_view("nopour", example, 3).name == "nopour" and net_name("nopour") == "NOPOUR"
        r = CliRunner().invoke(main, ["experiment", "--networks", "nopour", "--solvers", "native-complete",
                                      "--trials", "1", "--goals", "3", "-o", str(tmp_path), "--no-progress"])
        assert r.exit_code == 0, r.output + r.stderr
        assert "NOPOUR" in (tmp_path / "report.md").read_text()
    finally:
        del NETWORKS["nopour"]
