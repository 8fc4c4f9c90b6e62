"""Graph analysis shared by retrieval and PDDL: the producer/consumer index, reachability, statistics."""
