"""A choice between two liquids that the vocabulary reads as different
values ("what is better to pour, honey or water?": a sticky liquid or an
ordinary one), asked without a goal, is two questions: it is refused,
asking for one of them, as "high or low" is (reading.py), where the first
would otherwise be read alone and the second, the ordinary liquid, said
nothing of. With a goal ("I want none on the table: honey or water?")
the goal is what is asked, and it is left to the reader. Two liquids set
against each other ("pouring water vs pouring olive oil, which drips
more?") that the vocabulary reads as one value are read as one pour, the
first, said back: it cannot tell them apart, and its answer is the same
for both (as "water or olive oil" is); two poured at once ("pour bleach and vinegar
into the same bowl") are refused too: it pours one liquid, never a mix.
So are two containers poured from set against each other with nothing
said of either that the vocabulary reads ("a wine bottle vs a wide mug",
"kids plastic cup vs glass mug"): its containers differ only in how heavy,
slippery or bouncy they are, and the source in how much it holds (a scene
set against another that differs from it in such names alone, "glass bowl vs
steel bowl", "into the fryer basin vs into a mixing bowl", is set_against.py's)."""
from __future__ import annotations

import re
from functools import lru_cache

from pantarhei.bridge.errors import UserError
from pantarhei.bridge.reasoning.everyday import alternation, names, sections
from pantarhei.bridge.reasoning.two_liquids import chosen_liquids, liquid_values, poured_together, read_alike, set_against_liquids


def read_choice(text: str) -> tuple[str, tuple[str, ...]]:
    """UserError where `text` (normalised) chooses between two liquids read as different values, with no goal,
    or pours two at once; `text` with two liquids read as one value set against each other read as the first,
    and what is said back of it."""
    value = liquid_values()
    both = poured_together(text)
    if both and both.group(1) != both.group(2):
        raise UserError(f"\"{both.group(0)}\": the vocabulary pours one liquid at a time, and says nothing of two "
                        f"mixed: ask about one of them (\"pour {both.group(1)}\")")
    against = set_against_liquids(text)
    told_how = re.search(r"\b(?:thick|thin|runny|sticky|watery|viscous|syrupy|heavy|light)\b",
                         text[max(0, against.start() - 12):against.end()]) if against else None     # "thick paint vs water"
    alike: tuple[str, ...] = ()
    if against and not told_how and read_alike(against):
        said = sections()[value[against.group(1)]].said_back.removeprefix("read as ").split(":")[0] or "an ordinary liquid"
        alike = (f"{against.group(0)}: both read as {said}: the vocabulary does not tell them apart, so the answer "
                 f"is the same for both",)
        text = text[:against.start()] + text[against.start():against.end(1)] + text[against.end():]
    vessels = _vessels_set_against().search(text)
    if vessels and not _READ.search(vessels.group(0)):
        raise UserError(f"\"{vessels.group(0)}\": the vocabulary's containers differ only in how heavy, slippery or "
                        f"bouncy they are (and the source in how much it holds), so it cannot tell the two pours apart: "
                        f"ask about one of them, or set against it one it reads otherwise (\"a heavy jug vs a light one\")")
    m = chosen_liquids(text)
    if m is None or read_alike(m):
        return text, alike                      # "water or milk": both read as an ordinary liquid
    from pantarhei.bridge.reasoning.outcomes import hear       # here: outcomes reads words with wording.py
    if hear(text).goals:
        return text, alike
    said = {k: s.said_back.removeprefix("read as ").split(":")[0] or "an ordinary liquid"
            for k, s in enumerate(sections())}
    raise UserError(f"\"{m.group(0)}\" chooses between two liquids, {m.group(1)} ({said[value[m.group(1)]]}) "
                    f"and {m.group(2)} ({said[value[m.group(2)]]}): ask about one of them (\"if I pour "
                    f"{m.group(1)}, will it splash?\")")


#: Words of a container the vocabulary reads: set against another with one of them, the two differ.
_READ = re.compile(r"\b(?:heavy|heavier|light|lighter|slippery|slick|grippy|bouncy|full|fuller|empty|half|little|much"
                   r"|sticky|thick|thin|runny|non ?slip|\d)")


@lru_cache(maxsize=None)
def _vessels_set_against() -> re.Pattern:
    """Two containers poured from (no bowl) set against each other, a few words of their own before each
    ("a wine bottle vs a wide mug")."""
    poured_from = (n for n in names("bowl") if not re.search(r"bowl|dish|basin", n))
    before, vessel = (r"(?:(?:pouring |pour |poured )?from )?(?:(?:a|an|the|my|her|his|our) )?(?:[a-z]+ ){0,2}",
                      rf"(?:{alternation(poured_from)})\b")      # ("pouring from the bottle vs pouring from the cup")
    return re.compile(rf"\b{before}?{vessel} (?:vs|versus|compared (?:to|with)) {before}{vessel}")
