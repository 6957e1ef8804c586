"""Each curiosity's Python side: the modules of its foreign predicates.

A curiosity is a module of theory/curiosity/ and, when its numbers are
Python's, modules that declare their own request handlers: a function
`handlers()` that returns, by the name of a foreign predicate of the
module `bridge`, the key of the run's timings it counts towards and the
handler, called with the Host (bridge/exploration/session.py) and the
request, replying with a dict. The session registers what the modules of
the curiosities of the one list (the `curiosity` row of the option table,
theory/defaults.pl) declare, and names no curiosity itself; a module
shared by two curiosities is registered once.
"""
from __future__ import annotations

from importlib import import_module
from typing import Any, Callable, Mapping, Sequence

#: A handler of a curiosity's foreign predicate: (host, request) -> reply.
Handler = Callable[[Any, dict], dict]


def python_sides() -> dict[str, tuple[str, ...]]:
    """Each curiosity of the option table that has a Python side, and the
    modules that declare its handlers (a curiosity all Prolog is absent)."""
    planes = "pantarhei.bridge.exploration.steepest"
    return {"paper": (planes,),
            "discover": (planes, "pantarhei.bridge.exploration.novelty"),
            "learn": ("pantarhei.bridge.exploration.teaching",)}


def curiosities() -> tuple[str, ...]:
    """The one list of curiosities: the choices of the option table's
    `curiosity` row."""
    from pantarhei.theory.option_table import option

    return tuple(option("curiosity").choices)


def curiosity_handlers(names: Sequence[str] | None = None,
                       sides: Mapping[str, Sequence[str]] | None = None
                       ) -> dict[str, tuple[str, Handler]]:
    """The handlers the Python sides of the curiosities `names` (the one
    list unless given) declare, by foreign predicate: (timing key, handler).
    `sides` maps a curiosity to its modules (python_sides() unless given).
    Two modules declaring one foreign predicate is an error."""
    sides = python_sides() if sides is None else sides
    modules = dict.fromkeys(m for name in (curiosities() if names is None else names)
                            for m in sides.get(name, ()))
    out: dict[str, tuple[str, Handler]] = {}
    for module in modules:
        for predicate, handler in import_module(module).handlers().items():
            if predicate in out:
                raise ValueError(f"{module} declares {predicate}, which another curiosity's module declares")
            out[predicate] = handler
    return out
