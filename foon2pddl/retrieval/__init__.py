"""Native task tree retrieval: FOON's own planner.

- `analysis.reachability.reachable`: which nodes a kitchen can make (AND/OR fixpoint, linear time);
- `complete`, `greedy`, `optimal` (fewest units, or `weighted`: highest success probability);
- `retrieve`: one entry point returning a `Retrieval` (tree or reason), by a method of `methods.METHODS`;
- `io.tree_formats.render_tree`: steps, FOON text, JSON, DOT, SVG; `io.rates.read_rates`: motion success rates.
See docs/retrieval.md for the algorithms, their complexity and tie-break orders.
"""

from ..analysis.reachability import Reachability, blockers, reachable
from ..io.rates import DEFAULT_RATE, Rates, read_rates
from ..io.tree_formats import FORMATS, render_tree
from .api import retrieve
from .methods import METHODS
from .result import Retrieval

__all__ = ["DEFAULT_RATE", "FORMATS", "METHODS", "Rates", "Reachability", "Retrieval", "blockers", "reachable",
           "read_rates", "render_tree", "retrieve", "api", "batch", "branch", "complete", "constrained", "explain",
           "extract", "greedy", "improve", "lmcut", "methods", "optimal", "result"]
