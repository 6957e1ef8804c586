"""The progress bar of a running exploration, counted in the unit of the
curiosity's budget, which explore/1 names when it begins
(`bar: _{total, unit}`): pours (the learning and the discovering
curiosity: the pours spent, probes included) or explored antecedents,
rules (the paper's)."""
from __future__ import annotations

import sys
from dataclasses import dataclass
from typing import Any


@dataclass
class Bar:
    """A progress bar (tqdm) and its unit, `pour` or `rule`."""
    bar: Any
    unit: str

    def show(self, iteration: int, pours: int, a_new: int | None = None) -> None:
        """The bar after `iteration` iterations and `pours` pours, with the
        candidates in A_new."""
        self.bar.set_postfix_str(postfix(self.unit, iteration, pours, a_new), refresh=False)
        self.bar.update(position(self.unit, iteration, pours) - self.bar.n)

    def close(self) -> None:
        self.bar.close()


def open_bar(total: int, unit: str, iteration: int, pours: int) -> Bar:
    """Show a progress bar to `total` in `unit`, `iteration` iterations
    and `pours` pours in."""
    from tqdm import tqdm

    bar = tqdm(total=total, initial=position(unit, iteration, pours), unit=unit,
               desc="exploring", file=sys.stderr, dynamic_ncols=True)
    bar.set_postfix_str(postfix(unit, iteration, pours))
    return Bar(bar, unit)


def position(unit: str, iteration: int, pours: int) -> int:
    """The bar's position after `iteration` iterations and `pours` pours:
    the pours, or the explored antecedents (one an iteration)."""
    return pours if unit == "pour" else iteration


def postfix(unit: str, explored: int, pours: int, a_new: int | None = None) -> str:
    """The text after the progress bar: batches so far (a bar of pours) or
    simulations and rules (a bar of rules), and the candidates in A_new."""
    text = (f"{explored} batch{'' if explored == 1 else 'es'}" if unit == "pour"
            else f"{pours} simulations, {explored} rules")
    if a_new is not None:
        text += f", {a_new} in A_new"
    return text
