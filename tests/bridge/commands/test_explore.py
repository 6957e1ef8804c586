"""`pantarhei explore` and `pantarhei prolog` (bridge/commands/explore.py) as a
user runs them. The oracle at the prompt: exploration/test_prompt_oracle.py."""
from __future__ import annotations

import re

import pytest

from tests.conftest import assert_one_line_error, run_cli

FAST = ["--oracle", "synthetic", "--executor", "inline", "--no-progress"]


@pytest.mark.parametrize("args, words", [
    (["--initial", "pour_sideways"], "unknown proposition 'pour_sideways'"),
    (["--initial", "pour_low,pour_high"], "invalid antecedent"),
    (["--budget", "0"], "argument --budget: must be at least 1, not 0"),
    (["--pours", "0"], "argument --pours: must be at least 1, not 0"),
    (["--oracle", "nope"], "invalid choice"),
    (["--curiosity", "wild"], "invalid choice"),
    (["--body", "5"], "argument --body: must be at most 4, not 5"),
    (["--queue", "0"], "argument --queue: must be at least 1, not 0"),
    (["--uncertainty", "-1"], "argument --uncertainty: must be at least 0, not -1"),
    # an option of explore/1 alone is no flag
    (["--novelty", "0.5"], "unrecognized arguments: --novelty"),
])
def test_bad_input_is_one_line_and_nonzero(tmp_path, args, words):
    r = run_cli("explore", *FAST, *args, "--out", str(tmp_path / "t.pl"),
                "--store", str(tmp_path / "s.sqlite"))
    assert r.code != 0
    assert words in r.err
    assert len(r.err.strip().splitlines()) == 1 and "Traceback" not in r.err
    assert not (tmp_path / "t.pl").exists()


def test_explore_has_at_most_20_flags():
    r = run_cli("explore", "--help")
    assert r.code == 0, r.err
    flags = set(re.findall(r"(?<![\w-])(--[a-z][a-z-]*)", r.out)) - {"--help"}
    assert 0 < len(flags) <= 20, sorted(flags)


def test_each_option_the_command_line_leaves_is_explore_1_s_and_named_in_dropped():
    """An option of explore/1 alone has no flag, is still an option of
    explore/1, and docs/dropped.md names it (as `name(value)`) with the
    figure that kept its default."""
    from pantarhei.theory import THEORY_DIR
    from pantarhei.theory.option_table import option_table

    dropped = (THEORY_DIR.parent / "docs" / "dropped.md").read_text(encoding="utf-8")
    help_text = run_cli("explore", "--help").out
    alone = [o for o in option_table() if o.prolog_only]
    assert alone
    for o in alone:
        assert o.flag not in help_text, o.flag
        assert f"`{o.name}(" in dropped, f"docs/dropped.md does not name {o.name}"


def test_explore_1_checks_an_option_of_its_own_in_one_line(tmp_path):
    goal = (f"explore([curiosity(discover), oracle(synthetic), budget(1), novelty(1.5), "
            f"out('{tmp_path / 'p.pl'}'), store('{tmp_path / 's.sqlite'}')])")
    line = assert_one_line_error(run_cli("prolog", "-g", goal), code=1)
    assert "novelty: expected a number from 0 to 1" in line, line
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("args, words", [
    (["--curiosity", "learn", "--budget", "5"],
     "budget: not an option of curiosity(learn), whose budget is pours(N); its own options are "
     "pours, body, queue, uncertainty, doubt, newness, reach and whole_every (budget is read by "
     "curiosity(discover) and curiosity(paper))"),
    (["--budget", "5"], "budget: not an option of curiosity(learn), whose budget is pours(N)"),
    (["--curiosity", "discover", "--pours", "40"],
     "pours: not an option of curiosity(discover), whose budget is budget(N)"),
    (["--curiosity", "paper", "--body", "1"], "body: not an option of curiosity(paper); "),
    (["--curiosity", "learn", "--no-general"], "general: not an option of curiosity(learn); "),
])
def test_a_flag_the_curiosity_does_not_read_is_refused_in_one_line(tmp_path, args, words):
    r = run_cli("explore", *FAST, *args, "--out", str(tmp_path / "t.pl"),
                "--store", str(tmp_path / "s.sqlite"))
    assert words in assert_one_line_error(r)
    assert not (tmp_path / "t.pl").exists()


def test_python_passes_explore_1_the_options_its_curiosity_reads():
    """The options Python passes: those the chosen curiosity reads, and
    another only when set to another value than its default (which
    explore/1 refuses)."""
    from pantarhei.bridge.exploration.explore_call import ExploreOptions
    from pantarhei.theory.option_table import option_table

    for curiosity in ("learn", "discover", "paper"):
        passed = {item.split("(")[0] for item in ExploreOptions(curiosity=curiosity).prolog()
                  .strip("[]").split(", ")}
        assert passed and all(o.read_by(curiosity) for o in option_table() if o.name in passed)
        assert {"pours" if curiosity == "learn" else "budget", "seed", "out"} <= passed
    assert "budget(5)" in ExploreOptions(curiosity="learn", budget=5).prolog()
    assert "budget(" not in ExploreOptions(curiosity="learn", budget=25).prolog()
    # and explore/1 takes them
    from pantarhei.bridge.exploration.session import install

    for curiosity in ("learn", "discover", "paper"):
        o = ExploreOptions(curiosity=curiosity, oracle="synthetic")
        r = install().once(f"curiosity_settings:settings({o.prolog()}, S), get_dict(curiosity, S, C)")
        assert str(r["C"]) == curiosity


@pytest.mark.parametrize("store, out, words", [
    ("x.sqlite", "x.sqlite", "--store and --out are the same file"),
    ("x.trace.jsonl", "x.pl", "--store and --out's trace are the same file"),
    ("x.trace.png", "x.pl", "--store and --out's trace plot are the same file"),
])
def test_one_file_for_two_roles_is_refused_before_anything_is_written(tmp_path, store, out, words):
    r = run_cli("explore", *FAST, "--pours", "4", "--batch", "4",
                "--store", str(tmp_path / store), "--out", str(tmp_path / "sub" / ".." / out))
    assert words in assert_one_line_error(r)
    assert list(tmp_path.iterdir()) == []


def test_explore_1_at_the_prolog_prompt_refuses_one_file_for_two_roles_too(tmp_path):
    import sqlite3

    store = tmp_path / "x.sqlite"
    with sqlite3.connect(store) as db:          # what must survive
        db.execute("CREATE TABLE keep (x)")
        db.execute("INSERT INTO keep VALUES (1)")
    r = run_cli("prolog", "-g", f"explore([oracle(synthetic), pours(4), store('{store}'), "
                                f"out('{tmp_path / 'sub' / '..' / 'x.sqlite'}')])")
    assert r.code != 0
    assert "store(...) and out(...) are the same file" in r.err and "Traceback" not in r.err
    with sqlite3.connect(store) as db:
        assert db.execute("SELECT x FROM keep").fetchall() == [(1,)]


def test_explore_command_reports_what_it_wrote(tmp_path):
    out = tmp_path / "sub" / "learned.pl"
    r = run_cli("explore", *FAST, "--curiosity", "paper", "--budget", "3", "--batch", "12", "--no-general",
                "--out", str(out), "--store", str(tmp_path / "s.sqlite"))
    assert r.code == 0, r.err
    assert out.is_file() and out.with_suffix(".trace.jsonl").is_file()
    # what it says it explored is what its trace holds: one line an antecedent
    steps = out.with_suffix(".trace.jsonl").read_text().splitlines()
    assert 1 <= len(steps) <= 3
    assert f"explored {len(steps)} antecedents with {12 * len(steps)} simulations" in r.out
    assert out.with_suffix(".trace.png").is_file()
    assert "setting(batch, 12)." in out.read_text()


def test_progress_counts_the_budget_it_spends(tmp_path):
    """The discovering curiosity's budget is in pours (probes included), so
    its progress bar counts pours against `budget` batches of them; the
    paper's counts explored antecedents."""
    base = ["--oracle", "synthetic", "--executor", "inline", "--budget", "3", "--batch", "12",
            "--no-general", "--store", str(tmp_path / "s.sqlite")]
    r = run_cli("explore", *base, "--curiosity", "discover", "--out", str(tmp_path / "d.pl"))
    assert r.code == 0, r.err
    last = [ln for ln in r.err.replace("\r", "\n").splitlines() if ln.startswith("exploring")][-1]
    spent = int(r.out.split(" simulations")[0].split()[-1])
    assert f"{spent}/36" in last and "pour" in last, last
    assert "stopped: 36 pours" in r.out        # the budget as the curiosity counts it
    r = run_cli("explore", *base, "--curiosity", "paper", "--out", str(tmp_path / "p.pl"))
    assert r.code == 0, r.err
    last = [ln for ln in r.err.replace("\r", "\n").splitlines() if ln.startswith("exploring")][-1]
    explored = int(r.out.split("explored ")[1].split()[0])   # A_new may empty before the budget
    assert f"{explored}/3" in last and "rule" in last, last


def test_prolog_command_drives_exploration(tmp_path):
    out = tmp_path / "p.pl"
    goal = (f"explore([curiosity(paper), oracle(synthetic), budget(2), executor(inline), progress(false), "
            f"general(false), out('{out}'), store('{tmp_path / 's.sqlite'}')]), "
            f"theory_files:load_facts('{out}', m), aggregate_all(count, m:rule(_, _, _), N), "
            f"format('rules: ~w~n', [N])")
    r = run_cli("prolog", "-g", goal)
    assert r.code == 0, r.err
    assert "rules: 18" in r.out


A0_QUESTION = ("what_happens([pour_near_rim, pour_mid_height, pour_steeply_tilted], O), "
               "forall(member(outcome(E, V, _, R), O), format('~w ~w ~w~n', [E, V, R])).")


def _decided_by_shipped_rules(out: str) -> list[str]:
    """The rules of the shipped theory that decide an expectation in `out`."""
    from pantarhei.bridge.theories.loading import DEFAULT_THEORY, load

    ids = {r.id for r in load([DEFAULT_THEORY]).rules}
    lines = [ln.split() for ln in out.splitlines() if len(ln.split()) == 3]
    return [r for _e, v, r in lines if v in ("holds", "fails", "uncertain") and r in ids]


def test_explore_at_the_prompt_refuses_an_unknown_option_before_it_runs(tmp_path):
    goal = (f"explore([curiosity(paper), oracle(synthetic), budget(1), batch(4), executor(inline), "
            f"progress(false), general(false), seeed(3), out('{tmp_path / 'p.pl'}'), "
            f"store('{tmp_path / 's.sqlite'}')])")
    r = run_cli("prolog", "-g", goal)
    line = assert_one_line_error(r, code=1)
    assert "unknown option seeed(3)" in line, line
    assert list(tmp_path.iterdir()) == []


def test_prolog_command_interactive_prompt_has_the_shipped_theory(tmp_path):
    import subprocess
    import sys

    p = subprocess.run([sys.executable, "-m", "pantarhei.bridge", "prolog"],
                       input=A0_QUESTION + "\nhalt.\n", capture_output=True, text=True, timeout=120)
    assert _decided_by_shipped_rules(p.stdout), p.stdout + p.stderr


def test_prolog_command_loads_the_theory_it_is_given(tmp_path):
    t = tmp_path / "mine.dfl"
    t.write_text("mine: pour_to_side => neg(no_spill)\n")
    r = run_cli("prolog", "--theory", str(t), "-g",
                "what_happens([pour_to_side], O), memberchk(outcome(no_spill, V, _, R), O), "
                "format('~w ~w~n', [V, R])")
    assert r.code == 0, r.err
    assert r.out.split() == ["fails", "mine"]


def test_plain_swipl_answers_with_the_shipped_theory():
    import subprocess

    from pantarhei.theory import PROLOG_ENTRY

    p = subprocess.run(["swipl", "-q", "-g", A0_QUESTION.rstrip("."), "-t", "halt", str(PROLOG_ENTRY)],
                       capture_output=True, text=True, timeout=120, cwd="/")
    assert p.returncode == 0, p.stderr
    assert _decided_by_shipped_rules(p.stdout), p.stdout + p.stderr


def test_what_happens_without_a_theory_says_how_to_load_one():
    import subprocess

    from pantarhei.theory import PROLOG_ENTRY

    p = subprocess.run(["swipl", "-q", "-g", "clear_theory, what_happens([pour_to_side], _)", "-t", "halt",
                        str(PROLOG_ENTRY)], capture_output=True, text=True, timeout=120)
    assert p.returncode != 0
    assert "no theory is loaded" in p.stderr and "load_theory" in p.stderr
