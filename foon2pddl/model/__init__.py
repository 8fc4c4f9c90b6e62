"""The FOON model: immutable nodes, units, networks, hierarchy levels, goals, kitchens and task trees."""
