"""`pantarhei ask` and `conclusions` (bridge/commands/querying.py; `plan`
is tests/bridge/commands/test_plan.py),
run as a user runs them: their output, their one-line errors, and the
answers, plans and conclusions of bridge/reasoning (answers.py,
planning.py, logic.py) and bridge/reasoning/reading.py as the commands give
them."""
from __future__ import annotations

import re

import itertools
import json
from pathlib import Path

import pytest

from tests.conftest import assert_one_line_error

EX = Path(__file__).resolve().parents[3] / "examples" / "extend_by_hand"
LEARNED = str(EX / "learned.pl")
HAND = str(EX / "hand.dfl")
SCENE = "light_liquid,pour_steeply_tilted,slow_retreat,pour_centred"


def test_ask_in_words_says_what_it_understood_and_why(cli) -> None:
    r = cli("ask", "pour from the side with a light liquid", "--theory", LEARNED)
    assert r.code == 0, r.err
    assert "understood: light_liquid, pour_to_side" in r.out
    assert "[no        ] no_spill" in r.out and "rule r1" in r.out


def test_ask_json_before_and_after_a_rule_added_by_hand(cli) -> None:
    before = json.loads(cli("ask", "--props", SCENE, "--theory", LEARNED, "--json").out)
    after = json.loads(cli("ask", "--props", SCENE, "--theory", LEARNED, "--theory", HAND, "--json").out)
    assert before["understood"] == sorted(SCENE.split(","))
    assert {o["verdict"] for o in before["outcomes"].values()} <= {"holds", "fails", "unknown"}
    assert len(before["outcomes"]) == 9
    leaves, leaves_after = (x["outcomes"]["liquid_leaves_source"] for x in (before, after))
    assert leaves["verdict"] == "fails" and leaves["rule"] == "r4"
    assert leaves["likelihood"] is None        # hand-written rules record none
    assert leaves_after["verdict"] == "holds" and leaves_after["rule"] == "h1"
    assert before["outcomes"]["no_spill"]["verdict"] == after["outcomes"]["no_spill"]["verdict"] == "holds"


def test_ask_why_and_why_not(cli) -> None:
    why = cli("ask", "--props", "light_liquid,pour_steeply_tilted", "--theory", LEARNED,
              "--why", "neg(liquid_leaves_source)")
    assert why.code == 0, why.err
    assert "by rule r4" in why.out and "r3 is overridden by r4" in why.out
    why_not = json.loads(cli("ask", "--props", "pour_to_side", "--theory", LEARNED,
                             "--why", "no_spill", "--json").out)
    assert why_not["literal"] == "no_spill"
    assert "rule r2 (pour_centred => no_spill) does not apply" in why_not["why"]


def test_conclusions_of_both_engines_agree_and_use_dfl_literals(cli, tmp_path: Path) -> None:
    f = tmp_path / "t.dfl"
    f.write_text(">> bird\n>> penguin\nr1: bird => flies\nr2: penguin => -flies\nr2 > r1\n")
    out = {e: json.loads(cli("conclusions", str(f), "--engine", e, "--json").out) for e in ("prolog", "asp")}
    assert out["prolog"] == out["asp"]
    assert set(out["prolog"]) == {"+D", "-D", "+d", "-d"}
    assert "-flies" in out["prolog"]["+d"] and "flies" in out["prolog"]["-d"]
    loop = tmp_path / "loop.pl"
    loop.write_text("rule(r1, defeasible, p).\nbody(r1, q).\nrule(r2, defeasible, q).\nbody(r2, p).\n")
    wf = json.loads(cli("conclusions", str(loop), "--json").out)
    kunen = json.loads(cli("conclusions", str(loop), "--no-well-founded", "--engine", "asp", "--json").out)
    assert "p" in wf["-d"] and "p" not in kunen["-d"]
    text = cli("conclusions", str(loop)).out
    assert "-d p\n" in text


@pytest.mark.parametrize("engine", ["prolog", "asp"])
@pytest.mark.parametrize("text,out", [
    ("=> a\n", "-D a\n-D -a\n+d a\n-d -a\n"),
    ("-> a\n", "+D a\n-D -a\n+d a\n-d -a\n"),
    (">> a\n", "+D a\n-D -a\n+d a\n-d -a\n"),
])
def test_a_theory_of_facts_only_from_the_command_line(cli, engine: str, text: str, out: str,
                                                      tmp_path: Path) -> None:
    """In a process of its own, as a user runs it."""
    f = tmp_path / "facts.dfl"
    f.write_text(text)
    r = cli("conclusions", str(f), "--engine", engine)
    assert (r.code, r.out, r.err) == (0, out, "")


@pytest.mark.parametrize("args,words", [
    (("ask", "--props", "pour_to_sid", "--theory", LEARNED), "did you mean pour_to_side"),
    (("ask", "--props", "pour_to_side,pour_centred", "--theory", LEARNED), "one_value_per_dimension"),
    (("ask", "--props", "pour_below_rim,pour_centred", "--theory", LEARNED), "inside_destination"),
    (("ask", "sing me a song", "--theory", LEARNED), "understood none"),
    (("conclusions", "/nonexistent/theory.dfl"), "no such theory file"),
])
def test_bad_input_gets_one_line_and_a_non_zero_exit(cli, args, words: str) -> None:
    line = assert_one_line_error(cli(*args))
    assert words in line, line


def test_malformed_files_name_the_line(cli, tmp_path: Path) -> None:
    f = tmp_path / "bad.dfl"
    f.write_text("r1: a => b\nr2 b -> c\n")
    assert f"{f}:2:" in assert_one_line_error(cli("conclusions", str(f)))
    g = tmp_path / "bad.pl"
    g.write_text("rule(r1, defeasible, b).\nrule(r2, maybe, c).\n")
    assert f"{g}:2:" in assert_one_line_error(cli("ask", "--props", "pour_centred", "--theory", str(g)))


def test_the_shipped_theory_answers_without_a_theory_option(cli) -> None:
    from pantarhei.bridge.theories.loading import DEFAULT_THEORY, load, settings

    shipped = load()
    assert shipped.source == str(DEFAULT_THEORY)
    s = settings(shipped)
    assert s["oracle"] == ["pybullet"] and s["curiosity"] == ["learn"]
    # every pour in the budget, none of the learner's own
    assert s["simulations"][0] <= s["pours"][0] == 775 and s["general_own_pours"] == [0]
    assert 1 <= s["explored"][0] <= s["simulations"][0] // s["batch"][0]
    r = cli("ask", "--props", "light_liquid", "--json")
    assert r.code == 0, r.err
    import json

    answer = json.loads(r.out)
    # the rules decide a one-phrase question, each answer with its likelihood
    outcomes = answer["outcomes"].values()
    assert {o["verdict"] for o in outcomes} <= {"holds", "fails", "uncertain"}
    assert all(o["rule"].startswith("g") and 0 <= o["likelihood"] <= 1 for o in outcomes)
    assert all((o["verdict"] == "holds") == (o["likelihood"] >= 0.65) for o in outcomes)


# -- a question is asked as given --------------------------------------------------

# a_0 of the exploration in file order; r1 needs all of it, r2 the side instead
# of the centre, r3 a pour below the rim (where the centre would be invalid).
ORDINARY = """\
setting(seed, 1).
setting(initial, pour_mid_height).
setting(initial, pour_centred).
setting(initial, pour_steeply_tilted).
rule(r1, defeasible, no_spill).
body(r1, light_liquid).
body(r1, pour_mid_height).
body(r1, pour_centred).
body(r1, pour_steeply_tilted).
rule(r2, defeasible, neg(no_spill)).
body(r2, pour_to_side).
body(r2, pour_mid_height).
body(r2, pour_steeply_tilted).
rule(r3, defeasible, liquid_leaves_source).
body(r3, pour_below_rim).
body(r3, pour_steeply_tilted).
"""


@pytest.fixture
def ordinary(tmp_path: Path) -> str:
    f = tmp_path / "ordinary.pl"
    f.write_text(ORDINARY)
    return str(f)


def test_a_value_asked_for_with_a_goal_is_the_goal_of_the_ordinary_pour(cli, ordinary: str) -> None:
    # "how high should I hold it": a plan's to find; the goal is heard, the scene is the
    # ordinary pour, said so, and plan is pointed to
    r = cli("ask", "how high should I hold it so nothing spills", "--theory", ordinary)
    assert r.code == 0, r.err
    assert r.out.splitlines()[0] == "understood: the ordinary pour (nothing said of the scene)"
    assert "wanted: no_spill" in r.out and "pantarhei plan --goal no_spill" in r.out
    r = cli("ask", "how high should I hold it", "--theory", ordinary)
    assert r.code != 0 and "asks for a value" in r.err and "pantarhei plan" in r.err


def test_ask_asks_the_question_as_given(cli, ordinary: str) -> None:
    # the ordinary pour's rule r1 needs pour_mid_height, pour_centred, pour_steeply_tilted:
    # a question that leaves them out is not completed with them
    r = cli("ask", "--props", "light_liquid", "--theory", ordinary)
    assert r.code == 0, r.err
    assert r.out.splitlines()[0] == "understood: light_liquid"
    assert "assumed" not in r.out
    assert "[?         ] no_spill" in r.out
    out = json.loads(cli("ask", "--props", "light_liquid", "--theory", ordinary, "--json").out)
    assert out["understood"] == ["light_liquid"] and "assumed" not in out
    assert out["outcomes"]["no_spill"]["verdict"] == "unknown"
    full = json.loads(cli("ask", "--props", "light_liquid,pour_mid_height,pour_centred,"
                          "pour_steeply_tilted", "--theory", ordinary, "--json").out)
    assert full["outcomes"]["no_spill"]["verdict"] == "holds"
    assert full["outcomes"]["no_spill"]["rule"] == "r1"


def test_ask_says_the_deciding_rule_in_words_with_its_evidence(cli, tmp_path: Path) -> None:
    # one voice: the likelihood that the expectation holds (the pooled
    # estimate), and the pours of the deciding rule's body counted for the
    # expectation holding, whatever the polarity of the rule's head
    f = tmp_path / "general.pl"
    f.write_text("rule(g0_no_spill, defeasible, no_spill).\nlearned(g0_no_spill).\n"
                 "provenance(g0_no_spill, support, 60).\nprovenance(g0_no_spill, kept, 50).\n"
                 "provenance(g0_no_spill, confidence_permille, 830).\n"
                 "rule(g1_no_spill, defeasible, neg(no_spill)).\nbody(g1_no_spill, pour_to_side).\n"
                 "learned(g1_no_spill).\nprovenance(g1_no_spill, support, 52).\n"
                 "provenance(g1_no_spill, kept, 41).\n"
                 "provenance(g1_no_spill, confidence_permille, 912).\n")
    r = cli("ask", "pour from the side", "--theory", str(f))
    assert r.code == 0, r.err
    assert "[no      9%] no_spill" in r.out
    # a failing head: 41 of its 52 pours kept neg(no_spill), so it held in 11
    assert ("because pour from the side: holds in 9% of such pours (the pooled estimate)\n"
            "            held in 11 of 52 pours of pour from the side (rule g1_no_spill)\n") in r.out
    # a holding head, and a proposition asked that has no rule of its own
    light = cli("ask", "--props", "light_liquid", "--theory", str(f))
    assert "[yes    83%] no_spill" in light.out
    assert ("because an ordinary pour: holds in 83% of such pours (the pooled estimate)\n"
            "            held in 50 of 60 ordinary pours (rule g0_no_spill)\n"
            "            a light liquid: no rule of its own decides this, so it is answered as "
            "an ordinary pour\n") in light.out
    out = json.loads(cli("ask", "--props", "light_liquid", "--theory", str(f), "--json").out)
    assert out["outcomes"]["no_spill"]["evidence"] == {
        "held": 50, "pours": 60, "of": [], "explored": None, "body": [],
        "unruled": ["light_liquid"]}
    assert out["outcomes"]["source_clear"]["rule"] is None      # unknown: no rule
    assert out["outcomes"]["source_clear"]["evidence"] is None
    # where such pours split, the answer says so
    f.write_text(f.read_text().replace("confidence_permille, 912", "confidence_permille, 550"))
    maybe = json.loads(cli("ask", "pour from the side", "--theory", str(f), "--json").out)
    assert maybe["outcomes"]["no_spill"] == {
        "verdict": "uncertain", "likelihood": 0.45, "rule": "g1_no_spill",
        "because": "because pour from the side: holds in 45% of such pours (the pooled estimate); "
                   "held in 11 of 52 pours of pour from the side (rule g1_no_spill)",
        "evidence": {"held": 11, "pours": 52, "of": ["pour_to_side"], "explored": None,
                     "body": ["pour_to_side"], "unruled": []}}


EXPLORED = """\
rule(g0_no_spill, defeasible, no_spill).
learned(g0_no_spill).
provenance(g0_no_spill, support, 60).
provenance(g0_no_spill, kept, 50).
provenance(g0_no_spill, confidence_permille, 830).
rule(g1_no_spill, defeasible, neg(no_spill)).
body(g1_no_spill, pour_to_side).
learned(g1_no_spill).
provenance(g1_no_spill, support, 52).
provenance(g1_no_spill, kept, 41).
provenance(g1_no_spill, confidence_permille, 912).
held(a1, no_spill, 50, 60).
explored(a2, light_liquid).
held(a2, no_spill, 11, 12).
explored(a3, heavy_liquid).
held(a3, no_spill, 2, 12).
explored(a4, light_liquid).
explored(a4, pour_to_side).
held(a4, no_spill, 1, 9).
"""


def test_ask_cites_the_pours_of_an_antecedent_explored_without_a_rule_of_its_own(
        cli, tmp_path: Path) -> None:
    # light_liquid and heavy_liquid were explored (held/4) but have no rule
    # for no_spill: the answer is the ordinary pour's, and the pours it
    # cites are those of the antecedent asked, in the likelihood's polarity
    f = tmp_path / "explored.pl"
    f.write_text(EXPLORED)
    light = cli("ask", "--props", "light_liquid", "--theory", str(f))
    assert light.code == 0, light.err
    assert ("[yes    83%] no_spill" in light.out and
            "because an ordinary pour: holds in 83% of such pours (the pooled estimate)\n"
            "            held in 11 of 12 pours of a light liquid (explored, no rule of its own: "
            "its pours agree with rule g0_no_spill)\n") in light.out
    assert "no rule of its own decides this" not in light.out
    # where its pours say otherwise than the rule that decides, it says so
    heavy = cli("ask", "--props", "heavy_liquid", "--theory", str(f))
    assert ("held in 2 of 12 pours of a heavy liquid (explored, no rule of its own: "
            "rule g0_no_spill decides, though its pours differ)\n") in heavy.out
    # an antecedent of two, under a failing head: counted for no_spill holding
    side = cli("ask", "--props", "light_liquid,pour_to_side", "--theory", str(f))
    assert ("because pour from the side: holds in 9% of such pours (the pooled estimate)\n"
            "            held in 1 of 9 pours of a light liquid, pour from the side (explored, "
            "no rule of its own: its pours agree with rule g1_no_spill)\n") in side.out
    out = json.loads(cli("ask", "--props", "light_liquid", "--theory", str(f), "--json").out)
    assert out["outcomes"]["no_spill"]["evidence"] == {
        "held": 11, "pours": 12, "of": ["light_liquid"], "explored": "a2", "body": [],
        "unruled": ["light_liquid"]}
    # an antecedent not explored is answered as before
    tilted = cli("ask", "--props", "pour_steeply_tilted", "--theory", str(f))
    assert "held in 50 of 60 ordinary pours (rule g0_no_spill)\n" in tilted.out
    assert ": no rule of its own decides this, so it is answered as an ordinary pour" in tilted.out
    # --why gives the same answer with its evidence, in words and as JSON
    why = cli("ask", "--props", "light_liquid", "--theory", str(f), "--why", "no_spill")
    assert why.code == 0, why.err
    assert "no_spill by rule g0_no_spill" in why.out
    assert ("\n  held in 11 of 12 pours of a light liquid (explored, no rule of its own: "
            "its pours agree with rule g0_no_spill)\n") in why.out
    why_json = json.loads(cli("ask", "--props", "light_liquid", "--theory", str(f),
                              "--why", "neg(no_spill)", "--json").out)
    assert why_json["answer"]["evidence"]["explored"] == "a2"
    assert why_json["answer"]["because"] == out["outcomes"]["no_spill"]["because"]


def test_ask_why_in_words(cli, ordinary: str) -> None:
    r = cli("ask", "--props", "light_liquid,pour_mid_height,pour_centred,pour_steeply_tilted",
            "--theory", ordinary, "--why", "no_spill")
    assert r.code == 0, r.err
    assert "no_spill by rule r1" in r.out
    out = json.loads(cli("ask", "--props", "light_liquid", "--theory", ordinary, "--why", "no_spill",
                         "--json").out)
    assert "no_spill is not concluded" in out["why"]


# -- a short why-not on a large theory --------------------------------------------

def test_why_not_names_few_rules_however_many_there_are(cli, tmp_path: Path) -> None:
    # r0 misses one proposition of the scene, r1..r150 two each
    lines = ["rule(r0, defeasible, no_spill).", "body(r0, pour_mid_height).", "body(r0, pour_near_rim)."]
    for i in range(1, 151):
        head = "no_spill" if i % 2 else "neg(no_spill)"
        lines += [f"rule(r{i}, defeasible, {head}).", f"body(r{i}, pour_near_rim).",
                  f"body(r{i}, pour_mid_height).", f"body(r{i}, other{i})."]
    f = tmp_path / "many.pl"
    f.write_text("\n".join(lines) + "\n")
    r = cli("ask", "--props", "pour_to_side,pour_mid_height", "--theory", str(f))
    assert r.code == 0, r.err
    out = r.out.splitlines()
    at = out.index(next(line for line in out if "[?         ] no_spill" in line))
    block = list(itertools.takewhile(lambda line: line.startswith(" " * 8), out[at + 1:]))
    assert block[0] == "          why not: no rule for no_spill or neg(no_spill) applies"
    assert block[1].startswith("            rule r0 (pour_mid_height, pour_near_rim => no_spill) "
                               "also needs pour_near_rim (instead of pour_to_side)")
    assert len(block) <= 4 and len(r.out) < 3000, r.out
    # ... and --why still lists every rule for the literal
    why = cli("ask", "--props", "pour_to_side,pour_mid_height", "--theory", str(f), "--why", "no_spill")
    assert why.code == 0, why.err
    assert sum("does not apply" in line for line in why.out.splitlines()) == 76


def test_the_shipped_theory_is_current_and_its_dfl_twin_agrees() -> None:
    """The shipped theory was learned with today's oracle and settings, and
    its DFL version (written by make demo) holds the same rules."""
    from pantarhei.bridge.exploration.session import ALGORITHM_VERSION
    from pantarhei.bridge.exploration.simulation import oracle_identity
    from pantarhei.bridge.theories.loading import DEFAULT_THEORY, load, settings

    native = load()
    s = settings(native)
    assert [str(v) for v in s["oracle_version"]] == [oracle_identity("pybullet")[0]], \
        "the oracle changed: learn the shipped theory again with make demo"
    # the version the shipped theory was learned with (make demo): learn it
    # again, and set this, when the course of an exploration changes
    assert ALGORITHM_VERSION == "5"
    dfl = load([DEFAULT_THEORY.with_suffix(".dfl")])
    assert {(r.id, r.head, frozenset(r.body)) for r in dfl.rules} == \
           {(r.id, r.head, frozenset(r.body)) for r in native.rules}


def test_the_same_why_not_is_said_once(cli, tmp_path: Path) -> None:
    """A theory whose rules need pouring high or centred (and, for no_spill,
    pouring low): nothing applies to pouring from the side, and the nine "?"
    share why-nots, each printed once with the rules it names; the others
    point back to it."""
    from pantarhei.theory.lexicon import load_vocabulary

    lines = []
    for e in load_vocabulary().expectation_names:
        yes, no = ("pour_low", "pour_centred") if e == "no_spill" else ("pour_high", "pour_centred")
        lines += [f"rule(h_{e}, defeasible, {e}).", f"body(h_{e}, {yes}).",
                  f"rule(c_{e}, defeasible, neg({e})).", f"body(c_{e}, {no})."]
    f = tmp_path / "bodies.pl"
    f.write_text("\n".join(lines) + "\n")
    r = cli("ask", "pour from the side", "--theory", str(f))
    assert r.code == 0, r.err
    assert r.out.count("[?         ]") == 9
    said = len(re.findall(r"why not: no rule (for|concludes)", r.out))
    pointed = re.findall(r"why not: as for (\w+)", r.out)
    assert said + len(pointed) == 9 and pointed
    # each points back to an expectation whose why-not is said in full above it
    full = []
    for line in r.out.splitlines():
        if line.lstrip().startswith("[?         ]"):
            current = line.split()[2]
        elif re.search(r"why not: no rule (for|concludes)", line):
            full.append(current)
        elif "why not: as for" in line:
            assert line.split()[-1] in full
    assert len(r.out.splitlines()) < 12 * said + 12
    # a rule of the same dimension is named with what it needs instead (on a
    # theory of its own: which rules come nearest depends on the theory)
    g = tmp_path / "far.pl"
    g.write_text("rule(x_no_spill, defeasible, neg(no_spill)).\nbody(x_no_spill, pour_far_away).\n")
    far = cli("ask", "pour from the side", "--theory", str(g))
    assert far.code == 0, far.err
    assert "(instead of pour_to_side)" in far.out


def _limited_file_size(limit: int):
    """For a subprocess: files larger than `limit` bytes cannot be written
    (the kernel fails the write with EFBIG, as a full disk fails it with
    ENOSPC; Python ignores the signal that comes with it)."""
    import resource

    def preexec() -> None:
        resource.setrlimit(resource.RLIMIT_FSIZE, (limit, limit))
    return preexec


def test_convert_that_cannot_write_its_output_says_so_in_one_line(tmp_path: Path) -> None:
    import os
    import subprocess
    import sys

    out = tmp_path / "learned.dfl"
    p = subprocess.run([sys.executable, "-m", "pantarhei.bridge", "convert", LEARNED, "-o", str(out)],
                       capture_output=True, text=True, stdin=subprocess.DEVNULL,
                       preexec_fn=_limited_file_size(512), env={**os.environ, "PYTHONDONTWRITEBYTECODE": "1"})
    from tests.conftest import Run

    line = assert_one_line_error(Run(p.returncode, p.stdout, p.stderr))
    assert line.startswith(f"pantarhei convert: -o {out}: cannot write (") and "nothing was written" in line
    assert os.listdir(tmp_path) == []       # no half file, no temporary


def test_convert_into_a_read_only_folder_says_so_in_one_line(tmp_path: Path, monkeypatch, capsys) -> None:
    """A read-only file system refuses even root: the temporary file beside
    the output cannot be made."""
    import errno
    import tempfile

    from pantarhei.bridge.cli import main

    def read_only(*args, **kwargs):
        raise OSError(errno.EROFS, "Read-only file system")

    monkeypatch.setattr(tempfile, "mkstemp", read_only)
    out = tmp_path / "learned.dfl"
    assert main(["convert", LEARNED, "-o", str(out)]) == 2
    err = capsys.readouterr().err
    assert err == f"pantarhei convert: -o {out}: cannot write (Read-only file system); nothing was written\n"
    assert not out.exists()


def _ask_stdin(data: bytes, *args: str, timeout: float = 60):
    """`pantarhei ask ARGS` with `data` on standard input."""
    import subprocess
    import sys

    from tests.conftest import Run

    p = subprocess.run([sys.executable, "-m", "pantarhei.bridge", "ask", "--theory", LEARNED, *args],
                       input=data, capture_output=True, timeout=timeout)
    return Run(p.returncode, p.stdout.decode(), p.stderr.decode())


def test_ask_json_on_standard_input_writes_json_lines() -> None:
    r = _ask_stdin(b"pour from the side\n\n# a comment\nsing me a song\npour low\n", "--json")
    assert r.code == 1
    lines = r.out.splitlines()
    assert len(lines) == 2, r.out
    first, second = (json.loads(line) for line in lines)
    assert (first["line"], first["question"], first["understood"]) == (1, "pour from the side", ["pour_to_side"])
    assert (second["line"], second["question"], second["understood"]) == (5, "pour low", ["pour_low"])
    assert set(first["outcomes"]) == set(second["outcomes"]) and len(first["outcomes"]) == 9
    assert r.err.startswith("pantarhei ask: line 4: understood none of") and len(r.err.splitlines()) == 1
    r = _ask_stdin(b"pour low\n", "--json", "--why", "no_spill")
    assert r.code == 0 and len(r.out.splitlines()) == 1 and json.loads(r.out)["literal"] == "no_spill"


def test_a_question_that_is_not_utf8_says_so() -> None:
    import subprocess
    import sys

    r = _ask_stdin(b"pour \xff low\npour low\n")
    assert r.code == 1
    assert r.err == "pantarhei ask: line 1: the question: byte 0xff is not UTF-8: give text in UTF-8\n"
    assert "understood: pour_low" in r.out
    # and as an argument (which pyswip used to take for a missing SWI-Prolog)
    import os

    for args, what in (([os.fsdecode(b"pour \xfe low")], "the question"),
                       (["--props", "pour_low", "--why", os.fsdecode(b"no_spill\xfe")], "--why")):
        p = subprocess.run([sys.executable, "-m", "pantarhei.bridge", "ask", *args], capture_output=True,
                           text=True, stdin=subprocess.DEVNULL)
        from tests.conftest import Run

        line = assert_one_line_error(Run(p.returncode, p.stdout, p.stderr))
        assert line == f"pantarhei ask: {what}: byte 0xfe is not UTF-8: give text in UTF-8", line


def test_one_long_line_on_standard_input_is_answered_in_time_linear_in_it() -> None:
    """190 KB in one line (it took 73 s)."""
    line = " ".join(["a light bowl , not heavy and then pour low"] * 4400).encode() + b"\npour low\n"
    r = _ask_stdin(line, "--json", timeout=20)
    assert r.code == 1 and "line 1: " in r.err
    assert json.loads(r.out)["understood"] == ["pour_low"]
