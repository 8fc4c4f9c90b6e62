"""File formats at the edges: FOON text and JSON, kitchens, goals, rates, task tree formats, atomic output."""
