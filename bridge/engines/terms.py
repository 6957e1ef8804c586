"""Prolog terms as Python values and back, for foreign predicates.

The exploration's foreign predicates (bridge/exploration/session.py) take a
Prolog dict and unify their second argument with one. `value(t)` reads a
term handle as Python values; `put(value)` writes Python values as a new
term:

=================================  =================================
Prolog                             Python
=================================  =================================
dict ``_{k: V, ...}``              ``dict`` with ``str`` keys
list                               ``list`` (a tuple is written as one)
atom, string                       ``str`` (written as an atom)
``true``, ``false``, ``null``      ``True``, ``False``, ``None``
integer, float                     ``int``, ``float``
=================================  =================================

Any other term (a compound, a variable) is a TypeError, as it would be
in JSON. The C interface is reached through pyswip's own libswipl, with
prototypes of this module's own, so pyswip's are left as they are.
"""
from __future__ import annotations

import ctypes
from ctypes import (CFUNCTYPE, POINTER, byref, c_char_p, c_double, c_int, c_int64,
                    c_size_t, c_uint, c_void_p, string_at)
from functools import lru_cache
from typing import Any, Callable

__all__ = ["foreign", "put", "value"]

TERM = c_size_t        # term_t and atom_t are uintptr_t
ATOM = c_size_t
# SWI-Prolog.h
PL_VARIABLE, PL_ATOM, PL_INTEGER, PL_FLOAT, PL_STRING, PL_TERM = 1, 2, 3, 5, 6, 7
PL_NIL, PL_LIST_PAIR, PL_DICT = 8, 10, 44
CVT_ATOM, CVT_STRING, REP_UTF8, BUF_DISCARDABLE = 0x1, 0x2, 0x100000, 0x0
FLAGS = CVT_ATOM | CVT_STRING | REP_UTF8 | BUF_DISCARDABLE
NAMES = {True: "true", False: "false", None: "null"}
CONSTANTS = {v: k for k, v in NAMES.items()}

_PROTOTYPES: dict[str, tuple[Any, ...]] = {
    "PL_term_type": (c_int, TERM),
    "PL_get_nchars": (c_int, TERM, POINTER(c_size_t), POINTER(c_char_p), c_uint),
    "PL_get_int64": (c_int, TERM, POINTER(c_int64)),
    "PL_get_float": (c_int, TERM, POINTER(c_double)),
    "PL_get_list": (c_int, TERM, TERM, TERM),
    "PL_get_name_arity_sz": (c_int, TERM, POINTER(ATOM), POINTER(c_size_t)),
    "PL_get_arg_sz": (c_int, c_size_t, TERM, TERM),
    "PL_new_term_ref": (TERM,),
    "PL_new_term_refs": (TERM, c_size_t),
    "PL_copy_term_ref": (TERM, TERM),
    "PL_new_atom_mbchars": (ATOM, c_int, c_size_t, c_char_p),
    "PL_unregister_atom": (None, ATOM),
    "PL_put_chars": (c_int, TERM, c_int, c_size_t, c_char_p),
    "PL_put_int64": (c_int, TERM, c_int64),
    "PL_put_float": (c_int, TERM, c_double),
    "PL_put_nil": (c_int, TERM),
    "PL_cons_list": (c_int, TERM, TERM, TERM),
    "PL_put_dict": (c_int, TERM, ATOM, c_size_t, POINTER(ATOM), TERM),
    "PL_unify": (c_int, TERM, TERM),
    "PL_register_foreign_in_module": (c_int, c_char_p, c_char_p, c_int, c_void_p, c_int),
}


class _C:
    """The functions of libswipl this module calls."""

    def __init__(self) -> None:
        from pyswip.core import _lib

        for name, (restype, *argtypes) in _PROTOTYPES.items():
            setattr(self, name, CFUNCTYPE(restype, *argtypes)((name, _lib)))


@lru_cache(maxsize=1)
def _c() -> _C:
    return _C()


def value(t: int) -> Any:
    """The term of handle t as Python values (see the table above)."""
    c = _c()
    kind = c.PL_term_type(t)
    if kind in (PL_ATOM, PL_STRING):
        n, s = c_size_t(), c_char_p()
        if not c.PL_get_nchars(t, byref(n), byref(s), FLAGS):
            raise TypeError("a blob where a value was expected")
        text = string_at(s, n.value).decode("utf-8")
        return CONSTANTS.get(text, text) if kind == PL_ATOM else text
    if kind == PL_INTEGER:
        i = c_int64()
        if not c.PL_get_int64(t, byref(i)):
            raise TypeError("an integer beyond 64 bits")
        return i.value
    if kind == PL_FLOAT:
        d = c_double()
        c.PL_get_float(t, byref(d))
        return d.value
    if kind == PL_NIL:
        return []
    if kind == PL_LIST_PAIR:
        out, head, rest = [], c.PL_new_term_ref(), c.PL_copy_term_ref(t)
        while c.PL_get_list(rest, head, rest):
            out.append(value(head))
        return out
    if kind == PL_DICT:
        return _dict(c, t)
    raise TypeError("a term that is not a dict, list, atom, string or number")


def _dict(c: _C, t: int) -> dict[str, Any]:
    name, arity = ATOM(), c_size_t()
    c.PL_get_name_arity_sz(t, byref(name), byref(arity))
    arg, out = c.PL_new_term_ref(), {}
    for i in range(2, arity.value + 1, 2):     # argument 1 is the tag, then value, key
        c.PL_get_arg_sz(i + 1, t, arg)
        key = value(arg)
        c.PL_get_arg_sz(i, t, arg)
        out[str(key)] = value(arg)
    return out


def put(v: Any) -> int:
    """A new term handle holding v (see the table above)."""
    c = _c()
    t = c.PL_new_term_ref()
    _put(c, t, v)
    return t


def _put(c: _C, t: int, v: Any) -> None:
    if v is None or isinstance(v, bool):
        v = NAMES[v]
    if isinstance(v, str):
        b = v.encode("utf-8")
        ok = c.PL_put_chars(t, PL_ATOM | REP_UTF8, len(b), b)
    elif isinstance(v, int):
        if not -2**63 <= v < 2**63:
            raise TypeError(f"the integer {v} is beyond 64 bits")
        ok = c.PL_put_int64(t, v)
    elif isinstance(v, float):
        ok = c.PL_put_float(t, v)
    elif isinstance(v, (list, tuple)):
        ok = c.PL_put_nil(t)
        item = c.PL_new_term_ref()
        for x in reversed(v):
            _put(c, item, x)
            ok = ok and c.PL_cons_list(t, item, t)
    elif isinstance(v, dict):
        ok = _put_dict(c, t, v)
    else:
        raise TypeError(f"cannot write a {type(v).__name__} as a Prolog term")
    if not ok:
        raise MemoryError("Prolog's stacks are full")


def _put_dict(c: _C, t: int, d: dict) -> int:
    n = len(d)
    keys = (ATOM * max(n, 1))()
    values = c.PL_new_term_refs(max(n, 1))
    for i, (k, x) in enumerate(d.items()):
        b = str(k).encode("utf-8")
        keys[i] = c.PL_new_atom_mbchars(REP_UTF8, len(b), b)
        _put(c, values + i, x)
    try:
        return c.PL_put_dict(t, 0, n, keys, values)
    finally:
        for i in range(n):
            c.PL_unregister_atom(keys[i])


def foreign(module: str, name: str, fn: Callable[[Any], Any], keep: list) -> None:
    """Register module:name/2: fn of its first argument's value, unified
    with its second. A request or reply that is not a value of the table
    above gives the reply `_{error: Text}`. The C callback is appended to
    keep, which must live as long as Prolog may call it."""
    def call(a: int, b: int) -> int:
        try:
            reply = put(fn(value(a)))
        except TypeError as e:
            reply = put({"error": f"{name}: {e}"})
        return _c().PL_unify(b, reply)

    callback = CFUNCTYPE(c_int, TERM, TERM)(call)
    keep.append(callback)
    if not _c().PL_register_foreign_in_module(module.encode(), name.encode(), 2,
                                              ctypes.cast(callback, c_void_p), 0):
        raise RuntimeError(f"cannot register {module}:{name}/2")
