"""How fast the source moves in and away, said in other words, part of
words.py's PHRASES: a speed said with "speed" ("at high speed" is fast),
a quick in-and-out (both moves; "fast in fast out"), a move quick by its
verb ("darts right out": the move away fast), moving fast with no
way said (both moves), "the robot come fastly" (it comes in), and tipping
the source fast or slowly, which is the move into the pouring pose: it
tilts the source as it goes ("tip it really slowly", "a slow steady tilt" is a slow approach).
A pour said fast or slowly, or a speed asked of pouring ("what speed should I
pour at"), is refused where words.py and this module say so: pouring has
no speed of its own.
"""
from __future__ import annotations

from pantarhei.bridge.reasoning.everyday import UNCLEAR

#: A speed said of pouring itself: "what speed should I pour at", "the speed of pouring", "a
#: pour speed" (a speed said of a move is read below).
POURING_SPEED = (r"\b(?:speed|rate|pace|velocity)s? (?:(?:of|for) |(?:(?:should|do|can|could|would|must|shall)"
                 r" (?:i|we|you|one|it|they|the robot) )?(?:to )?)pour\w*\b(?! (?:it |them |the \w+ )?(?:in|away|out)\b)"
                 r"|\bpour(?:ing)? (?:speed|rate|pace|velocity)\b")
#: A speed asked last, of no move: "goal: no splashing. what height and speed?" (pouring's).
SPEED_LAST = r"\b(?:what|which) (?:[a-z]+ (?:and|or|n) )?(?:speed|rate|pace|velocity)(?= *[?.!]* *$)"

#: How a tilt is made, said beside its speed ("a slow steady tilt"): its speed is what is read.
_MANNER = r"(?:steady|smooth|gentle|careful|even|controlled|gradual|slow|fast|quick|sharp|sudden|rapid)"
#: Verbs of a move quick in itself.
_DASH = r"(?:dart(?:s|ed|ing)?|zip(?:s|ped|ping)?|zoom(?:s|ed|ing)?|whizz(?:es|ed|ing)?|fling(?:s|ing)?|flung)"
_NO_RATE = r"(?! (?:rate|speed|velocity|pace)\b)"        # a speed of tilting: refused
_SAID = "read as the move into the pouring pose, which tilts the source as it goes"
#: The source moved at a speed (SPEED) toward the bowl: "moved the jug really fast toward the bowl".
_TOWARD = (r"re(toward|to the):\b(?:move|moves|moved|moving|bring|brings|brought|bringing|carr(?:y|ies|ied|ying))"
           r"(?: it| the \w+| my \w+)? (?:very |really |too |quite |super )?SPEED"
           r" (?:toward|towards|to|over to) (?:the |my |a )?(?:bowl|destination)\b")

SPEEDS: tuple[tuple, ...] = (
    # a speed asked of pouring itself: refused, pouring has no speed of its own
    (UNCLEAR, (rf"re(speed|rate|pace|velocit):{POURING_SPEED}|{SPEED_LAST}",)),
    # a speed said with "speed": "at high speed" is fast, "at a slow speed" slowly (a pour
    # said so is refused below: pouring has no speed)
    ("fast", (r"re(speed|velocity|pace):\b(?:at |with )?(?:a |full |top )?(?:high|great|full|top|fast|quick|rapid|max(?:imum)?)"
              r" (?:speed|velocity|pace)\b", r"re(at full|at top):\bat (?:full|top) speed\b|\bat top tilt\b",
              r"re(at speed):\bat speed\b")),
    ("slowly", (r"re(speed|velocity|pace):\b(?:at |with )?(?:a )?(?:low|slow|reduced|gentle|leisurely|relaxed|easy|min(?:imum)?)"
                r" (?:speed|velocity"
                r"|pace)\b",)),
    # neither too fast nor too slow: at a moderate speed
    ("moderate", (r"re(too):\b(?:not too (?:fast|quick(?:ly)?|slow(?:ly)?)(?:,| and| or| but)? (?:not )?too"
                  r" (?:slow(?:ly)?|fast|quick(?:ly)?)|neither too (?:fast|quick(?:ly)?|slow(?:ly)?) nor too"
                  r" (?:slow(?:ly)?|fast|quick(?:ly)?))\b",),
     "read as moderate: neither fast nor slow"),
    ("moderate", (r"re(speed|velocity|pace):\b(?:at |with )?(?:a )?(?:moderate|medium|normal|average|steady) (?:speed|velocity"
                  r"|pace)\b",)),
    # one speed in, another out: "slow in fast out" (each move at its own speed, the pour between)
    ("approach slowly ; retreat fast ; pour", (r"re( out):\b(?:slow|slowly) in(?: ?,)? (?:and |then )?(?:fast|quick|quickly) out\b",)),
    ("approach fast ; retreat slowly ; pour", (r"re( out):\b(?:fast|quick|quickly) in(?: ?,)? (?:and |then )?(?:slow|slowly) out\b",)),
    # not moving fast, with no way said: neither move fast ("if i don't move the pitcher fast")
    ("approach not fast ; retreat not fast ; pour", (
        r"re(mov):\b(?:do not|does not|did not|never) mov(?:e|es|ed|ing)(?: it| the \w+| them)? (?:really |very |too |quite )?"
        r"(?:fast|quickly|quick|rapidly|swiftly|briskly)\b(?! (?:in|into|to|towards?|away|out|off|back|up|down|over|from|before"
        r"|after|then)\b)",)),
    # a quick in-and-out: the move in and the move out both quick, the pour between
    ("approach fast ; retreat fast ; pour", (
        r"re( out):\b(?:fast|quick|quickly|fastly) in,? (?:and |then )?(?:fast|quick|quickly|fastly) out\b",
        r"re( out):\b(?:a |an )?(?:quick|fast|rapid|swift|brisk|sudden|snappy)(?: in(?: and)? out| in and"
        r" then out)(?: (?:motion|movement|move|moves|path|trajectory|action))?\b",
        r"re( out):\bin(?: and)? out (?:quickly|fast|rapidly|swiftly|briskly)\b",
        # moving fast, with no way said: both moves ("if I move fast")
        r"re(mov):\bmov(?:e|es|ed|ing)(?: it| the \w+| them)? (?:really |very |too |quite )?(?:fast|quickly|quick"
        r"|rapidly|swiftly|briskly)\b(?! (?:in|into|to|towards?|away|out|off|back|up|down|over|from|before"
        r"|after|then)\b)")),
    ("approach slowly ; retreat slowly ; pour", (
        r"re( out):\b(?:slow|slowly) in,? (?:and |then )?(?:slow|slowly) out\b",
        r"re( out):\b(?:a |an )?(?:slow|gentle|careful|gradual|leisurely)(?: in(?: and)? out| in and"
        r" then out)(?: (?:motion|movement|move|moves|path|trajectory|action))?\b",
        r"re( out):\bin(?: and)? out (?:slowly|gently|carefully|gradually)\b",
        r"re(mov):\bmov(?:e|es|ed|ing)(?: it| the \w+| them)? (?:really |very |too |quite )?(?:slowly|slow"
        r"|gently|carefully|gradually)\b(?! (?:in|into|to|towards?|away|out|off|back|up|down|over|from"
        r"|before|after|then)\b)")),
    # brought in, or gone away, fast or slowly: the move in, the move away
    # (brought with no way said is brought in: "if I bring the bottle very fast")
    ("approach fast", (r"re(bring|brought|swing|swung):\b(?:bring|brings|brought|bringing|swing|swings|swung|swinging)(?: it| the \w+)?"
                       r"(?: in (?:very |really |too |quite |rather )?(?:fast|quickly|quick|rapidly|swiftly|briskly|hastily)\b"
                       r"| (?:very |really |too |quite |rather )?(?:fast|quickly|quick|rapidly|swiftly|briskly|hastily)\b(?! (?:to|toward|towards|than|as)\b))",)),
    ("approach slowly", (r"re(bring|brought):\b(?:bring|brings|brought|bringing)(?: it| the \w+)?(?: in (?:very |really |too |quite |rather )?"
                         r"(?:slowly|slow|gently|gradually|steadily)\b| (?:very |really |too |quite |rather )?(?:slowly|slow|gently|gradually|steadily)\b"
                         r"(?! (?:to|toward|towards|than|as)\b))",)),
    ("retreat fast", (r"re( away):\b(?:go|goes|going|went|gone) away (?:very |really |too |quite )?(?:fast|quickly|quick)\b",
                      r"re(yank|jerk|snatch|whip):\b(?:yank|yanks|yanked|yanking|jerk|jerks|jerked|snatch|snatches|snatched|whip|whips|whipped)"
                      r"(?: it| the \w+)? (?:away|back|out)\b")),
    # flicked upright: righted, fast, as the source moves away ("flick the shaker upright after the pour")
    ("end upright ; retreat fast", (r"re(flick):\bflick(?:s|ed|ing)?(?: it| the \w+| them)? (?:back )?(?:up(?:right)?|straight)\b"
                                    r"(?: (?:really |very )?(?:fast|quickly|quick))?",)),
    ("retreat slowly", (r"re( away):\b(?:go|goes|going|went|gone) away (?:very |really |too |quite )?(?:slowly|slow)\b",)),
    # "fastly", as learners of English say it; "the robot come fastly": it comes in
    # (or came at the bowl so: "i came at the bowl too fast with the jug")
    ("approach fast", (r"re(com|came):\b(?:come|comes|coming|came)(?: at (?:the |my )?bowl)? (?:very |really |too )?(?:fastly|fast|quickly)\b",)),
    # moved fast or slowly toward the bowl: in ("moved the jug really fast toward the bowl")
    ("approach fast", (_TOWARD.replace("SPEED", "(?:fast|quickly|quick)"),)),
    ("approach slowly", (_TOWARD.replace("SPEED", "(?:slowly|slow)"),)),
    ("approach slowly", (r"re(com|came):\b(?:come|comes|coming|came) (?:very |really |too )?(?:slowly|slow)\b",)),
    # a note's item of one move: "full jug, fast in", "slow out."
    *((f"{move} {speed}", (rf"re({cue}):(?:^|(?<=[,;:.!?] )|(?<= - ))(?:{said}) {way}(?= *(?:[,;:.!?]| - |$))",))
      for way, move in (("in", "approach"), ("out", "retreat"))
      for said, speed, cue in (("fast|quick|quickly", "fast", "fast|quick"), ("slow|slowly", "slowly", "slow"))),
    # brought in hard: fast ("bring the shaker in hard")
    ("approach fast", (r"re(hard):\b(?:bring|brings|brought|bringing|come|comes|came|coming|mov(?:e|es|ed|ing)|swing|swings|swung"
                       r"|swinging)(?: it| the \w+| my \w+)? in (?:really |very |too |quite )?hard\b",)),
    ("fast", ("fastly",)),
    # tipped all the way over fast or slowly: upside down, in a clause of its own, and the move into it
    ("; approach fast", (r"re(fast|quick|rapid):(?:(?<=all the way over )|(?<=right over ))(?:(?:very|really|too|quite|super) )?"
                         r"(?:fast|quick(?:ly)?|rapidly)\b(?! (?:than|as)\b)",)),
    # (or turned upside down fast, over the bowl or not: "turn the jug upside down over the bowl really fast";
    # not poured so, a speed of pouring)
    ("upside down ; approach fast ; pour", (r"re(fast|quick|rapid):\b(?:turn|turns|turned|turning|tip|tips|tipped|tipping|flip|flips"
                                           r"|flipped|flipping|invert|inverts|inverted|inverting)(?: (?:it|them|the \w+|my \w+))?"
                                           r"(?: all the way| clean| right| totally| completely| fully)? upside down(?: over (?:the \w+|it|my \w+(?: bowl)?))?"
                                           r" (?:(?:very|really|too|quite|super) )?(?:fast|quick(?:ly)?|rapidly)\b(?! (?:than|as)\b)"
                                           # a note naming the source held so (or not), then the speed: "jug upside down over bowl, fast", "bowl, upside down fast"
                                           r"|(?:^|(?<=[,;:.!?] ))(?:(?:the |a |my )?(?!pour)[a-z]+(?: of [a-z]+)?(?: over (?:the |a |my )?[a-z]+)? )?upside down"
                                           r"(?: over (?:the |a |my )?[a-z]+)?(?: ?,)?"
                                           r" (?:(?:very|really|too|quite|super) )?(?:fast|quick(?:ly)?|rapidly)\b(?! (?:than|as|in|out|away)\b)",),
     _SAID),
    ("; approach slowly", (r"re(slow|gradual|steadi):(?:(?<=all the way over )|(?<=right over ))(?:(?:very|really|too|quite|super) )?"
                           r"(?:slow(?:ly)?|gradually|steadily)\b(?! (?:than|as)\b)",)),
    # tipped fast or slowly: the move into the pouring pose, which tilts the source as it goes
    # (where it is tipped is where it pours: "tilt the jug slowly right over the bowl", "held right above
    # the rim tilted slowly", the place before it in a clause of its own; what is tipped, named, is
    # tipping_speed.py's to keep)
    ("; approach fast ; pour", (rf"re(fast|quick|rapid):\b(?:tilt|tip)\w*(?: it| them)?(?: in| it in)?(?: (?:very|really|too|quite))?"
                              r" (?:fast|quick(?:ly)?|rapidly)\b(?! (?:than|as)\b)",
                              r"re(fast|quick|rapid):\b(?:quickly|fast|rapidly) (?:tilt|tip)\w*\b")),
    ("; approach slowly ; pour", (rf"re(slow|gradual|steadi):\b(?:tilt|tip)\w*(?: it| them)?(?: in| it in)?(?: (?:very|really|too|quite))?"
                                r" (?:slow(?:ly)?|gradually|steadily)\b(?! (?:than|as)\b)",
                                r"re(slow|gradual|steadi):\b(?:slowly|gradually|steadily) (?:tilt|tip)\w*\b")),
    # a move that is quick by its verb: darted, zipped, flung in or out ("flings it over the bowl",
    # "darts right out again"): the move in or away, fast
    ("approach fast ; retreat fast ; pour", (rf"re(dart|zip|zoom|whizz):\b{_DASH}(?: it| the \w+| them)? in(?: and|,)?"
                                             r" (?:then )?out\b",)),
    ("approach fast", (rf"re(dart|zip|zoom|whizz|fling|flung):\b{_DASH}(?: it| the \w+| them)?(?: right| straight)?"
                       r" (?:in|over|into)\b",)),
    ("retreat fast", (rf"re(dart|zip|zoom|whizz|fling|flung):\b{_DASH}(?: it| the \w+| them)?(?: right| straight)?"
                      r" (?:out|away|back)\b(?! of\b)",)),
    # a tilt said slow or quick ("a slow steady tilt", "a quick tip"): the move into the pouring pose
    ("approach slowly ; pour", (rf"re(slow|gradual):\b(?:slow|gradual)(?:,? (?:and )?{_MANNER})* (?:tilt|tip)s?\b{_NO_RATE}",), _SAID),
    ("approach fast ; pour", (rf"re(fast|quick|rapid|sudden):\b(?:fast|quick|rapid|sudden)(?:,? (?:and )?{_MANNER})* (?:tilt|tip)s?\b"
                       rf"{_NO_RATE}",), _SAID),
)
