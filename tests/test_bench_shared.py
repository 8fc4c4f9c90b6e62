"""A benchmark given no FOON data directory says where the data is, without a traceback (stop 46's pass).

The docs show the benchmarks as `python -m bench... --shared ../shared/data`, the project's own layout; in a
fresh clone that directory does not exist, and every one of them died with a Python traceback.
"""

from __future__ import annotations

import re
import subprocess
import sys

import pytest
from conftest import ROOT

#: Every benchmark entry point with a `--shared` option.
MODULES = sorted({"bench" if path.name == "__main__.py" else f"bench.{path.stem}"
                  for path in (ROOT / "bench").glob("*.py") if '"--shared"' in path.read_text()})


def test_the_benchmarks_with_shared_data_are_found():
    assert {"bench", "bench.nested_lists", "bench.pddl_relational", "bench.physical_replay"} <= set(MODULES)


@pytest.mark.parametrize("module", MODULES)
def test_a_missing_shared_directory_is_a_clear_error(module, tmp_path):
    missing = tmp_path / "shared" / "data"
    needs = [str(tmp_path / "blind.tsv"), str(tmp_path / "key.tsv")] if module == "bench.similarity_sample" else []
    r = subprocess.run([sys.executable, "-m", module, "--shared", str(missing), *needs], cwd=ROOT,
                       capture_output=True, text=True, timeout=120)
    assert r.returncode == 2, (r.returncode, r.stderr[-2000:])
    assert "Traceback" not in r.stderr, r.stderr[-2000:]
    assert re.search(rf"{re.escape(str(missing))}: no FOON data here \(no foon-subgraphs/\)", r.stderr), r.stderr
    assert "--shared tests/data" in r.stderr
