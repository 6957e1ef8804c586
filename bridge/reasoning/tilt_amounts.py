"""How far the source is tilted, said by how much tilt or how strong it
is, as learners of English say it, part of words.py's PHRASES: "with much
angle", "with a lot of angle", "a strong tilt", "make the tilting of the
bottle very strong", "a high tilt" (no number after it: "jug high tilt 90" is high,
tilted 90 degrees), "full tilt" are steeply tilted, as "tilt it hard" and "a big tilt" are
(everyday.txt); "a little angle" or "a weak tilt" slightly tilted. An angle
asked for ("how much angle") is a value asked, not said: left to be read
as one. A little either side of horizontal ("slightly past horizontal", "a
little less than horizontal") is steeply tilted still, as horizontal is; a
move made horizontally ("retreat horizontally", "pull it back
horizontally") is the way the source moves, which no proposition says, and
no tilt; so is how far something moved ("bowl is move away little bit"). How far, said with "far": "not tilted very far" is slightly
tilted ("not going to tip it much" too), unless a value follows that says how far; "tip it really far"
steeply; "tilted too far" is refused (past what?), but for a pour told ("I tipped the jug too
far and it went on the counter"), where it is tipped far: steeply tilted, said back."""
from __future__ import annotations

from pantarhei.bridge.reasoning.everyday import UNCLEAR

#: Much of a tilt: "much", "a lot of", "a big".
_MUCH = r"(?:much|a lot of|lots of|a great|great|a strong|strong|plenty of)"
_LITTLE = r"(?:a little|little|a weak|weak)"
_TILTING = r"(?:angle|tilt|tilting|tip|tipping|inclination)"

#: A little on either side: "slightly past", "a little less than", "just short of".
_NEAR = (r"(?:just |only )?(?:slightly|a (?:little |tiny )?bit|a little|a tad|just)(?: (?:less|more) than| past| beyond"
         r"| over| under| below| short of| shy of)")

#: A little either side of horizontal (90 degrees): still steeply tilted (80 to 120 degrees); read
#: before a comparison takes "less than" (words.py).
NEAR_HORIZONTAL = ("steeply tilted", (rf"re(horizontal):\b{_NEAR} (?:the )?horizontal(?:ly)?\b",),
                   "read as steeply tilted: a little either side of horizontal (90 degrees) is within 80 to 120 degrees")

TILT_AMOUNTS: tuple[tuple, ...] = (
    ("steeply tilted", (rf"re(angle|tilt|tip|inclin):(?<!how )\b(?:with |at )?{_MUCH} {_TILTING}\b",
                        r"re(strong):\b(?:make|makes|making|made) the (?:tilt|tilting|tipping|angle)(?: of (?:it|the \w+))?"
                        r" (?:very |really |so |more |too )?strong(?:er)?\b",
                        r"re(tilt):\b(?:a )?high tilt\b(?! ?(?:of |at |to |-)?[0-9])",
                        # "tilt the jug way over" (as "tilted way over" is, everyday.txt)
                        r"re(way over|far over):\b(?:tilt|tip)\w* (?:it|them|the \w+) (?:way|far) over\b",
                        r"re(full tilt):\b(?:at |on )?full tilt\b")),        # "teapot. 30cm. full tilt. spill?"
    ("slightly tilted", (rf"re(angle|tilt|tip|inclin):(?<!how )\b(?:with |at )?{_LITTLE} {_TILTING}\b",
                         r"re(little bit):\blittle bit (?:tilted|tipped)\b")),     # "pouring little bit tilted only"
    # how far something moved, said as learners of English say it: "bowl is move away little bit" (no amount of
    # liquid, as "pour little bit water" is)
    ("hedge", (r"re(little bit):(?:(?<=away )|(?<=retreat )|(?<=moved )|(?<=moves )|(?<=move )|(?<=slid )|(?<=slides ))little bit\b",),
     "ignored: how far it moves is no value the vocabulary says (whether it moves is)"),
    ("hedge", (r"re(horizontally):(?:(?<=away )|(?<=back )|(?<=out )|(?<=retreat )|(?<=retract )|(?<=withdraw )"
               r"|(?<=retreat it )|(?<=move )|(?<=moves )|(?<=moving )|(?<=move it ))horizontally\b",),
     "the way the source moves: no proposition says it, and it is no tilt"),
)

#: How far, said with "far" (read before the negations of tilting in words.py's PHRASES).
FAR_TILTS: tuple[tuple, ...] = (
    # not tilted all the way: partway, as halfway is ("if i dont tilt the cup all the way", "without tilting it
    # all the way")
    ("tilted halfway", (r"re( all the way):\b(?:not|without|never) (?:tilt|tip|turn|lean)\w*(?: (?:it|them|the \w+))?"
                        r" all the way(?: over)?\b(?! (?:upside|in|into|to|towards?|from|across|back|up|down|above|onto)\b)",),
     "read as tilted partway, as halfway"),
    # not tipped (very, too) far: slightly tilted ("I wasn't even tilting it much"), unless a value
    # follows that says how far ("not tipping it very far, only slightly past horizontal")
    ("slightly tilted", (r"re( far| much):\b(?:not|without|never) (?:even |really )?(?:be |being )?(?:going |gonna )?(?:to )?(?:tilt|tip|lean)\w*\b(?: (?:it|the \w+))?"
                         r" (?:too |very |so |that |as )?(?:far|much)\b(?! (?:from|away|off|to)\b)"
                         r"(?: ,? (?:just|only) a (?:little|tiny bit|bit|tad)(?: bit)?\b)?"     # ("..., just a little")
                         r"(?![^.?!;]*\b(?:only|just|but|rather|tilted|tilt|steeply|slightly|halfway|upside|upright"
                         r"|degrees?|horizontal)\b)",),
     "read as slightly tilted: tilted, not far"),
    # very inclined, as learners of English say it: steeply tilted ("pour the water from the bottle very inclined")
    ("steeply tilted", (r"re(very|really|highly|strongly|heavily):\b(?:very|really|highly|strongly|heavily) (?:inclined|tilted|tipped"
                        r"|angled|slanted)\b(?! (?:back|away|towards?|like|almost|nearly|about|around|at|to|by|past)\b)",),
     "read as steeply tilted"),
    # not much inclined, as learners of English say it: slightly tilted; tilted very much: steeply
    ("slightly tilted", (r"re( much):\bnot (?:so |that |too |very )?much (?:inclined|tilted|tipped|angled)\b",),
     "read as slightly tilted: tilted, not much"),
    ("steeply tilted", (r"re( much):\b(?:tilt|tip|angl|inclin|lean)\w*(?: (?:it|them|the \w+))? (?:very|so|really) much\b",),
     "read as steeply tilted"),
    # tipped (really) far: steeply ("tilted far, right at the edge"; too far stays refused: past what?)
    ("steeply tilted", (r"re( far):\b(?:tilt|tip)\w*(?: (?:it|them|the \w+))? (?:(?:really|very|way|pretty|quite) )?far\b"
                        r"(?! (?:from|away|off|to)\b)",), "read as steeply tilted"),
    # tipped too far (or too much), told of a pour that went wrong ("I tipped the jug too far and ...",
    # "was it because i tilted it too much?"): tipped far, the least of which is steeply
    ("steeply tilted", (r"re(too far|too much):\b(?:tilted|tipped)(?: (?:it|them|the \w+))? (?:(?:way |much |far )?too far\b"
                        r"(?! (?:from|away|off|to)\b)|(?:way |far )?too much\b)",),
     'read as steeply tilted: tipped far, as a pour told says it (say "upside down" for further)'),
    # too tilted, as a note tells it ("jug too tilted bowl tips?"): tipped too far
    ("steeply tilted", (r"re(too tilted|too tipped):\b(?:way |much |far )?too (?:tilted|tipped)\b",),
     'read as steeply tilted: tipped far, as a pour told says it (say "upside down" for further)'),
    # tipped too far, or too much: past what? (not far from the bowl)
    (UNCLEAR, (r"re:\b(?:tilt|tip|angl|inclin|lean)\w*(?: (?:it|them|the \w+))? (?:(?:too |so |that |very )?far\b"
               r"(?! (?:from|away|off|to)\b)|(?:way )?too much\b)",)),
)
