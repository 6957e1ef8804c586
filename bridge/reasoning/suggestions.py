"""Words a refusal offers for a word it could not read: the vocabulary's
word it is close to ("tilded": "tilted"), as the glosses, the everyday
phrases of words.py and the everyday word list (everyday.txt) write them."""
from __future__ import annotations

import re
from functools import lru_cache

from pantarhei.bridge.reasoning.everyday import sections
from pantarhei.bridge.reasoning.words import PHRASES
from pantarhei.theory.lexicon import load_vocabulary


@lru_cache(maxsize=None)
def _spelt() -> tuple[str, ...]:
    """The words of four letters or more of the glosses and the phrases."""
    texts = [p.gloss for p in load_vocabulary().propositions.values()] + [
        " ".join(re.findall(r"[a-z]+", p)) for ps in (*(ps for _, ps, *_ in PHRASES), *(s.phrases for s in sections()))
        for p in ps if not p.startswith("re:")]
    return tuple(sorted({w for t in texts for w in re.findall(r"[a-z]{4,}", t.lower())}))


def misspelt(words: list[str]) -> list[str]:
    """One "did you mean" for those of `words` close to one of the
    vocabulary's (and not one of them), or none."""
    import difflib

    near = {w: difflib.get_close_matches(w.lower(), _spelt(), n=1, cutoff=0.8) for w in words
            if w.lower() not in _spelt()}      # a word spelt right is not misspelt
    return [f'did you mean {", ".join(f"{m[0]!r} for {w!r}" for w, m in near.items() if m)}?'
            ] if any(near.values()) else []
