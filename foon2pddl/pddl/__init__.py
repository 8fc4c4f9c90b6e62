"""FOON to PDDL: planning-task IR, encodings, rendering, planners and plan decoding."""
