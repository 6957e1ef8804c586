"""An outcome supposed never to happen, in a condition ("if the jug never
touches the bowl, can the bowl still tip over?"): said as "does not", the
way the outcomes are read when supposed not to happen ("if the jug doesn't
touch the bowl, ..."): both are asked. Said as a statement with a tag that
asks it ("the jug never touches the bowl if i pour from the side, right?"),
it is asked: "does the jug not touch the bowl". So is a touch supposed not to happen said of the person
("if i never touch the bowl with the bottle") or of the bowl ("if the bowl isn't touched by the bottle"). A condition so said and not ended
with a comma before the question is ended with one ("if the pitcher never touches the bowl can the bowl
still tip over")."""
from __future__ import annotations

import re
from functools import lru_cache

from pantarhei.bridge.reasoning.everyday import alternation
from pantarhei.bridge.reasoning.rim_strikers import source_names

#: The outcome verbs said with "never" in a condition, each in its plain form.
_VERBS = ("touch", "hit", "bump", "knock", "spill", "splash", "drip", "tip", "slide", "move", "wobble", "collide",
          "overflow", "rock", "shift", "slip", "budge")
_NEVER = re.compile(rf"\b(if|when|as long as|so long as) ((?:the|a|my|your|it)\b(?: [a-z]+){{0,2}}?(?: (?:is|are) [a-z]+(?: still)? and)?) never "
                    rf"({'|'.join(_VERBS)})(?:es|s)?\b")


#: ... or stated first, with a tag after it that asks whether it holds.
_TAGGED = re.compile(rf"^((?:the|a|my|your) [a-z]+) never ({'|'.join(_VERBS)})(?:es|s)?\b(?=.*,? (?:right|yes|correct|yeah|no|eh)\?+$)")


#: A condition that an outcome does not happen, ended with no comma before what is asked ("if the pitcher
#: doesn't touch the bowl can the bowl still tip over"): the comma put back.
_UNENDED = re.compile(r"\b((?:if|when) (?:the|a|my|your|it)\b(?: [a-z]+){0,2}? (?:does|do|did) not [a-z]+ (?:(?:the|a|my|your|its) )?"
                      r"[a-z]+)(?= (?:can|could|will|would|does|do|is|are|might|should) )")


#: The touch supposed not to happen said of the person ("if i never touch the bowl with the bottle") or of the
#: bowl ("if the bowl is not touched by the bottle at all"): of the source, as the condition above says it.
_BY_ME = re.compile(r"\b(if|when) (?:i|we|you) (never|do not) (touch|hit|bump|knock)(?: into)? ((?:the|my|a) [a-z]+) with ((?:the|my|a) [a-z]+)")
_BY_IT = re.compile(r"\b(if|when) ((?:the|my|a) [a-z]+) (?:is|gets) (not|never) (touch|hitt|bump|knock)(?:ed) by ((?:the|my|a) [a-z]+)")


@lru_cache(maxsize=None)
def _not_touching() -> re.Pattern:
    """A touch said not to happen with no verb that says it ("with the cup not touching the bowl",
    "jug not touching bowl"), or with no one said at a clause's start ("not touching the bowl, ...");
    not before "is that possible" (a goal so said: goal_wordings.py's)."""
    return re.compile(rf"(?:\b(?:(with) )?((?:(?:the|a|my|your) )?(?:{alternation(source_names())}|source)) not touching\b"
                      r"|(?:^|(?<=[,;.] ))not touching(?= (?:the |a |my )?bowl\b))(?!.*\bpossible\b)")


def _is_not_touching(m: re.Match) -> str:
    """_not_touching()'s touch said with its verb: "and the cup is not touching", "the source is not touching"."""
    return f"{'and ' if m.group(1) else ''}{m.group(2) or 'the source'} is not touching"


def _by_me(m: re.Match) -> str:
    """_BY_ME's touch said of the source: "if the bottle does not touch the bowl"."""
    return f"{m.group(1)} {m.group(5)} does not {m.group(3)} {m.group(4)}"


def _by_it(m: re.Match) -> str:
    """_BY_IT's touch said of the source: "if the bottle does not touch the bowl"."""
    return f"{m.group(1)} {m.group(5)} does not {m.group(4).removesuffix('t')} {m.group(2)}"


def never_as_not(text: str) -> tuple[str, tuple[str, ...]]:
    """Normalised `text` with an outcome supposed never to happen said as "does not", and what is said back."""
    text = _not_touching().sub(_is_not_touching, text) if "not touching" in text else text
    said = tuple(f"{m.group(0)}: read as {_by_me(m)}" for m in _BY_ME.finditer(text))
    said += tuple(f"{m.group(0)}: read as {_by_it(m)}" for m in _BY_IT.finditer(text))
    text = _BY_IT.sub(_by_it, _BY_ME.sub(_by_me, text))
    said += tuple(f"never {m.group(0).split(' never ', 1)[1]}: read as does not {m.group(3)}" for m in _NEVER.finditer(text))
    if tagged := _TAGGED.match(text):          # "the jug never touches the bowl ..., right?"
        said += (f"{tagged.group(0)}: read as does {tagged.group(1)} not {tagged.group(2)}",)
        text = f"does {tagged.group(1)} not {tagged.group(2)}{text[tagged.end():]}"
    return _UNENDED.sub(r"\1,", _NEVER.sub(r"\1 \2 does not \3", text)), said
