"""Beginning an exploration's session: the settings that decide its course
(hashed into the run's key, bridge/exploration/state.py), and the progress
bar, counted in the budget's own unit."""
from __future__ import annotations

import sys
from typing import Any

from pantarhei.bridge.exploration.pool import Session

#: Bumped when the course of an exploration may change for the same settings.
ALGORITHM_VERSION = "4"


def course(request: dict, version: str, oracle_settings: Any) -> dict:
    """The settings of explore/1's request that decide the exploration's
    course, with the algorithm's and the oracle's versions: what the run
    key hashes. The keys of a mode or option left off stay out, so that
    runs without it keep their keys."""
    out = {"algorithm": ALGORITHM_VERSION, "oracle": str(request["oracle"]),
           "oracle_version": version, "oracle_settings": oracle_settings,
           "seed": int(request["seed"]), "samples": int(request["samples"]),
           "threshold": float(request["threshold"]),
           "initial": sorted(str(p) for p in request["initial"]),
           "breadth": int(request["breadth"]), "ridge": float(request["ridge"])}
    if request.get("curiosity", "paper") != "paper":   # the paper's runs keep their keys
        out.update(curiosity=str(request["curiosity"]),
                   permutations=int(request["permutations"]),
                   resample=int(request["resample"]),
                   novelty=float(request["novelty"]), queue=int(request["queue"]),
                   jumps=int(request["jumps"]))
        if int(request.get("probe", 0)):       # runs without probes keep their keys
            out.update(probe=int(request["probe"]),
                       probe_attempts=int(request["probe_attempts"]))
            if int(request.get("cover", 0)):   # runs without coverage keep their keys
                out.update(cover=int(request["cover"]))
        if int(request.get("prior", 0)):       # runs without the priors keep their keys
            out.update(prior=int(request["prior"]), prior_batch="last")
    return out


def open_bar(s: Session, done: int) -> None:
    """Show the session's progress bar, `done` iterations in."""
    from tqdm import tqdm

    total, unit, initial = progress(s, done)
    s.bar = tqdm(total=total, initial=initial, unit=unit,
                 desc="exploring", file=sys.stderr, dynamic_ncols=True)
    s.bar.set_postfix_str(postfix(s, done))


def progress(s: Session, iteration: int) -> tuple[int, str, int]:
    """The progress bar's total, unit and position after `iteration`
    iterations: for the discovering curiosity, whose budget is in pours,
    the pours of max_rules batches and the pours spent (probes included);
    for the paper's, max_rules explored antecedents."""
    rules = int(s.settings["max_rules"])
    if s.settings.get("curiosity") == "discover":
        return rules * int(s.settings["samples"]), "pour", len(s.params)
    return rules, "rule", iteration


def postfix(s: Session, explored: int, a_new: int | None = None) -> str:
    """The text after the progress bar: batches (discover) or simulations
    and rules (paper) so far, and the candidates in A_new."""
    text = (f"{explored} batch{'' if explored == 1 else 'es'}"
            if s.settings.get("curiosity") == "discover"
            else f"{len(s.params)} simulations, {explored} rules")
    if a_new is not None:
        text += f", {a_new} in A_new"
    return text


def note(text: str) -> None:
    """A line for the person exploring, on stderr."""
    print(f"pantarhei explore: {text}", file=sys.stderr)


def truthy(v: Any) -> bool:
    """A Prolog or JSON truth value as a bool."""
    return v in (True, "true", 1, "1")
