"""The reader's lexicon kept between questions: building it reads every
gloss of the vocabulary through every rewrite, most of the time `ask`
spends in Python. It is kept as JSON in the cache folder `ask` keeps its
compiled Prolog in ($XDG_CACHE_HOME/pantarhei, else ~/.cache/pantarhei),
named by a digest of the reader's sources and the vocabulary's files, so
that a changed source never reads an old lexicon. A file that cannot be
read, or is damaged, is built again; a folder that cannot be written
keeps nothing, and the lexicon is built each time."""
from __future__ import annotations

import json
from pathlib import Path
from typing import Callable, TypeVar

from pantarhei.bridge.reasoning.cache_files import cache_file, reader_sources, write_whole

T = TypeVar("T")


def _path() -> Path | None:
    """Where the lexicon of the present sources is kept, or None."""
    return cache_file("lexicon", reader_sources(), ".json")


def _encode(lexicon) -> dict:
    return {"phrases": [[list(k), sorted(v)] for k, v in lexicon.phrases.items()],
            "slots": {k: list(v) for k, v in lexicon.slots.items()},
            **{k: sorted(getattr(lexicon, k)) for k in ("placeable", "known", "amounts", "asking")},
            "saying": {k: list(v) for k, v in lexicon.saying.items()}}


def _decode(data: dict, kind: Callable[..., T]) -> T:
    return kind({tuple(k): frozenset(v) for k, v in data["phrases"]},
                {k: (v[0], v[1]) for k, v in data["slots"].items()},
                *(frozenset(data[k]) for k in ("placeable", "known", "amounts", "asking")),
                {k: tuple(v) for k, v in data["saying"].items()})


def cached_lexicon(build: Callable[[], T], kind: Callable[..., T]) -> T:
    """The lexicon `build` makes, read from the cache where the present
    sources left one, else built and kept there."""
    path = _path()
    if path is not None:
        try:
            return _decode(json.loads(path.read_text(encoding="utf-8")), kind)
        except (OSError, ValueError, KeyError, TypeError, IndexError):
            pass
    lexicon = build()
    if path is not None:
        write_whole(path, json.dumps(_encode(lexicon)).encode("utf-8"))
    return lexicon
