"""FOON to PDDL: planning-task IR, the registry of encodings (`compile.ENCODINGS`), rendering, UP problems."""

#: The package's modules (import them by name).
__all__ = ["compile", "costs", "encode_compat", "encode_lifted", "encode_state", "encode_tree", "encoding", "examples",
           "instance_replay", "lifted_atoms", "names", "prune", "registry", "render", "task", "trace_view", "up_problem"]
