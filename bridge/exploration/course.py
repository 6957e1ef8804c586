"""The course of an exploration: the settings of explore/1's request that
decide it, with the algorithm's and the oracle's versions, which the run
key hashes (bridge/exploration/checkpoints.py)."""
from __future__ import annotations

from typing import Any

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
