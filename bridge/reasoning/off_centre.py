"""Where the source is said from the bowl's middle, part of words.py's
PHRASES: a length off the centre ("3 cm off-center", "4 cm off-centre
toward the bowl edge") is the source's distance from the bowl's axis, as
"3 cm from the centre" is, read by the range that holds it, never a
height; so is an offset said toward the rim, the edge or the robot the
source comes from ("offset 3 cm from bowl center toward the rim", "offset
of 1.5 inches toward the robot"): that way lies the distance from the
axis, not the sideways offset. A side of the middle is offset sideways,
its side unread ("a bit to the left of centre", "off center to the left");
the source held to a side of the bowl with no length ("off to the left of
the bowl", "too far left", "in from the left") is from the side, and a
rim named by its side ("the left edge", "over the right side of the bowl")
near the rim, each said back; a length to a side is refused, as "5 cm to
the left" is (its side is the number's sign), and so is a tilt to a side.
"Off-centre" with no length says no distance ("how far?", words.py); "far off-centre" is from the side."""
from __future__ import annotations

from pantarhei.bridge.reasoning.everyday import UNCLEAR
from pantarhei.bridge.reasoning.units import UNITS

#: Units of length, as a question writes them after a number (units.py's).
LENGTHS = tuple(w for w, (kind, _) in UNITS.items() if kind == "length")
#: Right after a number and its unit of length.
_AFTER_LENGTH = "(?:" + "|".join(rf"(?<=\d {u} )" for u in LENGTHS) + ")"
#: The way from the middle toward the source: the rim or edge, or the robot it comes from.
_TOWARD = (r"toward(?:s)? (?:the )?(?:destination |bowl )?(?:rim|edge|lip|brim|robot|arm|gripper|source"
           r"|side it comes from)\b")
_CENTRE = r"(?:the )?(?:destination |bowl )?(?:centre|center|middle)\b"
_SAID = "read as the source's distance from the bowl's axis (the way to the rim), not a sideways offset"

OFF_CENTRE: tuple[tuple, ...] = (
    (UNCLEAR, (rf"re(left|right):(?<![\w.-])-?\d+(?:\.\d+)? (?:{'|'.join(LENGTHS)}) (?:to )?(?:the )?(?:left|right)"
               rf" (?:of|from) {_CENTRE}",)),
    # a side of the middle, or off it to a side: offset sideways ("a bit to the left of centre", "off center to the left")
    ("offset sideways", (r"re:\b(?:(?:just|slightly|a (?:little |tiny )?bit|a little|a tad|off) )?(?:to )?(?:the )?"
                         rf"(?:left|right) (?:of|from) {_CENTRE}",
                         r"re(left|right):\boff[ -]?cent(?:er|re)d?(?: ,)? (?:to|towards?) (?:the|your|my|its) (?:left|right)\b"),
     "read as offset sideways: the vocabulary's offset names no side"),
    # a length to a side, or the source tilted to one: refused, as words.py refuses a side (its sign unsaid)
    (UNCLEAR, (rf"re(left|right):(?<![\w.-])-?\d+(?:\.\d+)? (?:{'|'.join(LENGTHS)}) (?:(?:off|over|out) )?"
               r"(?:to|towards?) (?:the|your|my|its) (?:left|right)\b",
               r"re(left|right):\b(?:tilt|tip|lean|roll|turn|twist|rotat|angl|cock|swivel|swing|bank)\w*"
               r"(?: (?:it|them|(?:the|a|my|your) \w+))?(?: (?:over|slightly|a bit|a little|way))?"
               r" (?:to(?:wards?)?|on) (?:the|its|your|my|one) (?:left|right)\b")),
    # a rim named by its side: near the rim ("pouring from the left edge of the bowl")
    ("near the rim", (r"re(left|right):\b(?:(?:off|over|out) )?(?:(?:to|at|on) )?(?:the |its )?(?:left|right)(?:[- ]hand)? (?:edge|rim|lip)\b",
                      # over a side of the bowl, not beside it: "jug over the left side of the bowl"
                      r"re(left|right):\bover (?:the |its )?(?:left|right)(?:[- ]hand)? (?:side|half|part)"
                      r"(?: of (?:the |my |a )?(?:bowl|destination|it))?\b"),
     "read as near the rim: the vocabulary's offset names no side"),
    # the source held to a side of the bowl, no length said: from the side ("held off to the left of
    # the bowl", "way over to the right", "too far left", "bring it in from the left")
    ("side", (r"re(left|right):\b(?:(?:way|far|well|too far|so far|really far|very far|a bit|a little|slightly|just) )?"
              r"(?:(?:off|over|out|across) )?(?:to|towards?|on|from) (?:the|your|my|its) (?:left|right)\b"
              r"(?:[- ]hand(?: side)?\b)?(?: (?:of|from) (?:the |my |your )?(?:bowl|destination|it|them)\b)?",
              r"re(left|right):\b(?:way|far|too far|so far|really far|very far) (?:left|right)\b"),
     "read as from the side: the vocabulary's offset names no side"),
    # far off the middle, no length said: from the side, said back ("pitcher far off center")
    ("to the side", (r"re(far|way):\b(?:far|way|well) off[ -]?(?:cent(?:er|re)d?|the (?:center|centre|middle))\b",),
     "read as from the side: far from the middle"),
    # an offset toward the rim or the robot: the distance from the axis, its number kept
    ("hedge", (r"re(offset):\boffset(?= (?:of |by )?(?:about |around |roughly )?-?\d+(?:\.\d+)? (?:"
               + "|".join(LENGTHS) + rf") (?:(?:from|off) {_CENTRE} )?{_TOWARD})",), _SAID),
    ("axis", (rf"re(cent|toward):{_AFTER_LENGTH}(?:(?:off|from|away from) {_CENTRE} ?)?(?:{_TOWARD})",
              rf"re(cent):{_AFTER_LENGTH}off {_CENTRE}d?"), _SAID),
)
