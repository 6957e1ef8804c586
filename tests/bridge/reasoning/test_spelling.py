"""Mistyped words (spelling.py): read as the one word meant and said back,
never a real word read as another, and the dictionary loaded only for a
question holding a word the reader does not know."""
from __future__ import annotations

import subprocess
import sys

import pytest

from pantarhei.bridge.reasoning.spelling import corrected


@pytest.mark.parametrize("typed,meant", [
    ("will it spil", "will it spill"),             # spill, not the rarer spilt
    ("pour from hihg up", "pour from high up"),     # two letters swapped
    ("a havy bowl", "a heavy bowl"),                # a word that says something, not "have"
    ("tilt it verry far", "tilt it very far"),      # very, not jerry (of "jerry can")
    ("does it ovreflow", "does it overflow"),       # a word of outcomes.py's patterns
    ("tilt it hslfway", "tilt it halfway"),         # a key beside the one meant
    ("does teh bowl tip", "does the bowl tip"),     # three letters, two swapped
])
def test_a_mistyped_word_is_read_as_the_word_meant_and_said_back(typed, meant):
    text, said = corrected(typed)
    assert text == meant
    wrong = next(a for a, b in zip(typed.split(), meant.split()) if a != b)
    assert said == (f"{wrong}: read as {meant.split()[typed.split().index(wrong)]}",)


@pytest.mark.parametrize("typed", [
    "pour from the left",      # an English word near "lift": never read as it
    "fill the bowl",           # near "full"
    "pour from the sde",       # too short to say which word
    "pour it realy high",      # near "really" and "real": neither far commoner
    "will it glug",            # "glue" is a letter away, but no slip of the keys: g is far from e
])
def test_a_real_word_or_a_doubtful_one_is_left_as_written(typed):
    assert corrected(typed) == (typed, ())


def test_the_dictionary_is_loaded_only_for_a_word_the_reader_does_not_know():
    code = ("import sys; from pantarhei.bridge.reasoning.reading import read_question; "
            "read_question('pour from the side, does it spill?'); "
            "print('spellchecker' in sys.modules); "
            "read_question('pour from the sied'); print('spellchecker' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.split() == ["False", "True"]
