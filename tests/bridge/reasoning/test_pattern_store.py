"""The reader's patterns kept compiled between questions (pattern_store.py):
a process reads its patterns back from the file an earlier one kept,
compiles none of them again, and reads every question as one that
compiled them all; a damaged file is compiled anew, and a cache that
cannot be written keeps nothing. Each process is a fresh Python, as
`ask` is, so that the reader's modules compile their patterns in it."""
from __future__ import annotations

import json
import os
import subprocess
import sys

QUESTIONS = ["will the bowl slide if I pour milk from a jug really high?",
             "Honey, if I'm pouring coffee from a pot into a mug, will it splash?",
             "the jug hit the rim and the bowl tipped, why",
             "how do I pour oil without spilling any on the table",
             "which spills less, pouring high or low"]

#: Reads QUESTIONS within kept_patterns() (or not, with "plain"), and
#: prints the readings and how many patterns were compiled anew.
_READ = """
import json, sys
from contextlib import nullcontext
from pantarhei.bridge.reasoning import pattern_store
anew = []
compiled = pattern_store._compiled
pattern_store._compiled = lambda text, flags: anew.append(text) or compiled(text, flags)
with (nullcontext() if sys.argv[1] == "plain" else pattern_store.kept_patterns()):
    from pantarhei.bridge.reasoning.reading import read_question
    out = []
    for q in json.loads(sys.argv[2]):
        try:
            r = read_question(q)
            out.append([list(r.scene), list(r.asked), list(r.goals), list(r.notes)])
        except Exception as e:
            out.append(str(e))
print(json.dumps({"readings": out, "anew": len(anew)}))
"""


def _read(cache, how: str = "kept") -> dict:
    env = {**os.environ, "XDG_CACHE_HOME": str(cache)}
    p = subprocess.run([sys.executable, "-c", _READ, how, json.dumps(QUESTIONS)], env=env,
                       capture_output=True, text=True, timeout=300)
    assert p.returncode == 0, p.stderr[-2000:]
    return json.loads(p.stdout)


def _kept(cache) -> list:
    return sorted((cache / "pantarhei").glob("patterns-*.bin"))


def test_patterns_are_read_back_and_read_every_question_alike(tmp_path):
    plain = _read(tmp_path, "plain")
    first = _read(tmp_path)
    assert first["anew"] > 300 and len(_kept(tmp_path)) == 1
    second = _read(tmp_path)
    assert second["anew"] == 0                      # every one read back
    assert first["readings"] == second["readings"] == plain["readings"]
    assert any(isinstance(r, list) and r[1] for r in plain["readings"])    # (read, with something asked)


def test_a_damaged_file_is_compiled_anew(tmp_path):
    plain = _read(tmp_path, "plain")
    _read(tmp_path)
    kept = _kept(tmp_path)[0]
    data = bytearray(kept.read_bytes())
    data[len(data) // 2] ^= 0xFF
    kept.write_bytes(bytes(data))
    again = _read(tmp_path)
    assert again["anew"] > 300 and again["readings"] == plain["readings"]
    assert _read(tmp_path)["anew"] == 0             # and kept whole again


def test_a_cache_that_cannot_be_written_keeps_nothing(tmp_path):
    (tmp_path / "pantarhei").write_text("not a folder", encoding="utf-8")
    plain = _read(tmp_path, "plain")
    first = _read(tmp_path)
    assert first["readings"] == plain["readings"]
    assert _read(tmp_path)["anew"] == first["anew"] > 300
    assert (tmp_path / "pantarhei").is_file()


def test_the_compiler_is_given_back(tmp_path, monkeypatch):
    import re

    from pantarhei.bridge.reasoning.pattern_store import kept_patterns

    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    before = re._compiler.compile
    with kept_patterns():
        assert re._compiler.compile is not before
        assert re.compile(r"(?P<w>jug|jar)s?\b").search("two jars").group("w") == "jar"
    assert re._compiler.compile is before
    assert len(_kept(tmp_path)) == 1
