"""A value said against another, part of words.py's PHRASES (applied
before its comparatives, which refuse a comparison with nothing): a liquid
thicker than water is sticky, one thinner than honey runny ("instead of
water use something thicker"; the everyday word list has read water as
"liquid" and honey as "sticky liquid" by then); a place the vocabulary
cannot name, set against one it reads ("from the side rather than from
above"), is read as nothing, the place said beside it read, and so is an
ordinary liquid set against a liquid said ("a thick liquid instead of
water"), or a container with nothing said of it against one said ("a
slippery cup instead of a ceramic mug"); the rim set against the middle
("right above the rim rather than over the center") is near the rim; a little off
the centre is near the rim (off-centre with no amount stays refused: how
far?); "right in the middle" is in the middle; a length "relative to the
rim" is above it (a minus sign below it), "-2 cm height relative to the rim" too; "lower, close to the rim" is
low, as is "bring the bottle down near the rim", and "but not touching" says how close.
"""
from __future__ import annotations

from pantarhei.bridge.reasoning.units import UNITS

#: Something poured, unnamed: "something thicker", "a liquid that is runnier".
_THING = r"(?:(?:something|some ?thing|stuff|one|a liquid|liquid)(?: that is| that's)? )?"
_MORE = r"(?:(?:a bit|a little|much|a lot|even|far|way) )?"
#: The comparatives, which every match of a comparison holds (cued.py's cues too).
_THICK_CUES = "thicker|stickier|gloopier|more viscous|more sticky"
_THIN_CUES = "thinner|runnier|more watery|more runny|less viscous|less sticky"
_THICKER = f"(?:{_THICK_CUES})"
_THINNER = f"(?:{_THIN_CUES})"
_CONTRAST = r"(?:instead of|rather than|in place of)"
_USE = r"(?:(?:,|;) )?(?:(?:use|pour|try|take|pick|with|using|have) )?"
#: A place the vocabulary cannot name, set against one it reads.
_VAGUE = r"(?:from )?(?:above|overhead|the top|on top)"
#: After a length: "-2 cm relative to the rim".
_AFTER_LENGTH = "|".join(rf"(?<=\d {u} )" for u, (measures, _) in UNITS.items() if measures == "length")
_NOT_AFTER_LENGTH = "".join(rf"(?<!\d {u} )" for u, (measures, _) in UNITS.items() if measures == "length")

CONTRASTS: tuple[tuple, ...] = (
    ("sticky liquid", (rf"re({_THICK_CUES}):\b{_CONTRAST} (?:the |using |pouring )?liquid {_USE}{_THING}{_MORE}{_THICKER}\b",
                       rf"re({_THICK_CUES}):\b{_THING}{_MORE}{_THICKER} (?:than|{_CONTRAST}) (?:the |plain |regular |normal )?liquid\b"),
     "read as a sticky liquid: thicker than an ordinary one"),
    ("runny liquid", (rf"re({_THIN_CUES}):\b{_CONTRAST} (?:the |using |pouring )?sticky liquid {_USE}{_THING}{_MORE}{_THINNER}\b",
                      rf"re({_THIN_CUES}):\b{_THING}{_MORE}{_THINNER} (?:than|{_CONTRAST}) (?:the )?sticky liquid\b"),
     "read as a runny liquid: thinner than a sticky one"),
    ("hedge", (rf"re(instead|rather|in place):(?:(?:,|;) )?\b{_CONTRAST} {_VAGUE}\b(?= *(?:$|[,;.!?]))",),
     "read as nothing: a place the vocabulary cannot name, set against the one said beside it"),
    # an ordinary liquid set against the liquid said ("a thick liquid instead of water"): nothing more
    ("hedge", (rf"re(instead|rather|in place):(?<=liquid ){_CONTRAST} (?:the |plain |regular |normal |ordinary )?liquid\b",
               r"re(not):(?<=liquid ), not (?:the |plain |regular |normal |ordinary )?liquid\b(?= ,)"),
     "read as nothing: an ordinary liquid, set against the one said beside it"),
    # a container with nothing said of it set against one said ("a slippery cup instead of a
    # ceramic mug"; the word list has read both as bowls by then): nothing more
    ("hedge", (rf"re(instead|rather|in place):(?<=bowl ){_CONTRAST} (?:a |an |the |my |your )?(?:material )*(?:bowl|one)\b",),
     "read as nothing: a container with nothing said of it, set against the one said beside it"),
    # a value set against its opposite ("heavy ceramic instead of light plastic"; the word list has read the
    # materials by then): nothing more
    ("hedge", tuple(rf"re(instead|rather|in place):(?:(?<={said} )|(?<={said} material )|(?<={said} bowl )|(?<={said} material bowl )){_CONTRAST} (?:a |an )?{other}\b(?: material)?"
                    for said, other in (("heavy", "light"), ("light", "heavy"), ("slippery", "grippy"), ("grippy", "slippery"))),
     "read as nothing: the value said, set against its opposite"),
    # the rim set against the middle is where it is poured, not a height ("right above the rim rather
    # than over the center", "off the edge of the bowl, not the middle")
    ("near the rim", (r"re(rather than|instead of|not):\b(?:right |just |directly )?(?:above|off|over) (?:the |its )?(?:bowl )?"
                      r"(?:rim|edge|lip|brim)(?: of (?:the |a )?bowl)?(?= (?:, )?(?:not|rather than|instead of) (?:over |above |in |at )?"
                      r"(?:the )?(?:very )?(?:centre|center|middle)\b)",),
     "read as near the rim: set against the middle, the rim is where it is poured"),
    ("near the rim", (r"re(off the |off cent|off midd|off dest|off bowl):\b(?:just |only )?(?:slightly|a (?:little |tiny )?bit|a little|a tad) off (?:the )?"
                         r"(?:destination |bowl )?(?:centre|center|middle)\b",),
     "read as near the rim: a little off the middle, where the rim is nearer"),
    # off the middle, how far not said (said of the pour, the source or alone; not "way off", "3 cm off", "how far
    # off"): near the rim, the nearest place off it
    ("near the rim", (r"re(off the |off cent|off midd|off dest|off bowl):(?:(?<=[a-z,;:.!?] )(?<!\bway )(?<!\bfar )(?<!\bmuch )(?<!\bvery )(?<!\bhow )"
                      rf"(?<!\bmore )(?<!\bless )(?<!\bbit )(?<!\blittle )(?<!\btad )(?<!\bslightly ){_NOT_AFTER_LENGTH}|^(?=off \w+ (?:pour|,)))off (?:the )?"
                      r"(?:destination |bowl )?(?:centre|center|middle)\b(?! by\b)(?!(?: ,)? (?:to|towards?) (?:the|its) (?:left|right)\b)(?:(?: ,)? (?:near|close to|toward|towards|at|by)"
                      r" (?:the |its )?(?:destination |bowl )?(?:edge|rim|lip)\b"
                      r"(?! of(?! (?:the |a |an |my |its )?(?:[a-z]+ ){0,3}?(?:bowl|destination|dish)\b)))?",),
     "read as near the rim: off the middle, how far not said, the nearest place off it (say \"from the side\" or \"offset sideways\" for others)"),
    # not poured from the middle: "I pour not from center" (its negation read, as "not centred")
    ("centred", (r"re(not from):(?<=\bnot )from (?:the )?(?:very )?(?:destination |bowl |cup )?(?:centre|center|middle)\b"
                 r"(?! (?:by|of the \w+ by) )",)),
    # the bowl centred under the source: centred ("the bowl is centered under it")
    ("centred", (r"re(under):\b(?:centred|centered) under (?:it|them|the \w+)\b",
                 # ... or said to stand right under it ("if the bowl isn't right under the spout": its negation read)
                 r"re(under):(?:(?<=bowl )|(?<=bowl is )|(?<=bowl is not )|(?<=bowl was )|(?<=bowl was not )|(?<=bowl sits )"
                 r"|(?<=bowl sitting ))(?:right |directly |straight |dead |exactly )?(?:under|underneath|beneath)"
                 r" (?:it|them|the (?:bowl|spout|stream|source|pour|part))\b")),
    # a height measured from the rim: above it (a minus sign below it)
    ("above the rim", (rf"re(relative|respect|vs|versus):(?:{_AFTER_LENGTH})(?:height )?(?:relative to|with respect to|vs|versus)"
                       r" (?:the )?(?:destination |bowl )?(?:rim|edge|lip|brim)\b(?! (?:of the )?(?:source|cup))",)),
    # lower, with the rim it comes down to said: low ("hold it lower, close to the rim")
    ("low", (r"re(lower , |lower and |lower close|lower near|lower right|lower just|lower down):\b(?:a bit |a little |slightly )?lower(?: ,| and)? (?:close to|near|right above|just above|down to)"
             r" (?:the |its )?(?:destination |bowl )?(?:rim|edge|lip|brim)\b",),
     "read as low: lower, to just above the rim"),
    # brought down near the rim: held just above it ("bring the bottle down near the rim")
    ("low", (r"re(down):\b(?:bring|brings|bringing|brought|lower|lowers|lowering|lowered|move|moves|moving|moved)"
             r"(?: it| them| the \w+)? down (?:to )?(?:close to|near|right above|just above|to) (?:the |its )?(?:destination |bowl )?"
             r"(?:rim|edge|lip|brim)\b",),
     "read as low: brought down to just above the rim"),
    # from the side, not from above: the side said, set against being over the bowl
    ("hedge", (r"re(not):(?:(?<=side )|(?<=side of the bowl )|(?<=side of the destination )|(?<=side of bowl ))(?:, )?"
               r"not (?:from |on )?(?:the )?(?:top|above|overhead|over it|over the (?:bowl|destination))\b",),
     "read as nothing: set against the side said, over the bowl is where it is not"),
    # close but not touching: how close, not a goal
    ("hedge", (r"re(touch):(?:" + "|".join(rf"(?<={w} )" for w in ("low", "rim", "edge", "lip", "bowl", "close", "near"))
               + r")(?:, )?but not touch(?:ing)?(?: it| the \w+)?\b",),
     "read as nothing: close, not touching, says how close"),
    ("hedge", (r"re(straight|right in|dead|smack|bang):\b(?:straight|right(?= in)|dead|smack|bang)(?= (?:in )?(?:the )?(?:middle|centre|center)\b)",)),
)
