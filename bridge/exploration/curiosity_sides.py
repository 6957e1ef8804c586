"""Each curiosity's Python side: the modules of its foreign predicates.

A curiosity is a module of theory/curiosity/ and, when its numbers are
Python's, modules that declare their own request handlers: a function
`handlers()` that returns, by the name of a foreign predicate of the
module `bridge`, the key of the run's timings it counts towards and the
handler, called with the Host (bridge/exploration/session.py) and the
request, replying with a dict. The curiosity's Prolog module names those
modules (its python_side/1, of the interface of
theory/curiosity/interface.pl), read here through the process's Prolog.
The session registers what the modules of the curiosities of the one list
(the `curiosity` row of the option table, theory/defaults.pl) declare,
and names no curiosity itself; a module shared by two curiosities is
registered once.
"""
from __future__ import annotations

from importlib import import_module
from typing import Any, Callable, Mapping, Sequence

#: A handler of a curiosity's foreign predicate: (host, request) -> reply.
Handler = Callable[[Any, dict], dict]


def python_sides(names: Sequence[str] | None = None) -> dict[str, tuple[str, ...]]:
    """Each curiosity of `names` (the one list unless given) that has a
    Python side, and the modules that declare its handlers, as its Prolog
    module declares them (curiosity_python_side/2 of
    theory/curiosity/interface.pl; a curiosity all Prolog is absent)."""
    from pantarhei.bridge.engines.swipl import engine, text

    eng = engine()
    eng.use_module("curiosity")
    out: dict[str, tuple[str, ...]] = {}
    for name in curiosities() if names is None else names:
        try:
            side = eng.once("curiosity_interface:curiosity_python_side(C, Ms), "
                            "atomic_list_concat(Ms, ' ', S)", C=name)
        except RuntimeError:
            raise ValueError(f"the curiosity {name} has no module loaded "
                             "(theory/curiosity/interface.pl)") from None
        if modules := tuple(text(side["S"]).split()):
            out[name] = modules
    return out


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
    `sides` maps a curiosity to its modules (python_sides(names) unless
    given). Two modules declaring one foreign predicate is an error."""
    names = curiosities() if names is None else names
    sides = python_sides(names) if sides is None else sides
    modules = dict.fromkeys(m for name in names for m in sides.get(name, ()))
    out: dict[str, tuple[str, Handler]] = {}
    for module in modules:
        for predicate, handler in import_module(module).handlers().items():
            if predicate in out:
                raise ValueError(f"{module} declares {predicate}, which another curiosity's module declares")
            out[predicate] = handler
    return out
