"""The words of a question its reading accounts for neither way: not read,
not heard as what is asked, not said back, not shown as ignored, and not a
word of the question's frame (words.py's fillers). A question read with
such a word has dropped it silently; the reader is built so that none is."""
from __future__ import annotations

import re

from pantarhei.bridge.reasoning.wording import unaccented
from pantarhei.bridge.reasoning.words import FILLERS


def dropped_words(question: str, reading) -> list[str]:
    """The words of `question` (as typed) that `reading` (a reading.Reading) drops silently."""
    accounted = {w for phrase in (*reading.heard, *reading.ignored) for w in re.findall(r"[a-z]+", phrase.lower())}
    accounted |= {w for n in reading.notes for w in re.findall(r"[a-z]+", n.split(":")[0].lower())}
    accounted |= set(FILLERS) | {"s", "minus"}
    # as typed: a contraction with its apostrophe spelt out ("won't": will not), one typed
    # without it ("wont", "im") or a word mistyped ("teh") said back in the notes
    said = re.sub(r"\bcan't\b|\bcannot\b", "can not", unaccented(question.lower().replace("\u2019", "'")))
    said = re.sub(r"n't\b", " not", re.sub(r"\bwon't\b", "will not", re.sub(r"\bma'am\b", "maam", said)))
    return [w for w in re.findall(r"[a-z]+", said) if w not in accounted]
