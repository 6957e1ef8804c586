"""Flags that several commands share, each declared once here: the oracle,
the store, where simulations run, the seed and the progress bar. Defaults
come from theory/defaults.pl (through pantarhei.theory.defaults)."""
from __future__ import annotations

import argparse

from pathlib import Path

from pantarhei.theory import THEORY_DIR, defaults

#: The shipped learned theory and the store, as bridge.theories.loading and
#: oracle.store name them (read here from theory/defaults.pl alone, so that
#: declaring the flags imports neither the theory readers nor numpy).
DEFAULT_THEORY = THEORY_DIR / str(defaults()["theory"])
DEFAULT_STORE = Path(str(defaults()["store"]))

#: The oracles a command may simulate with.
ORACLES = ("pybullet", "synthetic")


def add_oracle(p: argparse.ArgumentParser) -> None:
    default = defaults()["oracle"]
    p.add_argument("--oracle", choices=ORACLES, default=default,
                   help=f"the simulation (default {default}) or analytic test scores (synthetic)")


def add_store(p: argparse.ArgumentParser, what: str = "simulations") -> None:
    p.add_argument("--store", default=str(DEFAULT_STORE),
                   help=f"SQLite file of {what} (default {DEFAULT_STORE})")


def add_theory_out(p: argparse.ArgumentParser, flag: str = "--out", extra: str = "") -> None:
    p.add_argument(flag, default=str(DEFAULT_THEORY),
                   help=f"the learned theory (default {_shown(DEFAULT_THEORY)}){extra}")


def add_execution(p: argparse.ArgumentParser, progress: str = "no progress bar") -> None:
    """--executor, --workers, --ray-address and --no-progress."""
    p.add_argument("--executor", choices=("local", "ray", "inline"), default="local",
                   help="worker processes here (default), a Ray cluster, or this process")
    p.add_argument("--workers", type=int, help="worker processes (default: one per core)")
    p.add_argument("--ray-address", metavar="ADDR",
                   help="Ray cluster to join (with --executor ray; default: start a local Ray "
                        "on this machine)")
    p.add_argument("--no-progress", action="store_true", help=progress)


def add_seed(p: argparse.ArgumentParser, default: int | None = None, what: str = "every random choice") -> None:
    value = int(defaults()["seed"]) if default is None else default
    p.add_argument("--seed", type=int, default=value, help=f"seed of {what} (default {value})")


def _shown(path) -> str:
    try:
        return str(Path(path).resolve().relative_to(Path.cwd()))
    except ValueError:
        return str(path)
