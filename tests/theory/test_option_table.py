"""The option table (theory/option_table.py, read from theory/defaults.pl),
`pantarhei explore --help` and docs/options.md say the same: the page is
what the table gives, and every option of the table but those of
explore/1 alone (prolog_only/1) is a flag of the command, and the
reverse."""
from __future__ import annotations

import re

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
