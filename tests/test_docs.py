"""Every Python example in the docs runs: README.md and docs/*.md code blocks, and docstring `>>>` examples.

A ```python block with `>>>` prompts is a doctest (its outputs are checked); any
other ```python block is executed as a script. Docstring examples of every module
of the package run as doctests (what `pytest --doctest-modules foon2pddl` does),
so `make test` checks them.
"""

from __future__ import annotations

import doctest
import importlib

import pytest

from bench.doc_commands import PAGES, ROOT, blocks

#: Modules not imported for doctests: the entry points run code at import.
NOT_IMPORTED = {"foon2pddl.__main__"}


def _blocks() -> list[tuple[str, str]]:
    out = []
    for page in PAGES:
        python = [b for b in blocks(page.read_text()) if b.lang == "python"]
        out += [(f"{page.relative_to(ROOT)}#{k}", "".join(line + "\n" for line in b.lines))
                for k, b in enumerate(python, start=1)]
    return out


def _modules() -> list[str]:
    package = ROOT / "foon2pddl"
    names = [".".join(("foon2pddl", *p.relative_to(package).with_suffix("").parts)).removesuffix(".__init__")
             for p in sorted(package.rglob("*.py"))]
    return [n for n in names if n not in NOT_IMPORTED]


def _run(tests) -> None:
    """Run doctests; fail with doctest's report of every mismatch."""
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    out: list[str] = []
    for test in tests:
        runner.run(test, out=out.append)
    assert not runner.failures, "".join(out)


def test_the_readme_has_a_python_example():
    assert any(page == "README.md#1" and ">>>" in code for page, code in _blocks())


@pytest.mark.parametrize(("where", "code"), _blocks(), ids=[w for w, _ in _blocks()])
def test_docs_python_blocks_run(where, code, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)  # examples may write files
    if ">>>" in code:
        _run([doctest.DocTestParser().get_doctest(code, {}, where, where, 0)])
    else:
        exec(compile(code, where, "exec"), {"__name__": "__docs__"})


@pytest.mark.parametrize("name", _modules())
def test_docstring_examples_run(name, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    module = importlib.import_module(name)
    _run(doctest.DocTestFinder(exclude_empty=True).find(module, name))


def test_some_public_functions_have_examples():
    import foon2pddl.api as api

    with_examples = [n for n in api.__all__ if ">>>" in (getattr(getattr(api, n), "__doc__", "") or "")
                     and callable(getattr(api, n)) and getattr(api, n).__module__.startswith(api.__name__ + ".")]
    assert len(with_examples) >= 6, with_examples


def test_the_api_package_holds_each_public_function_in_one_module_by_what_it_does():
    """api.py reached the 400-line limit (stop 59's re-read F6) and was split by what it holds: `inputs`
    (network, kitchen, goal, constraints), `solve` (one goal), `batches` (many goals, the experiment); the
    package re-exports every public name, so `foon2pddl.X` and `foon2pddl.api.X` are the one object."""
    import foon2pddl
    import foon2pddl.api as api

    where = {n: getattr(api, n).__module__ for n in api.__all__ if callable(getattr(api, n))
             and getattr(api, n).__module__.startswith(api.__name__)}
    assert {where[n] for n in ("load_network", "load_kitchen", "kitchen_of", "resolve_goal", "constraints_of")} \
        == {"foon2pddl.api.inputs"}, where
    assert {where[n] for n in ("retrieve", "compile_goal", "to_pddl", "plan", "skill_plan")} \
        == {"foon2pddl.api.solve"}, where
    assert {where[n] for n in ("retrieve_goals", "plan_goals", "run_experiment")} == {"foon2pddl.api.batches"}, where
    assert all(getattr(foon2pddl, n) is getattr(api, n) for n in foon2pddl.__all__ if n != "__version__")
