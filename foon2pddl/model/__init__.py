"""The FOON model: immutable nodes, units, networks, hierarchy levels, goals, kitchens and task trees."""

#: The package's modules (import them by name).
__all__ = ["aliases", "bulk", "constraints", "containment", "dedupe", "foon", "goal", "kitchen", "levels", "memo", "merge", "node_table", "pairing", "physical", "places", "scene",
           "tasktree", "where", "words"]
