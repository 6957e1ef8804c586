"""A move up or down said with where it goes or which way the stream
falls, part of words.py's PHRASES. Lowered or raised to a height said in
words, with no move before or after pouring said, is held there while
pouring, as "lowered to 5 mm above the lip" is: "lower the carafe to just
over the rim" pours low (just over the rim), and a bare "lower it" is still
refused (lower than what?). Poured "straight down" into the bowl says the
way the stream falls, as it falls from every pour: no move down, and no
place over the bowl, said back as read as nothing, and so is "pour it
straight down" with no bowl said (people who pour read it as any pour:
over the middle, upside down or neither); the source moved straight down
("move it straight down before pouring") is still refused. Held or lowered
down inside the bowl ("lower the jug right down inside it to pour") is
below its rim."""
from __future__ import annotations

#: Where a move up or down may be said to go, in words: just over the rim ("just over the rim": low).
_RIM_SAID = (r"(?:just |right |slightly |a bit |a little |only )?(?:above|over) (?:the )?(?:destination |bowl )?"
             r"(?:rim|edge|lip|brim)\b")

MOVED_TO: tuple[tuple, ...] = (
    ("hedge", (r"re(lower|rais|lift|brought|bring|down|up):\b(?:(?:lower(?:ed|ing|s)?|rais(?:e|ed|es|ing)|lift(?:ed|ing|s)?)"
               r"(?: (?:it|them|the \w+))?(?: (?:up|down))?|(?:brought|bring|brings|bringing|go|goes|going|went|come|comes"
               rf"|coming|came|move[sd]?|moving)(?: (?:it|them|the \w+))? (?:down|up)) to(?= {_RIM_SAID})"
               r"(?![^;.?!]*\b(?:before|after|then)\b)",),
     "read as held there while pouring"),
    # told as lifted up high and poured: held high while pouring ("I lifted the jug up high and poured"; "raise
    # it up high and then pour", asked, is still refused: raised before pouring, or held high?)
    ("hedge", (r"re(lifted|raised):\b(?:lifted|raised)(?: (?:it|them|the(?: \w+){1,2}))?"
               r"(?= (?:up )?(?:really |very |way )?(?:up )?high(?: ,| and)(?: then)? pour)",),
     "read as held there while pouring"),
    # held down inside the bowl: below its rim ("lower the jug right down inside it to pour")
    ("below the rim", (r"re(inside):\b(?:(?:lower(?:ed|ing|s)?|dip(?:s|ped|ping)?|put(?:s|ting)?|hold(?:s|ing)?|held"
                       r"|keep(?:s|ing)?|kept)(?: (?:it|them|the \w+))?(?: right)?(?: down)?|(?:right )?down)"
                       r" inside (?:of )?(?:it|the (?:bowl|destination|dish))\b(?![^;.?!]*\b(?:before|after|then)\b)",),
     "read as below the destination's rim: the source held down inside it while pouring"),
    # (poured straight down with no bowl said, too: "pour it straight down from high up"; not a move, "move it straight
    # down", nor a tilt, "pointing straight down", nor what runs down, "went straight down the side")
    ("hedge", (r"re(straight down):\bstraight down\b(?= (?:into|in|onto) )"
               r"|(?<!come )(?<!comes )(?<!came )(?<!coming )(?<!bring )(?<!brought )(?<!lower )(?<!move )(?<!it )"
               r"(?<!point )(?<!pointing )(?<!tilt )(?<!tilted )(?<!slam )(?<!go )(?<!goes )(?<!went )(?<!going )"
               r"(?<!run )(?<!runs )(?<!ran )(?<!running )\bstraight down\b(?! (?:the|its|along|onto|on|to)\b)"
               r"|(?:(?<=\bpour it )|(?<=\bpours it )|(?<=\bpoured it )|(?<=\bpouring it ))straight down\b"
               r"(?! (?:the|its|along|onto|on|to)\b)",),
     "read as nothing: the stream falls straight down from every pour; where the source is held is "
     "said by \"centred\" or \"near the rim\", a move down by \"lower it before pouring\""),
)
