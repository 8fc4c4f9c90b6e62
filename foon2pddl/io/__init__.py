"""File formats at the edges: FOON text and JSON, kitchens, goals, rates, task tree formats, atomic output."""

#: The package's modules (import them by name).
__all__ = ["atomic", "constraints_file", "files", "goal_files", "inputs", "jsonio", "kitchen_files", "parser", "rates",
           "tree_formats", "writer"]
