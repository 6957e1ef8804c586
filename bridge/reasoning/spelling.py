"""Words a person mistyped, read as the word meant: "will it spil if I
pour from hihg up?" is "will it spill if I pour from high up?", and `ask`
says so ("spil: read as spill"). reading.py looks for them only in a
question it refused as typed.

A word is read as another only when nothing else is near: the reader
does not know it, an English dictionary does not hold it (pyspellchecker's
word list, loaded only when a question holds a word the reader does not
know), and one word the reader reads is one edit away (a letter left
out, added, changed for a key beside it or a letter that sounds alike, or
two swapped; for a word of three letters, only
two swapped: "teh" is the), or, for a word of six letters or
more with none one edit away, two edits; where several are, a word that
says something before a word of the question's frame ("havy": heavy, not
have), and of those the one far commoner in English than the others
("verry": very, not jerry). An -ing word typed without its g is
read as it ("spilin": spilling). A real word the reader does
not know ("pour from the left") is never read as one it knows ("lift"),
and a word near two ("tilr": tilt or tile?) is left as written, for the
reader to refuse with its "did you mean".

The words the reader reads are those of the vocabulary's glosses, the
everyday word list (everyday.txt), the phrases of words.py and
outcomes.py, the units and numbers, and the question's frame (FILLERS).
"""
from __future__ import annotations

import re
from functools import lru_cache

from pantarhei.bridge.reasoning.everyday import sections
from pantarhei.bridge.reasoning.negation import NEGATIONS
from pantarhei.bridge.reasoning.numerals import NUMBER_WORDS
from pantarhei.bridge.reasoning.outcome_verbs import OUTCOMES
from pantarhei.bridge.reasoning.properties import LEVELS, NAMES
from pantarhei.bridge.reasoning.units import UNITS
from pantarhei.bridge.reasoning.stages import MARKERS
from pantarhei.bridge.reasoning.wording import stem
from pantarhei.bridge.reasoning.words import FILLERS, PHRASES
from pantarhei.theory.lexicon import load_vocabulary

#: The shortest word read as another by any one edit: "tlt" could be too many things.
_SHORTEST = 4
#: The shortest word read as another with two of its letters swapped ("teh": the).
_SHORTEST_SWAPPED = 3
#: The shortest word read as one two edits away.
_SHORTEST_TWO = 6
#: How many times more common in English the word read must be than the next one near
#: ("verry": very, not jerry; "spil": spill, not spilt).
_COMMONER = 5


@lru_cache(maxsize=None)
def _words() -> tuple[frozenset[str], frozenset[str], frozenset[str]]:
    """(the whole words the reader reads, the letters of its patterns, the
    words of a question's frame): the second may hold parts of words
    ("dribbl" of "dribbl\\w*")."""
    vocab = load_vocabulary()
    texts = [*(f"{n.replace('_', ' ')} {p.gloss}" for n, p in vocab.propositions.items()),
             *(d.gloss for d in vocab.dimensions.values()), *(p.gloss for p in vocab.parameters),
             *(e.name.replace("_", " ") for e in vocab.expectations),
             *(p for s in sections() for p in s.phrases), *FILLERS, *NEGATIONS, *MARKERS,
             *UNITS, *NUMBER_WORDS, *NAMES, *LEVELS,
             *(p for _, phrases, *_ in PHRASES for p in phrases if not p.startswith("re:"))]
    patterns = [*(p for _, phrases, *_ in PHRASES for p in phrases if p.startswith("re:")),
                *(verb for verb, _, _ in OUTCOMES)]
    whole = {w for t in texts for w in re.findall(r"[a-z]+", t.lower())}
    parts = {w for t in patterns for w in re.findall(r"[a-z]+", t.lower())}
    # (a word of a hedge that says something elsewhere, "tilt" of "same tilt", is no word of the frame)
    saying = {w for t in (*(p.gloss for p in vocab.propositions.values()), *(words for words, *_ in PHRASES),
                          *(s.words for s in sections() if s.words != "hedge"), *(p for s in sections() if s.words.startswith("bowl")
                                                                                   for p in s.phrases))
              for w in re.findall(r"[a-z]+", t.lower())}
    frame = {w for s in sections() if s.words == "hedge" for p in s.phrases for w in p.split()} - (saying - FILLERS)
    return frozenset(whole), frozenset(parts), frozenset(frame | FILLERS)


@lru_cache(maxsize=None)
def _dictionary():
    from spellchecker import SpellChecker       # only for a question with a word not known

    return SpellChecker(language="en", distance=1)


def unknown_to_reader(word: str) -> bool:
    """Whether the reader reads no word `word` (neither whole nor as part of
    its patterns, nor as a word of a question's frame)."""
    whole, parts, frame = _words()
    singular = {word, word[:-1] if word.endswith("s") else word, word[:-2] if word.endswith("es") else word}
    return not any(w in whole or w in parts or w in frame for w in singular)


def english(word: str) -> bool:
    """Whether an English dictionary (pyspellchecker's word list) holds `word`."""
    return word in _dictionary()


#: Letters written for one another as they sound alike ("tilded": tilted, "evrywhere").
_SOUNDS = ("aeiouy", "dt", "bp", "gkc", "csz", "fv", "mn")
#: The rows of a keyboard: a letter typed for another is one beside it.
_ROWS = ("qwertyuiop", "asdfghjkl", "zxcvbnm")


@lru_cache(maxsize=None)
def _beside() -> dict[str, frozenset[str]]:
    """Each letter's neighbours on a QWERTY keyboard."""
    at = {c: (r, i) for r, row in enumerate(_ROWS) for i, c in enumerate(row)}
    return {c: frozenset(d for d, (r2, j) in at.items()
                         if d != c and abs(r2 - r) <= 1 and j - i in ((-1, 0, 1) if r2 == r else
                                                                      (0, 1) if r2 < r else (-1, 0)))
            for c, (r, i) in at.items()}


def _slip(typed: str, meant: str) -> bool:
    """Whether `typed` is `meant` with one slip of the keys: a letter left
    out or added, two swapped, or one changed for a key beside it or for
    one that sounds alike ("tilded": tilted; "glug" is no slip for "glue":
    g is far from e and sounds nothing like it)."""
    if len(typed) != len(meant):
        return True
    diff = [k for k in range(len(typed)) if typed[k] != meant[k]]
    if len(diff) == 1:
        a, b = typed[diff[0]], meant[diff[0]]
        return b in _beside().get(a, frozenset()) or any(a in g and b in g for g in _SOUNDS)
    return True                        # two letters swapped


def _dropped_g(w: str, whole, parts, english) -> str:
    """The one word of -ing `w` is, as chat types it without its g
    ("pourin", "spilin": spilling), whose stem the reader reads; or ""."""
    def reads(t: str) -> bool:
        return t in english and t.endswith("ing") and (stem(t) in whole or stem(t) in parts)
    if reads(w):
        return w
    near = {t for t in english.edit_distance_1(w) if reads(t) and _slip(w, t)}
    return near.pop() if len(near) == 1 else ""


def corrected(text: str) -> tuple[str, tuple[str, ...]]:
    """`text` (normalised: wording.normalised) with its mistyped words read
    as the words meant, and what is said back of each ("spil: read as
    spill"); see the module's docstring."""
    whole, parts, frame = _words()
    unknown = [w for w in dict.fromkeys(re.findall(r"(?<![\w-])[a-z]+(?![\w-])", text))
               if len(w) >= _SHORTEST_SWAPPED and w not in whole and w not in parts]
    if not unknown:
        return text, ()
    english = _dictionary()
    meant: dict[str, str] = {}
    for w in unknown:
        squeezed = re.sub(r"(.)\1{2,}", r"\1", w)        # "sooo", "hiiigh", "reallyyy"
        if squeezed != w and (squeezed in whole or squeezed in parts):
            meant[w] = squeezed
            continue
        if w in english:
            continue
        if w.endswith("in") and len(w) >= 5 and (ing := _dropped_g(w + "g", whole, parts, english)):
            meant[w] = ing                   # "spillin", "spilin"
            continue
        if len(w) < _SHORTEST:           # "teh": only two letters swapped
            swapped = {w[:k] + w[k + 1] + w[k] + w[k + 2:] for k in range(len(w) - 1)} & whole
            if len(swapped) == 1:
                meant[w] = swapped.pop()
            continue
        targets = {t for t in english.edit_distance_1(w) if (t in whole or (t in parts and t in english))
                   and _slip(w, t)}
        if not targets and len(w) >= _SHORTEST_TWO:
            targets = {t for t in english.edit_distance_2(w)
                       if t in whole or (t in parts and t in english)}
        # a word that says something before one of the question's frame: "havy" is heavy, not have
        saying = {t for t in targets if t in whole and t not in frame}
        best = sorted(saying or targets, key=lambda t: (-english.word_frequency[t], t))
        if len(best) == 1 or (best and english.word_frequency[best[0]]
                              >= _COMMONER * english.word_frequency[best[1]]):
            meant[w] = best[0]
    if not meant:
        return text, ()
    text = re.sub(r"(?<![\w-])(?:" + "|".join(map(re.escape, meant)) + r")(?![\w-])",
                  lambda m: meant[m.group(0)], text)
    return text, tuple(f"{w}: read as {c}" for w, c in meant.items())
