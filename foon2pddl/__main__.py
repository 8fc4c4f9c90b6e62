"""`python -m foon2pddl`."""

from .cli import main

main()
