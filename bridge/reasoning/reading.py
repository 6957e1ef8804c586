"""From a question in words to scene propositions.

`understand("pour from the side with a light liquid")` matches the words
against each proposition's gloss and name: a proposition is a candidate
when one clause of the question holds most of the weight of its gloss's
words (rare words weigh more than common ones, such as "pour" or "source"),
or names it outright (`pour_to_side`), and the stage it speaks of ("start",
"end", ...) is named.

Words are read where they stand. A gloss's value words (those that set it
apart from the other values of its dimension: "light" in "a light liquid",
not "liquid") are each read once, as part of the candidate whose words lie
closest together: in "a heavy source bowl and a light destination bowl",
"light" is the destination's, not the source's.

Negation ("not", "never", "no", "without", "don't", ...) covers the rest
of its clause: a proposition whose value words it covers is excluded, and
its dimension is read as its other value when one is left (or another value
is said), or the question is refused naming the values left. Two values of
one dimension ("a light and heavy liquid") are refused as contradictory.
A refusal is a UserError: one line saying what was not understood.
"""
from __future__ import annotations

import math
import re
from collections import Counter
from dataclasses import dataclass

from pantarhei.bridge.errors import UserError
from pantarhei.theory.lexicon import load_vocabulary

_STOP = {"a", "an", "the", "of", "to", "with", "from", "and", "at", "is", "in", "on", "over",
         "that", "does", "not", "it", "its", "when", "what", "if", "happens", "i", "we", "then",
         "be", "by", "for", "while", "very", "bowl", "above", "do", "s"}
THRESHOLD = 0.8

#: Words that end a clause (besides punctuation): negation stops there.
_CLAUSE_ENDS = {"but", "then", "while", "whereas", "instead", "rather", "except", "so"}
#: Words that end the scope of a negation within a clause.
_SCOPE_ENDS = _CLAUSE_ENDS | {"and", "or", "yet"}
#: Words that negate what follows them in their clause.
_NEGATIONS = {"not", "never", "no", "without", "nor", "neither", "cannot", "none", "nothing"}

# the stage a proposition is about must be named: "end" for end_upright
_STAGES = {"start": ("start", "begin"), "end": ("end", "finally", "final"),
           "approach": ("approach", "before"), "retreat": ("retreat", "after")}


def _stem(w: str) -> str:
    for suffix in ("ing", "ly", "ed", "s"):
        if len(w) > 4 and w.endswith(suffix):
            return w[: -len(suffix)]
    return w


def _words(text: str) -> list[str]:
    return [_stem(w) for w in re.findall(r"[a-z]+", text.lower())]


def _keep_very(gloss: str) -> list[str]:
    # "very" separates "very high" from "high": keep it as a word then.
    return ["very"] if "very" in gloss.lower().split() else []


@dataclass(frozen=True)
class _Token:
    word: str        # stemmed, lower case
    raw: str         # as written (a proposition's name keeps its underscores)
    clause: int


@dataclass(frozen=True)
class _Candidate:
    name: str
    score: float
    matched: int                 # gloss words found
    gap: int                     # other words between the first and the last of them
    values: frozenset[int]       # positions of its value words
    clause: int


def _tokens(question: str) -> list[_Token]:
    out: list[_Token] = []
    clause = 0
    for m in re.finditer(r"[a-z_]+(?:'[a-z]+)?|[,;.!?:()]", question.lower()):
        raw = m.group(0)
        if not re.match(r"[a-z_]", raw) or raw in _CLAUSE_ENDS:
            clause += 1
            if not re.match(r"[a-z_]", raw):
                continue
        if raw.endswith("n't") or raw in ("dont", "doesnt", "isnt", "cant", "wont"):
            raw = "not"                   # don't, isn't, can't, won't: a negation
        elif "'" in raw:
            raw = raw.split("'")[0]       # the destination's rim
        out.append(_Token(_stem(raw) if "_" not in raw else raw, raw, clause))
    return out


def understand(question: str) -> list[str]:
    """The propositions the question names, sorted; UserError for a
    question that negates or contradicts itself in a way not understood."""
    vocab = load_vocabulary()
    props = vocab.propositions
    glosses = {p.name: [w for w in _words(p.gloss) if w not in _STOP] + _keep_very(p.gloss)
               for p in props.values()}
    # a name in words is a second gloss: "fast approach", "heavy destination"
    named = {p: [w for w in _words(p.replace("_", " ")) if w not in _STOP] + _keep_very(p.replace("_", " "))
             for p in glosses}
    df = Counter(w for ws in (*glosses.values(), *named.values()) for w in set(ws))
    idf = {w: math.log(1 + len(glosses) / c) for w, c in df.items()}
    frame = {d.name: set.intersection(*(set(glosses[v]) for v in d.values))
             for d in vocab.dimensions.values()}
    tokens = _tokens(question)
    lexical = _lexical_negations()
    cues = [i for i, t in enumerate(tokens)
            if t.word in _NEGATIONS and not _is_lexical(tokens, i, lexical)]

    # each value word is read once: greedily, by the reading whose words lie closest
    # together, the others then read again without the words taken
    claimed: set[int] = set()
    accepted: list[_Candidate] = []
    left = set(glosses)
    while True:
        candidates = []
        for name in left:
            frame_d = frame[props[name].dimension]
            best = None
            for ws in (glosses[name], named[name]):
                c = _match(name, ws, tokens, idf, frame_d, claimed)
                if c is not None and (best is None or (c.score >= THRESHOLD, _rank(c))
                                      > (best.score >= THRESHOLD, _rank(best))):
                    best = c
            if best is not None and best.score >= THRESHOLD and _stage_named(name, tokens, best.clause):
                candidates.append(best)
        if not candidates:
            break
        c = max(candidates, key=_rank)
        accepted.append(c)
        claimed |= c.values
        left.discard(c.name)

    covered = _negated_positions(tokens, cues)
    for i in cues:
        scope = _scope(tokens, i)
        if any(tokens[j].word not in _STOP for j in scope) and not any(scope & c.values for c in accepted):
            phrase = " ".join(tokens[j].raw for j in (i, *sorted(scope)))
            raise UserError(f"understood nothing that \"{phrase}\" excludes: describe the scene "
                            f"with the words of `pantarhei vocab`, or give --props P1,P2")
    said: dict[str, list[str]] = {}
    negated: dict[str, list[str]] = {}
    for c in accepted:
        target = negated if c.values & covered else said
        target.setdefault(props[c.name].dimension, []).append(c.name)

    out = []
    for dim, names in said.items():
        if len(names) > 1:
            a, b = sorted(names)[:2]
            raise UserError(f"\"{question}\" says both {a} ({props[a].gloss}) and {b} "
                            f"({props[b].gloss}), two values of {dim}: ask about one of them")
        out.append(names[0])
    for dim, names in negated.items():
        if dim in said:
            continue                  # "never from the side, centred over it": the one said
        others = [v for v in vocab.dimensions[dim].values if v not in names]
        if len(others) == 1:
            out.append(others[0])
            continue
        raise UserError(f"not {', '.join(names)} leaves {_or(others)}: say which one (or give "
                        f"--props P1,P2)" if others else f"\"{question}\" excludes every value of {dim}")
    return sorted(out)


def _or(names: list[str]) -> str:
    return ", ".join(names[:-1]) + " or " + names[-1] if len(names) > 1 else names[0]


def _rank(c: _Candidate) -> tuple:
    # closest together first, then the fuller match, then the surer
    return (-c.gap, c.matched, c.score, c.name)


def _match(name: str, ws: list[str], tokens: list[_Token], idf: dict[str, float],
           frame: set[str], claimed: set[int]) -> _Candidate | None:
    """The best reading of one gloss (its words `ws`) in one clause of the
    question, or None when no clause holds any of its value words; value
    words at the positions `claimed` are another reading's."""
    for i, t in enumerate(tokens):
        if t.raw == name and i not in claimed:      # named outright
            return _Candidate(name, 2.0, len(ws) or 1, 0, frozenset({i}), t.clause)
    total = sum(idf[w] for w in ws)
    if not total:
        return None
    best = None
    for clause in sorted({t.clause for t in tokens}):
        where: dict[str, list[int]] = {}
        for i, t in enumerate(tokens):
            if t.clause == clause and t.word in ws and (t.word in frame or i not in claimed):
                where.setdefault(t.word, []).append(i)
        if not any(w not in frame for w in where):
            continue
        score = sum(idf[w] for w in where) / total
        # anchored on each occurrence of its words, the nearest occurrence of each other
        for a in sorted(p for ps in where.values() for p in ps):
            chosen = {w: min(ps, key=lambda p: (abs(p - a), p)) for w, ps in where.items()}
            gap = max(chosen.values()) - min(chosen.values()) + 1 - len(chosen)
            values = frozenset(p for w, p in chosen.items() if w not in frame)
            c = _Candidate(name, score, len(where), gap, values, clause)
            if best is None or (c.score >= THRESHOLD, _rank(c)) > (best.score >= THRESHOLD, _rank(best)):
                best = c
    return best


def _stage_named(name: str, tokens: list[_Token], clause: int) -> bool:
    """Is the stage of the proposition named: in the question for the start,
    the end and the moves between; for the pouring pose, no other stage is
    named in its clause without "pour" ("end with the source upright")."""
    stage = name.split("_", 1)[0]
    if any(t.raw == name for t in tokens):
        return True
    if stage == "pour":
        here = {t.word for t in tokens if t.clause == clause}
        return "pour" in here or not here & {"start", "begin", "end", "finally", "final"}
    words = _STAGES.get(stage)
    return words is None or any(t.word in words for t in tokens)


def _lexical_negations() -> set[tuple[str, str]]:
    """(negation, next word) pairs that glosses use themselves: "does not
    bounce" is a dull bowl, not a negation."""
    vocab = load_vocabulary()
    pairs = set()
    for p in vocab.propositions.values():
        ws = [_stem(w) for w in re.findall(r"[a-z]+", p.gloss.lower())]
        pairs |= {(a, b) for a, b in zip(ws, ws[1:]) if a in _NEGATIONS}
    return pairs


def _is_lexical(tokens: list[_Token], i: int, lexical: set[tuple[str, str]]) -> bool:
    return i + 1 < len(tokens) and (tokens[i].word, tokens[i + 1].word) in lexical


def _scope(tokens: list[_Token], i: int) -> set[int]:
    """The positions a negation at i covers: the rest of its clause, up to
    the next "and", "with", "or"..."""
    out = set()
    for j in range(i + 1, len(tokens)):
        if tokens[j].clause != tokens[i].clause or tokens[j].word in _SCOPE_ENDS:
            break
        if tokens[j].word not in _NEGATIONS:
            out.add(j)
    return out


def _negated_positions(tokens: list[_Token], cues: list[int]) -> set[int]:
    return set().union(*(_scope(tokens, i) for i in cues)) if cues else set()
