"""Everyday phrases for the stages of a pour and the moves between them,
read as the vocabulary's words: part of words.py's PHRASES, applied in
order at their place there ("put it back upright" is the end upright,
"bring it in low" a path in at a height, "pull it out fast" the move
out, "once it's poured" afterwards).

The stage words ("start", "pour", "end", "approach", "retreat") are
read by stages.py: the rewrites here only bring other words to them.
"""
from __future__ import annotations

_IT = "[the source|the bowl|it]"
#: Words that begin a manner of pouring ("from the side", "with a light liquid").
_MANNER = ("from|with|over|into|onto|low|high|very|steeply|slightly|halfway|tilted|"
           "upside|centred|centered|far|near|below|above")

#: Verbs of a smooth move, said of the move in or out as "move" is ("glide in slowly",
#: "swing the jug over", "ease it out"); not "slide" (the bowl sliding is an outcome).
_GLIDE = (r"(?:swing(?:s|ing)?|swung|swoop\w*|glid(?:e|es|ed|ing)|sweep(?:s|ing)?|swept"
          r"|eas(?:e|es|ed|ing)|carr(?:y|ies|ied|ying))")

#: Someone pouring, done or finished with it: "when I'm done pouring", "once she has finished pouring",
#: "after the jar stops pouring", "after I'm done tipping".
DONE = (r"(?: (?!(?:and|then|but|or|pour\w*)\b)\w+){0,2} (?:(?:done|finished|through)(?: with(?: the)?)?"
         r"|(?:finish|finishes|stop|stops|stopped)(?: to)?) (?:pour(?:s|ed|ing)?|tipping|tilting)\b")

MOVES: tuple[tuple, ...] = (
    # done pouring: after the pour ("when I'm done pouring, pull it away fast"); a move away said
    # before it is done is the move away, as the vocabulary's pour ends when the source moves away
    ("after pour", (rf"re(done|finish|through|stop):\b(?:when|once|after|as soon as){DONE}",
                    # or the pour itself done: "after the pouring stops"
                    r"re(stops|stopped|ends|ended|over|done|finished):\b(?:when|once|after|as soon as) the pour(?:ing)? (?:has |is )?"
                    r"(?:stops|stopped|ends|ended|over|done|finished)\b(?! (?:from|at|over|above|near|off)\b)",
                    # or the liquid in: "after it's already gone in"
                    r"re(gone):\b(?:when|once|after) it (?:(?:is|has|was) )?(?:already )?gone in\b")),
    ("hedge", (rf"re(done|finish|through|stop):\b(?:before|until){DONE}",),
     "read as nothing: the vocabulary's pour ends when the source moves away; how much is poured by then is not said"),
    # where the pour itself starts is where it pours, not the start pose before the move in
    # (and the pour done from a place is poured from it: "when the pour is done from higher up", not its end)
    ("pour", (r"re(starts|begins|happens|takes place):\bthe pour(?:ing)? (?:starts|begins|happens|takes place)(?= (?:at|from)\b)",
              r"re(done):\bthe pour(?:ing)? (?:is|was|gets|got|is being) done(?= (?:from|at|over|above|near|off)\b)")),
    # on the way in or out: the move in or away ("much faster on the way out")
    ("approach", (r"re(way):\bon (?:the|its|their|his|her|my) way (?:in|over|there)\b",)),
    ("retreat", (r"re(way):\bon (?:the|its|their|his|her|my) way (?:out|back|away)\b",)),
    # the stages: the move into the pouring pose, the move out of it, the end pose
    # (brought back up: raised, or righted? a tilting verb rights it, "bring" says upright)
    ("end upright", (r"re:\b(?:tip|tips|tipped|tipping|tilt\w*|turn\w*|put\w*|set\w*|stand\w*)(?: it"
                     r"| the \w+| them)? back (?:up(?:right)?|to (?:upright|vertical|straight))\b"
                     r"(?! (?:high|higher|above|to \d|\d))",
                     r"re:\b(?:bring\w*|brought|return\w*)(?: it| the \w+| them)? back (?:upright|to "
                     r"(?:upright|vertical|straight))\b",
                     r"re:\b(?:return\w*|turn\w*)(?: it| the \w+| them)? to (?:upright|vertical)\b",
                     # said of the source itself: "after the cup goes back upright"
                     r"re:\b(?:go|goes|going|gone|went|come|comes|coming|came|get|gets|got|swing\w*|rock\w*)"
                     r" back (?:upright|to (?:upright|vertical|straight))\b",
                     r"re:\bstraighten\w*(?: it| the \w+| them)?(?: up| out)?\b",
                     r"re:\bright(?:s|ed|ing)?(?: it| the \w+| them)? up\b(?! (?:high|above|over|there|to)\b)", f"put {_IT} back upright", f"set {_IT} back upright",
                     f"set {_IT} upright", f"stand {_IT} back up", f"stand {_IT} up",
                     "back upright")),
    ("end", (f"put {_IT} down", f"set {_IT} down", f"put {_IT} back down", f"set {_IT} back down",
             "at the end", "in the end", "finish")),
    # "after pouring from the side": the manner after it is the pour's
    # emptying a bowl into another, decanting, chucking it in, straining or ladling it: pouring
    ("pour", (r"re:\bempt(?:y|ies|ied|ying)(?= (?:it|(?:the|a|an|my) (?:\w+ )?\w+) (?:into|in|onto)\b)",
              r"re:\bchuck(?:s|ed|ing)?(?= (?:(?:it|them|the \w+|\w+) )?(?:in|into)\b)",
              # straining a drink into a glass, ladling soup into a bowl
              r"re:\bstrain(?:s|ed|ing)?(?= (?:(?:it|them|the \w+|\w+) )?(?:in|into|over)\b)",
              r"re:\bladl(?:e|es|ed|ing)(?= (?:(?:it|them|the \w+|\w+) )?(?:in|into|out)\b)",
              r"re:\bdump(?:s|ed|ing)?(?= out\b)",      # the liquid dumping out: coming out
              "decant", "free pour", "transfer", "serve", "dispense", "top up",
              # stopping to pour, once brought in: pouring where it stops ("bring it in quick then stop and pour")
              r"re(stop):\bstop(?:s|ped|ping)?(?: ,)? (?:and|then|to) pour\b")),
    # filling the bowl from the source, said as what one is doing ("filling the mop bucket from a jug, how do
    # i stop ..."): pouring into it (a bowl wanted filled is seeking.py's goal)
    ("pour", (r"re(fill):(?:^|(?<=[,;:.!?] )|(?<=\bi )|(?<=\bwe )|(?<=\bthey )|(?<=\bto ))fill(?:s|ed|ing)? (?:up )?"
              r"(?:the|a|my|our|your|his|her|their)(?= (?:[a-z]+ ){0,3}(?:bowl|bucket|basin|dish|tub)s? (?:up )?(?:from|with)\b)",),
     "read as pouring into it"),
    # dumping it: pouring it tipped far, the least of which is steeply
    ("pour steeply tilted", (r"re:\bdump(?:s|ed|ing)?\b",), "read as pour steeply tilted: tipped far"),
    ("retreat ; pour", (rf"re:\bafter pour(?:s|ed|ing)?\b(?= (?:{_MANNER})\b)",
                        # "after tilting it halfway": the tilt is the pour's
                        r"re:\bafter\b(?= (?:tilt|tip|lean|angl|inclin)\w*\b)")),
    # "bring it back up", "lift it back down": up and down, in the stage they are said in
    ("raise", (r"re:\b(?:bring|brings|bringing|brought|lift|lifts|lifted|lifting|mov(?:e|es|ed|ing)"
               r"|tak(?:e|es|ing)|took|pull(?:s|ed|ing)?)(?: it| the \w+| them)? back up\b",)),
    # "lift it away slowly": the move away, raised as it goes (not "lift it away from the bowl": a direction)
    ("retreat raise", (r"re:\b(?:lift|lifts|lifted|lifting)(?: it| the \w+| them)? (?:away|off)\b(?! (?:from|of)\b)",)),
    ("lower", (r"re:\b(?:bring|brings|bringing|brought|lift|lifts|lifted|lifting|mov(?:e|es|ed|ing)"
               r"|tak(?:e|es|ing)|took)(?: it| the \w+| them)? back down\b",)),
    # "once it's poured", "when done": after pouring
    # ("when poured from the side" is how it is poured, not after)
    ("afterwards", (r"re:\b(?:when|once|after) (?:(?:it|you|i|we|they|the \w+) )?(?:(?:is|are|am|has"
                    r"|have|was|were|been) )*(?:done|finished|through)\b(?: pour\w*)?",
                    r"re:\b(?:once|after) (?:(?:it|you|i|we|they|the \w+) )?(?:(?:is|are|am|has"
                    r"|have|was|were|been) )*(?:poured|emptied)\b(?= *(?:$|[,;.!?]))")),
    ("afterwards", (r"re:\bafter(?= *(?:$|[,;.!?]))",)),
    ("before pour", (r"re:\bbefore(?= *(?:$|[,;.!?]))",)),
    ("approach ; pour", (rf"re:\bbefore pour(?:s|ed|ing)?\b(?= (?:{_MANNER})\b)",)),
    # a path in at a height ("bring it in low", "come in low", "approach high"): the start and
    # the pouring pose both there (stages.py), unless the pour's height is said; "move in
    # from high up" says only where it starts
    # where the move in stops is the pouring pose: "move in fast and stop just above the cup"
    ("pour", (r"re:\b(?:stop|stops|stopped|stopping|halt\w*)\b(?= (?:just |right |directly |exactly )?"
              r"(?:above|over|near|by|beside|\d)\b)",)),
    ("approach same_height_in", (r"re:\b(?:(?:mov(?:e|es|ed|ing)|bring(?:s|ing)?|brought|com(?:e|es|ing)"
                                 r"|came|swing(?:s|ing)?|swung|lower(?:s|ed|ing)?)(?: it| the \w+)? in"
                                 r"|approach(?:es|ed|ing)?)\b(?= (?:(?:slowly|fast|quickly|gently|carefully|steadily)(?: and)? )?"
                                 r"(?:very |really |quite |fairly |too |so |nice and )?"
                                 r"(?:low|high)\b(?! (?:friction|mass|weight|bounc)))",)),
    # brought down from a height: the move in, lowering, from where it starts
    ("approach lower from", (rf"re:\b(?:mov(?:e|es|ed|ing)|bring(?:s|ing)?|brought|com(?:e|es|ing)|came"
                             rf"|{_GLIDE})(?: it| the \w+)? down from\b",)),
    ("approach", (r"re:\b(?:mov(?:e|es|ed|ing)|bring(?:s|ing)?|brought) (?:it|the \w+) (?:in|over)\b",
                  rf"re:\b{_GLIDE}(?: it| the \w+)? (?:in|over)\b",
                  "before pour", "before the pour", "move to the pour pose", "move into the pour pose",
                  "move in", "come in", r"re:\bcame in\b(?! (?:and|to|at|from)\b)",
                  # going in, said with how fast by who pours: "if i go in slow" (not the liquid going in)
                  r"re:(?:(?<=\bi )|(?<=\bwe )|(?<=\byou ))(?:go|going|went) in\b(?= (?:very |really |real |too |way )?(?:slow|fast|quick|gentl|rapid)\w*\b)", r"re:\b(?:get|gets|getting|got|go|goes|going|went|move|moves|moving"
                  r"|moved) (?:in|into) (?:position|place|hedge)\b")),
    # leaving slowly: the move away
    ("retreat", (r"re:\bleav(?:e|es|ing)\b(?= (?:very |really )?(?:slow|fast|quick|rapid|gentl)\w*\b)",)),
    ("away from", ("move away from", "pull away from")),    # a direction, not the retreat
    ("retreat", (r"re:\bpull(?:s|ed|ing)? (?:it|the \w+) (?:back|away)\b",
                 # pulled out: the move out of the pouring pose ("pull it out fast")
                 r"re:\b(?:pull(?:s|ed|ing)?|draw(?:s|ing)?|drew|yank\w*|whip\w*|tak(?:e|es|ing)|took"
                 r"|jerk\w*|snatch\w*)"
                 r"(?: (?:it|the \w+|them))?(?: straight| right)? (?:out|away|back)\b(?! of (?:the |a )?(?:context|liquid)\b)",
                 r"re:\bmov(?:e|es|ed|ing) (?:it|the \w+|them) (?:away|back|out)\b(?! from)",
                 rf"re:\b{_GLIDE}(?: it| the \w+)? (?:away|back|out)\b(?! from| of)",
                 "after pour", "after the pour", "afterwards", "move away", "pull away", "pull back",
                 "back off", "back away", "withdraw", "withdrawn", "withdrew", "retract", "withdrawal", "retraction")),
    ("start", ("begin", "at first", "at the start", "initially")),
    # a pose named by its stage, as a lab note lists them: "initial pose: 20 cm to the side"
    ("start", (r"re:\b(?:initial|starting|start) (?:pose|position|configuration|state)\b",
               r"re:\binitial\b")),
    ("pour", (r"re:\b(?:pour|pouring) (?:pose|position|configuration)\b",)),
    ("end", (r"re:\b(?:end|ending|final) (?:pose|position|configuration|state)\b",)),
)
