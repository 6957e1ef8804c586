"""Reading theories (bridge/theories/loading.py): read as a theory of
pouring (ask, plan, prolog, demo), a rule that names no proposition or
expectation gets a warning with file:line and the nearest known name
(theory/ask.pl's check, bridge/theories/unknown_names.py's words), the same
whether SWI-Prolog reads the file (ask, prolog) or Python does (a DFL
file, plan), while `conclusions` reads any theory without one; a
path that is no theory file, an empty theory and a missing shipped theory
are refused in one line; the settings of a theory learned before explore's
options were renamed read by today's names."""
from __future__ import annotations

from pathlib import Path

import pytest

from pantarhei.bridge.errors import UserError
from pantarhei.bridge.theories import loading
from pantarhei.bridge.theories.loading import DEFAULT_THEORY, load
from pantarhei.bridge.theories.prolog_checks import check
from pantarhei.bridge.theories.unknown_names import warning_lines
from tests.conftest import assert_one_line_error

TYPO_PL = ("% a misspelled rule\n"
           "rule(h1, defeasible, no_spil).\n"
           "body(h1, light_liquid).\n"
           "body(h1, pour_to_sidee).\n")
TYPO_DFL = "# a misspelled rule\n\nh1: light_liquid, pour_to_sidee => -no_spil\n"


def _warnings(path: Path) -> list[str]:
    return warning_lines(unknown_names(load(path)))


def unknown_names(theory) -> list[tuple[str, str, str]]:
    return check([theory], names=True)


@pytest.mark.parametrize("name,text,lines", [("typo.pl", TYPO_PL, (2, 4)), ("typo.dfl", TYPO_DFL, (3, 3))])
def test_a_misspelled_rule_is_named_with_the_nearest_word(cli, capsys, tmp_path: Path, name, text,
                                                          lines) -> None:
    path = tmp_path / name
    path.write_text(text)
    expected = [f"warning: {path}:{lines[0]}: rule h1: head no_spil is not a proposition or expectation "
                "of pouring (did you mean no_spill?)",
                f"warning: {path}:{lines[1]}: rule h1: body pour_to_sidee is not a proposition or "
                "expectation of pouring (did you mean pour_to_side?)"]
    assert sorted(_warnings(path)) == sorted(expected)
    load(path, pouring=True)            # as plan and demo read it
    assert sorted(capsys.readouterr().err.splitlines()) == sorted(expected)
    r = cli("prolog", "--theory", str(path), "-g", "true")
    assert r.code == 0 and sorted(r.err.splitlines()) == sorted(expected), r.err
    r = cli("ask", "--props", "pour_to_side", "--theory", str(path))
    assert r.code == 0, r.err
    assert sorted(x for x in r.err.splitlines() if x.startswith("warning:")) == sorted(expected)
    r = cli("conclusions", str(path))
    assert r.code == 0 and "warning" not in r.err, r.err


def test_a_theory_s_own_words_and_the_shipped_theory_pass(tmp_path: Path) -> None:
    chain = tmp_path / "chain.dfl"
    chain.write_text("c1: pour_to_side => wet_table\nc2: wet_table => -no_spill\n")
    assert unknown_names(load(chain)) == []
    if DEFAULT_THEORY.is_file():
        assert unknown_names(load()) == []


def test_prolog_warns_too(cli, tmp_path: Path) -> None:
    path = tmp_path / "typo.pl"
    path.write_text(TYPO_PL)
    r = cli("prolog", "--theory", str(path), "-g", "true")
    assert r.code == 0, r.err
    assert any("pour_to_sidee" in x and x.startswith(f"warning: {path}:4:") for x in r.err.splitlines())


# -- a general rule and a cycle: one check, whichever reader read the file ----

GENERAL_DFL = {
    "body": ("# a general rule\ng1: pour_sideways => no_spill\n# pantarhei: provenance(g1, layer, general).\n",
             "2: general rule g1: pour_sideways is not a proposition of the vocabulary"),
    "evidence": ("g1: pour_to_side => no_spill\n# pantarhei: provenance(g1, layer, general).\n"
                 "# pantarhei: provenance(g1, support, 4).\n# pantarhei: provenance(g1, kept, 9).\n",
                 "4: general rule g1: 9 pours kept of 4 described"),
    "cycle": ("r1: pour_to_side => no_spill\nr2: pour_to_side => -no_spill\n\nr1 > r2\nr2 > r1\n",
              "4: the superiority relation has a cycle, r1 > r2 > r1: it must be acyclic"),
}


@pytest.mark.parametrize("name", sorted(GENERAL_DFL))
def test_a_dfl_file_is_refused_at_its_line_by_every_command(cli, tmp_path: Path, name: str) -> None:
    """theory/ask.pl checks a DFL file's general rules and superiority
    relation at the DFL file's lines, whether `ask` hands it over or a
    command that reads it in Python (conclusions, convert, plan)."""
    text, said = GENERAL_DFL[name]
    path = tmp_path / "t.dfl"
    path.write_text(text)
    expected = f"{path}:{said}"
    for argv in (["conclusions", str(path), "--engine", "asp"],
                 ["conclusions", str(path), "--engine", "prolog"],
                 ["convert", str(path), "--to", "native"],
                 ["ask", "--props", "pour_to_side", "--theory", str(path)]):
        assert assert_one_line_error(cli(*argv)) == f"pantarhei {argv[0]}: {expected}", argv
    with pytest.raises(UserError) as e:
        load(path)
    assert str(e.value) == expected


# -- what is no theory ---------------------------------------------------------

@pytest.mark.parametrize("path,words", [
    ("/dev/null", "/dev/null: not a regular file"),
    ("/nonexistent/theory.dfl", "no such theory file"),
])
def test_what_is_wrong_with_a_path(cli, path: str, words: str) -> None:
    assert words in assert_one_line_error(cli("conclusions", path))


def test_a_directory_and_empty_files(cli, tmp_path: Path) -> None:
    assert "a directory, not a theory file" in assert_one_line_error(cli("conclusions", str(tmp_path)))
    for name, text in (("empty.pl", ""), ("comments.dfl", "# nothing yet\n")):
        f = tmp_path / name
        f.write_text(text)
        assert f"{f}: an empty theory" in assert_one_line_error(cli("conclusions", str(f)))


def test_a_theory_file_past_the_documented_size_is_refused_by_both_readers(cli, tmp_path: Path) -> None:
    import subprocess

    from pantarhei.theory import THEORY_DIR, defaults

    most = int(defaults()["theory_bytes_at_most"])
    big = tmp_path / "big.pl"
    with big.open("wb") as f:           # one fact, then blanks past the bound
        f.write(b"fact(a).\n")
        f.write(b" " * (most + 1 - f.tell()))
    words = f"{most + 1:,} bytes, past the {most:,} a theory file may have"
    for args in (("conclusions", str(big)), ("conclusions", "--engine", "asp", str(big)),
                 ("ask", "pour from the side", "--theory", str(big))):
        assert words in assert_one_line_error(cli(*args))
    p = subprocess.run(["swipl", "-q", "-g", f"use_module('{THEORY_DIR / 'defeasible'}'), "
                        f"catch(load_theory('{big}'), theory_error(_, _, M), (write(M), halt(3)))",
                        "-t", "halt"], capture_output=True, text=True)
    assert p.returncode == 3 and p.stdout.startswith(words)
    with big.open("r+b") as f:          # at the bound, it is read
        f.truncate(most)
    assert cli("conclusions", str(big)).code == 0


def test_without_a_theory_the_commands_say_how_to_get_one(monkeypatch, tmp_path: Path) -> None:
    monkeypatch.setattr(loading, "DEFAULT_THEORY", tmp_path / "learned" / "pouring.pl")
    with pytest.raises(UserError, match="no learned theory yet") as e:
        loading.load()
    assert "--theory" in str(e.value)


# -- settings ------------------------------------------------------------------

def test_a_theory_learned_before_the_renames_reads_by_todays_names(tmp_path: Path) -> None:
    old = tmp_path / "old.pl"
    old.write_text("setting(seed, 3).\nsetting(samples, 31).\nsetting(max_rules, 8).\n"
                   "setting(threshold_permille, 100).\nsetting(prior, 1).\n"
                   "rule(r0_no_spill, defeasible, no_spill).\nbody(r0_no_spill, pour_low).\n")
    s = loading.settings(loading.load([old]))
    assert s["batch"] == [31] and s["budget"] == [8] and s["slope_permille"] == [100]
    assert s["prior_batch"] == [1] and "samples" not in s and "max_rules" not in s


def test_swi_prolog_is_started_only_for_a_theory_it_has_something_to_check(tmp_path: Path) -> None:
    """A theory without a general rule or a sup/2 pair gives the checks
    made in SWI-Prolog nothing to look at: reading it (convert, rules, the
    loading benchmark's theories) starts no engine; with a sup/2 pair it
    does."""
    import subprocess
    import sys

    plain = tmp_path / "plain.pl"
    plain.write_text("rule(r1, defeasible, no_spill).\nbody(r1, pour_to_side).\n")
    ordered = tmp_path / "ordered.dfl"
    ordered.write_text("r1: pour_to_side => no_spill\nr2: pour_to_side => -no_spill\nr1 > r2\n")
    code = ("import sys; from pantarhei.bridge.theories.loading import load; load(sys.argv[1]); "
            "print('pyswip' in sys.modules)")
    started = [subprocess.run([sys.executable, "-c", code, str(p)], capture_output=True, text=True,
                              timeout=120).stdout.strip() for p in (plain, ordered)]
    assert started == ["False", "True"]
