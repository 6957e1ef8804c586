"""The flags several commands share (bridge/commands/options.py): the types
that refuse a bad value as the arguments are parsed, and a row of the
option table made into a flag with its type, range and default."""
from __future__ import annotations

import argparse

import pytest

from pantarhei.bridge.commands.options import add_seed, add_table_option, count, number, SEED_MAX
from pantarhei.theory.option_table import option


@pytest.mark.parametrize("text, says", [("x", "must be a whole number, not 'x'"),
                                        ("2.0", "must be a whole number"),
                                        ("0", "must be at least 1, not 0"),
                                        ("11", "must be at most 10, not 11")])
def test_a_count_refuses_what_is_not_a_whole_number_in_range(text, says):
    with pytest.raises(argparse.ArgumentTypeError, match=says):
        count(1, 10)(text)
    assert count(1, 10)("10") == 10


@pytest.mark.parametrize("text, says", [("nan", "must be a finite number"),
                                        ("inf", "must be a finite number"),
                                        ("0", "must be more than 0, not 0"),
                                        ("1.5", "must be at most 1, not 1.5")])
def test_a_number_refuses_what_is_not_finite_and_in_range(text, says):
    with pytest.raises(argparse.ArgumentTypeError, match=says):
        number(0, 1, above=True)(text)
    assert number(0, 1, above=True)("0.25") == 0.25
    assert number(0, 1)("0") == 0.0


def parser_with(*names: str) -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(exit_on_error=False)
    for name in names:
        add_table_option(p, option(name))
    return p


def test_table_rows_become_flags_with_their_type_range_and_default():
    p = parser_with("budget", "novelty", "prior_batch", "general", "resume")
    d = p.parse_args([])
    assert (d.budget, d.novelty, d.prior_batch, d.general, d.resume) == (25, 0.1, 1, True, False)
    d = p.parse_args(["--budget", "3", "--novelty", "0.5", "--prior-batch", "0",
                      "--no-general", "--resume"])
    assert (d.budget, d.novelty, d.prior_batch, d.general, d.resume) == (3, 0.5, 0, False, True)
    with pytest.raises(argparse.ArgumentError, match="must be at most 1"):
        p.parse_args(["--novelty", "2"])
    with pytest.raises(argparse.ArgumentError, match="invalid choice"):
        p.parse_args(["--prior-batch", "2"])
    assert "(default 25)" in p.format_help()


def test_seeds_are_what_every_engine_keeps():
    p = argparse.ArgumentParser(exit_on_error=False)
    add_seed(p)
    assert p.parse_args([]).seed == 1
    assert p.parse_args(["--seed", str(SEED_MAX)]).seed == SEED_MAX
    with pytest.raises(argparse.ArgumentError, match="must be at most"):
        p.parse_args(["--seed", str(SEED_MAX + 1)])
