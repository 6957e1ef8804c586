"""The option table (theory/option_table.py, read from theory/defaults.pl
and the curiosities' modules), `pantarhei explore --help` and
docs/options.md say the same: the page is what the table gives, and every
option of the table but those of explore/1 alone (prolog_only/1) is a
flag of the command, and the reverse. A curiosity's own options, declared
in its module, are rows of the table, for Python and SWI-Prolog alike."""
from __future__ import annotations

import re
import subprocess

import pytest

from pantarhei.theory.locations import PROLOG_ENTRY
from pantarhei.theory.option_table import (OPTIONS_PAGE, command_line_options, option_table,
                                           options_page)
from tests.conftest import run_cli


def test_the_options_page_is_what_the_table_gives():
    assert OPTIONS_PAGE.read_text(encoding="utf-8") == options_page(), \
        "run: .venv/bin/python -m pantarhei.theory.option_table"


def test_every_option_is_a_flag_of_explore_and_the_reverse():
    r = run_cli("explore", "--help")
    assert r.code == 0, r.err
    flags = set(re.findall(r"(?<![\w-])(--[a-z][a-z-]*)", r.out)) - {"--help"}
    assert flags == {o.flag for o in command_line_options()}


def test_every_option_has_help_and_a_known_type():
    for o in option_table():
        assert o.help and "%" not in o.help and "|" not in o.help, o.name
        assert o.type in ("count", "permille", "choice", "oracle", "flag", "antecedent",
                          "path", "text"), o.name


#: A toy curiosity's module declaring options of its own, beside its code.
TOY = '''\
:- module(curiosity_toy, []).
budget(_, 1).
option(toy_depth, count, range(1, 9), 3,
  "toy: how deep (a term: option(x). is no row)").
option(toy_width, permille, range(0, none), 500, "toy: how wide").
prolog_only(toy_depth).
option_after(toy_width, seed).
optional(X) :- option(X, _, _, _, _).
'''

SHARED = '''\
option(seed, count, range(0, 9), 1, "seed").
option(curiosity, choice, one_of(toy), toy, "the toy").
option(general, flag, none, true, "--no-general: no general rules").
used_by(general, toy).
'''


def test_a_curiosity_s_own_options_are_rows_of_the_table(tmp_path):
    """A curiosity's module declares the options it alone reads: they join
    the table after the curiosity row (or the row option_after/2 names),
    read by that curiosity alone."""
    from pantarhei.theory.option_table import read_table

    (tmp_path / "defaults.pl").write_text(SHARED, encoding="utf-8")
    (tmp_path / "toy.pl").write_text(TOY, encoding="utf-8")
    table = read_table(tmp_path / "defaults.pl", tmp_path)
    assert [o.name for o in table] == ["seed", "toy_width", "curiosity", "toy_depth", "general"]
    depth = next(o for o in table if o.name == "toy_depth")
    assert (depth.default, depth.high, depth.prolog_only, depth.curiosities) == (3, 9, True, ("toy",))
    assert depth.help == "toy: how deep (a term: option(x). is no row)"
    width = next(o for o in table if o.name == "toy_width")
    assert (width.default, width.prolog_only, width.read_by("toy")) == (0.5, False, True)


def test_an_option_declared_twice_or_placed_nowhere_is_refused(tmp_path):
    from pantarhei.theory.option_table import read_table

    (tmp_path / "defaults.pl").write_text(SHARED, encoding="utf-8")
    (tmp_path / "toy.pl").write_text(TOY + 'option(seed, count, range(0, 9), 1, "again").\n',
                                     encoding="utf-8")
    with pytest.raises(ValueError, match="declared twice: seed"):
        read_table(tmp_path / "defaults.pl", tmp_path)
    (tmp_path / "toy.pl").write_text(TOY.replace("option_after(toy_width, seed)",
                                                 "option_after(toy_width, sede)"), encoding="utf-8")
    with pytest.raises(ValueError, match="after no row of defaults.pl: sede"):
        read_table(tmp_path / "defaults.pl", tmp_path)


def test_python_and_prolog_read_the_same_table():
    """SWI-Prolog's table (theory/curiosity/settings.pl, the curiosities'
    modules as loaded) has the rows of Python's, in its order, of the same
    types, read by the same curiosities."""
    goal = ("forall(curiosity_settings:table_option(K, T, _, _), "
            "(findall(C, curiosity_settings:option_used_by(K, C), Cs), "
            "atomic_list_concat(Cs, ',', W), format('~w ~w ~w~n', [K, T, W]))), halt")
    r = subprocess.run(["swipl", "-q", "-g", goal, str(PROLOG_ENTRY)], capture_output=True,
                       text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    prolog = [line.split(" ") for line in r.stdout.splitlines()]
    python = [[o.name, o.type, ",".join(o.curiosities)] for o in option_table()]
    assert prolog == python
