"""`bench.pddl_relational --every K --offset I` / `--sample N --seed S`: a universal FOON of a seeded subset of the
subgraphs, so a user can check the floors on universal FOONs no rule was tuned on (docs/pddl.md, Unseen universal
FOONs)."""

from __future__ import annotations

import subprocess
import sys

import pytest
from conftest import ROOT, SHARED

from bench.pddl_relational import pick

FILES = [f"{i:04d}.txt" for i in range(10)]


def test_every_and_offset_take_the_subgraphs_of_that_index_modulo():
    assert pick(FILES, 3, 1) == ["0001.txt", "0004.txt", "0007.txt"]
    assert pick(FILES) == FILES


def test_a_sample_is_the_seeds_draw_kept_in_sorted_order():
    drawn = pick(FILES, sample=7, seed=55)
    assert drawn == pick(FILES, sample=7, seed=55) == sorted(drawn)
    assert len(set(drawn)) == 7 and drawn != pick(FILES, sample=7, seed=56)
    assert pick(FILES, 2, 0, sample=5, seed=1) == pick(FILES, 2, 0)  # all five of the even ones


@pytest.mark.parametrize("args, says", [(["--every", "2", "--offset", "2"], "--offset 2 is not in 0..1"),
                                        (["--sample", "0"], "--sample 0: there are"),
                                        (["--every", "0"], "--every 0: must be 1 or more"),
                                        (["--every", "-3", "--offset", "1"], "--every -3: must be 1 or more")])
def test_a_subset_that_cannot_be_made_is_a_clear_error(args, says):
    """Each error names the option that is wrong: `--every 0` said `--offset 0 is not in 0..-1` (stop 55's pass)."""
    r = subprocess.run([sys.executable, "-m", "bench.pddl_relational", "--shared", str(SHARED), *args], cwd=ROOT,
                       capture_output=True, text=True, timeout=120)
    assert r.returncode == 2 and says in r.stderr and "Traceback" not in r.stderr
    assert "0..-" not in r.stderr


def test_the_bench_plans_only_the_picked_subgraphs():
    r = subprocess.run([sys.executable, "-m", "bench.pddl_relational", "--shared", str(SHARED), "--encodings",
                        "relational", "--every", "50", "--offset", "1", "-v"], cwd=ROOT,
                       capture_output=True, text=True, timeout=600)
    assert r.returncode == 0, r.stderr
    assert [line.split("\t")[0] for line in r.stdout.splitlines() if "\trelational\t" in line] == [
        "0002-bacon_macaroni_and_cheese.txt", "0052-pigs_in_a_blanket.txt"]


def test_level_2_plans_the_network_kitchen_and_goal_projected():
    """`--level 2` (issue 21's level-2 figures): the subgraph is planned at FOON's object+state level, as `plan
    --level 2` does: whipped cream's level-2 task merges nodes that differ only by their lists (fewer objects)."""
    from bench.pddl_relational import check_file

    path = SHARED / "foon-subgraphs" / "0001-whipped_cream.txt"
    (three,), (two,) = (check_file(path, 60.0, ("relational",), level) for level in (3, 2))
    assert three.status == two.status == "solved" and not two.kinds
    assert two.objects < three.objects
