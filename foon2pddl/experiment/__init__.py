"""Experiments: the seed paper's REG/EXP/GEN comparison, native retrieval against classical planners.

- `protocol`: seeded trials (random kitchens, random goals);
- `params`: the sweepable parameters (one registry entry each) and the points of a sweep;
- `networks`: the REG, EXP and GEN views of a network (kitchen and goal mapped);
- `solvers`: the registry of solvers compared (role in the report, cost order); `setting`: what a solver is
  prepared for and the prepared solver's interface; `native_solver`, `fd_solvers`: the prepared solvers;
  `outcomes`: a solver's answer for one goal, its tree validated and scheduled;
- `records`: one JSON line per (trial, goal, network, solver, swept values); cell statuses;
- `worker`: one task = a batch of cells; networks and prepared solvers cached per process;
- `engine`: where tasks run (this process, or Dask: a LocalCluster or a cluster's scheduler);
- `config`: what defines a run; `grid`: its cells and the batches they run in;
- `runner`: what is already done, resumable runs;
- `progress`: a bar on a terminal, periodic lines otherwise;
- `tables`, `render`, `plots`, `report`: report rows, Markdown and CSV, PNG plots, the written report;
- `physical`: report rows for success as physical execution (schedule verdicts of the trees).
"""

#: The package's modules (import them by name).
__all__ = ["bans", "collector", "config", "engine", "fd_solvers", "grid", "native_solver", "networks", "outcomes", "params",
           "physical", "plots", "progress", "protocol", "provenance", "records", "render", "report", "runner", "setting",
           "solvers", "tables", "worker"]
