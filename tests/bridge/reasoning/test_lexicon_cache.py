"""The reader's lexicon kept between questions (lexicon_cache.py): the
lexicon read back is the one built, a damaged file is built again, and a
cache that cannot be written keeps nothing; the reader answers either way."""
from __future__ import annotations

from pantarhei.bridge.reasoning import reading
from pantarhei.bridge.reasoning.lexicon_cache import cached_lexicon


def _kept(tmp_path) -> list:
    return sorted((tmp_path / "pantarhei").glob("lexicon-*.json"))


def test_the_lexicon_read_back_is_the_one_built(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    built = cached_lexicon(reading._built_lexicon, reading._Lexicon)
    assert len(_kept(tmp_path)) == 1
    read = cached_lexicon(lambda: (_ for _ in ()).throw(AssertionError("built again")), reading._Lexicon)
    assert read == built


def test_a_damaged_lexicon_is_built_again(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    built = cached_lexicon(reading._built_lexicon, reading._Lexicon)
    kept = _kept(tmp_path)[0]
    kept.write_text('{"phrases": [[', encoding="utf-8")
    assert cached_lexicon(reading._built_lexicon, reading._Lexicon) == built
    assert cached_lexicon(lambda: (_ for _ in ()).throw(AssertionError("built again")), reading._Lexicon) == built


def test_a_cache_that_cannot_be_written_keeps_nothing(tmp_path, monkeypatch):
    (tmp_path / "pantarhei").write_text("not a folder", encoding="utf-8")
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    assert cached_lexicon(reading._built_lexicon, reading._Lexicon) == reading._built_lexicon()
    assert (tmp_path / "pantarhei").is_file()
