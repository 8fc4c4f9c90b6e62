"""Graph analysis shared by retrieval and PDDL: the producer/consumer index, reachability, statistics."""

#: The package's modules (import them by name).
__all__ = ["additions", "blocking", "constraints", "index", "reachability", "stats"]
