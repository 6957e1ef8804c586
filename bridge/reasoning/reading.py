"""From a question in words to scene propositions.

`understand("pour a heavy liquid into a light bowl, steeply tilted")` reads
the question in four steps:

1. Everyday phrases become the vocabulary's words (words.py: "a full cup",
   "move in fast", "right it up", "over the rim"), and a number with its
   unit the proposition whose range holds it (quantities.py: "tilted at 45
   degrees", "30 cm above the bowl").
2. Each word gets the stage it speaks of: "start", "pour", "end",
   "approach" (the move into the pouring pose) or "retreat" (the move out
   of it), said by a stage word ("then", "after pouring", "move away" ...).
   A stage word speaks for its clause from there on, and for the words of
   its clause before it; a clause without one goes on in the stage before
   (pouring, at first). A pose said while moving in is the start pose,
   while moving away the end pose.
3. Each proposition is said by its value words: the words of its gloss
   or of its name, without its stage or body ("far" for `pour_far_away`,
   "tilted halfway" or "half tilted" for `pour_half_tilted`), found close
   together in one clause, in the stage of the proposition; the readings
   with the most words first, each word read once. A word said of the
   bodies ("light", "slippery") belongs to the noun it qualifies: the one
   it stands before ("a light, slippery bowl"), or else the one before it
   ("the liquid is light"). A bowl is the destination unless the source is
   said ("a source bowl", "pour out of a cup"). A proposition's name said
   outright (`pour_to_side`) is read as it is.
4. Negation ("not", "never", "no", "without", "don't", ...) covers the
   rest of its clause: a proposition said there is excluded, and its
   dimension is read as its other value when one is left (or another value
   is said), or the question is refused naming the values left. Two values
   of one dimension ("a light and heavy liquid") are refused as
   contradictory, and so is a question with a word that cannot be placed
   ("pour light": the light what?). A refusal is a UserError: one line.
   A question of pouring that names no proposition ("what happens if I
   pour?") reads as no propositions: the ordinary pour; a question that
   says nothing of a pour is refused.
"""
from __future__ import annotations

import re
from bisect import bisect_left
from dataclasses import dataclass
from functools import lru_cache

from pantarhei.bridge.errors import UserError
from pantarhei.bridge.reasoning.quantities import (ALSO_READ, CUES, REACH, UNITS, Quantity,
                                                   parameter, proposition)
from pantarhei.bridge.reasoning.words import FILLERS, UNCLEAR, rewrites
from pantarhei.theory.lexicon import load_vocabulary

#: Words that end a clause (besides punctuation): negation stops there.
_CLAUSE_ENDS = {"but", "then", "while", "whereas", "instead", "rather", "except", "so"}
#: Words that end the scope of a negation within a clause.
_SCOPE_ENDS = _CLAUSE_ENDS | {"and", "or", "yet"}
#: Words that negate what follows them in their clause.
_NEGATIONS = {"not", "never", "no", "without", "nor", "neither", "cannot", "none", "nothing"}

#: Stage words (words.py brings "before pouring", "move in", ... to them), and
#: where "then" goes on to from each stage.
_MARKERS = {"start": "start", "pour": "pour", "end": "end", "finally": "end", "final": "end",
            "approach": "approach", "retreat": "retreat", "then": None}
_THEN = {"start": "pour", "approach": "pour", "pour": "end", "retreat": "end", "end": "end"}
#: The pose and the movement a stage speaks of: "move in from low down" is start_low.
_POSE = {"start": "start", "approach": "start", "pour": "pour", "retreat": "end", "end": "end"}
_MOVE = {"start": "approach", "approach": "approach", "pour": None, "retreat": "retreat",
         "end": "retreat"}
_OBJECTS = ("source", "destination", "liquid")
#: Words that may stand between a body's value word and its noun: "a light, slippery bowl".
_BETWEEN = {"a", "an", "the", "and", "or", "very"}
_ARTICLES = {"a", "an", "the"}
#: A number as a question writes it ("45", "1.5"): one token.
_NUMBER = r"\d+(?:\.\d+)?"
#: The most other words between the words of one reading.
_MAX_GAP = 4


def _stem(w: str) -> str:
    for suffix in ("ing", "ly", "ed", "es", "s"):
        if len(w) > len(suffix) + 2 and w.endswith(suffix):
            w = w[: -len(suffix)]
            break
    return w[:-1] if len(w) > 3 and w.endswith("e") else w


_MARKER_STEMS = {_stem(w): s for w, s in _MARKERS.items()}
_OBJECT_STEMS = {_stem(o): o for o in _OBJECTS}
_BOWL = _stem("bowl")
#: (word, next word) before a bowl that the liquid is poured out of: "pour from a cup",
#: "into a bowl from a cup" (not "far from the cup": the destination)
_POURED_FROM = {(_stem(a), _stem(b))
                for a, b in (("out", "of"), ("pour", "from"), ("liquid", "from"),
                             ("bowl", "from"), ("destination", "from"))}
_IGNORED = {_stem(w) for w in FILLERS}
_NEGATION_STEMS = {_stem(w) for w in _NEGATIONS}


@dataclass(frozen=True)
class _Token:
    word: str        # stemmed, lower case (a proposition's name as written)
    raw: str         # as written
    clause: int


def _tokens(text: str) -> list[_Token]:
    """The words of `text` in the vocabulary's words, stemmed, each with its clause."""
    text = text.lower().replace("\u2019", "'")
    text = re.sub(r"\bcan't\b|\bcannot\b", "can not", text)
    text = re.sub(r"\bwon't\b", "will not", text)
    text = re.sub(r"n't\b|\b(do|does|did|is|are|was|were)nt\b", r"\1 not", text)
    text = re.sub(r"'s?\b", "", text)                 # the destination's rim
    text = re.sub(r"(\d)\s*\u00b0", r"\1 degrees ", text)  # 45°
    text = re.sub(r"(\d)([a-z])", r"\1 \2", text)       # 30cm
    pairs = [(w, w) for w in re.findall(rf"{_NUMBER}|[a-z0-9_]+|[,;.!?:()]", text)]
    joined = " ".join(w for w, _ in pairs)
    for pattern, words in rewrites():
        if pattern.search(joined):
            pairs = _rewrite(pairs, pattern, words)
            joined = " ".join(w for w, _ in pairs)
    out, clause = [], 0
    for word, raw in pairs:
        if not re.match(r"[a-z0-9_]", word) or word in _CLAUSE_ENDS:
            clause += 1
            if not re.match(r"[a-z0-9_]", word):
                continue
        out.append(_Token(word if "_" in word else _stem(word), raw, clause))
    return out


def _rewrite(pairs: list[tuple[str, str]], pattern: re.Pattern, words: tuple[str, ...]):
    """(word, as written) pairs with each match of `pattern` read as `words`."""
    starts, at = [], 0
    for w, _ in pairs:
        starts.append(at)
        at += len(w) + 1
    out, last = [], 0
    for m in pattern.finditer(" ".join(w for w, _ in pairs)):
        i, j = bisect_left(starts, m.start()), bisect_left(starts, m.end())
        if i < last or i == len(starts) or starts[i] != m.start():
            continue
        raw = " ".join(r for _, r in pairs[i:j])
        out += pairs[last:i] + [(w, raw) for w in words]
        last = j
    return out + pairs[last:]


@dataclass(frozen=True)
class _Lexicon:
    phrases: dict[tuple[str, ...], frozenset[str]]   # value words -> the propositions they say
    slots: dict[str, tuple[str, str]]                # proposition -> ("stage"|"object", which)
    placeable: frozenset[str]                        # words a question must place
    known: frozenset[str]
    amounts: frozenset[str]                          # propositions of how much liquid the source holds
    asking: frozenset[str]                           # words of a question of the ordinary pour


@lru_cache(maxsize=None)
def _lexicon() -> _Lexicon:
    vocab = load_vocabulary()
    props = vocab.propositions
    slot_words = set(_MARKER_STEMS) | set(_OBJECT_STEMS) | {_BOWL}
    phrases: dict[tuple[str, ...], set[str]] = {}
    slots = {}
    for n, p in props.items():
        # said by its gloss, read as a question is, or by its name word by word
        for words in ({t.word for t in _tokens(p.gloss)}, {_stem(w) for w in n.split("_")}):
            phrases.setdefault(tuple(sorted(words - _IGNORED - slot_words)), set()).add(n)
        first, last = n.split("_")[0], n.split("_")[-1]      # pour_low, fast_approach, light_liquid
        slots[n] = ("stage", first) if first in _POSE else (
            ("stage", last) if last in _POSE else ("object", last))
    placeable = set().union(*phrases) - {"very"}
    # the expectations' words, by their names and glosses ("does the liquid spill?")
    asked = {_stem(w) for e in vocab.expectations
             for w in re.findall(r"[a-z]+", f"{e.name} {e.gloss}".lower())}
    texts = [*(p.gloss for p in props.values()), *(d.gloss for d in vocab.dimensions.values()),
             *(p.gloss for p in vocab.parameters)]
    known = {_stem(w) for t in texts for w in re.findall(r"[a-z]+", t.lower())} | asked
    known |= {_stem(w) for _, words in rewrites() for w in words}
    known |= _IGNORED | slot_words | _NEGATION_STEMS | {"very"}
    # the dimension whose gloss says the liquid is in the source: its values
    # may be said of the source ("a full cup")
    amounts = {n for n, p in props.items() if slots[n] == ("object", "liquid")
               and "source" in vocab.dimensions[p.dimension].gloss}
    # what a question of the ordinary pour may hold: its frame, the bodies,
    # pouring and the expectations it asks of ("does the liquid spill?")
    asking = _IGNORED | set(_OBJECT_STEMS) | {_BOWL, "pour"} | asked
    return _Lexicon({k: frozenset(v) for k, v in phrases.items()}, slots,
                    frozenset(placeable | {UNCLEAR}), frozenset(known), frozenset(amounts),
                    frozenset(asking))


def understand(question: str) -> list[str]:
    """The propositions the question names, sorted (none: the ordinary
    pour); UserError for a question that negates or contradicts itself in
    a way not understood, holds a word that cannot be placed or a number
    no proposition holds, or says nothing of a pour."""
    vocab = load_vocabulary()
    props = vocab.propositions
    lex = _lexicon()
    tokens = _quantities(_tokens(question), lex)
    accepted = _read(tokens, lex)
    cues = [i for i, t in enumerate(tokens) if t.word in _NEGATION_STEMS]
    ends = _scope_ends(tokens)
    # per position: how many words before it say something (neither filler
    # nor negation); the positions read, negations left out
    saying = [0]
    for t in tokens:
        saying.append(saying[-1] + (t.word not in _IGNORED and t.word not in _NEGATION_STEMS))
    read = sorted(j for _, positions in accepted for j in positions
                  if tokens[j].word not in _NEGATION_STEMS)
    for i in cues:
        k = bisect_left(read, i + 1)
        if saying[ends[i]] > saying[i + 1] and not (k < len(read) and read[k] < ends[i]):
            phrase = " ".join(tokens[j].raw for j in (i, *sorted(_scope(tokens, i, ends))))
            raise UserError(f"understood nothing that \"{phrase}\" excludes: describe the scene "
                            f"with the words of `pantarhei vocab`, or give --props P1,P2")
    covered = _covered(tokens, cues, ends)
    said: dict[str, list[str]] = {}
    negated: dict[str, list[str]] = {}
    for name, positions in accepted:
        target = negated if positions & covered else said
        names = target.setdefault(props[name].dimension, [])
        if name not in names:
            names.append(name)

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
                        f"--props P1,P2)" if others
                        else f"\"{question}\" excludes every value of {dim}")
    _refuse_unplaced(question, tokens, accepted, lex)
    if not accepted and not _ordinary(tokens, lex):
        raise UserError(f"understood none of \"{question}\": describe the scene with the "
                        f"words of `pantarhei vocab`, or give --props P1,P2")
    return sorted(out)


def _ordinary(tokens: list[_Token], lex: _Lexicon) -> bool:
    """Whether a question that names no proposition asks of the ordinary
    pour: it says pouring ("what happens if I pour water into a cup?") in
    words the vocabulary knows, and nothing else."""
    return any(t.word == "pour" for t in tokens) and all(t.word in lex.asking for t in tokens)


def _quantities(tokens: list[_Token], lex: _Lexicon) -> list[_Token]:
    """The tokens with each number and its unit ("45 degrees"), and the
    words beside it that picked its parameter ("tilted at"), read as one:
    the proposition whose range holds it (quantities.py)."""
    numbers = [i for i, t in enumerate(tokens[:-1]) if re.fullmatch(_NUMBER, t.word)
               and tokens[i + 1].raw in UNITS and tokens[i + 1].clause == t.clause]
    if not numbers:
        return tokens
    stages = _stages(tokens)
    noun = _Nouns(tokens, _roles(tokens, lex), lex)
    cue_of = {_stem(w): w for ws in (*CUES.values(), *ALSO_READ.values()) for w in ws}
    read: dict[int, _Token] = {}
    dropped: set[int] = set()
    for i in numbers:
        unit = tokens[i + 1].raw
        q = Quantity(float(tokens[i].word) * UNITS[unit][1], UNITS[unit][0],
                     f"{tokens[i].raw} {unit}")
        near = [k for k in range(max(0, i - REACH), min(len(tokens), i + 2 + REACH))
                if k not in (i, i + 1) and tokens[k].clause == tokens[i].clause
                and tokens[k].word in cue_of and k not in dropped]
        cues = {cue_of[tokens[k].word] for k in near}         # "tilt" picks a pitch, as a cue
        param, by = parameter(q, _POSE[stages[i]], _MOVE[stages[i]], cues, noun(i, i + 1))
        read[i] = _Token(proposition(q, param, cues), q.text, tokens[i].clause)
        read_too = (*CUES.get(by, ()), *ALSO_READ.get(by, ()))
        dropped |= {i + 1} | {k for k in near if cue_of[tokens[k].word] in read_too}
    return [read.get(i, t) for i, t in enumerate(tokens) if i not in dropped]


def _read(tokens: list[_Token], lex: _Lexicon) -> list[tuple[str, frozenset[int]]]:
    """Each proposition said, with the positions of the words that say it:
    names given outright, then the readings with the most words, then the
    closest together, each word read once."""
    stages = _stages(tokens)
    noun = _Nouns(tokens, _roles(tokens, lex), lex)
    found = [(t.word, frozenset({i})) for i, t in enumerate(tokens) if t.word in lex.slots]
    claimed = set().union(*(p for _, p in found))
    for words, positions in sorted(_occurrences(tokens, lex), key=_closest):
        if positions & claimed:
            continue
        name = _resolve(lex.phrases[words], positions, stages, noun, lex)
        if name is not None:
            found.append((name, positions))
            claimed |= positions
            found += [(n, positions) for n in _shared(name, words, positions, noun, lex)]
    return found


def _shared(name: str, words: tuple[str, ...], positions: frozenset[int], noun: "_Nouns",
            lex: _Lexicon) -> list[str]:
    """The same value said of the other bodies its noun is coordinated with
    ("the source and the destination are heavy", "a light source and
    destination", "both bowls are light"): their propositions of `words`."""
    kind, body = lex.slots[name]
    at = noun.at(min(positions), max(positions))
    if kind != "object" or at is None:
        return []
    others = noun.partners(at) - {body}
    return sorted(n for n in lex.phrases[words] if lex.slots[n][0] == "object"
                  and lex.slots[n][1] in others)


def _occurrences(tokens: list[_Token], lex: _Lexicon):
    """(value words, their positions) for every reading the question holds:
    anchored on each of its words, the nearest of each other in its clause."""
    where: dict[str, list[int]] = {}              # word -> its positions, in order
    for i, t in enumerate(tokens):
        where.setdefault(t.word, []).append(i)
    for words in lex.phrases:
        if not all(w in where for w in words):
            continue
        for a in sorted({i for w in words for i in where[w]}):
            t = tokens[a]
            at = {t.word: a}
            for w in words:
                if w != t.word:
                    near = _nearest(where[w], a, tokens, t.clause)
                    if near is not None:
                        at[w] = near
            span = max(at.values()) - min(at.values()) + 1
            if len(at) == len(words) and span - len(words) <= _MAX_GAP:
                yield words, frozenset(at.values())


def _nearest(positions: list[int], a: int, tokens: list[_Token], clause: int) -> int | None:
    """The position of `positions` (in order) in `clause` nearest to `a`,
    the earlier of two as near; None if there is none. Words of one clause
    stand together, so the nearest is beside where `a` would go, or the
    nearest in the clause on that side."""
    k = bisect_left(positions, a)
    near = [positions[j] for j in (k - 1, k)
            if 0 <= j < len(positions) and tokens[positions[j]].clause == clause]
    return min(near, key=lambda i: (abs(i - a), i)) if near else None


def _closest(reading: tuple[tuple[str, ...], frozenset[int]]) -> tuple:
    words, positions = reading
    return (-len(words), max(positions) - min(positions), min(positions))


def _resolve(names: frozenset[str], positions: frozenset[int], stages: list[str],
             noun: "_Nouns", lex: _Lexicon) -> str | None:
    """The one proposition of `names` that the words at `positions` say in
    their stage and of their noun, or None."""
    stage = stages[min(positions)]
    fits = [n for n in names if lex.slots[n][0] == "stage" and lex.slots[n][1] in
            (_POSE[stage], _MOVE[stage])]
    of_bodies = sorted(n for n in names if lex.slots[n][0] == "object")
    if len(of_bodies) > 1:
        body = noun(min(positions), max(positions))
        of_bodies = [n for n in of_bodies if lex.slots[n][1] == body]
    fits += of_bodies
    if len(fits) != 1:
        return None
    return fits[0] if _agrees(fits[0], min(positions), max(positions), noun, lex) else None


def _agrees(name: str, first: int, last: int, noun: "_Nouns", lex: _Lexicon) -> bool:
    """Whether the proposition `name`, said by the words from `first` to
    `last`, fits the noun they qualify: a property of the liquid said of a
    bowl ("a sticky bowl"), how full the source is said of the destination
    ("the destination is full"), or a pose of the source said of the
    destination ("with the cup upside down": a bowl is the destination) is
    no reading, and the words are refused as not placed."""
    kind, which = lex.slots[name]
    at = noun.at(first, last)
    if at is None:
        return True
    body = noun.roles[at]
    if kind == "stage":             # only "with the <destination> ..." says it of the destination
        t = noun.tokens
        said_with = at == first - 1 and any(
            k >= 0 and t[k].word == "with" and all(t[m].word in _ARTICLES for m in range(k + 1, at))
            for k in (at - 1, at - 2))
        return not (said_with and body == "destination")
    if body == which:
        return True
    # how much liquid there is, said of the source: "a full cup", "a source full of liquid"
    return which == "liquid" and name in lex.amounts and not noun.names_destination(at)


def _stages(tokens: list[_Token]) -> list[str]:
    """The stage each word speaks of (see the module's docstring)."""
    out: list[str] = []
    stage = "pour"
    clauses: dict[int, list[int]] = {}          # clause -> its positions, in order
    for i, t in enumerate(tokens):
        clauses.setdefault(t.clause, []).append(i)
    for clause in sorted(clauses):
        at = clauses[clause]
        marks = [i for i in at if tokens[i].word in _MARKER_STEMS]
        current = _next(tokens[marks[0]].word, stage) if marks else stage
        marked = set(marks[1:])
        for i in at:
            if i in marked:
                current = _next(tokens[i].word, current)
            out.append(current)
        stage = current
    return out


def _next(word: str, stage: str) -> str:
    return _MARKER_STEMS[word] or _THEN[stage]


def _roles(tokens: list[_Token], lex: _Lexicon) -> dict[int, str]:
    """The body each noun names: a bowl is the destination, unless it is a
    source bowl or what is poured from ("pour from a cup", "out of a cup")."""
    roles: dict[int, str] = {}
    for i, t in enumerate(tokens):
        if t.word in _OBJECT_STEMS:
            roles[i] = _OBJECT_STEMS[t.word]
        elif t.word == _BOWL:
            if roles.get(i - 1) in ("source", "destination"):
                roles[i] = roles[i - 1]
                continue
            j = i - 1
            while j > 0 and (tokens[j].word in _BETWEEN or tokens[j].word in lex.placeable):
                j -= 1
            before = (tokens[j - 1].word, tokens[j].word) if j > 0 else None
            k = _past_articles(tokens, i + 2, 1)              # "a glass as the source"
            as_source = (i + 1 < len(tokens) and tokens[i + 1].word == "as" and k < len(tokens)
                         and _OBJECT_STEMS.get(tokens[k].word) == "source")
            roles[i] = "source" if before in _POURED_FROM or as_source else "destination"
    return roles


class _Nouns:
    """`noun(first, last)`: the body the value words from `first` to `last`
    qualify: the noun they stand before, through other value words ("a
    light, slippery bowl"), or else the nearest noun before them in their
    clause ("the liquid is very light"). Where each search ends is found
    once for the whole question, so that a long one is read in linear time."""

    def __init__(self, tokens: list[_Token], roles: dict[int, str], lex: _Lexicon):
        n = len(tokens)
        self.roles, self.tokens = roles, tokens
        # stop[j]: the first position from j on that is a noun or a word
        # that cannot stand between a value word and its noun
        self.stop = [n] * (n + 1)
        for j in range(n - 1, -1, -1):
            passes = j not in roles and (tokens[j].word in _BETWEEN or tokens[j].word in lex.placeable)
            if tokens[j].word in ("and", "or") and j + 1 < n and tokens[j + 1].word in _ARTICLES:
                passes = False          # "heavy and the destination ...": a new noun's words
            self.stop[j] = self.stop[j + 1] if passes else j
        # before[i]: the nearest noun before i in its clause, or None
        self.before: list[int | None] = []
        last = None
        for i, t in enumerate(tokens):
            if last is not None and tokens[last].clause != t.clause:
                last = None
            self.before.append(last)
            if i in roles:
                last = i

    def __call__(self, first: int, last: int) -> str | None:
        at = self.at(first, last)
        return None if at is None else self.roles[at]

    def at(self, first: int, last: int) -> int | None:
        """The position of the noun the words from `first` to `last` qualify."""
        j = self.stop[last + 1]
        return j if j in self.roles else self.before[first]

    def partners(self, i: int) -> set[str]:
        """The bodies the noun at `i` names with others: those of the nouns
        coordinated with it ("the source and the destination"), or both
        bowls for bowls in the plural ("both cups")."""
        t = self.tokens
        if t[i].word == _BOWL and (re.search(r"[^s]s$", t[i].raw) or (i > 0 and t[i - 1].word == "both")):
            return {"source", "destination"}
        out = set()
        for step in (-1, 1):            # "X and [the] <i>" and "<i> and [the] Y"
            j = _past_articles(t, i + step, step)
            if 0 <= j < len(t) and t[j].word == "and":
                j = _past_articles(t, j + step, step)
                if j in self.roles:
                    out.add(self.roles[j])
        return out

    def names_destination(self, i: int) -> bool:
        """Whether the noun at `i` says the destination in so many words
        ("the destination", "a destination bowl"), not a bowl by default."""
        return self.roles.get(i) == "destination" and (
            self.tokens[i].word == "destination" or (i > 0 and self.tokens[i - 1].word == "destination"))


def _past_articles(tokens: list[_Token], j: int, step: int) -> int:
    """The first position from j on, going by `step`, that holds no article."""
    while 0 <= j < len(tokens) and tokens[j].word in _ARTICLES:
        j += step
    return j


def _refuse_unplaced(question: str, tokens: list[_Token], accepted, lex: _Lexicon) -> None:
    """UserError naming the words of the question that were not read: value
    words that fit nothing said ("pour light": the light what?) and, when
    something else was read, words the vocabulary does not know (a question
    with nothing read is understand's to answer as the ordinary pour or to
    refuse)."""
    read = set().union(*(p for _, p in accepted))
    words: dict[str, None] = {}           # in order, each once
    for i, t in enumerate(tokens):
        if i not in read and (t.word in lex.placeable or (accepted and t.word not in lex.known)):
            words.setdefault(t.raw)
    if words:
        said = ", ".join(f'"{w}"' for w in words)
        raise UserError(f"could not place {said} in \"{question}\": describe the scene with "
                        f"the words of `pantarhei vocab`, or give --props P1,P2")


def _or(names: list[str]) -> str:
    return ", ".join(names[:-1]) + " or " + names[-1] if len(names) > 1 else names[0]


def _scope_ends(tokens: list[_Token]) -> list[int]:
    """For each position i, where the scope of a negation at i ends: the
    end of its clause, or the next "and", "or", "yet"... after it."""
    ends = [len(tokens)] * len(tokens)
    for j in range(len(tokens) - 2, -1, -1):
        nxt = tokens[j + 1]
        ends[j] = j + 1 if nxt.clause != tokens[j].clause or nxt.word in _SCOPE_ENDS else ends[j + 1]
    return ends


def _scope(tokens: list[_Token], i: int, ends: list[int]) -> set[int]:
    """The positions a negation at i covers: the rest of its clause, up to
    the next "and", "or", "yet"..., its negations left out."""
    return {j for j in range(i + 1, ends[i]) if tokens[j].word not in _NEGATION_STEMS}


def _covered(tokens: list[_Token], cues: list[int], ends: list[int]) -> set[int]:
    """The positions the negations at `cues` cover, together (each position
    is looked at once: a scope that starts inside another ends with it)."""
    out: set[int] = set()
    reach = 0
    for i in cues:                            # in order
        for j in range(max(i + 1, reach), ends[i]):
            if tokens[j].word not in _NEGATION_STEMS:
                out.add(j)
        reach = max(reach, ends[i])
    return out
