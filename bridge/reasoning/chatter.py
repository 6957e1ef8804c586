"""A sentence said before the question that says nothing of a pour ("My
grandson set this up for me.", "Long day at the cafe!"): every word of it
one the reader reads as nothing (everyday.txt's hedges) or an English word
it does not know at all, at least one of them, with no number, no negation, no verb of an
outcome and no word it could mistake for another. It is read as nothing
and said back, so that its words neither refuse the question nor go
unheard. So is a sentence after the question ("... splash less than water?
Asking for a science lesson."), where its words may also be words the
reader knows but never places in a scene ("I want to show them with a
simple demo."), but for one that supposes ("if its to close"), asks
("does it go inside", its question mark left out) or tells an outcome
("It spilled everywhere yesterday."). The question itself, the last sentence ending in a question mark (the last sentence, with none), is
never chatter; a sentence with a word the reader knows ("The bowl is
plastic.") is read as any other, and one with a word it cannot spell
("Bowl slidez.") is refused as mistyped."""
from __future__ import annotations

import re

from pantarhei.bridge.reasoning.outcome_verbs import outcome_verb
from pantarhei.bridge.reasoning.spelling import english

#: A sentence after the question that says when or how it is asked ("cup hits bowl??? if its to close"), or asks: no chatter.
_SUPPOSED = re.compile(r"\b(?:if|when|while|without|unless|because|once|before|after)\b"
                       # (or asks, its question mark left out: "does the jug hit the bowl? does the milk go inside")
                       r"|^(?:does|do|did|will|would|can|could|is|are|was|were|should)\b")
#: What is said back of a sentence read as chatter.
SAID = "read as nothing: it says nothing of a pour"


def chatter(text: str, words_of, known: frozenset[str], nothing: frozenset[str],
            negations: frozenset[str], placeable: frozenset[str]) -> tuple[str, tuple[str, ...]]:
    """`text` (normalised) without the sentences around its question that are
    chatter (the module's docstring), and what is said back of each;
    `words_of` gives a text's tokens, `known` the words the reader knows,
    `nothing` those it reads as nothing, `negations` the negations',
    `placeable` the words it places in a scene."""
    sentences = re.split(r"(?<=[.!?])\s+", text.strip())
    if len(sentences) < 2:
        return text, ()
    asked = max((i for i, s in enumerate(sentences) if s.endswith("?")), default=len(sentences) - 1)
    kept, said = [], []
    for i, sentence in enumerate(sentences):
        after = i > asked               # after the question: known words placed nowhere are nothing too
        if i != asked and _chatter(sentence, words_of, known, nothing, negations, placeable if after else None) and not (
                after and (_SUPPOSED.search(sentence) or any(outcome_verb(t.raw) for t in words_of(sentence)))):
            said.append(f"{sentence.rstrip(' .!?')}: {SAID}")
        else:
            kept.append(sentence)
    if not said:
        return text, ()
    return " ".join(kept), tuple(said)


def _chatter(sentence: str, words_of, known, nothing, negations, placeable=None) -> bool:
    """Whether `sentence` is chatter: every word read as nothing or an English word the reader does not
    know, one at least, and (with `placeable`) any word it knows but never places in a scene."""
    if re.search(r"\d", sentence):
        return False
    tokens = words_of(sentence)
    return any(t.word not in known for t in tokens) and all(
        t.word in nothing or (placeable is not None and t.word in known and t.word not in placeable)
        or (t.word not in known and english(t.raw) and not outcome_verb(t.raw))
        for t in tokens) and not any(t.word in negations for t in tokens)
