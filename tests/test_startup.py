"""Start-up imports only what the command needs: the light commands load no heavy third-party stack.

Each check runs the CLI in a fresh interpreter and reads `sys.modules` afterwards, so an
import added anywhere on the command's path (eager subcommand registration, a module-level
import in a shared option) fails here. Timing is measured in `bench/startup.py`, not here.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys

import pytest
from conftest import ROOT

#: Third-party packages the light commands must not import (each costs 0.1-1 s to load).
HEAVY = ("networkx", "jinja2", "unified_planning", "nltk", "dask", "distributed", "up_fast_downward")

_PROBE = """
import json, sys
from foon2pddl.cli import main
try:
    main(sys.argv[1:], prog_name="foon2pddl")
except SystemExit as exc:
    code = exc.code
heavy = sorted({m.split(".")[0] for m in sys.modules} & set(json.loads(HEAVY)))
ours = sorted(m for m in sys.modules if m.startswith("foon2pddl."))
print("\\nPROBE " + json.dumps({"code": code, "heavy": heavy, "ours": ours}))
"""


def _probe(*args: str) -> dict:
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    proc = subprocess.run([sys.executable, "-c", _PROBE.replace("HEAVY", repr(json.dumps(HEAVY))), *args],
                          capture_output=True, text=True, env=env, timeout=300)
    assert proc.returncode == 0, proc.stderr
    return json.loads(proc.stdout.rsplit("PROBE ", 1)[1])


EXAMPLE_FILE = ROOT / "foon2pddl" / "data" / "example" / "02-whipped_cream.foon"


@pytest.mark.parametrize("args", [("--version",), ("stats",), ("stats", str(EXAMPLE_FILE)),
                                  ("stats", "--json", str(EXAMPLE_FILE))], ids=" ".join)
def test_light_commands_import_no_heavy_stack(args):
    out = _probe(*args)
    assert (out["code"], out["heavy"]) == (0, [])


#: Package modules no light command needs (the planning, PDDL, search and experiment stacks).
NOT_FOR_LIGHT = ("foon2pddl.pddl", "foon2pddl.retrieval", "foon2pddl.generalize", "foon2pddl.experiment",
                 "foon2pddl.skills", "foon2pddl.api")


@pytest.mark.parametrize("args", [("--version",), ("stats", str(EXAMPLE_FILE))], ids=" ".join)
def test_light_commands_import_only_their_own_modules(args):
    """`--version` loads no network model and `stats` no PDDL; of the planners only the process cleanup
    every command runs in (its package `__init__` must not pull in the PDDL task model)."""
    ours = _probe(*args)["ours"]
    assert not [m for m in ours if m.startswith(NOT_FOR_LIGHT)], ours
    assert [m for m in ours if m.startswith("foon2pddl.planners")] == ["foon2pddl.planners",
                                                                      "foon2pddl.planners.cleanup"], ours
    if args == ("--version",):
        assert not [m for m in ours if m.startswith(("foon2pddl.model", "foon2pddl.analysis"))], ours


def test_probe_sees_heavy_imports():
    """The probe itself can fail: `compile --help` defines options from the encoding registry (jinja2 behind it)."""
    out = _probe("compile", "--help")
    assert out["code"] == 0
    assert out["heavy"], "the probe reported nothing for a command that loads the PDDL stack"


def test_lazy_registry_names_every_command():
    """`COMMANDS` maps each name to the module that defines it, and nothing else is registered."""
    import importlib

    from foon2pddl import cli

    for name, module in cli.COMMANDS.items():
        importlib.import_module(f"foon2pddl.cli.{module}")
        assert name in cli.main.commands, (name, module)
    assert set(cli.main.commands) == set(cli.COMMANDS)


def test_help_lists_every_command():
    from click.testing import CliRunner

    from foon2pddl import cli

    result = CliRunner().invoke(cli.main, ["--help"])
    assert result.exit_code == 0
    listed = {line.split()[0] for line in result.output.split("Commands:")[1].splitlines() if line.strip()}
    assert listed == set(cli.COMMANDS)
