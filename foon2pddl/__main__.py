"""`python -m foon2pddl` and the `foon2pddl` console script."""


def run() -> None:
    """Exit 130/143 on SIGINT/SIGTERM even while the CLI's modules load, then run the CLI."""
    from .io.interrupts import exit_on_signals

    exit_on_signals()
    from .cli import main
    from .planners import cleanup

    cleanup.SPARE_HELPERS = False  # this process ends with the command: nothing it started may stay
    main()


if __name__ == "__main__":
    run()
