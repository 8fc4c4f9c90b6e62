"""File formats at the edges: FOON text and JSON, kitchens, goals, rates, task tree formats, atomic output."""

#: The package's modules (import them by name).
__all__ = ["atomic", "batch_report", "constraints_file", "files", "foon_lines", "goal_files", "goal_lists", "inputs",
           "interrupts", "json_text", "jsonio", "kitchen_files", "parser", "rates", "raw_objects", "recipe_words", "scene_file", "steps", "tree_formats",
           "writer"]
