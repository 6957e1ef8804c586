"""The bodies a question speaks of: each noun's body (a bowl is the
destination unless it is a source bowl or what is poured from: "pour
from a cup", "out of a cup", "a glass as the source"), and the noun that
value words qualify (the one they stand before, through other value
words: "a light, slippery bowl"; or else the one before them: "the liquid
is very light")."""
from __future__ import annotations

import re
from functools import cached_property, lru_cache

from pantarhei.bridge.reasoning.everyday import forms, names, sections
from pantarhei.bridge.reasoning.wording import Token, stem

OBJECTS = ("source", "destination", "liquid")
OBJECT_STEMS = {stem(o): o for o in OBJECTS}
BOWL = stem("bowl")
#: Words that may stand between a body's value word and its noun: "a light, slippery bowl",
#: Words of degree between a copula and its value: "the jug is really light".
_DEGREES = frozenset(stem(w) for w in "very really quite so pretty too rather fairly somewhat extra super".split())
#: "a heavy ceramic bowl", "the spout of a light jug" (everyday.txt's materials and parts).
BETWEEN = {"a", "an", "the", "and", "or", "very", "material", "part"}
ARTICLES = {"a", "an", "the"}
#: Verbs that say a value of the noun before them ("the bowl is light"), not of one after.
_COPULAS = {stem(w) for w in ("is", "are", "was", "were", "be", "being", "seems", "looks", "feels")}
#: What everyday.txt's context nouns are read as: a noun, but of nothing in the scene
#: ("a slippery counter" says nothing of a bowl).
CONTEXT = "context"
#: (word, next word) before a bowl that the liquid is poured out of: "pour from a cup",
#: "into a bowl from a cup" (not "far from the cup": the destination)
#: Words before a bowl poured into: "into a jug", "in the kettle".
_INTO = {"into", "onto", "in", "to"}
#: Words between a bowl and its being poured into another: "a pot (that is) poured into a bowl".
_BEING = {stem(w) for w in ("be", "is", "are", "being", "was", "were", "get", "gets", "that", "which")}
_INSTEAD = {stem(w) for w in ("not", "no", "nor", "instead", "rather", "than", "or")}
_POURED_FROM = {(stem(a), stem(b))
                for a, b in (("out", "of"), ("pour", "from"), ("liquid", "from"),
                             ("bowl", "from"), ("destination", "from"), (CONTEXT, "from"))}


def roles(tokens: list[Token], placeable: frozenset[str], bowl: bool = False) -> dict[int, str]:
    """The body each noun names: a bowl is the destination, unless it is a
    source bowl or what is poured from ("pour from a cup", "out of a cup"),
    or named again ("pour from a carton ... the carton is light"), or one
    people pour from ("a heavy jug", everyday.txt) and not poured into, or
    named beside "the bowl" (`bowl`: named in what is asked, "with a
    slippery cup, does it end up in the bowl?"); a context noun ("the
    table") names CONTEXT, no body of the scene."""
    roles: dict[int, str] = {}
    sources: dict[str, bool] = {}       # a bowl's name -> whether it names the source alone
    for i, t in enumerate(tokens):
        if t.word in OBJECT_STEMS:
            roles[i] = OBJECT_STEMS[t.word]
        elif t.word == CONTEXT:
            roles[i] = CONTEXT
        elif t.word == BOWL:
            if roles.get(i - 1) in ("source", "destination") and tokens[i - 1].clause == t.clause:
                roles[i] = roles[i - 1]         # "a glass mixing bowl" (not "from the bottle, bowl is ...")
                continue
            j = i - 1
            while j > 0 and (tokens[j].word in BETWEEN or tokens[j].word in placeable):
                j -= 1
            # (within its clause: "pour from the side, light bowl" pours into the bowl)
            before = (tokens[j - 1].word, tokens[j].word) if j > 0 and tokens[j].clause == t.clause else None
            k = past_articles(tokens, i + 2, 1)              # "a glass as the source"
            as_source = (i + 1 < len(tokens) and tokens[i + 1].word == "as" and k < len(tokens)
                         and OBJECT_STEMS.get(tokens[k].word) == "source")
            name = t.raw.split()[-1]
            again = tokens[i - 1].word == "the" and sources.get(name)   # "the carton" again
            # a jug, a bottle is poured from, unless poured into ("into a jug")
            # (the liquid in a jug is held in it: "lots of water in a light jug", not "pour water in")
            held = (j >= 1 and tokens[j].word == "in" and tokens[j - 1].word == "liquid"
                    and all(tokens[m].word != "pour" for m in range(max(0, j - 4), j - 1)))
            usual = ((t.raw in poured_from() or name in poured_from())
                     and (held or not (j >= 0 and tokens[j].word in _INTO)))
            k = i + 1                   # "can a heavy pot be poured into a bowl": the pot is poured
            while k < len(tokens) and tokens[k].word in _BEING:
                k += 1
            poured = (k + 2 < len(tokens) and tokens[k].raw == "poured" and tokens[k + 2].clause == t.clause
                      and tokens[k + 1].word in ("into", "onto")) or (       # "pour a light cup into ..."
                j >= 0 and tokens[j].word == stem("pour") and k < len(tokens) and tokens[k].word in ("into", "onto"))
            into = j >= 0 and tokens[j].word in _INTO
            roles[i] = ("source" if before in _POURED_FROM or as_source or again or usual or poured
                        or (not into and _handled(tokens, i, j))
                        else "destination")
            # (a name said of both bowls, "from a cup into a cup", refers to neither again)
            sources[name] = roles[i] == "source" and sources.get(name, True)
    return _ones(tokens, _beside_the_bowl(tokens, roles, bowl), placeable)


#: What is done to the source, said before it ("tilt the heavy cup", "lift the mug") or after
#: it ("the cup comes in low", "a heavy mug, tilted halfway", "with the cup upside down"): a bowl
#: handled so is the source.
_HANDLING = {stem(w) for w in ("tilt", "tip", "tipped", "lift", "raise", "lower", "hold", "held", "move",
                               "bring", "brought", "swing", "rotate", "incline", "lean", "carry", "invert",
                               "upend", "approach", "retreat", "upside")}


def _handled(tokens: list[Token], i: int, j: int) -> bool:
    """Whether the bowl at `i` is what is handled: the object of a verb of
    handling (`j`: the first word before it that is no value word or
    article), or its subject in its clause ("the cup, tilted": a new
    clause; "a glass pouring"); a bowl called a bowl excepted: the
    destination's name, its tilt the pour's."""
    if tokens[i].raw.split()[-1] in ("bowl", "bowls"):
        return False                    # the destination's name: "tilt the bowl halfway" is the pour's tilt
    if j >= 0 and tokens[j].word in _HANDLING and tokens[j].clause == tokens[i].clause \
            and not any(tokens[m].word in ("and", "or") for m in range(j + 1, i)):
        return True                     # (not "the mug comes in fast and the bowl is light")
    k = i + 1
    while k < len(tokens) and tokens[k].word in _BEING:
        k += 1
    return (k < len(tokens) and (tokens[k].word in _HANDLING or tokens[k].raw in ("pours", "pouring"))
            and tokens[k].clause - tokens[i].clause <= 1)


def _ones(tokens: list[Token], roles: dict[int, str], placeable: frozenset[str]) -> dict[int, str]:
    """`roles`, with "one" after a value word (what it is made of may stand between) the body the
    question names, where it names one: "rather than a heavy bowl, use a really light one" (a light
    bowl), "it's a lightweight melamine one"; with what it is made of said, only a container is meant
    ("the bowl flipped as I poured the oil, it was a light plastic one")."""
    named = {r for r in roles.values() if r != CONTEXT}
    made = {r for r in named if r != "liquid"}          # what a material may be said of
    ones = {i: v for i, t in enumerate(tokens) if t.word == "one" and i > 0
            and (v := _value_before(tokens, i)) is not None and tokens[v].word in placeable and tokens[v].word not in BETWEEN}
    if len(named) == 1:
        return {**roles, **{i: next(iter(named)) for i in ones}}
    return {**roles, **{i: next(iter(made)) for i, v in ones.items() if len(made) == 1 and v < i - 1}}


def _value_before(tokens: list[Token], i: int) -> int | None:
    """The position of the word before `i` that may qualify it, past what a bowl is made of
    ("a lightweight melamine one": lightweight); None at the start."""
    k = i - 1
    while k > 0 and tokens[k].word == "material":
        k -= 1
    return k if k >= 0 else None


def _beside_the_bowl(tokens: list[Token], roles: dict[int, str], bowl: bool = False) -> dict[int, str]:
    """`roles`, with a container named beside "the bowl" the source: "the bowl is glass and
    the mug is bouncy" names two bodies, the bowl poured into and the mug poured from (not
    where the other is poured into, "from a jug into a cup", nor "both bowls"; nor where one
    may be said instead of the other: "a light bowl, not a heavy cup")."""
    if any(t.word in _INSTEAD for t in tokens):
        return roles
    named = {tokens[i].raw.split()[-1] for i in roles        # ("the bowl is glass": what it is made of)
             if tokens[i].word == BOWL and not (i > 0 and tokens[i - 1].word in _COPULAS)} | ({"bowl"} if bowl else set())
    others = named - {"bowl"}
    other = others.pop() if len(others) == 1 else None
    if "bowl" not in named or other is None or any(
            r == "source" and tokens[i].word == BOWL and tokens[i].raw.split()[-1] != other for i, r in roles.items()):
        return roles
    return {i: "source" if tokens[i].word == BOWL and tokens[i].raw.split()[-1] == other else r
            for i, r in roles.items()}


#: Words that cannot name what kind of bowl the next one is ("into bowl", "is bowl", "pour bowl").
_NOT_NAMING = frozenset(stem(w) for w in """into in onto on from to of over under with by for at than then and or but if when while
    is are was were be been am do does did will would can could should not no nor pour pours poured pouring tip tilt it
    its my your our their his her this that these those what which who one each every both either neither""".split())


def _naming(tokens: list[Token], j: int, roles: dict[int, str]) -> bool:
    """Whether the word at `j` names the kind of the bowl right after it, a word no other reading takes
    ("a light ramen bowl", "a lightweight plastic feeding bowl"): the bowl's, between a value word and it."""
    return (j + 1 in roles and tokens[j + 1].word == BOWL and tokens[j].word.isalpha()
            and tokens[j].word not in _NOT_NAMING and tokens[j].clause == tokens[j + 1].clause)


#: How old a body is, or whose, said between a value word and its noun ("a heavy old enamel bowl"):
#: words read as nothing (everyday.txt's hedges).
_AGED = frozenset(("old", "own"))


#: Who has the bowls said in the plural: "our bowls" are the kind someone pours with, not both bowls.
_OWNERS = frozenset(("our", "my", "your", "their"))


class Nouns:
    """`noun(first, last)`: the body the value words from `first` to `last`
    qualify: the noun they stand before, through other value words ("a
    light, slippery bowl"), or else the nearest noun before them in their
    clause ("the liquid is very light"). Where each search ends is found
    once for the whole question, so that a long one is read in linear time."""

    def __init__(self, tokens: list[Token], roles: dict[int, str], placeable: frozenset[str]):
        n = len(tokens)
        self.roles, self.tokens = roles, tokens
        # stop[j]: the first position from j on that is a noun or a word
        # that cannot stand between a value word and its noun
        self.stop = [n] * (n + 1)
        for j in range(n - 1, -1, -1):
            passes = j not in roles and (tokens[j].word in BETWEEN or tokens[j].word in placeable
                                         or _measured(tokens[j])        # "a heavy 2 kg bowl"
                                         or _naming(tokens, j, roles)    # "a light ramen bowl"
                                         or tokens[j].raw.split()[-1] in _AGED and tokens[j].word == "hedg")   # "a heavy old ... bowl"
            if tokens[j].word in ("and", "or") and j + 1 < n and (tokens[j + 1].word in ARTICLES
                                                                  or j + 1 in roles):
                passes = False          # "heavy and the destination ...", "heavy and jug ...": a new noun's
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
        """The position of the noun the words from `first` to `last` qualify:
        the one they stand before ("a light, slippery cup"), unless it is
        past the end of their clause and they are said of a noun before them
        in it ("the table is slippery, the bowl ...": the table)."""
        j = self.stop[last + 1]
        t = self.tokens
        k = first - 1
        while k > 0 and t[k].word in _DEGREES:  # "the bowl is very light": said of the bowl
            k -= 1
        if k >= 0 and t[k].word in _COPULAS and self.before[first] is not None:
            return self.before[first]           # said of the noun before: "bowl is light and ..."
        ahead = j in self.roles and (t[j].clause == t[last].clause or self.before[first] is None
                                     or (first > 0 and t[first - 1].word in BETWEEN))
        return j if ahead else self.before[first]

    def said_of(self, at: int, first: int, last: int) -> bool:
        """Whether the value words from `first` to `last` are said of the
        noun at `at` itself: before it ("a high table"), or after it with
        nothing but articles, value words and "is" between ("the table is
        high"); not where a clause goes on ("in the kitchen we pour from high")."""
        if at > last:
            return True
        t = self.tokens
        return all(t[m].word in BETWEEN or t[m].word in _COPULAS for m in range(at + 1, first))

    @cached_property
    def source_names(self) -> set[str]:
        """The names of the bowls read as the source ("jug"), each in the singular."""
        return {self.tokens[j].raw.split()[-1].rstrip("s") for j, r in self.roles.items()
                if r == "source" and self.tokens[j].word == BOWL}

    def partners(self, i: int) -> set[str]:
        """The bodies the noun at `i` names with others: those of the nouns
        coordinated with it ("the source and the destination"), or both
        bowls for bowls in the plural ("both cups"), unless the source is
        named apart ("from a jug ... the bowls are light": the bowls poured
        into), or they are said poured into ("slippery bowls ... when you pour in them")."""
        t = self.tokens
        last = t[i].raw.split()[-1]
        plural = re.search(r"[^s]s$", last) and last not in _singular()      # not "a thermos"
        # "our bowls", "my light cups": the ones someone has, each poured into or from as one is
        owned = any(w.raw in _OWNERS for w in t[max(0, i - 3):i]) and not any(
            w.word in ("both", "two") for w in t[max(0, i - 3):i])
        # "bowls light and kinda slick" after "out of a jug": the bowls poured into, the jug named apart
        # ("into light bowls": poured into, the destination)
        apart = plural and (bool(self.source_names - {last.rstrip("s")}) or self.poured_into(i) or any(     # "... when you pour in them"
            t[j].word == "pour" and t[j + 1].word in ("in", "into") and t[j + 2].raw == "them" for j in range(i + 1, len(t) - 2)))
        if t[i].word == BOWL and ((plural and not owned and not apart) or (i > 0 and t[i - 1].word == "both")):
            return {"source", "destination"}
        out = set()
        for step in (-1, 1):            # "X and [the] <i>" and "<i> and [the] Y"
            j = past_articles(t, i + step, step)
            if 0 <= j < len(t) and t[j].word == "and":
                j = past_articles(t, j + step, step)
                if j in self.roles and not (j > 0 and t[j - 1].word in _COPULAS):   # "is glass and"
                    out.add(self.roles[j])
        return out

    def poured_into(self, i: int) -> bool:
        """Whether the bowl at `i` is said as what is poured into ("into a
        full cup"), past the words that may stand before it."""
        j = i - 1
        while j >= 0 and self.stop[j] != j:     # value words and articles
            j -= 1
        return j >= 0 and self.tokens[j].word in ("into", "onto")

    def names_destination(self, i: int) -> bool:
        """Whether the noun at `i` says the destination in so many words
        ("the destination", "a destination bowl"), not a bowl by default."""
        return self.roles.get(i) == "destination" and (
            self.tokens[i].word == "destination" or (i > 0 and self.tokens[i - 1].word == "destination"))


@lru_cache(maxsize=None)
def poured_from() -> frozenset[str]:
    """The names of the containers people pour from (everyday.txt), singular
    and plural: whole ("measuring cup") or, for a one-word name, as the last
    word of the bowl's ("milk carton")."""
    return frozenset(" ".join(f) for s in sections() if s.words == "bowl poured from"
                     for p in s.phrases for f in forms(p))


@lru_cache(maxsize=None)
def _singular() -> frozenset[str]:
    """The last words of the containers' names (everyday.txt), in the singular."""
    return frozenset(p.split()[-1] for p in names("bowl"))


def _measured(t: Token) -> bool:
    """Whether `t` is a number with its unit read as a proposition (quantities.py): a value
    word may stand before it and its noun ("a heavy 1.2 kg jug")."""
    return "_" in t.word and any(c.isdigit() for c in t.raw)


def past_articles(tokens: list[Token], j: int, step: int) -> int:
    """The first position from j on, going by `step`, that holds no article."""
    while 0 <= j < len(tokens) and tokens[j].word in ARTICLES:
        j += step
    return j
