"""A value said against the ordinary pour ("lower than last time", "a bit
lower": comparisons.py) says only which way from it; a value of the same
dimension said outright beside it ("not as high as last time, just a bit
lower than the rim": below the rim) says where, and is read in its place
when it lies the same way from the ordinary pour. One the other way ("pour
lower, 30 cm up") is left to be refused as two values. So is a value said
in words and then a number put forward as what it is ("too high, like a
foot up": the number's), where both lie the same way from the ordinary pour.

Two values of one dimension set against each other, joined by "or",
"than", "versus" or "different from", in a question that compares
("which", "better", "worse", "more", "less", "different", a comparative in
"-ier": "is it messier to pour from high up or from just above the bowl?",
"does it splash less if I pour close to the rim or right in the middle")
are two pours compared, however the two are worded: the one said first is
answered, the other said back as not read, as compared_or.py does for the
wordings it knows. Without a word that compares ("pour high or low, does
it spill?") the two are still refused, asking for one."""
from __future__ import annotations

import re
from typing import Any

#: What comparisons.py says back of a value read against the ordinary pour.
AGAINST = "read against the ordinary pour: each question is read alone"


def outright(names: list[str], accepted: list[tuple[str, frozenset[int]]], tokens: list[Any],
             vocab) -> list[str]:
    """`names`, values said of one dimension, without those read against the
    ordinary pour where one said outright lies the same way from it."""
    against = {n for n, at in accepted if n in names and any(tokens[k].said_back.startswith(AGAINST) for k in at)}
    said = [n for n in names if n not in against]
    if not against or len(said) != 1 or not all(_way(n, vocab) == _way(said[0], vocab) != 0 for n in against):
        return _exemplified(names, accepted, tokens, vocab)
    return said


#: Words that put a number forward as what the value said before it is: "too high, like a foot up".
_EXAMPLE = frozenset(("like", "about", "around", "roughly", "approximately", "say"))


def _exemplified(names: list[str], accepted: list[tuple[str, frozenset[int]]], tokens: list[Any],
                 vocab) -> list[str]:
    """`names`, two values of one dimension, as the one a number says where it is put forward
    right after the other, said in words, as what it is ("too high, like a foot up": the number's),
    and both lie the same way from the ordinary pour; `names` otherwise."""
    at = {n: p for n, p in accepted if n in names}
    numbers = [n for n, p in at.items() if len(p) == 1 and tokens[min(p)].word == n]
    if len(names) != 2 or len(numbers) != 1:
        return names
    number = numbers[0]
    k = min(at[number])
    word = next(n for n in names if n != number)
    if (k > 0 and tokens[k - 1].raw in _EXAMPLE and max(at[word]) < k - 1
            and _way(word, vocab) == _way(number, vocab) != 0):
        return [number]
    return names


def _way(name: str, vocab) -> int:
    """Which way the middle of the value `name` lies from the middle of the
    ordinary pour's range: -1 below, 1 above, 0 at it or unknown."""
    model = vocab.propositions[name].model
    if model.kind != "uniform":
        return 0
    p = next(p for p in vocab.parameters if p.name == model.param)
    middle, ordinary = model.low + model.high, p.prior_low + p.prior_high
    return (middle > ordinary) - (middle < ordinary)


#: Words that set a value against another said before it: "high or low", "than", "versus".
_AGAINST = frozenset(("or", "than", "different", "compar", "versus", "vs"))
#: Words of a comparison asked: "which", "better", "more", "less".
#: (and any "-ier": "messier", "riskier").
_COMPARING = frozenset(("which", "better", "wors", "worse", "safer", "cleaner", "more", "less", "different", "compar"))
#: A word that compares, in the question's text (an outcome's clause too: "does it splash less if ...").
_COMPARES = re.compile(rf"\b(?:{'|'.join(sorted(_COMPARING))}\w*|[a-z]+ier)\b")
#: What is said back of a word that compares the two.
_COMPARISON = "read as nothing: the two pours compared, the one said first is answered"
#: What is said back of the value compared with.
COMPARED = "read as nothing: the scene compared with is not read, the answer is for the one said first"


def first_compared(names: list[str], accepted: list[tuple[str, frozenset[int]]], tokens: list[Any],
                   text: str) -> tuple[list[str], tuple[str, ...], set[int]]:
    """`names`, two values of one dimension, as the one said first where
    the second is set against it and the question (`text`, normalised)
    compares (the module's docstring); what is said back of the second
    and of the words that compare ("more", "different", "than"); and
    their positions. `names`, (), and none otherwise."""
    at = {n: p for n, p in accepted if n in names}
    if len(names) != 2 or len(at) != 2:
        return names, (), set()
    first, second = sorted(names, key=lambda n: min(at[n]))
    between = tokens[max(at[first]) + 1:min(at[second])]
    comparing = {k for k, t in enumerate(tokens) if t.word in _COMPARING or t.raw in _COMPARING
                 or t.raw in ("than", "likely") or t.raw.endswith("ier")}
    if (max(at[first]) >= min(at[second]) or not any(t.word in _AGAINST for t in between)
            or not _COMPARES.search(text)):
        return names, (), set()
    said = [f"{' '.join(tokens[k].raw for k in sorted(at[second]))}: {COMPARED}"]
    said += [f"{tokens[k].raw}: {_COMPARISON}" for k in sorted(comparing)]
    return [first], tuple(dict.fromkeys(said)), comparing
