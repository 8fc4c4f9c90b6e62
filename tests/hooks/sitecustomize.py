"""Test hook (put this directory on PYTHONPATH): simulate missing optional dependencies in a subprocess.

`FOON2PDDL_TEST_BLOCK=distributed,nltk` makes importing those modules (and their submodules) fail as if
they were not installed; `FOON2PDDL_TEST_NO_WORDNET=1` hides every WordNet corpus from
`foon2pddl.generalize.wordnet.locate` (no NLTK data root, no Debian files), as on a machine without one.
Nothing is uninstalled.
"""

from __future__ import annotations

import importlib.abc
import importlib.machinery
import os
import sys

_BLOCKED = tuple(m for m in os.environ.get("FOON2PDDL_TEST_BLOCK", "").split(",") if m)
_WORDNET = "foon2pddl.generalize.wordnet"


class _Hook(importlib.abc.MetaPathFinder):
    def find_spec(self, name, path=None, target=None):
        if any(name == b or name.startswith(b + ".") for b in _BLOCKED):
            raise ModuleNotFoundError(f"No module named {name!r}", name=name)
        if name == _WORDNET and os.environ.get("FOON2PDDL_TEST_NO_WORDNET"):
            spec = importlib.machinery.PathFinder.find_spec(name, path)
            run = spec.loader.exec_module

            def exec_module(module):
                run(module)
                module.nltk_data_roots = lambda: []
                module.locate.__defaults__ = (module.Path("/nonexistent-wordnet"), None, None)

            spec.loader.exec_module = exec_module
            return spec
        return None


sys.meta_path.insert(0, _Hook())
