"""Everyday words for the vocabulary's words, read by reading.py.

The vocabulary (theory/vocabulary/propositions.pl) says each proposition
once, in its own words; people say the same things in others ("a full
cup", "move in fast", "right it up after pouring"). `PHRASES` rewrites
such phrases into the vocabulary's words before a question (or a gloss) is
read: each entry is (the vocabulary's words, the phrases that mean them),
and what `ask` says back of them where it reads them as nothing.
A phrase is written in plain words and matches their inflections ("move
in" matches "moving in"); "[the source|it]" is an optional part, and a
pattern starting with "re:" is a regular expression. Entries apply in
order, so a longer phrase comes before a word it holds.

The names of things (liquids, containers, materials, what is around a
pour), hedges, degree phrases and the words the vocabulary cannot say
are data: the everyday word list, everyday.txt, read by everyday.py and
applied before PHRASES; each of its phrases carries
what `ask` says back of it ("milk: read as an ordinary liquid ...").

The phrases of the stages and the moves between them ("put it back
upright", "pull it out fast") are moves.py's, a comparison with an
earlier pour comparisons.py's, a speed said in other words speeds.py's,
how near the bowl the source is nearness.py's, where it is from the middle
off_centre.py's, each applied at its place in PHRASES.
"""
from __future__ import annotations

from functools import lru_cache

from pantarhei.bridge.reasoning.everyday import UNCLEAR, Matcher, names, sections
from pantarhei.bridge.reasoning.fullness import SAID as FULLNESS_SAID, Filled, Fullness
from pantarhei.bridge.reasoning.bodies import BODIES
from pantarhei.bridge.reasoning.comparisons import COMPARATIVES as _COMPARATIVES, COMPARISONS, DEGREE as _DEGREE
from pantarhei.bridge.reasoning.contrasts import CONTRASTS
from pantarhei.bridge.reasoning.cued import Cued
from pantarhei.bridge.reasoning.moved_to import MOVED_TO
from pantarhei.bridge.reasoning.moves import MOVES
from pantarhei.bridge.reasoning.nearness import A_BIT_SIDE as _A_BIT_SIDE, NEARNESS
from pantarhei.bridge.reasoning.numerals import NumberWords
from pantarhei.bridge.reasoning.off_centre import LENGTHS as _LENGTHS, OFF_CENTRE
from pantarhei.bridge.reasoning.properties import SURFACE_SAID, Levels, Surfaces, Values
from pantarhei.bridge.reasoning.ramps import Ramps
from pantarhei.bridge.reasoning.speeds import SPEEDS
from pantarhei.bridge.reasoning.tilt_amounts import FAR_TILTS, NEAR_HORIZONTAL, TILT_AMOUNTS
from pantarhei.bridge.reasoning.tipping_speed import SAID as TIPPED, TippingSpeed
from pantarhei.bridge.reasoning.poured_off import POURED_OFF_SAID, PouredOff

#: Value words an intensifier may raise to "very" ("incredibly high" is very high; a value
#: with no "very" of its own is the value: "incredibly heavy" is heavy). "really" is a
#: hedge as often as a degree ("is it really high?"): it raises nothing.
_INTENSIFIED = ("high|low|fast|quick|quickly|slow|slowly|heavy|light|sticky|runny|thick|thin|"
                "bouncy|slippery|grippy|steep|steeply|far|close|near|tilted")
#: A reference point a comparison may be made to: the destination's rim.
_RIM = (r"(?:the )?(?:destination |bowl )?(?:rim|edge|lip|brim|top)\b(?: of (?:the |a )?"
        r"(?:destination|bowl)\b)?")

PHRASES: tuple[tuple, ...] = (
    NEAR_HORIZONTAL,          # "a little less than horizontal": steeply tilted (tilt_amounts.py)
    ("hedge", ("how much", "how many",    # asks, does not say: "how much liquid spills"
               "nearly",                   # a hedge (its stem would be "near")
               r"re:\bbetween(?= -?\d+(?:\.\d+)? and -?\d)")),   # a range: quantities.py's
    # "rather" as a degree ("the bowl is rather slippery"), not a contrast ("rather than")
    ("hedge", (r"re(rather):\brather(?= (?:very )?(?:slippery|heavy|light|sticky|runny|thick|thin|bouncy|grippy|high|low|fast"
               r"|slow|slowly|quick|quickly|far|steep|steeply|full|smooth)\b)",)),
    # not tilted enough: slightly ("the cup is not turning enough", "if i do not tilt it enough")
    ("slightly tilted", (r"re(enough):\b(?:not|never) (?:tilt|tip|turn)\w*(?: (?:it|the \w+))? (?:far |much )?enough\b",)),
    # "is a 100 degree tilt enough?": whether it happens, asked
    ("hedge", (r"re(enough):\benough(?= *[?.!]* *$)",)),
    # "anything but upside down": not it; "not water but something thick": the one said
    ("not", ("anything but",)),
    ("hedge", (r"re(but):\bnot (?:liquid|the liquid) but\b",)),
    # when the liquid lands: while pouring ("does it slide when the water hits it")
    ("hedge", (r"re(when|after|once):\b(?:when|after|once) (?:the )?(?:liquid|it) (?:hits|lands in|reaches|goes into|enters|is in) (?:it|the bowl)\b"
               r"|\b(?:when|after|once) (?:the )?(?:liquid|it) (?:is )?(?:in|lands|has landed|goes in)(?= *(?:[?.!,]|$))",)),
    # a slippery liquid: its particles slide, a runny one ("a slippery oil")
    ("runny", (r"re(slippery|slick):\b(?:slippery|slick)(?= liquid\b)",)),
    # the liquid poured "inside": into the bowl ("I pour much water inside")
    ("hedge", (r"re(inside):(?<=\bliquid )inside(?= *(?:[,;.!?]|$|and\b|but\b|then\b))",)),
    # raised, lowered or brought to a number, or below the rim, no move before or after pouring
    # said: where it is held while pouring ("lowered to 5 mm above the lip", "go down to 8 cm", "brought down to 2 cm
    # above the rim while pouring", "the cup lowered below the rim")
    ("at a height of", (r"re(lower|rais|lift|brought|bring|down):\b(?:lower(?:ed|ing|s)?|rais(?:e|ed|es|ing)|lift(?:ed|ing|s)?"
                        r"|(?:brought|bring|brings|bringing) (?:down|up)|(?:go|goes|going|went|come|comes|coming|came|move[sd]?|moving) down)(?: (?:it|them|the \w+))?"
                        r"(?: (?:up|down))? to(?= (?:just |about |around |roughly |only )?-?\d)(?![^;.?!]*\b(?:before|after|then)\b)",),
     "read as held there while pouring"),
    *MOVED_TO,                # lowered to just over the rim, poured straight down (moved_to.py)
    ("hedge", (r"re(lower|dip):\b(?:lower(?:ed|ing|s)?|dipp?(?:ed|ing|s)?)(?: (?:it|them|the \w+))?(?: down)?"
               r"(?= (?:just |right |slightly |a bit |well )?(?:below|under|beneath)\b)(?![^;.?!]*\b(?:before|after|then)\b)",)),
    *CONTRASTS,               # a value said against another: thicker than water (contrasts.py)
    ("very", (rf"re:\b(?:super duper|super|extremely|incredibly|insanely|ridiculously|awfully|terribly"
              rf"|exceptionally|unusually|crazy|way)(?= (?:{_INTENSIFIED})\b)",)),
    # a low bowl, a high-sided one: its size, which the vocabulary does not say (a height is
    # where the source is)
    (UNCLEAR, (r"re:\b(?:high|low|tall|short)(?: |-)?(?:sided|walled|rimmed|edged)\b",
               r"re:(?:(?<=\ba )|(?<=\bthe ))(?:very )?(?:low|high)(?= bowl\b)")),
    # way above the bowl (or with nothing after it: "held way above, does any bounce out"): high, or very high?
    (UNCLEAR, (r"re:(?<!\ball the )\b(?:way|far|well) (?:up )?(?:above|over)(?= (?:the |a |it\b|hedge ))|\b(?:way|far|well) above(?= *(?:[,;:.?!]|$))",)),
    # said by the hand or the fingers alone, before where: "a hand above the bowl", "two
    # fingers above the rim"
    ("7 to 10 cm", (r"re:\b(?:a|one) (?:hand|palm)(?= (?:above|over|below|under|away|from|to the side"
                    r"|off|higher|lower)\b)",)),
    ("1.5 to 2 cm", (r"re:\b(?:a|one) finger(?= (?:above|over|below|under|away|from|to the side|off"
                     r"|higher|lower)\b)",)),
    ("3 to 4 cm", (r"re:\btwo fingers?(?: width| breadth)?s?\b",)),
    ("4.5 to 6 cm", (r"re:\bthree fingers?(?: width| breadth)?s?\b",)),
    # a length said "up" is a height above the destination ("hold it 20 cm up"), and so is
    # one said "over" it ("from 25 cm over the centre"; not "10 cm over to the side")
    ("above", ("re:(?:" + "|".join(rf"(?<=\d {u} )" for u in _LENGTHS) + r")\bup\b",
               "re:(?:" + "|".join(rf"(?<=\d {u} )" for u in _LENGTHS) + r")\bover\b(?! (?:to|there"
               r"|here|by|from|towards?|sideways)\b)")),
    # a comparison with the rim is where it puts the source: "higher than the rim" is above it
    # (as "above the bowl": the ordinary pour), "slightly higher than the rim" just above it
    # (low), "lower than the rim" below it; with a number, the number's ("2 cm higher than
    # the rim")
    ("low", (rf"re:\b{_DEGREE} (?:higher|above) than {_RIM}",)),
    ("above", (rf"re:\b(?:higher|above) than {_RIM}",)),
    ("below the rim", (rf"re:\b(?:{_DEGREE} )?(?:lower|below) than {_RIM}",)),
    *COMPARISONS,             # with an earlier pour, "more high" (comparisons.py)
    # neither too high nor too low: at medium height
    ("at medium height", (r"re(too):\b(?:not too (?:high|low)(?:,| and| or| but)? (?:not )?too (?:low|high)"
                          r"|neither too (?:high|low) nor too (?:low|high))\b",),
     "read as at medium height: neither high nor low"),
    # a comparison with nothing it is measured from: higher than what?
    (UNCLEAR, (rf"re:\b(?:{_DEGREE} |much |even |far |a lot |any |no )?(?:more |less )?"
               rf"(?:{_COMPARATIVES})\b(?: than (?:before|usual|normal|that|it|the \w+))?",
               rf"re:\b(?:{_DEGREE}|much|even|far|a lot|any|no) lower\b",
               r"re:\b(?:pour(?:s|ed|ing)?|hold(?:s|ing)?|held)(?: it| the \w+)? lower\b",
               r"re:\b(?:lower|closer|nearer|further|farther) than\b(?: (?:before|usual|normal|that"
               r"|it|the \w+))?",
               r"re:\b(?:more|less|fewer) than\b(?: (?:before|usual|normal|that|halfway"
               r"|half way|half))?",
               r"re:\b(?:at (?:least|most)|past|beyond|up to|no (?:more|less) than)(?= -?\d)")),
    *SPEEDS,                  # how fast the source moves in and away, said in other words (speeds.py)
    # just past the rim: to the side of the bowl (not a length past it: "5 cm past the rim")
    ("to the side", (r"re(past|beyond):(?<!cm )(?<!mm )\b(?:just |slightly |a bit |a little )?(?:past|beyond) the (?:bowl'?s? )?"
                     r"(?:edge|rim|lip)\b(?: of (?:it|the bowl|the destination)\b)?(?! (?:of|by|at) )",)),
    *FAR_TILTS,               # "not tilted very far", "tip it really far", "tilted too far" (tilt_amounts.py)
    # tilted a lot: steeply (the most before upside down, which "all the way" says)
    ("steeply tilted", (r"re:\b(?:tilt|tip|angl|inclin|lean)\w*(?: (?:it|them|the \w+))? (?:(?:quite |really |very )?a lot"
                        r"|lots|loads|heaps)\b",)),
    # tilting has no speed of its own in the vocabulary beside that move's: not a rate, nor a change
    (UNCLEAR, (r"re:\b(?:tilt|tip|rotat|turn)\w*(?: (?:it|the \w+))?(?: (?:very|really|too|quite))?"
               r" (?:slow(?:ly|er)?|fast(?:er)?|quick(?:ly|er)?|rapidly|gradually|steadily)\b",
               r"re:\b(?:tilt|tip|tilting|tipping|rotation|pour|pouring) (?:rate|speed|velocity)\b")),
    # asks for a value, which is a plan's to find, not a scene's to say: "how high should I pour?"
    (UNCLEAR, (r"re:\bhow (?:very |really )?(?:high|low|far|fast|quick|quickly|slow|slowly|steep|"
               r"steeply|heavy|light|long|close|near|tilted|full|sticky|slippery|grippy|bouncy)\b",)),
    # (the everyday word list, everyday.txt, is read here: see rewrites())
    # a bowl full of what is around the pour ("a bowl full of cereal") is not a full bowl
    ("hedge", (r"re:\b(?:full|filled) (?:up )?(?:with|of)(?= (?:the )?context\b)",)),
    ("pour", (r"re(empt):\bempt(?:y|ies|ied|ying)\b(?= (?:it|them|(?:the|a|an|my|our|this|that|his|her) [a-z ]{1,40}?) (?:into|in to)\b)",),
     "read as pour: the source poured into the bowl"),      # emptied into the bowl: "while I empty a full pitcher into it"
    # (an empty destination is every pour's: every_pour.py) an empty source pours nothing, nor is a
    # bowl that already holds liquid the vocabulary's: refused (suggestions.py says why)
    (UNCLEAR, (r"re:\balready (?:hedge|holds?|contains?|with|full|filled|half)\b",
               r"re:\bempty\b(?! (?:it|the \w+|a \w+|them|out)\b)",
               # the source is held throughout: nothing drops it
               r"re:\b(?:drop(?:s|ped|ping)?|let(?:s|ting)? go of) (?:it|them|the \w+)\b")),
    # poured into a liquid ("milk into the coffee"): the vocabulary's destination is empty
    (UNCLEAR, (r"re:\b(?:into|onto) (?:the |a |hedge |some )?(?:sticky |heavy )?liquid\b(?! particles)",)),
    # poured into the sink, onto the table: a place the vocabulary has no bowl for
    (UNCLEAR, (r"re:\b(?:(?:pour(?:s|ed|ing)?|spill(?:s|ed|ing)?)(?: it| them| the \w+| \w+)? "
               r"(?:on|onto|into|in|over|down)|into|onto) (?:the |a |hedge )?context\b",)),
    # what is left in the source is what it holds: "a little cream left in the jug"
    ("hedge", (r"re(left):(?:(?<=liquid )|(?<=much )|(?<=little )|(?<=bit )|(?<=some )|(?<=any )|(?<=lot ))left"
               r"(?= (?:in|inside) (?:the |a |it\b|my |its |our |hedge ))",),
     "read as nothing: what is left in the source is what it holds"),
    # leaving the source as it was poured: the end pose is the pour's
    ("end same_tilt", (r"re:\b(?:leave|leaves|leaving|left|keep|keeps|keeping|kept) (?:it|the \w+)"
                       r" (?:tilted|tipped|angled|inclined)(?= *(?:$|[,;.!?]|\b(?:and|then|at the end"
                       r"|afterwards|after\w*)\b))",)),
    ("end same_pose", (r"re:\b(?:leave|leaves|leaving|left|keep|keeps|keeping|kept) (?:it|the \w+)"
                       r" (?:there|in place|where it is|like that|as it is|as is|in that pose)\b",)),
    # a contrast: "near the rim instead of the middle" excludes the middle
    ("rather not", ("instead of", "rather than", "as opposed to")),
    # "end up right over the bowl": where the source ends
    ("end", (r"re:\bend(?:s|ed|ing)? up\b(?= (?:right|directly|straight|just) (?:over|above)\b)",)),
    # where the liquid ends up is an outcome (outcomes.py), never the end pose raised
    (UNCLEAR, (r"re:\bend(?:s|ed|ing)? up\b(?= (?:on|onto|in|into|inside|all|everywhere|outside|over"
               r"|above|below|under|underneath|beside|near|next|against|touching|where|somewhere|\w+ing|outcome)\b)",)),
    # "not tilted at all" is upright; "not tilted much" is slightly tilted or upright
    ("upright", (r"re:\b(?:not|without) (?:be |being |any )?(?:tilt|tip|lean)\w*\b(?!(?: (?:it|the \w+))?"
                 r" (?:much|a lot|far|too|very|so|that|sideways|back|steeply|slightly|halfway|half|a bit"
                 r"|a little|away|over|towards|past|beyond|more|up to|unclear|out|at \d|\d)\b)(?: (?:it|the \w+))?"
                 r"(?: at all)?",
                 r"re:\bno tilt(?: at all)?\b")),
    ("slightly tilted", (r"re:\b(?:not|without) (?:be |being )?(?:tilt|tip|lean)\w*\b(?: (?:it|the \w+))?"
                         r" (?:too |very |so |that )?(?:much|a lot|far)\b",)),
    (UNCLEAR, (
               # pouring has no speed of its own: the moves in and out have
               r"re:(?<!after )(?<!before )\bpour(?:s|ed|ing)?(?: (?:it|the \w+|really|very|too|more|a bit|quite))*"
               r" (?:slow(?:ly|er)?|fast(?:er)?|quick(?:ly|er)?|gently|carefully|rapidly)\b",
               # with what is poured between: "pouring honey slowly" (not "pour, then move in slowly")
               r"re:(?<!after )(?<!before )\bpour(?:s|ed|ing)?(?: (?!(?:then|and|move|moving|bring|"
               r"approach|retreat|in|away|out|before|after|lift|lower|raise|pose|position)\b)[a-z]+){1,3}"
               r" (?:slow(?:ly|er)?|fast(?:er)?|quick(?:ly|er)?|gently|carefully|rapidly)\b")),
    *OFF_CENTRE,              # a side of the middle, a length off it or toward the rim (off_centre.py)
    # not over the bowl: over neither its middle nor its rim (beside it, or far from it?)
    ("centred near rim", (r"re:(?<=\bnot )(?:(?:directly|right|quite|held|hold) )?(?:over|above) (?:the )?"
                          r"(?:destination|bowl)\b",)),
    # neither extreme names a place: the values said beside it are read
    ("hedge", (r"re:\bnot too (?:close|near|far)\b(?: ,)? (?:and |or |but |nor )?not too (?:close|near|far)\b",),
     "read as nothing: it names no place; the values said with it are read"),
    (UNCLEAR, (r"re:\ba (?:little|bit|tad) (?=to |more |further |closer |higher |lower |away |off )",
               r"re:\boff(?: |-)?cent(?:er|re)d?\b",
               "from above", r"re:\bfrom below\b(?! the (?:destination |bowl )?rim)",
               "from the top", "from the bottom", "overhead")),
    *MOVES,                   # the stages and the moves between them (moves.py)
    ("liquid", ("liquid particles", r"re:(?<!\d )\bparticles?\b", r"re:\bdroplets?\b",
                r"re:\b(?:the |its )?contents\b", r"re:\bthe stuff\b",      # something poured: the liquid
                r"re(something):(?:(?<=\bpour )|(?<=\bpours )|(?<=\bpoured )|(?<=\bpouring ))something\b")),
    # where the source is measured from: "offset 10 cm from the centre"
    # (poured from the centre, with no length or offset it is measured by: centred)
    ("pour centred", (r"re:\bpour(?:s|ed|ing)?(?: it| the \w+)? from (?:the )?(?:very )?"
                      r"(?:destination |bowl |cup )?(?:centre|center|middle)\b(?! (?:by|of the \w+ by) )",)),
    ("axis", (r"re:\bfrom (?:the )?(?:destination |bowl |cup )?(?:centre|center|middle|axis)\b",)),
    ("destination", ("target", "receiving")),
    # pouring while moving: the vocabulary pours from one pose
    (UNCLEAR, (r"re:\bwhile (?:(?:it is|it|the \w+ is) )?(?:mov|lift|rais|lower|bring|com|go|pull|walk|retreat|approach)\w*\b",)),
    # a height above the table: the vocabulary measures from the destination's rim
    (UNCLEAR, ("re:(?:" + "|".join(rf"(?<=\d {u} )" for u in _LENGTHS) + r")(?:above|over|off|from) "
               r"(?:the |a )?context\b",)),
    # a length from the rim: inside it or outside? (from the centre is the vocabulary's)
    (UNCLEAR, ("re:(?:" + "|".join(rf"(?<=\d {u} )" for u in _LENGTHS) + r")(?:(?:away )?from|off) (?:the )?"
               r"(?:destination |bowl )?(?:rim|edge|lip|brim)\b",)),
    *NEARNESS,                # close to the bowl, next to it, too close (nearness.py)
    # where the stream is aimed: "aim for the centre of the bowl" pours centred over it
    ("centred", (r"re:\baim(?:s|ed|ing)?(?: it| the \w+)? (?:for|at|into|towards?) (?:the )?(?:very )?"
                 r"(?:cent(?:re|er)|middle)\b",)),
    # the rim's height is the rim's ("just below the rim height"); at it, above or below it?
    (UNCLEAR, (r"re(level|height):\b(?:at|level with|even with) (?:the )?(?:bowl |destination )?(?:rim|edge|lip) (?:height|level)\b",)),
    ("rim", ("edge", "lip", "brim", "border", "rim height", "rim level")),
    ("low", (r"re:\b(?:just|right|slightly|barely|a bit|a little) (?:above|over) (?:the )?"
             r"(?:destination |bowl )?rim\b",
             r"re:(?<!tilted )(?<!tipped )(?<!tilt )(?<!tip )(?<!tilted just )(?<!tipped just )(?<!tilt it )(?<!tip it )"
             r"\b(?:slightly|barely|a bit|a little|a tad)(?= (?:above|over) (?:the )?(?:destination"
             r"|bowl|it)\b)")),
    # where the source is (a length before it says how far over: "5 cm over the rim" is above it)
    ("near the rim", (r"re:\b(?<!cm )(?<!mm )(?<! m )(?<!inch )(?<!inches )(?<!centimetre )"
                      r"(?<!centimetres )(?<!centimeter )(?<!centimeters )(?<!millimetres )"
                      r"(?<!millimeters )(?<!feet )(?<!foot )over (?:the |its |their |this |that )?"
                      r"(?:destination |bowl )?rim\b",
                      "at [the|its] [destination|bowl] rim",
                      "from [the|its] [destination|bowl] rim",
                      "by [the|its] [destination|bowl] rim", "close to [the|its] [destination|bowl] rim",
                      "right next to [the|its] [destination|bowl] rim", "next to [the|its] [destination|bowl] rim",
                      # poured on the rim, onto its very edge: over it
                      "on [the|its] [destination|bowl] rim", "onto [the|its] [destination|bowl] rim",
                      "onto [the|its] very rim", "on [the|its] very rim", "onto one rim", "on one rim")),
    ("very", ("extremely", "super")),
    ("very high", ("very high up", "way up high", "way up", "from a great height")),
    ("high", ("high up", "up high")),
    ("low", ("low down", "down low", "just above", "close above")),
    ("below", ("beneath", "underneath", "under")),
    ("centred", ("centered", "center", "centre", "central", "in the middle", "near the middle", "near the centre", "near the center", "middle",
                 r"re:\b(?:directly|straight|right) (?:above|over)(?= (?:the )?(?:destination|bowl"
                 r"|centre|center|middle)\b)",
                 # with nothing after it ("pour from directly above, does it spill?"): over the bowl's middle
                 r"re:\b(?:directly|straight|right) (?:above|overhead)\b(?= *[,;:.?!]| *$)")),
    ("far", (r"re:\bfar (?:off |away )?to (?:the|one) side\b", "far off", "distant", "a long way",
             "from a distance", "at a distance")),
    # lying on its side: tilted to about level, not poured from the side
    ("steeply tilted", (r"re:\b(?:(?:turn|tip|tilt|lay|lie|put|place|hold|rest|turned|tipped|tilted|laid"
                        r"|lying|held|placed|resting)\w*(?: it| the \w+| them)? )?on (?:its|their) side\b",)),
    # to the left or right, left after off_centre.py's: the vocabulary's offset names no side (refused)
    # (but "from the right side" is from the side)
    (UNCLEAR, (r"re:\b(?:to|on|from|at|towards?) (?:(?:the|your|my|its) (?:left|right)|left)\b"
               r"(?!(?:[- ]hand)? side\b)|\b(?:left|right)wards?\b",)),
    ("side", (r"re:\b(?:left|right)(?:[- ]hand)? side\b",)),
    ("offset sideways", ("offset to the side", "offset to one side")),
    ("sideways", ("lateral", "laterally", "sidewise")),
    ("near the rim", (r"re(side):\b(?:off )?to (?:one|the) side(?: ?,)? (?:just )?a (?:little |tiny )?bit\b", _A_BIT_SIDE),
     "read as near the rim: a little off the middle, as \"a bit off the centre\""),
    ("side", ("off to one side", "off to the side", "to one side")),
    # how the source is tilted and moved
    ("upside down", ("inverted", "upturned", "turned over", "full upside down", "fully upside down",
                     r"re:\b(?:turn|flip)(?:s|ed|ing|ped|ping)? (?:it|the \w+|them) over\b")),
    # tipped out: poured ("tip the milk out into a bowl")
    ("pour", (r"re:\btip(?:s|ped|ping)?\b(?= (?:(?:it|them|the \w+|a \w+) )?out\b)",)),
    # tilted all the way, or tipped right over: upside down; "all the way" said of nothing
    # tilted is refused (all the way where?); "tip it over the bowl" is where it pours
    ("upside down", (r"re:\b(?:tilt|tip|turn|lean|angl|inclin)\w*(?: (?:it|them|the \w+))?(?: (?:like|just))?"
                     r" (?:all the way|right over|fully|completely)\b(?! (?:(?:the|a|an|my|your|its)(?! (?:bowl|dish) outcome\b)"
                     r"|over|upside|in|into|to|towards?|from|across|back|up|down|above|onto)\b)",)),   # ("... does the bowl flip")
    (UNCLEAR, (r"re:\ball the way\b(?! (?:over|upside|up|down|in|into|to|from|across|back|around"
               r"|round|through)\b)",)),
    # tipped all the way over: upside down (the bowl it is said of is nouns.py's to place)
    ("upside down", ("all the way over", "all the way upside down")),
    # "tip the jug upside down": how it is held, as "hold the jug upside down" says
    ("hedge", (r"re:\b(?:tilt|tip|turn|flip)(?:s|ed|ped|ing|ping)?\b(?= (?:it |the \w+ |a \w+ )?"
               r"upside down\b)",)),
    # tipping the source is tilting it ("tip it a bit"); the bowl tipping over is outcomes.py's;
    # forward is the way a tilt goes (towards the destination)
    ("tilted", (r"re:\btipped\b",)),
    ("tilting", (r"re:\btipping\b",)),
    ("tilt", (r"re:\btips?\b", r"re(flip):\bflip(?:s|ped|ping)?\b(?= (?:\w+ ){1,3}?upside\b)")),
    ("tilt", (r"re:\btilt(?:s|ed|ing)?(?: it| the \w+)? forwards?\b",)),
    ("hedge", (r"re:(?:(?<=slightly )|(?<=halfway )|(?<=steeply )|(?<=bit )|(?<=little ))forwards?\b",)),
    ("rolled sideways", (r"re:\b(?:tilt|tip|lean)(?:s|ed|ing)?(?: (?:it|the \w+))? sideways\b",)),
    ("tilted away from the destination", ("tilted back", "tilted backwards", "leaning back",
                                          r"re:\btilt(?:s|ed|ing)?(?: it| the \w+)? (?:backwards?|back(?= at -\d))\b")),
    # "give it a little tilt": tilt it a little
    ("hedge", (r"re:\b(?:give|gives|gave|giving) (?:it|the \w+)(?= (?:a|an) (?:\w+ )?tilt\b)",)),
    *TILT_AMOUNTS,            # "with much angle", "a strong tilt" (tilt_amounts.py)
    # leaning, angling, inclining the source: tilting it
    ("tilt", (r"re:\b(?:lean|angle|incline)(?:s|d|ed|ing|t)?\b(?= (?:it|them|the \w+)\b)",)),
    # tilted too far, said before a speed ("way too far too fast"): how far? (suggestions.py)
    (UNCLEAR, (r"re(too far):\b(?:tilt|tip)(?:s|ed|ing|ped|ping)?(?: (?:it|the \w+))? (?:way |much |far )?too far\b",)),
    ("slightly tilted", (r"re:\b(?:tilt|tip)(?:s|ed|ing|ped|ping)?(?: (?:it|the \w+))?(?: only| just)?(?: very)? "
                         r"(?:a (?:little )?bit|a little|little)\b(?! (?:liquid|water|of)\b)",)),
    ("slightly", (r"re:\b(?:a (?:little )?bit|a little)(?= (?:tilt|angled|inclined))",)),
    # lifted straight up: raised, not righted
    ("raise", (r"re:\b(?:lift|lifts|lifted|lifting|rais(?:e|es|ed|ing)|mov(?:e|es|ed|ing)|bring|brings"
               r"|brought|pull(?:s|ed|ing)?)(?: it| the \w+| them)? straight up\b",)),
    ("retreat raise", (r"re(retreat):\bretreat\w*(?: it| the \w+| them)? straight up\b",)),     # "retract it straight up"
    # an angle measured from the vertical is the tilt ("tilted 30 degrees from vertical");
    # one from the horizontal is refused (suggestions.py says what would be read)
    ("hedge", (r"re:(?<=degrees )(?:from|off|away from|past) (?:the )?(?:vertical|upright)\b",)),
    (UNCLEAR, (r"re:(?<=degrees )(?:from|off|above|below|under|past|to|beyond) (?:the )?horizontal\b",)),
    # the height the liquid falls from is the source's: "drop height 20 cm"
    ("height", (r"re:\b(?:drop|fall|falling|release|pouring|pour) height\b",)),
    # a distance named by its direction is a length, never how the source is tilted:
    # "vertical distance 10 cm" a height, "horizontal distance 15 cm" the distance to the side
    ("height", (r"re:\bvertical(?:ly)? (?:distance|gap|separation|spacing|clearance|offset)\b",)),
    ("distance", (r"re:\bhorizontal(?:ly)? (?:distance|gap|separation|spacing|clearance)\b",)),
    ("upright", ("vertical", "straight up")),
    ("tilted", ("angled", "inclined")),
    ("steeply", ("sharply",)),
    ("pour steeply tilted", (r"re:\bpour(?:s|ed|ing)?(?: (?!(?:and|then|but|or|before|after)\b)[a-z]+){0,4}?"
                             r" steeply\b(?! tilt)",)),
    ("steeply tilted", (r"re:\b(?:tilt|tip|turn|lean)\w*(?: it| the \w+)? (?:to|until|till|so|so that)"
                        r"(?: it is| it's| its)? (?:lying )?(?:the )?horizontal(?:ly)?\b",)),
    ("steeply tilted", ("at a steep angle", "at a sharp angle", "horizontal", "horizontally")),
    ("slightly", ("gently", "barely")),
    ("halfway", ("half way",)),
    ("fast", ("quickly", "quick", "rapidly", "swiftly", "briskly", "rapid", "swift", "brisk", "speedy",
              "speedily", "hasty", "hastily", "hurried", "hurriedly", "in a split second")),
    ("slowly", ("leisurely", "unhurried", "gradual", "gradually", "sluggish", "sluggishly")),
    ("moderate", ("steadily", "medium speed")),
    *BODIES,                  # the bodies, the liquid and how much of it (bodies.py)
    # last, a bare "up" or "down" (not "high up", "upside down"): a move up or down
    ("raise", ("lift", "rise", "up")),
    ("lower", (r"re:(?<!upside )\bdown\b",)),
)

#: Words that say nothing about the scene: a question's frame, not its facts
#: ("very" is not one: it sets "very high" apart from "high"); "ll", "re", "ve", "m" and
#: "d" are what is left of "it'll", "we're", "I've", "I'm" and "I'd" (wording.py reads them
#: as will, are, have, am and would), "w" and "o" of "w/" (with) and "w/o" (without), "y" and "n" of "y/n" (or not). The everyday list's hedges ("okay") are read as "hedge".
FILLERS = frozenset("""
    what which how why when where whether if happen happens would will could should can may
    might must do does did is are was were be been being i we you it they me my our your its
    this that these those there here so as just really quite rather too also still only
    even keep hold turn make let use uses used using try get go put set move while during into onto out up down again
    like fully completely totally entirely absolutely pretty fairly somewhat
    anything something everything outcome hedge instead
    held robot arm gripper hand
    take takes took taking weigh weighs weighed weighing roughly about around approximately
    almost
    and or but then with without by for from at on in over above of to a an the say
    tell suppose imagine case ever all both each one way thing any
    ll re ve m d w o y n
""".split())

def _everyday() -> list[tuple[Matcher, str, str]]:
    """(matcher, the words it is read as, what is said back) for each section of the everyday
    word list: a liquid's or a context noun's name before a container's is part of its name
    ("a milk carton"), a sticky or heavy liquid's also read as what it holds when no other
    liquid is said ("the honey jar"), and "glass" before a container or what is around is
    what it is made of ("a glass jug", "a glass table")."""
    out, held = [], {p: tuple(s.words.split()) for s in sections()
                     if s.words in ("sticky liquid", "heavy liquid") for p in s.phrases}
    for s in sections():
        if s.words == "material":
            matcher = Matcher(s.phrases, glass_before=(*names("bowl", "context"), "one"))
        elif s.words.startswith("bowl"):        # a bowl, or one poured from (nouns.py)
            matcher = Matcher(s.phrases, before=names("liquid", "context"), held=held,
                              read_as=("bowl",), apart=names("liquid"))
        else:
            matcher = Matcher(s.phrases)
        words = {"unclear": UNCLEAR, "bowl poured from": "bowl"}.get(s.words, s.words)
        out.append((matcher, words, "" if s.words == "unclear" else s.said_back))
    return out


@lru_cache(maxsize=None)
def rewrites() -> tuple[tuple[Cued | Matcher | Levels | Values | Surfaces | Ramps | Fullness | Filled | TippingSpeed | PouredOff | NumberWords, tuple[str, ...], str], ...]:
    """Each rewrite in the order applied, with the words it is read as and what is said back: a
    property by its level or its number ("low friction", "a friction of 0.1": properties.py, which
    gives the words of each phrase itself), a speed of tipping said after it ("tip it, nice and
    slow": tipping_speed.py), words said after a verb of pouring ("pour it off":
    poured_off.py), the everyday word list, a number said in words ("two inches":
    numerals.py), then PHRASES; an entry's phrases as one pattern (cued.py), a section of the list as a Matcher."""
    return ((Levels(), (), ""), (Values(), (), ""), (Surfaces(), (), SURFACE_SAID), (Ramps(), (), ""),
            (Fullness(), (), FULLNESS_SAID), (Filled(), (), "read as a full source"), (TippingSpeed(), (), TIPPED),
            (PouredOff(), (), POURED_OFF_SAID),
            *((m, tuple(w.split()), said) for m, w, said in _everyday()),
            (NumberWords(), (), ""),
            *((Cued.of(phrases), tuple(words.split()), said[0] if said else "")
              for words, phrases, *said in PHRASES))
