"""WordNet as the reader asks it (bridge/reasoning/wordnet.py), on the real
database of Debian's wordnet-base that `make setup` installs."""
from pathlib import Path

import pytest

from pantarhei.bridge.reasoning import wordnet

LIQUIDS = frozenset(("liquid", "fluid", "beverage", "soup", "sauce", "broth"))


def test_the_database_is_installed():
    assert (wordnet.ROOT / "index.noun").exists() and (wordnet.ROOT / "data.noun").exists()


@pytest.mark.parametrize("noun,kind", [("merlot", "red wine"), ("gazpacho", "soup"), ("bouillon", "broth")])
def test_a_liquid_is_named_by_its_nearest_kind(noun, kind):
    assert wordnet.kind_named(noun, LIQUIDS) == kind


@pytest.mark.parametrize("noun", ["sand", "song", "stain", "flour", "nutella", "barolo", "zzzq"])
def test_a_noun_of_no_liquid_kind_or_none_at_all_is_none(noun):
    assert wordnet.kind_named(noun, LIQUIDS) is None


@pytest.mark.parametrize("noun,person", [("potter", True), ("cook", True), ("vendor", True), ("bit", False),
                                         ("robot", False)])
def test_a_person_by_the_first_two_senses(noun, person):
    assert wordnet.is_a(noun, frozenset(("person",)), first=2) is person


def test_every_noun_of_the_index_is_found_by_bisecting_it():
    """The search finds each line of the sorted index, the first and the last too (a sample of
    every hundredth, read whole from the file)."""
    lines = [line for line in Path(wordnet.ROOT / "index.noun").read_text(encoding="latin-1").splitlines()
             if not line.startswith(" ")]
    for line in [*lines[::100], lines[0], lines[-1]]:
        assert wordnet._line(wordnet.ROOT / "index.noun", line.split()[0]) == line + "\n"
