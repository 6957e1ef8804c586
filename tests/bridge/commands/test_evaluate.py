"""`pantarhei evaluate` (bridge/commands/evaluate.py) given a theory it
cannot measure: one line and a non-zero exit. The whole evaluation, run by
the command too, is tests/bridge/evaluation/test_pipeline.py."""
from __future__ import annotations

import pytest

from tests.conftest import assert_one_line_error, run_cli


@pytest.mark.parametrize("make, words", [
    (lambda d: d / "missing.pl", "no such theory"),
    (lambda d: (d / "hand.pl").write_text("rule(r1, defeasible, no_spill).\n") and d / "hand.pl",
     "not a theory written by `pantarhei explore`"),
    (lambda d: (d / "bad.pl").write_text("rule(r1, defeasible\n") and d / "bad.pl", "bad.pl:"),
])
def test_bad_theories_get_one_line(tmp_path, make, words):
    r = run_cli("evaluate", "--theory", str(make(tmp_path)), "--store", str(tmp_path / "s.sqlite"),
                "--out", str(tmp_path / "r"), "--no-progress")
    assert words in assert_one_line_error(r, code=r.code if r.code else 2)
    assert r.code != 0


@pytest.mark.parametrize("store, words", [
    ("evaluation.json", "--store and the report's evaluation.json are the same file"),
    ("README.md", "--store and the report's README.md are the same file"),
    ("pour_a2.gif", "the report draws its pours as GIFs of that name"),
])
def test_the_report_never_overwrites_the_store_it_measures(tmp_path, store, words):
    r = run_cli("evaluate", "--store", str(tmp_path / store), "--out", str(tmp_path),
                "--no-progress")
    assert words in assert_one_line_error(r)
    assert list(tmp_path.iterdir()) == []
