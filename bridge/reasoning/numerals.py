"""Numbers said in words before a unit, read as numbers: "two inches" is
"2 inches", "twenty-five degrees" "25 degrees", "an inch" and "a second"
"1 inch" and "1 second", "half an inch" "0.5 inch", "an inch or two" "1
to 2 inch", "a couple of
inches" the range "2 to 3 inches" and "a few seconds" "2 to 5 seconds" (read
only where one proposition holds all of it), so that quantities.py reads
them as it reads "2 inches". A number word before anything but a
unit ("one side", "two bowls") is left as it is.

A rewrite of words.py's kind (see wording.py): `spans(words)` gives the
words each number covers and the number they are read as.
"""
from __future__ import annotations

from pantarhei.bridge.reasoning.units import UNITS

_ONES = ("zero one two three four five six seven eight nine ten eleven twelve thirteen fourteen "
         "fifteen sixteen seventeen eighteen nineteen").split()
_TENS = {w: 10 * k for k, w in enumerate(
    "_ _ twenty thirty forty fifty sixty seventy eighty ninety".split()) if w != "_"}
#: A number word -> its value.
NUMBER_WORDS = {**{w: k for k, w in enumerate(_ONES)}, **_TENS}
#: Units said in the singular after "a", "an" or "one": "an inch", "a second".
_ONE = {"a", "an", "one"}


class NumberWords:
    """The rewrite (see the module's docstring)."""

    def spans(self, words: list[str]) -> list[tuple[int, int, tuple[str, ...]]]:
        out: list[tuple[int, int, tuple[str, ...]]] = []
        i = 0
        while i < len(words):
            found = _number_at(words, i)
            if found is not None and found[0] < len(words) and words[found[0]] in UNITS and not (
                    words[i] in _ONE and UNITS[words[found[0]]][0] == "count"):   # a particle of it
                end, value = found
                said = tuple(f"{v:g}" if isinstance(v, float) else v for v in value)
                if words[end + 1:end + 2] == ["or"] and end + 2 < len(words) \
                        and words[end + 2] in NUMBER_WORDS and len(value) == 1:   # an inch or two
                    out.append((i, end + 3, (*said, "to", str(NUMBER_WORDS[words[end + 2]]),
                                             words[end])))
                    end += 3
                else:
                    out.append((i, end, said))
                i = end
            else:
                i += 1
        return out


#: Vague counts before a unit, as the ranges they say: "a couple of inches", "a couple cm", "a few seconds".
_VAGUE = {("a", "couple", "of"): (2.0, "to", 3.0), ("a", "couple"): (2.0, "to", 3.0), ("a", "few"): (2.0, "to", 5.0)}


def _number_at(words: list[str], i: int) -> tuple[int, tuple] | None:
    """(the position after the number said in words from `i`, the words of
    its value: a number, or a range), or None."""
    w = words[i]
    for said, value in _VAGUE.items():
        if tuple(words[i:i + len(said)]) == said:
            return i + len(said), value
    if w == "half" and words[i + 1:i + 2] and words[i + 1] in ("a", "an"):     # half an inch
        return i + 2, (0.5,)
    if w in _ONE and w != "one":
        return i + 1, (1.0,)
    if w not in NUMBER_WORDS:
        return None
    value = float(NUMBER_WORDS[w])
    if w in _TENS and i + 1 < len(words) and words[i + 1] in _ONES[1:10]:   # twenty five
        return i + 2, (value + NUMBER_WORDS[words[i + 1]],)
    return i + 1, (value,)
