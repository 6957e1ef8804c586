"""An outcome asked as how likely it is against another scene or the ordinary pour: "would a
heavier bowl be less likely to move about", "which one is more likely to slide", "is it
likelier to spill", "is more easy to spill" (easy to happen: likely), or as a worry: "do i need to worry about the bowl
tipping". How likely is the answer's to say: the words are heard with the
outcome asked, never the scene's ("less" there says no less of anything)."""
from __future__ import annotations

import re

_LIKELY = re.compile(r"(?:^| )(?:be |is |are )?(?:(?:a )?(?:lot |bit |little |much |far )?(?:more|less|most|least) |as )?"
                     r"(?:likely|likelier|prone|apt|easy|easier)(?: than [a-z ]+?)?(?: as [a-z ]+?)? to$")

#: A worry about an outcome, said before its subject: "i need to worry about (the bowl tipping)".
_WORRY = re.compile(r"^(?:(?:i|we|you) )?(?:(?:need|have|got|ought) )?(?:to )?(?:be )?(?:worry|worried|concerned) about(?= )")


def likely(subject: list[str]) -> tuple[list[str], str]:
    """`subject` (the words before an outcome's verb) without how likely the outcome is said to
    be at its end ("a heavier bowl be less likely to") or a worry about it at its start ("i need
    to worry about the bowl"), and those words ("" where none)."""
    if m := _WORRY.match(" ".join(subject)):
        return " ".join(subject)[m.end():].split(), m.group(0).strip()
    m = _LIKELY.search(" ".join(subject))
    if m is None:
        return subject, ""
    return " ".join(subject)[:m.start()].split(), m.group(0).strip()
