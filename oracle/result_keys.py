"""The key of a stored result: a hash of the canonical parameterization
(each value rounded to `DECIMALS` places) and of the oracle's name, version
and settings, so that a parameterization is simulated once per oracle
configuration."""
from __future__ import annotations

import hashlib
import json
from typing import TYPE_CHECKING, Iterable

if TYPE_CHECKING:
    from pantarhei.oracle.base import Oracle

#: Decimal places a parameter value keeps in the key (theory units).
DECIMALS = 6


def canonical(p: Iterable[float]) -> list[float]:
    """A parameterization as the list of numbers its key is made of."""
    out = []
    for v in p:
        r = round(float(v), DECIMALS)
        out.append(0.0 if r == 0 else r)
    return out


def oracle_tag(oracle: Oracle) -> str:
    """The oracle's name, version and settings as one canonical string."""
    return json.dumps({"name": oracle.name, "version": oracle.version,
                       "settings": oracle.settings()}, sort_keys=True, separators=(",", ":"))


def key(p: Iterable[float], tag: str) -> str:
    """The key of a parameterization's result under an oracle's tag."""
    text = json.dumps(canonical(p), separators=(",", ":")) + "|" + tag
    return hashlib.sha256(text.encode()).hexdigest()
