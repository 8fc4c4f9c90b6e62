"""foon2pddl: FOON functional object-oriented networks to PDDL, with native task tree retrieval."""

__version__ = "0.1.0"
