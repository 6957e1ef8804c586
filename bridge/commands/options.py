"""Flags that several commands share, each declared once here: the oracle,
the store, where simulations run, the seed and the progress bar; and the
types that check a flag's value when the arguments are parsed, before any
work starts (one line and exit 2 otherwise). Defaults come from
theory/defaults.pl (through pantarhei.theory.defaults)."""
from __future__ import annotations

import argparse
import math
from pathlib import Path
from typing import Callable

from pantarhei.theory import THEORY_DIR, defaults
from pantarhei.theory.option_table import option

#: The shipped learned theory and the store, as bridge.theories.loading and
#: oracle.store name them (read here from theory/defaults.pl alone, so that
#: declaring the flags imports neither the theory readers nor numpy).
DEFAULT_THEORY = THEORY_DIR / str(defaults()["theory"])
DEFAULT_STORE = Path(str(defaults()["store"]))


def choices(name: str) -> tuple[str, ...]:
    """The values an option of the option table (theory/defaults.pl) may
    take: the oracles a command may simulate with, the executors..."""
    return option(name).choices

#: Seeds are 0 .. SEED_MAX: what SWI-Prolog, clingo (32-bit integers) and
#: numpy all keep as they are (the seed's row of the option table).
SEED_MAX = int(option("seed").high)
#: Most workers a command starts (the workers' row of the option table).
WORKERS_MAX = int(option("workers").high)
#: Bounds of counts: pours simulated to verify, and any other count (scenes,
#: pours, shuffles); explore's are in its option table (theory/defaults.pl).
VERIFY_MAX = 10_000
COUNT_MAX = 1_000_000


def count(low: int, high: int) -> Callable[[str], int]:
    """An argparse type: a whole number from `low` to `high`."""
    def parse(text: str) -> int:
        try:
            value = int(text, 10)
        except ValueError:
            raise argparse.ArgumentTypeError(f"must be a whole number, not '{text}'") from None
        if value < low:
            raise argparse.ArgumentTypeError(f"must be at least {low}, not {value}")
        if value > high:
            raise argparse.ArgumentTypeError(f"must be at most {high}, not {value}")
        return value
    return parse


def number(low: float = -math.inf, high: float = math.inf, *, above: bool = False) -> Callable[[str], float]:
    """An argparse type: a finite number from `low` (or above it) to `high`."""
    def parse(text: str) -> float:
        try:
            value = float(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"must be a number, not '{text}'") from None
        if not math.isfinite(value):
            raise argparse.ArgumentTypeError(f"must be a finite number, not '{text}'")
        if value < low or (above and value == low):
            raise argparse.ArgumentTypeError(
                f"must be {'more than' if above else 'at least'} {low:g}, not {text}")
        if value > high:
            raise argparse.ArgumentTypeError(f"must be at most {high:g}, not {text}")
        return value
    return parse


#: Seconds a simulation may take: more than 0 (a day at most).
seconds = number(0, 86400, above=True)


def add_oracle(p: argparse.ArgumentParser) -> None:
    default = defaults()["oracle"]
    p.add_argument("--oracle", choices=choices("oracle"), default=default,
                   help=f"the simulation (default {default}) or analytic test scores (synthetic)")


def add_store(p: argparse.ArgumentParser, what: str = "simulations") -> None:
    p.add_argument("--store", default=str(DEFAULT_STORE),
                   help=f"SQLite file of {what} (default {DEFAULT_STORE})")


def add_theory_out(p: argparse.ArgumentParser, flag: str = "--out", extra: str = "") -> None:
    p.add_argument(flag, default=str(DEFAULT_THEORY),
                   help=f"the learned theory (default {_shown(DEFAULT_THEORY)}){extra}")


def add_execution(p: argparse.ArgumentParser, progress: str = "no progress bar") -> None:
    """--executor, --workers, --ray-address and --no-progress."""
    p.add_argument("--executor", choices=choices("executor"), default=defaults()["executor"],
                   help="worker processes here (default), a Ray cluster, or this process")
    add_workers(p)
    p.add_argument("--ray-address", metavar="ADDR", help=option("ray_address").help)
    p.add_argument("--no-progress", action="store_true", help=progress)


def add_workers(p: argparse.ArgumentParser) -> None:
    p.add_argument("--workers", type=count(int(option("workers").low), WORKERS_MAX),
                   help=option("workers").help)


def add_seed(p: argparse.ArgumentParser, default: int | None = None, what: str = "every random choice") -> None:
    value = int(defaults()["seed"]) if default is None else default
    p.add_argument("--seed", type=count(int(option("seed").low), SEED_MAX), default=value,
                   help=f"seed of {what}, 0 to {SEED_MAX} (default {value})")


def add_table_option(p: argparse.ArgumentParser, o) -> None:
    """The flag of a row of the option table (pantarhei.theory.option_table):
    its type and range checked as the arguments are parsed, its help the
    table's with the default."""
    from pantarhei.theory.option_table import default_text

    kw: dict = {"dest": o.name, "help": o.help}
    if o.type == "flag":
        kw.update(action="store_false" if o.default else "store_true", default=o.default)
        p.add_argument(o.flag, **kw)
        return
    if o.type == "count":
        kw["type"] = count(int(o.low), int(o.high) if o.high is not None else COUNT_MAX)
    elif o.type == "permille":
        kw["type"] = number(o.low, o.high if o.high is not None else math.inf)
    elif o.choices:
        kw["choices"] = o.choices
        if all(isinstance(c, int) for c in o.choices):
            kw["type"] = int
    elif o.type == "antecedent":
        kw["metavar"] = "P1,P2,..."
    shown = default_text(o)
    if o.type == "path":
        value = DEFAULT_THEORY if o.ref == "theory" else Path(str(o.default))
        kw["default"], shown = str(value), _shown(value)
    elif o.type != "antecedent":
        kw["default"] = o.default
    if shown:
        kw["help"] += f" (default {shown})"
    p.add_argument(o.flag, **kw)


def _shown(path) -> str:
    try:
        return str(Path(path).resolve().relative_to(Path.cwd()))
    except ValueError:
        return str(path)
