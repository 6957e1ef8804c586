"""A curiosity's Python side is declared by its own Prolog module
(python_side/1 of theory/curiosity/interface.pl) and read from there
(bridge/exploration/curiosity_sides.py): the session registers, for the
curiosities of the one list, the handlers their modules declare, and
names no curiosity. This module is a toy curiosity's Python side; its
Prolog module is a file of its own, written below: adding the toy to the
list (here, the Host's) is all its handler needs to be dispatched by the
session's Host and called from Prolog."""
from __future__ import annotations

import re
import sys
from importlib import import_module
from pathlib import Path
from types import ModuleType

import numpy as np
import pytest

from pantarhei.bridge.errors import UserError
from pantarhei.bridge.exploration.curiosity_sides import (curiosities, curiosity_handlers,
                                                          python_sides)
from pantarhei.bridge.exploration.session import Host, install
from pantarhei.bridge.exploration.session_state import Session
from tests.conftest import toy_curiosity

SESSION = Path(__file__).resolve().parents[3] / "bridge" / "exploration" / "session.py"

#: The toy curiosity's Prolog module: the interface, and its Python side, this module.
TOY = toy_curiosity("curiosity_toy", python_side=__name__)


def handlers() -> dict:
    """The toy curiosity's one foreign predicate."""
    return {"exploration_toy_count": ("toy", toy_count)}


def toy_count(host: Host, request: dict) -> dict:
    return {"pours": len(host.need_session().params) + int(request["more"])}


@pytest.fixture(scope="module")
def toy(tmp_path_factory):
    """The toy curiosity's Prolog module, loaded into the process's Prolog
    (as interface.pl loads those of the list), and forgotten after."""
    path = tmp_path_factory.mktemp("toy") / "toy.pl"
    path.write_text(TOY, encoding="utf-8")
    eng = install()
    eng.once("curiosity_interface:load_curiosity(toy, F)", F=str(path))
    yield eng
    eng.once("retractall(curiosity_interface:curiosity_module(toy, _))")


def toy_host() -> Host:
    return Host(curiosities=(*curiosities(), "toy"))


def test_a_toy_curiosity_in_the_list_gets_its_handler_dispatched_and_timed(toy):
    assert python_sides(["toy"]) == {"toy": (__name__,)}       # its own module says so
    host = toy_host()
    assert "exploration_toy_count" not in Host().handlers        # not in the one list
    assert host.dispatch("exploration_toy_count", {"more": 1}) == {"error": "no exploration is running"}
    assert isinstance(host.take_error(), UserError)
    host.session = Session(run="r", store=None, simulator=None, oracle_version="",
                           params=np.zeros((4, 30)), scores=np.zeros((4, 9)))
    assert host.dispatch("exploration_toy_count", {"more": 3}) == {"pours": 7}
    assert "toy" in host.session.timings
    # every curiosity's own handlers are there beside the toy's
    assert set(curiosity_handlers()) < set(host.handlers)


def test_a_curiosity_without_a_module_is_refused_in_one_line():
    with pytest.raises(ValueError, match="the curiosity nonesuch has no module loaded"):
        Host(curiosities=("nonesuch",))


@pytest.fixture(scope="module")
def registered(toy):
    """The process's Prolog, with the toy's foreign predicate registered
    (the host, which keeps its callback, lives as long as the module's tests)."""
    host = toy_host()
    host.register(["exploration_toy_count"])
    return toy, host


def test_prolog_calls_the_toy_curiosity_s_handler_through_call_bridge(registered):
    eng, host = registered
    host.session = Session(run="r", store=None, simulator=None, oracle_version="",
                           params=np.zeros((2, 30)), scores=np.zeros((2, 9)))
    r = eng.once("curiosity_foreign:call_bridge(exploration_toy_count, _{more: 3}, R), "
                 "get_dict(pours, R, P)")
    assert r["P"] == 5
    host.session = None


def test_a_module_shared_by_two_curiosities_is_registered_once_and_a_clash_refused(monkeypatch):
    assert list(curiosity_handlers(["toy", "toy"], {"toy": (__name__, __name__)})) == \
        ["exploration_toy_count"]
    clash = ModuleType("toy_clash")
    monkeypatch.setitem(sys.modules, clash.__name__, clash)
    clash.handlers = lambda: {"exploration_toy_count": ("toy", toy_count)}
    with pytest.raises(ValueError, match="toy_clash declares exploration_toy_count"):
        curiosity_handlers(["toy", "clash"], {"toy": (__name__,), "clash": ("toy_clash",)})
    clash.handlers = lambda: {"exploration_begin": ("toy", toy_count)}
    with pytest.raises(ValueError, match="exploration_begin"):
        Host(curiosities=["clash"], sides={"clash": ("toy_clash",)})


def test_the_sides_are_of_curiosities_of_the_one_list_and_prolog_calls_each_handler():
    sides = python_sides()
    assert set(sides) <= set(curiosities())
    assert all(import_module(m).handlers() for modules in sides.values() for m in modules)
    prolog = "\n".join(p.read_text() for p in (SESSION.parents[2] / "theory").rglob("*.pl"))
    for name in curiosity_handlers():
        assert re.search(rf"\b{name}\b", prolog), name


def test_the_session_names_no_curiosity_nor_its_handlers_or_modules():
    source = SESSION.read_text()
    names = set(curiosities())
    for name, (_, handler) in curiosity_handlers().items():
        names |= {name, handler.__name__}
    for modules in python_sides().values():
        names |= {m.rpartition(".")[2] for m in modules}
    assert {n for n in names if re.search(rf"\b{n}\b", source)} == set()
