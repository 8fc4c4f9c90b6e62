"""Experiments: the seed paper's REG/EXP/GEN comparison, native retrieval against classical planners.

- `protocol`: seeded trials (random kitchens, random goals);
- `networks`: the REG, EXP and GEN views of a network (kitchen and goal mapped);
- `solvers`: the registry of solvers compared;
- `records`: one JSON line per (trial, goal, network, solver);
- `runner`: worker processes, resumable runs;
- `report`: CSV, Markdown tables and PNG plots.
"""

#: The package's modules (import them by name).
__all__ = ["engine", "networks", "params", "plots", "progress", "protocol", "records", "render", "report", "runner",
           "solvers", "tables", "worker"]
