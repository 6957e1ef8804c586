"""How near the bowl the source is said to be, part of words.py's PHRASES:
close to the bowl, or near it, is just above its rim (low; "near the rim"
would say over its edge); too close, or too near, with no bowl said ("does
the cup hit the bowl if it's too close") is close to it; right next to the
bowl, or beside it, is refused (beside it, or near its rim?); the near
side of the bowl is near its rim, and the far side is refused (the
vocabulary's places lie on the side the source comes from). A little to
one side ("off to one side a bit", "slightly to the side") is near the
rim, as "a bit off the centre" is (words.py)."""
from __future__ import annotations

from pantarhei.bridge.reasoning.everyday import UNCLEAR

#: A little to one side, the degree said first: "a little to the side" (not "... to the side of the bowl").
A_BIT_SIDE = (r"re(side):\b(?:just |only )?(?:slightly|a (?:little |tiny )?bit|a little|a tad) (?:off )?to (?:one|the) side"
              r"\b(?! of\b)")

NEARNESS: tuple[tuple, ...] = (
    # right next to the bowl: beside it, or near its rim?
    (UNCLEAR, (r"re:\b(?:right )?(?:next to|beside|alongside) (?:the )?(?:destination|bowl)\b(?! rim)",)),
    # held close to the bowl: just above it (its edge is "near the rim")
    ("low", (r"re(close to|near the bowl|near bowl|near to):\b(?:very |right )?(?:close to (?:the )?(?:destination|bowl)"
             r"|near (?:to )?(?:the )?bowl)\b(?! (?:rim|edge|lip|brim))",),
     "read as low: just above the bowl's rim (\"near the rim\" would say over its edge)"),
    # the near side of the bowl: the rim on the side the source comes from; the far side lies
    # where the vocabulary's places do not reach
    ("near the rim", (r"re(near side|near edge|near rim|near lip):\b(?:the |its )?near (?:side|edge|rim|lip)(?: of (?:the |its )?"
                      r"(?:destination|bowl))?\b",)),
    # poured into (or on) one side of the bowl ("into the side of it"), or from right above its edge: over its edge
    ("near the rim", (r"re(one side|the side|one edge|right above|directly above|right over|onto):\b(?:in|into|onto) (?:just |only )?(?:one|the) (?:side|edge) of (?:it|the (?:destination|bowl))\b"
                      # (landing on one side, the bowl's: "pour heavy stuff on one side", "into one side only",
                      # not "off to one side")
                      r"|(?<!off )\b(?:on|onto|into) (?:just |only )?one side\b(?! of\b)"
                      r"|(?<!off )\bon (?:just |only )?one (?:side|edge) of (?:it|the (?:destination|bowl))\b"
                      # (poured on the side of it, as "on one side": "if I pour on the side of the bowl and not the middle")
                      r"|(?:(?<=\bpour )|(?<=\bpours )|(?<=\bpoured )|(?<=\bpouring )|(?<=\bpour it )|(?<=\bpouring it ))"
                      r"on (?:just |only )?the side of (?:it|the (?:destination|bowl))\b"
                      r"|\bonto (?:its|the (?:destination|bowl)s?) (?:edge|rim|lip)\b"
                      r"|\b(?:right|directly) (?:above|over) (?:the |its )?(?:destination |bowl )?(?:edge|rim|lip)"
                      r"(?: of (?:it|the (?:destination|bowl)))?\b(?! of\b)",)),
    # close to the bowl's edge, the bowl named before it with no article ("too close to bowl edge"), or off,
    # or more, to its edge ("hold it off to the edge", "more to the edge"): near the rim
    ("near the rim", (r"re(close to):\b(?:close|near) to (?:the |its )?(?:destination|bowl)'?s? (?:edge|rim|lip|brim)\b",
                      r"re(to the edge|to the rim):\b(?:off|more|further|over|out) to (?:the |its )?(?:destination |bowl )?(?:edge|rim|lip)\b(?! of\b)")),
    # its very edge, and the bowl's edge named in a note ("jug bowl edge splash?", "jug, edge of bowl,
    # spill?"), not touched
    ("near the rim", (r"re(very edge|very rim|very lip):\b(?:at|on|onto|to|over|near) (?:the |its )?very (?:edge|rim|lip)"
                      r"(?: of (?:it|the (?:destination|bowl)))?\b",
                      r"re(destination edge|bowl edge):(?<!touch )(?<!touches )(?<!touching )(?<!hit )(?<!hits )(?<!hitting )(?<!bump )"
                      r"(?<!bumps )(?<!bumping )(?<!the )\b(?:destination|bowl) edge\b(?! of\b)",
                      # or as a note's item of its own: "jug, edge of bowl, milk, spill?"
                      r"re(edge of|rim of):(?:^|(?<=[,;:.] ))(?:the )?(?:edge|rim) of (?:the )?(?:destination|bowl)(?= *[,;:.?!]| *$)",)),
    (UNCLEAR, (r"re(far side|far edge|far rim|far lip|opposite):\b(?:the |its )?(?:far|opposite) (?:side|edge|rim|lip)"
               r"(?: of (?:the |its )?(?:destination|bowl))?\b",)),
    # poured from close, with no bowl said: just above it ("pour from close up")
    ("low", (r"re(close):\bfrom (?:really |very |quite |super )?(?:close(?: up| by)?|up close)\b(?! (?:to|by|from)\b)",),
     "read as low: close to the bowl, just above its rim"),
    # poured (held, kept) close, with no bowl said: just above it ("if I pour close", "if i hold it really close")
    ("low", (r"re(close|near):\b(?:pour(?:s|ed|ing)?|bring(?:s|ing)?|brought|hold(?:s|ing)?|held|keep(?:s|ing)?|kept)"
             r"(?: it| them| the \w+)?(?: (?:really|very|quite|so|too|super))?"
             r" (?:close|near)\b(?! (?:to|by|from|together|up|the|a|an|its|my|your|this|that)\b)",),
     "read as low: close to the bowl, just above its rim"),
    # too close, with no bowl said: to the bowl, just above it
    ("low", (r"re(too close|too near|so close|so near):\b(?:too|so) (?:close|near)\b(?! (?:to|by|from|the|its|a|together)\b)",),
     "read as low: close to the bowl, just above its rim"),
    # brought in close, or held low and close: just above it ("if I come in close", "hold it low and close")
    ("low", (r"re(in close|and close|approach close):\b(?:(?:come|comes|coming|came|go|goes|going|went|get|gets|getting|got) in|approach"
             r"|(?<=\blow )and) (?:really |very |quite |so |too )?close\b(?! (?:to|by|from|together|up)\b)",),
     "read as low: close to the bowl, just above its rim"),
)
