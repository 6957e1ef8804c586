"""Beginning an exploration's session: the settings that decide its course
(hashed into the run's key, bridge/exploration/checkpoints.py), and the progress
bar, counted in the budget's own unit."""
from __future__ import annotations

import sys
from typing import Any

from pantarhei.bridge.exploration.pool import Session
from pantarhei.theory.option_table import Option, option

#: Bumped when the course of an exploration may change for the same settings.
ALGORITHM_VERSION = "5"


def course(request: dict, version: str, oracle_settings: Any) -> dict:
    """The settings of explore/1's request that decide the exploration's
    course, with the algorithm's and the oracle's versions: what the run
    key hashes. The request names them (`course`: course_options/2 of
    theory/curiosity/settings.pl, from course/2 of theory/defaults.pl);
    the keys of a mode or option left off stay out, so that runs without
    it keep their keys."""
    out = {"algorithm": ALGORITHM_VERSION, "oracle_version": version,
           "oracle_settings": oracle_settings}
    for name in request["course"]:
        out[name] = _course_value(option(name), request[name])
    if "prior_batch" in out:    # where the priors' batch goes: the budget's last
        out["priors_at"] = "last"
    return out


def _course_value(o: Option, v: Any) -> Any:
    if o.type == "antecedent":
        return sorted(str(p) for p in v)
    if o.type == "count" or (o.choices and all(isinstance(c, int) for c in o.choices)):
        return int(v)
    return float(v) if o.type == "permille" else str(v)


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


def note(text: str) -> None:
    """A line for the person exploring, on stderr."""
    print(f"pantarhei explore: {text}", file=sys.stderr)


def truthy(v: Any) -> bool:
    """A truth value of a request (a bool, as the foreign predicates read
    true and false, or true and 1 as text) as a bool."""
    return v in (True, "true", 1, "1")
