"""The package map checks itself: `__all__` lists every module of a package, and the modules, names and
paths that docs and docstrings put in backticks exist."""

from __future__ import annotations

import ast
import importlib
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
PACKAGE = ROOT / "foon2pddl"
SUBPACKAGES = sorted(p.name for p in PACKAGE.iterdir() if (p / "__init__.py").is_file())
TOP = {p.stem for p in PACKAGE.glob("*.py")} | set(SUBPACKAGES)
PAGES = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]

#: `pkg.module.Name` and `pkg/module.py` references in backticks.
_DOTTED = re.compile(r"`((?:foon2pddl\.)?([a-z_]+)(?:\.[A-Za-z_][A-Za-z0-9_]*)+)`")
_PATH = re.compile(r"`((?:foon2pddl/)?(?:[a-z_]+/)*[a-z_]+\.py)`")


@pytest.mark.parametrize("package", SUBPACKAGES)
def test_all_lists_every_module(package):
    init = PACKAGE / package / "__init__.py"
    node = next(n for n in ast.parse(init.read_text()).body
                if isinstance(n, ast.Assign) and any(getattr(t, "id", None) == "__all__" for t in n.targets))
    listed = set(ast.literal_eval(node.value))
    modules = {p.stem for p in (PACKAGE / package).glob("*.py") if p.stem not in ("__init__", "__main__")}
    assert modules <= listed, sorted(modules - listed)


def _resolves(ref: str) -> bool:
    """Whether `ref` (`pkg.mod.Name...`, package-relative or absolute) names a module or an attribute."""
    parts = ref.removeprefix("foon2pddl.").split(".")
    for cut in range(len(parts), 0, -1):
        try:
            obj = importlib.import_module("foon2pddl." + ".".join(parts[:cut]))
        except ImportError:
            continue
        for name in parts[cut:]:
            if isinstance(obj, type) and name in getattr(obj, "__dataclass_fields__", {}):
                return True  # a dataclass field (no class attribute when it has no default)
            if not hasattr(obj, name):
                return False
            obj = getattr(obj, name)
        return True
    return False


def _path_resolves(ref: str) -> bool:
    ref = ref.removeprefix("foon2pddl/")
    return any((base / ref).is_file() for base in (PACKAGE, ROOT)) or \
        any(p.relative_to(PACKAGE).as_posix().endswith("/" + ref) for p in PACKAGE.rglob(Path(ref).name))


def _texts():
    for page in PAGES:
        yield str(page.relative_to(ROOT)), page.read_text()
    for path in sorted(PACKAGE.rglob("*.py")):
        tree = ast.parse(path.read_text())
        for node in ast.walk(tree):
            if isinstance(node, (ast.Module, ast.ClassDef, ast.FunctionDef, ast.AsyncFunctionDef)):
                doc = ast.get_docstring(node, clean=False)
                if doc:
                    yield f"{path.relative_to(ROOT)}:{getattr(node, 'lineno', 1)}", doc


def test_backticked_modules_names_and_paths_resolve():
    stale = []
    for where, text in _texts():
        for m in _DOTTED.finditer(text):
            if m.group(2) in TOP and not m.group(1).endswith(".py") and not _resolves(m.group(1)):
                stale.append(f"{where}: `{m.group(1)}`")
        for m in _PATH.finditer(text):
            first = m.group(1).removeprefix("foon2pddl/").split("/")[0]
            if (first in TOP or first.removesuffix(".py") in TOP) and not _path_resolves(m.group(1)):
                stale.append(f"{where}: `{m.group(1)}`")
    assert not stale, "\n".join(stale)
