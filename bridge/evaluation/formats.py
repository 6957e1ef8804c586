"""How the report writes what it shows: a share as a percentage, a number
to three decimals, an antecedent and a consequent in words."""
from __future__ import annotations

from typing import Sequence

from pantarhei.theory.lexicon import load_vocabulary


def pct(x: float | None) -> str:
    """A share as a percentage ("n/a" for none)."""
    return "n/a" if x is None else f"{100 * x:.1f}%"


def num(x: float | None) -> str:
    """A number to three decimals ("n/a" for none)."""
    return "n/a" if x is None else f"{x:.3f}"


def antecedent_words(props: Sequence[str]) -> str:
    """An antecedent's propositions in words."""
    v = load_vocabulary()
    return "; ".join(v.propositions[p].gloss for p in props)


def consequent_words(row: Sequence[bool]) -> str:
    """A consequent (the nine verdicts) in words: what fails."""
    v = load_vocabulary()
    failing = [e.name.replace("_", " ") for e, holds in zip(v.expectations, row) if not holds]
    if not failing:
        return "everything as expected"
    return "not: " + ", ".join(failing)
