"""The `pantarhei` command: one subcommand per module of bridge/commands/.

Each module has `register(subparsers)`, which adds its subcommands with
`set_defaults(run=function)`; `run(args)` returns the exit code. Registering
imports nothing heavy: each command imports what it uses when it runs, so
that `--help` and `ask` answer at once.

Commands that compute with floats (simulate, learn, evaluate) also set
`pin=True`, or `pin=function(args)` when it depends on their options: the
process is then started again with the baseline math (oracle/baseline.py)
after the arguments were checked, so that they compute the same numbers on
every x86-64 machine.
"""
from __future__ import annotations

import argparse
import importlib
import sys
from typing import Sequence

from pantarhei.bridge.errors import MissingEngine, TheoryFileError, UserError, safe_line

#: Modules of pantarhei.bridge.commands, in the order `--help` lists them.
COMMANDS = ("vocab", "demo", "simulate", "explore", "querying", "plan", "rules", "evaluate")


class _Parser(argparse.ArgumentParser):
    def error(self, message: str) -> None:  # one line, exit 2
        self.exit(2, safe_line(f"{self.prog}: {message}") + "\n")


def parser() -> argparse.ArgumentParser:
    p = _Parser(prog="pantarhei",
                description="Learn a defeasible theory of pouring by curious exploration "
                            "of a simulation, and ask it questions.")
    sub = p.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
    sub.required = True
    for name in COMMANDS:
        importlib.import_module(f"pantarhei.bridge.commands.{name}").register(sub)
    return p


def pinned(args: argparse.Namespace) -> bool:
    """Does the command compute with floats (start it with the baseline math)?"""
    pin = getattr(args, "pin", False)
    return bool(pin(args) if callable(pin) else pin)


def main(argv: Sequence[str] | None = None, pin_math: bool = False) -> int:
    """Run the command of `argv`; with `pin_math`, a command that computes
    with floats first restarts this process with the baseline math (the
    arguments are checked before, so that a bad one is refused at once)."""
    try:        # the help texts read the theory's defaults
        args = parser().parse_args(argv)
    except (MissingEngine, TheoryFileError) as e:
        _say("pantarhei", e)
        return 2
    try:
        if pin_math and pinned(args):
            from pantarhei.oracle import baseline

            try:
                baseline.restart_with(baseline.ENVIRONMENT)
            except OSError as e:
                raise UserError(f"cannot restart with the baseline math ({e.strerror or e}): "
                                f"start it with {' '.join(f'{k}={v!r}' for k, v in baseline.ENVIRONMENT.items())}") from None
        code = args.run(args)
    except UserError as e:
        _say(f"pantarhei {args.command}", e)
        code = e.exit_code
    except (MissingEngine, TheoryFileError) as e:
        _say(f"pantarhei {args.command}", e)
        code = 2
    except RecursionError:     # a backstop: every reader bounds its nesting first
        _say(f"pantarhei {args.command}", "an input nested too deeply to read")
        code = 2
    except MemoryError:        # a backstop: every reader bounds what it holds first
        _say(f"pantarhei {args.command}", "out of memory: the input is too large to read")
        code = 2
    except KeyboardInterrupt:
        print(f"pantarhei {args.command}: interrupted", file=sys.stderr)
        code = 130
    except BrokenPipeError:
        code = 0
    except Exception as e:
        if not _store_error(e):
            raise
        _say(f"pantarhei {args.command}", e)      # the results it could not
        code = 1                                                    # keep are in the file it names
    try:
        sys.stdout.flush()
    except BrokenPipeError:
        code = 0
    return code


def _say(who: str, message: object) -> None:
    """Print an error as one safe line (control characters escaped, long
    inputs cut): the message may quote any input."""
    print(f"{who}: {safe_line(str(message))}", file=sys.stderr)


def _store_error(e: BaseException) -> bool:
    """Is `e` the store's StoreError? (Only a command that opened the store
    can raise one: the store's module is not imported for the others.)"""
    store = sys.modules.get("pantarhei.oracle.store")
    return store is not None and isinstance(e, store.StoreError)


def entry() -> None:
    """The `pantarhei` command."""
    sys.exit(main(pin_math=True))


if __name__ == "__main__":
    entry()
