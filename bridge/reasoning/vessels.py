"""Which bowl the words of an outcome name: the destination by its names
(everyday.txt's bowls, its rim or edge), the source by its name or by
being poured from, and the liquid by its names."""
from __future__ import annotations

import re
from functools import lru_cache

from pantarhei.bridge.reasoning.everyday import Matcher, alternation, names, refused, sections
from pantarhei.bridge.reasoning.nouns import poured_from


@lru_cache(maxsize=None)
def bowl_names() -> tuple[str, ...]:
    """The names of everyday.txt's bowls (those poured from, a jug, are the source's)."""
    return tuple(p for s in sections() if s.words == "bowl" for p in s.phrases)


@lru_cache(maxsize=None)
def destinations() -> str:
    """What liquid leaves the destination by: its rim, or the destination by
    a name of everyday.txt's bowls (those poured from are the source)."""
    return alternation([*bowl_names(), "destination", "bowl", "target", "container", "rim", "edge",
                        "top", "side", "brim", "lip"])


#: Where liquid that leaves the destination leaves it by, in OUTCOMES: filled() writes in
#: its rim or the destination's names ("out of the mug").
OUT_OF = "(?:DESTINATION)"


#: Any container, by everyday.txt's names of bowls, those poured from among them, in OUTCOMES.
CONTAINER = "(?:CONTAINER)"


#: Safe, said of a pour, in OUTCOMES: filled() writes in that it is not said of what a liquid does (everyday.txt:
#: "is this bleach safe to pour", "safe to pour acid", whose words are refused there).
SAFE = "(?:SAFE)"


@lru_cache(maxsize=None)
def _safe() -> str:
    """The word safe, not where everyday.txt's phrases of what a liquid does say it."""
    said = [p.split("safe", 1) for p in refused("what a liquid does").phrases if "safe" in p.split()]
    return ("".join(f"(?<!{re.escape(before)})" for before, _ in said if before)
            + "safe(?:ly)?" + "".join(f"(?!{re.escape(after)})" for before, after in said if not before and after))


@lru_cache(maxsize=None)
def _containers() -> str:
    return alternation([*names("bowl"), "source", "container"])


def filled(verb: str) -> str:
    """An OUTCOMES verb phrase with the destination's names, "safe" as said of a pour, and the containers', written in."""
    verb = verb.replace(OUT_OF, f"(?:{destinations()})") if OUT_OF in verb else verb
    verb = verb.replace(SAFE, f"(?:{_safe()})") if SAFE in verb else verb
    return verb.replace(CONTAINER, f"(?:{_containers()})") if CONTAINER in verb else verb


def in_the_source(said: str, text: str = "") -> bool:
    """Whether liquid said to stay in a bowl (`said`: "stays in the jug")
    stays in the source: one named so, one people pour from, or one said in
    `text` to be held as a source is ("stay in the cup even when it's upside
    down", "does it stay in the mug if the mug is tipped", "stay in the cup when
    I only tilt it a little")."""
    bowl = said.split()[-1]
    if bowl == "source" or bowl in poured_from():
        return True
    if not text or not re.fullmatch(r"[a-z]+", bowl):
        return False
    turned = r"(?:upside down|inverted|turned (?:over|upside down))"
    return bool(_held_as_source(bowl, text) or re.search(
        rf"\b{re.escape(said)}\b(?: \w+)? (?:when|while|if|once) (?:it (?:is |gets |goes |being )?(?:held |turned )?{turned}"
        rf"|(?:i|you|we) (?:only |just |do not |did not )?(?:tilt|tip|turn|angle)\w* it\b)", text))     # ("... when I only tilt it a little")


def _held_as_source(noun: str, text: str) -> bool:
    """Whether `text` pours from the bowl `noun`, holds it tilted, or notes it first with what it holds ("mug of
    cocoa, tilted 90 degrees, ...")."""
    return bool(re.search(rf"\bfrom (?:the |a |an |my |your |this |that )?(?:[a-z]+ )?{noun}\b"
                          + (rf"|^(?:a |an |the |my )?{noun} of [a-z]+(?: [a-z]+)?(?=,| -)" if noun not in ("bowl", "dish", "basin") else "")
                          + rf"|\b{noun} (?:is |being |that is |held )?(?:tilted|tipped|angled|inclined"
                          rf"|upside|turned|held)\b", text))


def out_of_the_source(text: str, at: int) -> bool:
    """Whether the bowl that liquid is thrown out of, named in `text` from
    `at` on, is the one poured from ("does coffee splash out of a mug
    tilted halfway", "pour from the mug: does it splash out of the mug"):
    a spill, not liquid leaving the destination; so is liquid thrown out before
    it reaches the bowl ("does it slosh out before it even reaches the bowl")."""
    if re.match(r"(?: \w+)?(?: \w+)? before (?:it |the \w+ )?(?:even )?(?:reach|reaches|reaching|gets to|getting to)\b", text[at:]):
        return True
    said = re.match(rf" (?:the |a |an |my |your |its |their |this |that )?(?:[a-z]+ )?"
                    rf"(?P<noun>{destinations()})\b", text[at:])
    if said is None:
        return False
    return _held_as_source(re.escape(said.group("noun")), text)


liquids = lru_cache(maxsize=None)(lambda: Matcher(("liquid", *names("liquid"))))   # "water", "stream"
