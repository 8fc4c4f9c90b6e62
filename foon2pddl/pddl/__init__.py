"""FOON to PDDL: planning-task IR, the registry of encodings (`compile.ENCODINGS`), rendering, UP problems."""

#: The package's modules (import them by name).
__all__ = ["arg_types", "compile", "constraints", "costs", "count_order", "count_plans", "count_reasons", "count_returns", "count_reuse", "count_together", "effect_order", "encode_compat", "encode_instances", "encode_lifted", "encode_ocp",
           "encode_relational", "encode_state", "encode_tree", "encoding", "examples", "holder_flows", "holder_gaps", "holder_reach", "holder_words", "holders", "input_stitch", "instance_counts", "instance_lanes", "instance_names", "interchangeable",
           "instance_replay", "kitchen_pairs", "level_readings", "lifted_atoms", "lifted_plans", "list_arrivals", "list_brought", "list_drops", "list_placed", "live_holders", "mutual_lists", "names", "prune", "registry", "relational_init",
           "relational_action", "relational_objects", "relational_plan", "relational_reading", "relational_replay", "relational_sweep", "relational_stitch", "relational_touched", "render", "restore", "said_words", "shared", "split_actions", "tallies", "task", "trace_view", "transfer", "untouched", "untyped", "up_problem"]
