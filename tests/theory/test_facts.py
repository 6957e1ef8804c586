"""The fact reader of the theory's own files (`read_facts` of
theory/__init__.py, pantarhei.theory): the vocabulary files as the
engines read them, and bad files named by file and line."""
from pathlib import Path

import pytest

from pantarhei.theory import VOCABULARY_FILES, TheoryFileError, read_facts


def test_vocabulary_files_hold_the_vocabulary():
    f = read_facts(VOCABULARY_FILES)
    assert len(f["parameter"]) == 30
    assert len(f["proposition"]) == 86
    assert len(f["expectation"]) == 9
    # file order is kept: the parameter vector's order
    assert [p[0] for p in f["parameter"]][:3] == ["start_x", "start_y", "start_z"]
    assert ("pour_to_side", "pour_x", ("uniform", 105, 165)) in f["model"]


@pytest.mark.parametrize("text, line, words", [
    ("a(1).\nb(1.5).\n", 2, "not a float"),
    ("a(1).\nb(x) :- a(x).\n", 2, "not a rule"),
    ("a(1).\n\nc([1,2]).\n", 3, "not a list"),
    ("a(1).\nb(X).\n", 2, "no variables"),
    ("a(1).\nb(f(X)).\n", 2, "no variables"),
])
def test_malformed_files_name_file_and_line(tmp_path: Path, text, line, words):
    f = tmp_path / "bad.pl"
    f.write_text(text)
    with pytest.raises(TheoryFileError) as e:
        read_facts([f])
    msg = str(e.value)
    assert msg.startswith(f"{f}:{line}: "), msg
    assert words in msg
    assert "\n" not in msg


def test_terms_text_and_negative_numbers(tmp_path: Path):
    f = tmp_path / "ok.pl"
    f.write_text('% a comment\nx("a b", -3, f(g(1))).\ny.\n')
    assert read_facts([f]) == {"x": [("a b", -3, ("f", ("g", 1)))], "y": [()]}
