"""Graph analysis shared by retrieval and PDDL: the producer/consumer index, the forward fixpoints,
reachability, statistics."""

#: The package's modules (import them by name).
__all__ = ["additions", "betweenness", "blocking", "check", "check_labels", "check_units", "constraints", "defects", "fixpoint",
           "index", "network", "network_report", "reachability", "stats"]
