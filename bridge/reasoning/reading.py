"""From a question in words to scene propositions.

`understand("pour from the side with a light liquid")` matches the words
against each proposition's gloss and name: a proposition is understood
when the question holds most of the weight of its gloss's words (rare
words weigh more than common ones, such as "pour" or "source"), or names
it outright (`pour_to_side`). One proposition per dimension: the best.
"""
from __future__ import annotations

import math
import re
from collections import Counter

from pantarhei.theory.lexicon import load_vocabulary

_STOP = {"a", "an", "the", "of", "to", "with", "from", "and", "at", "is", "in", "on", "over",
         "that", "does", "not", "it", "its", "when", "what", "if", "happens", "i", "we", "then",
         "be", "by", "for", "while", "very", "bowl", "above"}
THRESHOLD = 0.8


def _words(text: str) -> list[str]:
    return [_stem(w) for w in re.findall(r"[a-z]+", text.lower())]


def _stem(w: str) -> str:
    for suffix in ("ing", "ly", "ed", "s"):
        if len(w) > 4 and w.endswith(suffix):
            return w[: -len(suffix)]
    return w


def understand(question: str) -> list[str]:
    """The propositions the question names, sorted."""
    vocab = load_vocabulary()
    glosses = {p.name: [w for w in _words(p.gloss) if w not in _STOP] + _keep_very(p.gloss)
               for p in vocab.propositions.values()}
    # a name in words is a second gloss: "fast approach", "heavy destination"
    named = {p: [w for w in _words(p.replace("_", " ")) if w not in _STOP] + _keep_very(p.replace("_", " "))
             for p in glosses}
    df = Counter(w for ws in (*glosses.values(), *named.values()) for w in set(ws))
    n = len(glosses)
    idf = {w: math.log(1 + n / c) for w, c in df.items()}
    asked = set(_words(question))
    names = set(re.findall(r"[a-z_]+", question.lower()))
    best: dict[str, tuple[float, int, str]] = {}
    for name, ws in glosses.items():
        if name in names:
            score = 2.0
        else:
            score = max(_score(ws, asked, idf), _score(named[name], asked, idf))
        if score >= THRESHOLD and name not in names and not _stage_named(name, asked):
            continue
        if score >= THRESHOLD:
            dim = vocab.propositions[name].dimension
            key = (score, len(ws), name)
            if dim not in best or key > best[dim]:
                best[dim] = key
    return sorted(v[2] for v in best.values())


# the stage a proposition is about must be named: "end" for end_upright
_STAGES = {"start": ("start", "begin"), "end": ("end", "finally", "final"),
           "approach": ("approach", "before"), "retreat": ("retreat", "after")}


def _stage_named(name: str, asked: set[str]) -> bool:
    words = _STAGES.get(name.split("_", 1)[0])
    return words is None or any(w in asked for w in words)


def _score(ws: list[str], asked: set[str], idf: dict[str, float]) -> float:
    total = sum(idf[w] for w in ws)
    return sum(idf[w] for w in ws if w in asked) / total if total else 0.0


def _keep_very(gloss: str) -> list[str]:
    # "very" separates "very high" from "high": keep it as a word then.
    return ["very"] if "very" in gloss.lower().split() else []
