"""Calling explore/1 from Python: the options of one exploration
(`ExploreOptions`) and `explore(options)`, which asks theory/curiosity.pl to
explore and returns what it did. The options and their defaults are the option table of
theory/defaults.pl."""
from __future__ import annotations

from dataclasses import field, make_dataclass
from pathlib import Path
from typing import Any

from pantarhei.bridge.engines.swipl import prolog_quote
from pantarhei.bridge.errors import UserError
from pantarhei.bridge.exploration.session import error_text, install
from pantarhei.theory import THEORY_DIR
from pantarhei.theory.option_table import Option, option_table


def _field(o: Option) -> tuple[str, Any, Any]:
    """The dataclass field of a row of the option table: its default, a
    path as a Path (the learned theory's relative to theory/)."""
    if o.type == "path":
        value = THEORY_DIR / str(o.default) if o.ref == "theory" else Path(str(o.default))
        return o.name, Path, field(default_factory=lambda: value)
    if o.type == "antecedent":
        return o.name, "Sequence[str] | None", field(default=None)
    return o.name, Any, field(default=o.default)


def _prolog_value(o: Option, v: Any) -> str:
    """A value of an option as explore/1 reads it."""
    if o.type == "count":
        return str(int(v))
    if o.type == "permille":
        return repr(float(v))
    if o.type == "flag":
        return prolog_quote(bool(v))
    if o.type == "antecedent":
        return prolog_quote(list(v))
    if o.type == "path":
        return prolog_quote(str(Path(v).absolute()))
    return prolog_quote(v)


def _prolog(self: "ExploreOptions") -> str:
    """The options as explore/1's option list: every option of the table
    that is set and that the chosen curiosity reads (used_by/2 of
    theory/defaults.pl), or that is set to another value than its
    default; explore/1 refuses the latter in one line."""
    def passed(o: Option) -> bool:
        v = getattr(self, o.name)
        return v not in (None, "") and (o.read_by(str(self.curiosity)) or not _default(o, v))

    items = [f"{o.name}({_prolog_value(o, getattr(self, o.name))})" for o in option_table()
             if passed(o)]
    if self.oracle_options:
        items.append(f"oracle_options({prolog_quote(self.oracle_options)})")
    return "[" + ", ".join(items) + "]"


def _default(o: Option, v: Any) -> bool:
    """Is `v` the option's default?"""
    if o.type == "path":
        return Path(v) == _field(o)[2].default_factory()
    if o.type == "antecedent":
        return o.default is not None and sorted(v) == sorted(o.default)
    return v == o.default


def _paths(self: "ExploreOptions") -> None:
    for o in option_table():
        if o.type == "path":
            setattr(self, o.name, Path(getattr(self, o.name)))


#: The options of one exploration (see explore/1 in theory/curiosity/run.pl):
#: a field for each row of the option table of theory/defaults.pl
#: (docs/options.md), with its default (None: explore/1 sets it: the pours
#: of a batch, a_0, workers), and oracle_options, the
#: keyword arguments of the oracle's constructor.
ExploreOptions = make_dataclass(
    "ExploreOptions", [*(_field(o) for o in option_table()),
                ("oracle_options", "dict | None", field(default=None))],
    namespace={"prolog": _prolog, "__post_init__": _paths, "__doc__": "The options of one exploration (the option table)."})


def explore(options: ExploreOptions) -> dict:
    """Run an exploration to the end and return what it did: the output
    files, why it stopped, the number of rules and simulations, and where
    the time went. UserError for bad options; an interruption is raised
    again as KeyboardInterrupt once the state is saved."""
    eng = install()
    host = eng.exploration_host
    host.take_error()
    host.result.clear()
    try:
        goal = (f"curiosity:explore_result({options.prolog()}, R0), "
                "(R0 == ok -> R = ok ; R0 = error(T), text_to_string(T, R))")
        result = eng.once(goal)["R"]
    finally:
        if host.session is not None:
            host.end({"aborted": True})
    if result not in ("ok", b"ok"):
        e = host.take_error()
        if e is not None:
            if isinstance(e, (UserError, KeyboardInterrupt)):
                raise e
            raise UserError(error_text(e)) from e
        raise UserError(_result_text(result))
    return dict(host.result)


def stop_text(result: dict) -> str:
    """Why an exploration stopped, in words: A_new empty, or its budget as
    its curiosity counts it (`budget` of the result: pours, or explored
    antecedents, rules)."""
    stopped = str(result.get("stopped", ""))
    if stopped == "budget":
        budget = result["budget"]
        return f"{budget['total']} {budget['unit']}s"
    return {"a_new_empty": "A_new is empty"}.get(stopped, stopped)


def _result_text(result: Any) -> str:
    from pantarhei.bridge.engines.swipl import text

    s = text(result)
    return s.splitlines()[0] if s else "exploration failed"
