"""Generalization of a FOON to objects it never saw (the seed paper's FOON-EXP and FOON-GEN): FOON -> FOON.

- `wordnet`: WordNet 3.0 through NLTK (an NLTK corpus, or Debian's files assembled once);
- `senses`, `wup`, `similarity`: Wu-Palmer similarity of object labels, cached as a matrix on disk
  (the seed paper's rule, mode `paper`); `cook`: the default mode (role senses, deepest common
  ancestor, broad ancestors rejected; `cook_kin`: its rules 5-8, kin in the categories; `purpose`: the foods a kind of tool is for, its rule 7; `classes`: a noun that names a class, rules 8-9); `modes`: the
  registry of modes; `pairs`: `expand --pairs`;
- `substitute`, `expand`: FOON-EXP, copies of units with similar objects substituted;
- `categories`: the shipped category index; `extend`: `categories --extend`; `compress`: FOON-GEN,
  objects replaced by categories (`readings`: a name read as its unit's object takes its category);
- `network`: the `--network reg|exp|gen` view used by retrieve, compile and plan; `stats`: tables.
The lifted FOON-GEN PDDL encoding (categories as types) is `pddl.encode_lifted`.
See docs/generalization.md.
"""

#: The package's modules (import them by name).
__all__ = ["bootstrap_categories", "cache", "categories", "classes", "compress", "cook", "cook_kin", "expand", "extend", "grounding", "hints", "modes",
           "network", "pairs", "purpose", "readings", "relevance", "senses", "similarity", "stats", "substitute", "substitution", "wordnet",
           "wup"]
