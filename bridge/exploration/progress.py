"""The progress bar of a running exploration, counted in the budget's own
unit."""
from __future__ import annotations

import sys
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from pantarhei.bridge.exploration.session import Session


def open_bar(s: Session, done: int) -> None:
    """Show the session's progress bar, `done` iterations in."""
    from tqdm import tqdm

    total, unit, initial = progress(s, done)
    s.bar = tqdm(total=total, initial=initial, unit=unit,
                 desc="exploring", file=sys.stderr, dynamic_ncols=True)
    s.bar.set_postfix_str(postfix(s, done))


def progress(s: Session, iteration: int) -> tuple[int, str, int]:
    """The progress bar's total, unit and position after `iteration`
    iterations: for the learning curiosity, `pours` and the pours spent;
    for the discovering one, whose budget is in pours, the pours of
    `budget` batches and the pours spent (probes included); for the
    paper's, `budget` explored antecedents."""
    rules = int(s.settings["budget"])
    if s.settings.get("curiosity") == "learn":
        return int(s.settings["pours"]), "pour", len(s.params)
    if s.settings.get("curiosity") == "discover":
        return rules * int(s.settings["batch"]), "pour", len(s.params)
    return rules, "rule", iteration


def postfix(s: Session, explored: int, a_new: int | None = None) -> str:
    """The text after the progress bar: batches (discover) or simulations
    and rules (paper) so far, and the candidates in A_new."""
    text = (f"{explored} batch{'' if explored == 1 else 'es'}"
            if s.settings.get("curiosity") in ("discover", "learn")
            else f"{len(s.params)} simulations, {explored} rules")
    if a_new is not None:
        text += f", {a_new} in A_new"
    return text
