"""The `pantarhei` command: one subcommand per module of bridge/commands/.

Each module has `register(subparsers)`, which adds its subcommands with
`set_defaults(run=function)`; `run(args)` returns the exit code.
"""
from __future__ import annotations

import argparse
import importlib
import sys
from typing import Sequence

from pantarhei.bridge.errors import MissingEngine, TheoryFileError, UserError

#: Modules of pantarhei.bridge.commands, in the order `--help` lists them.
COMMANDS = ("vocab", "demo", "simulate", "explore", "querying", "evaluate")


class _Parser(argparse.ArgumentParser):
    def error(self, message: str) -> None:  # one line, exit 2
        self.exit(2, f"{self.prog}: {message}\n")


def parser() -> argparse.ArgumentParser:
    p = _Parser(prog="pantarhei",
                description="Learn a defeasible theory of pouring by curious exploration "
                            "of a simulation, and ask it questions.")
    sub = p.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
    sub.required = True
    for name in COMMANDS:
        importlib.import_module(f"pantarhei.bridge.commands.{name}").register(sub)
    return p


def main(argv: Sequence[str] | None = None) -> int:
    try:        # the help texts read the theory's defaults: that needs clingo's parser
        args = parser().parse_args(argv)
    except (MissingEngine, TheoryFileError) as e:
        print(f"pantarhei: {e}", file=sys.stderr)
        return 2
    try:
        code = args.run(args)
    except UserError as e:
        print(f"pantarhei {args.command}: {e}", file=sys.stderr)
        code = e.exit_code
    except (MissingEngine, TheoryFileError) as e:
        print(f"pantarhei {args.command}: {e}", file=sys.stderr)
        code = 2
    except KeyboardInterrupt:
        print(f"pantarhei {args.command}: interrupted", file=sys.stderr)
        code = 130
    except BrokenPipeError:
        code = 0
    sys.stdout.flush()
    return code


def entry() -> None:
    """The `pantarhei` command: this process is started again with the
    baseline math (oracle/baseline.py) unless it was, so that learning, like
    simulating, computes the same numbers on every x86-64 machine."""
    from pantarhei.oracle import baseline

    baseline.restart_with(baseline.ENVIRONMENT)
    sys.exit(main())


if __name__ == "__main__":
    entry()
