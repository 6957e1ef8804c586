"""Liquid running down the outside of the source once the pour is over
("will olive oil drip down the side of the bottle after I stop pouring?",
"so nothing drips down the side of the pot afterwards") is no outcome the
vocabulary says: a spill is judged of the liquid that leaves the source,
and what clings to the source after the pour never leaves it. Such a
question is refused, naming what would be read: the same asked of the
pour itself ("does it drip down the side of the bottle?": a spill)."""
from __future__ import annotations

import re

from pantarhei.bridge.errors import UserError

#: Running down the source's outside (not the bowl's): "dribble down its own side", "drip down the jar",
#: "dripped off the bottle".
_DOWN = re.compile(r"\b(?:drip|dribbl|run|ran|trickl|roll|leak)\w* (?:back )?(?:down|off) (?:the |its |its own |their )?"
                   r"(?:outside|side|sides|jar|jug|bottle|cup|pot|pitcher|carton|can|kettle|spout|neck)\b"
                   r"(?! of (?:the |a |an |my )?(?:[a-z]+ )?(?:bowl|dish|destination)s?\b)")
#: Once the pour is over: "after I stop pouring", "after I pour it", "afterwards", "at the end of the pour",
#: the source tipped back.
_AFTER = re.compile(r"\b(?:after (?:(?:i|you|we|it|they|the \w+) (?:am |have |has |is |are )?(?:stop|stops|stopped|finish|finishes"
                    r"|finished|done)(?: (?:pour\w*|tipping|tilting))?|(?:i |you |we )?pour(?:ing|ed|s)?(?: it)?\b|the pour(?:ing)?"
                    r" (?:is over|ends|has ended)|the pour\b(?! (?:starts|begins)))|afterwards?|once (?:i |you |we )?(?:am |have )?"
                    r"(?:stop\w*|finish\w*|done)|at the end of the pour"
                    # "when you stop pouring", "when I tip it back upright", "... the bottle after?"
                    r"|when (?:i |you |we |it |they )?(?:am |are |is )?(?:stop|stops|stopped|finish\w*|done)\b"
                    r"|(?:tip|tips|tipped|tilt|tilts|tilted|turn|turns|bring|brings|set|sets|put|puts) (?:it |them |the \w+ )?back"
                    r"(?: up| upright| down)?\b|\bafter(?= *(?:[?.!,;]|$)))")


def refuse_drips_after(text: str) -> None:
    """UserError where `text` (normalised) asks of liquid running down the source once the pour is over."""
    down = _DOWN.search(text)
    if down and _AFTER.search(text):
        raise UserError(f"\"{down.group(0)}\" once the pour is over: what clings to the source after the pour "
                        f"is no outcome the vocabulary says; ask it of the pour (\"does it drip down the side "
                        f"of the bottle?\": a spill)")
